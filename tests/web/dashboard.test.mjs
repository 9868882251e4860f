// The dashboard in a real browser (Debian's Chromium through playwright-core) against the real
// server binary ($LIGHTPROBE_SERVER_BIN) holding a real map: every panel is used as a person would and
// checked against what the API says. Run: LIGHTPROBE_SERVER_BIN=build/bin/lightprobe-server node --test
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { envmaps, mapWidth, mapHeight, useDashboard, eventually, naturalWidth, waitForImage, screenshot,
  renderSphere, isRenderPost, download, pngSize, isExr, pfmValues } from './support.mjs';

const boxGlb = '/usr/share/assimp/models/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb'; // assimp-testmodels

let server, browser, page;
useDashboard({
  ready: (s) => ({ server, browser, page } = s),
  atEnd: (last) => screenshot(last, 'dashboard-end', { wholePage: true }),
});

test('the server serves the page at / and keeps the API and its JSON 404', async () => {
  const index = await fetch(`${server.base}/`);
  assert.equal(index.status, 200);
  assert.match(index.headers.get('content-type'), /text\/html/);
  const module = await fetch(`${server.base}/js/main.js`);
  assert.equal(module.status, 200);
  assert.match(module.headers.get('content-type'), /javascript/);
  const health = await (await fetch(`${server.base}/api/v1/health`)).json();
  assert.equal(health.status, 'ok');
  const missing = await fetch(`${server.base}/api/v1/no-such-thing`);
  assert.equal(missing.status, 404);
  assert.equal((await missing.json()).error.code, 'not_found');
});

test('maps panel lists the loaded map with its metadata and preview', async () => {
  const row = page.locator('#map-list tr[data-id="forest"]');
  await row.waitFor();
  const meta = await (await fetch(`${server.base}/api/v1/envmaps/forest`)).json();
  assert.match(await row.innerText(), new RegExp(`forest\\s+${mapWidth}×${mapHeight}\\s+exr`));
  assert.equal(await page.locator('#map-select').inputValue(), 'forest');
  await waitForImage(page, '#map-image', mapWidth);
  const shown = await page.locator('#map-meta').innerText();
  assert.ok(shown.includes(`${mapWidth} × ${mapHeight}`), shown);
  assert.ok(shown.includes(String(Number(meta.max_luminance.toPrecision(4)))), `max luminance ${meta.max_luminance} in:\n${shown}`);

  // The exposure slider asks the server for a brighter picture.
  await page.locator('#map-exposure').fill('2');
  await page.waitForFunction(() => document.querySelector('#map-image').src.includes('exposure=2'));
  await waitForImage(page, '#map-image', mapWidth);
});

test('upload shows the server error for a bad file, loads a real one, and delete unloads it', async () => {
  await page.locator('#upload-file').setInputFiles({ name: 'bad.exr', mimeType: 'application/octet-stream', buffer: Buffer.from('not an image at all') });
  await page.locator('#upload-name').fill('bad');
  await page.locator('#upload-form button[type=submit]').click();
  const error = page.locator('#maps-panel .error');
  await error.waitFor({ state: 'visible' });
  assert.match(await error.innerText(), /^415 unsupported_media_type: /);

  await page.locator('#upload-file').setInputFiles(path.join(envmaps, 'forest.pfm'));
  assert.equal(await page.locator('#upload-name').inputValue(), 'bad'); // kept: the user typed it
  await page.locator('#upload-name').fill('forest_pfm');
  await page.locator('#upload-form button[type=submit]').click();
  await page.locator('#map-list tr[data-id="forest_pfm"].selected').waitFor();
  assert.ok(await error.isHidden());
  assert.match(await page.locator('#map-meta').innerText(), /upload/);

  const del = page.locator('#map-list tr[data-id="forest_pfm"] button');
  await del.click(); // arms
  await del.click(); // deletes
  await page.locator('#map-list tr[data-id="forest_pfm"]').waitFor({ state: 'detached' });
  assert.equal(await page.locator('#map-select').inputValue(), 'forest');
  const { envmaps: left } = await (await fetch(`${server.base}/api/v1/envmaps`)).json();
  assert.deepEqual(left.map((m) => m.id), ['forest']);
});

test('sampling panel shows where samples fall and the marginal pdf / cdf charts', async () => {
  await waitForImage(page, '#samples-image', mapWidth);
  // Both series of the pdf chart are densities in v over the map's rows: each integrates to 1.
  const sums = await page.waitForFunction((rows) => {
    const plot = document.querySelector('#pdf-chart')?.chart?.plot;
    if (!plot || plot.data[0].length !== rows) return null;
    return plot.data.slice(1).map((ys) => ys.reduce((a, b) => a + b, 0) / ys.length);
  }, mapHeight);
  for (const s of await sums.jsonValue()) assert.ok(Math.abs(s - 1) < 1e-6, `pdf integrates to ${s}`);
  const cdfEnd = await page.$eval('#cdf-chart', (c) => c.chart.plot.data.slice(1).map((ys) => ys[ys.length - 1]));
  for (const v of cdfEnd) assert.ok(Math.abs(v - 1) < 1e-6, `cdf ends at ${v}`);
  assert.ok(await page.locator('#pdf-chart canvas').isVisible());
  assert.match(await page.locator('#pdf-chart .u-legend').innerText(), /with sin θ[\s\S]*without/);

  await page.locator('#sampling-form [name=strategy]').selectOption('sobol');
  await page.locator('#sampling-form [name=style]').selectOption('windows');
  await page.waitForFunction(() => /strategy=sobol.*style=windows/.test(document.querySelector('#samples-image').src));
  assert.equal(await naturalWidth(page, '#samples-image'), mapWidth);
  await page.locator('#sampling-form [name=style]').selectOption('marks');
  await page.waitForFunction(() => /style=marks/.test(document.querySelector('#samples-image').src));
});

test('Fresnel chart marks Brewster 55.4 for air to eta 1.45, and the critical angle back out', async () => {
  await page.locator('#fresnel-form [name=eta_t]').fill('1.45');
  await page.locator('#fresnel-stats').filter({ hasText: 'Brewster angle55.4°' }).waitFor();
  assert.equal(await page.locator('#fresnel-preset').inputValue(), 'custom');
  const stats = await page.locator('#fresnel-stats').innerText();
  const table = await (await fetch(`${server.base}/api/v1/fresnel?eta_i=1&eta_t=1.45&step=0.25`)).json();
  assert.ok(stats.includes(`R0 (normal incidence)\n${Number(table.r0.toPrecision(4))}`), stats);
  assert.ok(stats.includes(`Schlick max |error|\n${Number(table.schlick_max_abs_error.toPrecision(4))} at ${table.schlick_max_error_angle_deg.toFixed(1)}°`), stats);
  assert.match(stats, /critical angle\nnone/);
  const series = await page.$eval('#fresnel-chart', (c) => c.chart.plot.series.slice(1).map((s) => s.label));
  assert.deepEqual(series, ['rs', 'rp', 'unpolarized', 'Schlick']);
  assert.ok(await page.locator('#fresnel-chart canvas').isVisible());

  await page.locator('#fresnel-preset').selectOption({ label: 'glass → air' });
  await page.locator('#fresnel-stats').filter({ hasText: 'critical angle41.8°' }).waitFor();
  await page.locator('#fresnel-preset').selectOption({ label: 'gold' });
  await page.locator('#fresnel-stats').filter({ hasText: 'conductorgold' }).waitFor();
  assert.ok(await page.locator('#fresnel-form [name=eta_t]').isDisabled());
  await page.locator('#fresnel-preset').selectOption({ label: 'air → glass 1.5' });
  await page.locator('#fresnel-stats').filter({ hasText: 'Brewster angle56.3°' }).waitFor();
});

test('median cut shows N lights of nearly equal energy and their picture', async () => {
  await page.locator('#median-cut-form [name=count]').fill('16');
  await page.locator('#median-cut-stats').filter({ hasText: '16 lights' }).waitFor();
  await page.waitForFunction(() => document.querySelector('#median-cut-image').src.includes('count=16'));
  await waitForImage(page, '#median-cut-image', mapWidth);
  const api = await (await fetch(`${server.base}/api/v1/envmaps/forest/median-cut`, { method: 'POST', headers: { 'Content-Type': 'application/json' }, body: '{"count":16}' })).json();
  const stats = await page.locator('#median-cut-stats').innerText();
  assert.ok(stats.includes(`${Number(api.energy_min.toPrecision(4))} / ${Number(api.energy_max.toPrecision(4))}`), stats);
  assert.equal(await page.locator('#median-cut-lights tbody tr').count(), 5);
});

test('the SH panel shows the reconstruction, the API\'s coefficients and the BRDF table', async () => {
  await page.locator('#sh-form [name=bands]').selectOption('2');
  await page.waitForFunction(() => document.querySelector('#sh-image').src.includes('bands=2'));
  await waitForImage(page, '#sh-image', mapWidth);
  await page.locator('#sh-coefficients tbody tr').nth(3).waitFor();
  assert.equal(await page.locator('#sh-coefficients tbody tr').count(), 4);
  const api = await (await fetch(`${server.base}/api/v1/envmaps/forest/sh?bands=2`)).json();
  const first = await page.locator('#sh-coefficients tbody tr').first().innerText();
  const l00 = api.radiance.coefficients[0].rgb.map((x) => Number(x.toPrecision(4))).join(', ');
  assert.ok(first.includes(`[${l00}]`), `${first} vs ${l00}`);
  await page.locator('#sh-form [name=quantity]').selectOption('lambertian');
  await page.waitForFunction(() => document.querySelector('#sh-image').src.includes('quantity=lambertian'));
  await page.locator('#lut-form [name=size]').selectOption('64');
  await page.waitForFunction(() => document.querySelector('#lut-image').src.includes('size=64'));
  await waitForImage(page, '#lut-image', 64);
  assert.equal(await page.locator('#lut-image-downloads a[data-format=exr]').getAttribute('download'), 'brdf-lut-64.exr');
});

test('a small render streams its progress to done and shows its image', async () => {
  const id = await renderSphere(page, { width: 32, height: 32, spp: 4 });
  await waitForImage(page, '#render-image', 32);
  assert.match(await page.locator('#render-status').innerText(), /done · 100%/);
  assert.match(await page.locator('#render-stats').innerText(), /4 \/ 4 spp/);
  assert.equal(await page.$eval('#render-progress', (bar) => bar.style.width), '100%');
  const job = await (await fetch(`${server.base}/api/v1/renders/${id}`)).json();
  assert.equal(job.status, 'done');
  assert.equal(job.spp_done, 4);
  assert.equal(job.sampling, 'uniform');
  // The page followed the job through its event stream (the server logs it when the stream ends).
  await eventually('the events stream in the server log', () => server.log.join('').includes(`GET /api/v1/renders/${id}/events 200`));
  await page.locator(`#render-jobs tr[data-id="${id}"][data-status=done]`).waitFor();
  assert.ok(await page.locator('#renders-panel .error').isHidden());

  const adaptive = await renderSphere(page, { width: 32, height: 32, spp: 8, sampling: 'adaptive' });
  const adaptiveJob = await (await fetch(`${server.base}/api/v1/renders/${adaptive}`)).json();
  assert.deepEqual([adaptiveJob.status, adaptiveJob.spp_done, adaptiveJob.sampling], ['done', 8, 'adaptive']);
  await page.locator('#render-form [name=sampling]').selectOption('uniform');
});

async function finished(id) {
  for (;;) {
    const job = await (await fetch(`${server.base}/api/v1/renders/${id}`)).json();
    if (!['queued', 'running'].includes(job.status)) return job;
    await new Promise((r) => setTimeout(r, 100));
  }
}

test('map rotation, intensity and visibility go with the render; the intensity scales the image', async () => {
  const form = page.locator('#render-form');
  await form.locator('[name=rotation_deg]').fill('90');
  await form.locator('[name=intensity]').fill('2.5');
  await form.locator('[name=visible]').uncheck();
  const posted = page.waitForRequest(isRenderPost);
  const id = await renderSphere(page, { width: 16, height: 16, spp: 2 });
  const request = (await posted).postDataJSON();
  assert.deepEqual(request.lighting, { mode: 'envmap', rotation_deg: 90, intensity: 2.5, visible: false });

  // The same request at intensity 1 (same seed): every pixel 2.5 times smaller; the corners (the map,
  // hidden) black.
  const answer = await fetch(`${server.base}/api/v1/renders`, {
    method: 'POST', headers: { 'Content-Type': 'application/json' },
    body: JSON.stringify({ ...request, lighting: { ...request.lighting, intensity: 1 } }),
  });
  assert.equal(answer.status, 202);
  const unit = await finished((await answer.json()).id);
  assert.equal(unit.status, 'done');
  const pfm = async (job) => pfmValues(Buffer.from(await (await fetch(`${server.base}/api/v1/renders/${job}/image?format=pfm`)).arrayBuffer()));
  const [bright, plain] = [await pfm(id), await pfm(unit.id)];
  assert.ok(plain.some((v) => v > 0.01));
  plain.forEach((v, i) => assert.ok(Math.abs(bright[i] - 2.5 * v) <= 1e-5 * 2.5 * v, `value ${i}: ${bright[i]} against 2.5 × ${v}`));
  assert.deepEqual([bright[0], bright[1], bright[2]], [0, 0, 0]);

  await form.locator('[name=rotation_deg]').fill('0');
  await form.locator('[name=intensity]').fill('1');
  await form.locator('[name=visible]').check();
});

// The message shown next to a control, which must be the next thing after the control's label.
async function messageBeside(control) {
  await control.and(page.locator('[aria-invalid=true]')).waitFor();
  return control.evaluate((c) => {
    const box = document.getElementById(c.getAttribute('aria-describedby'));
    const label = c.closest('label');
    if (!box || label.nextElementSibling !== box) return null;
    const [a, b] = [label.getBoundingClientRect(), box.getBoundingClientRect()];
    return Math.abs(b.top - a.top) <= 2 * a.height + 8 ? box.textContent : null;
  });
}

test('a value out of range is refused beside its field: by the browser before sending, else by the API', async () => {
  const posts = [];
  const onRequest = (request) => { if (isRenderPost(request)) posts.push(request); };
  page.on('request', onRequest);
  const form = page.locator('#render-form');
  const intensity = form.locator('[name=intensity]');
  await intensity.fill('-1');
  await page.locator('#render-submit').click();
  assert.equal(await messageBeside(intensity), await intensity.evaluate((c) => c.validationMessage));
  assert.match(await messageBeside(intensity), /0/);
  await intensity.fill('1'); // typing clears the message
  await form.locator('#render-form-intensity-error').waitFor({ state: 'detached' });
  assert.equal(posts.length, 0);

  // Past --max-render-spp: the page cannot know that limit, the API's answer names the field.
  const spp = form.locator('[name=spp]');
  await spp.fill('10000000');
  await page.locator('#render-submit').click();
  assert.equal(await messageBeside(spp), "field 'spp': must be in [1, 65536], got 10000000");
  assert.equal(posts.length, 1);
  assert.ok(await page.locator('#renders-panel .error').isHidden());
  await spp.fill('4');
  assert.equal(await spp.getAttribute('aria-invalid'), null);

  // A panel that updates as values are typed: median cut past --max-lights, then back.
  const lights = page.locator('#median-cut-form [name=count]');
  await lights.fill('100000');
  assert.equal(await messageBeside(lights), "field 'count': must be in [1, 65536], got 100000");
  await lights.fill('16');
  await page.locator('#median-cut-stats').filter({ hasText: '16 lights' }).waitFor();
  assert.equal(await lights.getAttribute('aria-invalid'), null);
  page.off('request', onRequest);
});

// Both figures of the side-by-side view end done with a 48-pixel-wide image (saved as PNG and EXR
// by its links) and a caption naming the option's value and the render time; the two newest jobs are
// the request with the option each way ([value, its name in the caption]).
async function expectComparison(option, label, sides = [[true, 'on'], [false, 'off']]) {
  for (const [value, name] of sides) {
    const figure = page.locator(`#render-compare figure[data-option=${option}][data-value=${value}]`);
    await figure.and(page.locator('[data-status=done]')).waitFor({ timeout: 45000 });
    await waitForImage(page, `#render-compare figure[data-value=${value}] img`, 48);
    assert.match(await figure.locator('figcaption').innerText(), new RegExp(`^${label} ${name} · done · [0-9.e-]+ s$`));
    const png = await download(page, figure.locator('.downloads [data-format=png]'));
    assert.match(png.name, /^render-[0-9a-f]{16}\.png$/);
    assert.deepEqual(pngSize(png.bytes), [48, 32]);
    assert.ok(isExr((await download(page, figure.locator('.downloads [data-format=exr]'))).bytes));
  }
  const { renders } = await (await fetch(`${server.base}/api/v1/renders`)).json();
  const [first, second] = renders.slice(-2);
  assert.deepEqual([first[option], second[option], first.status, second.status], [sides[0][0], sides[1][0], 'done', 'done']);
  return [first, second];
}

test('two renders side by side: the textured preset with mipmaps on and off, an uploaded model with normal maps on and off, the sphere sampled adaptively and uniformly', async () => {
  const upload = await fetch(`${server.base}/api/v1/assets?name=box`, { method: 'POST', body: readFileSync(boxGlb) });
  assert.equal(upload.status, 201, await upload.text());
  const form = page.locator('#render-form');
  await form.locator('[name=preset]').selectOption('textured');
  await form.locator('[name=width]').fill('48');
  await form.locator('[name=height]').fill('32');
  await form.locator('[name=spp]').fill('2');
  await form.locator('[name=compare]').selectOption('mipmaps');
  await page.locator('#render-submit').click();
  const textured = await expectComparison('mipmaps', 'mipmaps');
  assert.deepEqual(textured.map((j) => [j.scene.preset, j.spp_done]), [['textured', 2], ['textured', 2]]);

  await form.locator('[name=preset]').focus(); // lists the uploaded assets
  await page.locator('#render-assets option[value="asset:box"]').waitFor({ state: 'attached' });
  await form.locator('[name=preset]').selectOption('asset:box');
  await form.locator('[name=compare]').selectOption('normal_maps');
  await page.locator('#render-submit').click();
  const box = await expectComparison('normal_maps', 'normal maps');
  assert.deepEqual(box.map((j) => j.scene.objects), [1, 1]);
  assert.ok(await page.locator('#renders-panel .error').isHidden());

  // Uniform and adaptive sampling at the same mean spp.
  await form.locator('[name=preset]').selectOption('sphere');
  await form.locator('[name=spp]').fill('8');
  await form.locator('[name=compare]').selectOption('sampling');
  await page.locator('#render-submit').click();
  const sampling = await expectComparison('sampling', 'sampling', [['adaptive', 'adaptive'], ['uniform', 'uniform']]);
  assert.deepEqual(sampling.map((j) => j.spp_done), [8, 8]);

  // Back to one render of the sphere for the next test.
  await form.locator('[name=compare]').selectOption('');
});

test('a long render shows its passes while running and can be cancelled', async () => {
  const form = page.locator('#render-form');
  await form.locator('[name=width]').fill('128');
  await form.locator('[name=height]').fill('96');
  await form.locator('[name=spp]').fill('65536');
  await page.locator('#render-submit').click();
  await page.locator('#render-status[data-status=running]').waitFor();
  await waitForImage(page, '#render-image', 128); // a finished pass, long before the end
  const id = (await page.locator('#render-status').innerText()).split(' ')[0];
  await page.locator('#render-cancel').click();
  await page.locator('#render-status[data-status=cancelled]').waitFor();
  const job = await (await fetch(`${server.base}/api/v1/renders/${id}`)).json();
  assert.equal(job.status, 'cancelled');
  assert.ok(job.spp_done >= 1 && job.spp_done < 65536, `spp_done ${job.spp_done}`);
  assert.equal(await naturalWidth(page, '#render-image'), 128);
  assert.ok(await page.locator('#render-cancel').isDisabled());
  await page.locator(`#render-jobs tr[data-id="${id}"][data-status=cancelled]`).waitFor();
  // Back to the small render for the screenshot, and nothing threw in the page all along.
  await form.locator('[name=spp]').fill('4');
  assert.deepEqual(browser.errors, []);
});
