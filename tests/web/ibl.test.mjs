// The image-based-lighting parts of the dashboard in Chromium against the real server: the prefiltered
// chain as a strip (a small job followed to done, a long one cancelled), the sun marked on a map with a
// synthetic sun, and the map shown in each projection the API offers. The forms' fields, defaults and
// choices are checked against the API's OpenAPI document.
// Run: LIGHTPROBE_SERVER_BIN=build/bin/lightprobe-server node --test
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { load } from '../../web/vendor/js-yaml.min.js';
import { mapWidth, mapHeight, useDashboard, waitForImage, screenshot, elementScreenshot,
  prefilterChain, latlongPfm } from './support.mjs';

let server, browser, page;
useDashboard({ ready: (s) => ({ server, browser, page } = s) });

const deg = (rad) => (rad * 180) / Math.PI;
const shown = (x) => String(Number(x.toPrecision(4))); // the page's num()

async function apiDocument() {
  return load(await (await fetch(`${server.base}/api/v1/openapi.yaml`)).text());
}

// A smooth sky (blue, brightening to the horizon, over a dim ground): no compact emitter.
function sky([, , z]) {
  if (z < 0) return [0.25, 0.2, 0.15].map((v) => v * (1 + 0.5 * z));
  const h = (1 - z) ** 2;
  return [0.3 + 0.5 * h, 0.45 + 0.45 * h, 0.8 + 0.3 * h];
}

// The sky with a sun of radiance 5000 over every pixel centre within 2 degrees of (theta 60, phi 120).
const SUN = { theta: 60, phi: 120, radius: 2 };
function sunnySky(d) {
  const [t, p] = [SUN.theta, SUN.phi].map((a) => (a * Math.PI) / 180);
  const axis = [Math.sin(t) * Math.cos(p), Math.sin(t) * Math.sin(p), Math.cos(t)];
  const cos = d[0] * axis[0] + d[1] * axis[1] + d[2] * axis[2];
  const inside = Math.acos(Math.min(1, cos)) <= (SUN.radius * Math.PI) / 180;
  return sky(d).map((v) => v + (inside ? 5000 : 0));
}

async function upload(name, pfm) {
  const res = await fetch(`${server.base}/api/v1/envmaps?name=${name}`, { method: 'POST', body: pfm });
  assert.equal(res.status, 201, await res.text());
}

// Shows `id` in the page (reloaded to list the maps uploaded by the test).
async function selectMap(id) {
  await page.reload();
  await page.locator(`#map-list tr[data-id="${id}"]`).waitFor();
  await page.locator('#map-select').selectOption(id);
  await page.locator(`#map-list tr.selected[data-id="${id}"]`).waitFor();
  await waitForImage(page, '#map-image', mapWidth);
}

test('the prefilter form has the API\'s fields, defaults and ranges', async () => {
  const fields = (await apiDocument()).paths['/api/v1/envmaps/{id}/prefilter'].post.requestBody.content['application/json'].schema.properties;
  const form = page.locator('#prefilter-form');
  await page.waitForFunction(() => document.querySelector('#prefilter-form [name=format]').options.length > 0);
  for (const name of ['levels', 'base_size', 'samples']) {
    const input = form.locator(`[name=${name}]`);
    const [value, min, max] = await input.evaluate((i) => [i.value, i.min, i.max]);
    assert.deepEqual([value, min, max], [fields[name].default, fields[name].minimum, fields[name].maximum].map(String), name);
  }
  for (const name of ['format', 'precision']) {
    const select = form.locator(`[name=${name}]`);
    assert.deepEqual(await select.evaluate((s) => [...s.options].map((o) => o.value)), fields[name].enum, name);
    assert.equal(await select.inputValue(), fields[name].default, name);
  }
});

test('a small prefilter job reaches done and shows every level side by side at one height with its roughness', async () => {
  const id = await prefilterChain(page, { levels: 3, base_size: 16, samples: 16, format: 'exr' });
  assert.match(await page.locator('#prefilter-status').innerText(), /done · 100%$/);
  assert.equal(await page.$eval('#prefilter-progress', (bar) => bar.style.width), '100%');

  const job = await (await fetch(`${server.base}/api/v1/prefilters/${id}`)).json();
  assert.equal(job.status, 'done');
  assert.equal(job.level_info.length, 3);
  assert.match(await page.locator('#prefilter-stats').innerText(), /^chain\nforest · 3 levels from 16×8 · 16 samples\n/);
  for (const level of job.level_info)
    await waitForImage(page, `#prefilter-strip figure[data-level="${level.level}"] img`, level.width);
  const figures = page.locator('#prefilter-strip figure');
  assert.equal(await figures.count(), 3);
  const boxes = await Promise.all(job.level_info.map((_, i) => figures.nth(i).locator('img').boundingBox()));
  for (const box of boxes) assert.ok(Math.abs(box.height - boxes[0].height) < 0.5, `heights ${boxes.map((b) => b.height)}`);
  for (let i = 1; i < boxes.length; ++i) assert.ok(boxes[i].x >= boxes[i - 1].x + boxes[i - 1].width, 'side by side');
  const captions = await figures.locator('figcaption').allInnerTexts();
  assert.deepEqual(captions, job.level_info.map((l) => `r ${shown(l.roughness)}`));
  assert.deepEqual(captions, ['r 0', 'r 0.5', 'r 1']);
  const sizes = await figures.locator('img').evaluateAll((imgs) => imgs.map((i) => [i.naturalWidth, i.naturalHeight]));
  assert.deepEqual(sizes, [[16, 8], [8, 4], [4, 2]]);

  // The chain's files as links under their names, each fetched whole.
  const links = page.locator('#prefilter-downloads a');
  assert.deepEqual(await links.evaluateAll((as) => as.map((a) => a.getAttribute('download'))), job.files.map((f) => f.name));
  for (const href of await links.evaluateAll((as) => as.map((a) => a.href))) {
    const file = await fetch(href);
    assert.equal(file.status, 200, href);
    assert.equal((Buffer.from(await file.arrayBuffer())).readUInt32LE(0), 20000630, 'OpenEXR magic');
  }
  assert.ok(await page.locator('#ibl-panel .error').isHidden());
});

test('a long prefilter job shows its progress while running and is cancelled', async () => {
  const id = await prefilterChain(page, { levels: 11, base_size: 2048, samples: 1024, status: 'running' });
  assert.ok(await page.locator('#prefilter-cancel').isEnabled());
  // A row of level 1 done: the bar and the status move past 0 while it runs.
  await page.waitForFunction(() => parseFloat(document.querySelector('#prefilter-progress').style.width) > 0, null, { timeout: 30000 });
  assert.match(await page.locator('#prefilter-status').innerText(), /running · (0\.[1-9]|[1-9])[0-9.]*%$/);
  await page.locator('#prefilter-cancel').click();
  await page.locator('#prefilter-status[data-status=cancelled]').waitFor();
  const job = await (await fetch(`${server.base}/api/v1/prefilters/${id}`)).json();
  assert.equal(job.status, 'cancelled');
  assert.ok(job.progress < 1);
  assert.ok(await page.locator('#prefilter-cancel').isDisabled());
  assert.equal(await page.locator('#prefilter-strip figure').count(), 0);
  assert.ok(await page.locator('#prefilter-downloads').isHidden());
});

test('the sun is marked where the API finds it on a map with a synthetic sun, with its figures', async () => {
  await upload('sunny', latlongPfm(mapWidth, sunnySky));
  await selectMap('sunny');
  await page.locator('#sun-find').click();
  await page.locator('#sun-figures[data-found=true]').waitFor();
  const marker = page.locator('#sun-marker');
  await marker.waitFor();

  const sun = await (await fetch(`${server.base}/api/v1/envmaps/sunny/sun`, { method: 'POST', headers: { 'Content-Type': 'application/json' }, body: '{}' })).json();
  assert.equal(sun.found, true);
  assert.ok(sun.cached, 'the page asked first');
  // The API within a pixel of the synthetic sun (u = phi / 2 pi, v = theta / pi of the map).
  const [x, y] = [(sun.phi / (2 * Math.PI)) * mapWidth, (sun.theta / Math.PI) * mapHeight];
  assert.ok(Math.abs(x - (SUN.phi / 360) * mapWidth) <= 1, `x ${x}`);
  assert.ok(Math.abs(y - (SUN.theta / 180) * mapHeight) <= 1, `y ${y}`);
  assert.deepEqual(sun.pixel, [Math.floor(x), Math.floor(y)]);

  // The marker's centre over that point of the displayed map, to half a map pixel.
  const [image, ring] = await Promise.all([page.locator('#map-image').boundingBox(), marker.boundingBox()]);
  const centre = [(ring.x + ring.width / 2 - image.x) / image.width * mapWidth, (ring.y + ring.height / 2 - image.y) / image.height * mapHeight];
  assert.ok(Math.abs(centre[0] - x) <= 0.5 && Math.abs(centre[1] - y) <= 0.5, `marker at ${centre}, sun at ${[x, y]}`);
  // As tall as the cone (2 r / pi of the map), or the smallest visible mark.
  assert.ok(Math.abs(ring.height - Math.max(14, (2 * sun.angular_radius / Math.PI) * image.height)) <= 1, `marker ${ring.height} px tall`);

  await page.locator('#map-list tr[data-id="sunny-sun"]').waitFor(); // the residual, listed
  const figures = await page.locator('#sun-figures').innerText();
  for (const text of [`θ ${shown(deg(sun.theta))}°, φ ${shown(deg(sun.phi))}°`, `pixel ${sun.pixel[0]}, ${sun.pixel[1]}`,
    `${shown(deg(sun.angular_radius))}°`, `[${sun.irradiance.map(shown).join(', ')}]`, `${Number((100 * sun.share).toPrecision(3))} %`, 'sunny-sun'])
    assert.ok(figures.includes(text), `${text} not in:\n${figures}`);
  await screenshot(page, 'sun-marker');
  await elementScreenshot(page, '#maps-panel', 'maps-panel-sun');
});

test('a map without a sun says so, with the API\'s reason, and shows no marker', async () => {
  await upload('overcast', latlongPfm(mapWidth, sky));
  await selectMap('overcast');
  assert.ok(await page.locator('#sun-marker').isHidden(), 'no marker of the last map');
  await page.locator('#sun-find').click();
  await page.locator('#sun-figures[data-found=false]').waitFor();
  const sun = await (await fetch(`${server.base}/api/v1/envmaps/overcast/sun`, { method: 'POST', headers: { 'Content-Type': 'application/json' }, body: '{}' })).json();
  assert.equal(sun.found, false);
  assert.equal(await page.locator('#sun-figures').innerText(),
    `sun\nnone in this map: ${sun.reason}\nsun parameters\nthreshold ${shown(sun.parameters.min_contrast)} times the sky around it, least share ${shown(sun.parameters.min_share)}`);
  assert.ok(await page.locator('#sun-marker').isHidden());
  assert.ok(await page.locator('#maps-panel .error').isHidden());
});

test('the projection select offers the API\'s projections and shows each at its size', async () => {
  await selectMap('sunny');
  await page.locator('#sun-find').click();
  await page.locator('#sun-marker').waitFor();
  const projection = (await apiDocument()).paths['/api/v1/envmaps/{id}/image'].get.parameters.find((p) => p.name === 'projection').schema;
  const select = page.locator('#map-projection');
  assert.deepEqual(await select.evaluate((s) => [...s.options].map((o) => o.value)), projection.enum);
  assert.equal(await select.inputValue(), projection.default);
  // Without `size`: a face of width / 4 for cube and cross, a side of width / 2 for the squares.
  const n = mapWidth / 4;
  const expected = { cube: [6 * n, n], cross: [4 * n, 3 * n], octahedral: [2 * n, 2 * n], 'equal-area': [2 * n, 2 * n], latlong: [mapWidth, mapHeight] };
  for (const name of [...projection.enum.filter((p) => p !== 'latlong'), 'latlong']) {
    await select.selectOption(name);
    await page.waitForFunction((p) => document.querySelector('#map-image').src.includes(`projection=${p}`), name);
    await page.waitForFunction(([w, h]) => {
      const img = document.querySelector('#map-image');
      return img.complete && img.naturalWidth === w && img.naturalHeight === h;
    }, expected[name]);
    assert.equal(await page.locator('#map-view').getAttribute('data-projection'), name);
    assert.equal(await page.locator('#sun-marker').isVisible(), name === 'latlong', `marker with ${name}`);
    const png = page.locator('#map-image-downloads a[data-format=png]');
    assert.match(await png.getAttribute('href'), new RegExp(`projection=${name}`));
    if (name === 'cross') await elementScreenshot(page, '#maps-panel', 'maps-panel-cross');
  }
  assert.deepEqual(browser.errors, []);
});

test('the IBL panel in a screenshot, its strip of a six-level chain', async () => {
  await prefilterChain(page, { levels: 6, base_size: 128, samples: 64 });
  await waitForImage(page, '#prefilter-strip figure[data-level="5"] img', 4);
  await elementScreenshot(page, '#ibl-panel', 'ibl-panel');
  assert.deepEqual(browser.errors, []);
});

test('the sun threshold is the API\'s, and the one set decides whether the sun is found', async () => {
  const fields = (await apiDocument()).components.schemas.SunParameters.properties;
  const input = page.locator('#sun-form [name=min_contrast]');
  await page.waitForFunction(() => document.querySelector('#sun-form [name=min_contrast]').value !== '');
  const [value, min, max] = await input.evaluate((i) => [i.value, i.min, i.max]);
  const want = fields.min_contrast;
  assert.deepEqual([value, min, max], [want.default, want.minimum, want.maximum].map(String));

  await upload('sunny_threshold', latlongPfm(mapWidth, sunnySky));
  await selectMap('sunny_threshold');
  const post = async (body) => (await fetch(`${server.base}/api/v1/envmaps/sunny_threshold/sun`,
    { method: 'POST', headers: { 'Content-Type': 'application/json' }, body: JSON.stringify(body) })).json();
  const sun = await post({});
  assert.equal(sun.found, true);

  // Above the sun's contrast: none, and the figures say why and with which threshold.
  const high = 10 ** Math.ceil(Math.log10(sun.contrast * 2));
  await input.fill(String(high));
  await page.locator('#sun-find').click();
  await page.locator('#sun-figures[data-found=false]').waitFor();
  const figures = await page.locator('#sun-figures').innerText();
  assert.match(figures, /min_contrast/);
  assert.match(figures, new RegExp(`threshold ${shown(high)} times`));
  assert.equal((await post({ min_contrast: high })).cached, true, 'the page asked with it');
  // Under it: found again.
  await input.fill(String(Math.floor(sun.contrast / 2)));
  await page.locator('#sun-find').click();
  await page.locator('#sun-figures[data-found=true]').waitFor();
  await screenshot(page, 'sun-threshold');
});
