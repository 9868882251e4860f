// The render panel's picture options in Chromium against the real server, each seen to act: a
// transparent background leaves the corners' alpha 0, a colour background fills them with that colour,
// a shadow-catcher ground under a model adds coverage only below it, and the passes asked for each get
// a tab that shows that pass, and a denoised render is shown beside its raw colour, smoother. The controls
// take their choices from the API's document.
// Run: LIGHTPROBE_SERVER_BIN=build/bin/lightprobe-server node --test
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { useDashboard, renderShown, renderPixels, isRenderPost, waitForImage, pixelsOf, elementScreenshot, apiDocument } from './support.mjs';

const boxGlb = '/usr/share/assimp/models/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb'; // assimp-testmodels

let server, browser, page;
useDashboard({ ready: (s) => ({ server, browser, page } = s) });

const form = () => page.locator('#render-form');
const alphaAt = (image, x, y) => image.data[4 * (y * image.width + x) + 3];

test('a transparent background: the corners\' alpha is 0, the sphere\'s 255', async () => {
  await form().locator('[name=background]').selectOption('transparent');
  const { body } = await renderShown(page, { width: 32, height: 32, spp: 4 });
  assert.equal(body.background, 'transparent');
  const image = await renderPixels(page, 'format=png');
  assert.deepEqual([image.width, image.height], [32, 32]);
  for (const [x, y] of [[0, 0], [31, 0], [0, 31], [31, 31]]) assert.equal(alphaAt(image, x, y), 0, `corner ${x}, ${y}`);
  assert.equal(alphaAt(image, 16, 16), 255);
  await elementScreenshot(page, '#renders-panel', 'render-transparent');
});

test('a colour background: sent as linear RGB, seen in the corners as the colour picked', async () => {
  await form().locator('[name=tone_mapping]').selectOption('standard');
  await form().locator('[name=background]').selectOption('colour');
  await form().locator('[name=background_colour]').fill('#4080c0');
  const { body } = await renderShown(page, { width: 32, height: 32, spp: 2 });
  const expected = [0x40, 0x80, 0xc0].map((c) => ((c / 255 + 0.055) / 1.055) ** 2.4);
  body.background.forEach((v, i) => assert.ok(Math.abs(v - expected[i]) < 1e-5, `background ${body.background}`));
  const image = await renderPixels(page, 'tone_mapping=standard');
  for (const [x, y] of [[0, 0], [31, 31]]) {
    const i = 4 * (y * 32 + x);
    assert.deepEqual(image.data.slice(i, i + 4), [0x40, 0x80, 0xc0, 255], `corner ${x}, ${y}`);
  }
  await form().locator('[name=background]').selectOption('map');
  await form().locator('[name=tone_mapping]').selectOption('neutral');
});

test('a shadow-catcher ground under a model on a transparent background adds coverage below the model only', async () => {
  const upload = await fetch(`${server.base}/api/v1/assets?name=box`, { method: 'POST', body: readFileSync(boxGlb) });
  assert.equal(upload.status, 201, await upload.text());
  await form().locator('[name=preset]').focus(); // lists the uploaded assets
  await page.locator('#render-assets option[value="asset:box"]').waitFor({ state: 'attached' });
  await form().locator('[name=preset]').selectOption('asset:box');
  await form().locator('[name=background]').selectOption('transparent');
  const ground = form().locator('[name=ground]');
  assert.ok(await ground.isEnabled(), 'a ground with a model');

  // Waits for this render's own finished picture, not the one the panel showed before it.
  const renderBox = async () => {
    const answered = page.waitForResponse((r) => isRenderPost(r.request()));
    await page.locator('#render-submit').click();
    const response = await answered;
    const body = response.request().postDataJSON();
    const { id } = await response.json();
    await page.locator('#render-status[data-status=done]').waitFor({ timeout: 45000 });
    const image = await renderPixels(page, `/renders/${id}/image`);
    assert.equal(image.width, 64);
    return { body, image };
  };
  await form().locator('[name=width]').fill('64');
  await form().locator('[name=height]').fill('64');
  await form().locator('[name=spp]').fill('16');
  await ground.uncheck();
  const alone = await renderBox();
  assert.equal(alone.body.scene.objects.length, 1);
  await ground.check();
  await form().locator('[name=shadow_catcher]').check();
  const caught = await renderBox();
  assert.deepEqual(caught.body.scene.objects[1], { type: 'ground', shadow_catcher: true });

  // The ground itself is invisible: where the model alone left alpha 0, only its shadow adds alpha, most
  // of it below the model (seen from above, the ground is lower in the picture); the top corners stay
  // transparent.
  const modelRows = [];
  const shadowRows = [];
  for (let y = 0; y < 64; ++y) {
    for (let x = 0; x < 64; ++x) {
      if (alphaAt(alone.image, x, y) > 0) modelRows.push(y);
      else if (alphaAt(caught.image, x, y) > 8) shadowRows.push(y);
    }
  }
  assert.ok(modelRows.length > 100, `the model covers ${modelRows.length} pixels`);
  assert.ok(shadowRows.length > 10, `the shadow covers ${shadowRows.length} pixels`);
  const mean = (rows) => rows.reduce((a, b) => a + b, 0) / rows.length;
  assert.ok(mean(shadowRows) > mean(modelRows), `shadow rows' mean ${mean(shadowRows)}, the model's ${mean(modelRows)}`);
  for (const [x, y] of [[0, 0], [63, 0]]) assert.equal(alphaAt(caught.image, x, y), 0);
  await elementScreenshot(page, '#renders-panel', 'render-shadow-catcher');
  await ground.uncheck();
  await form().locator('[name=background]').selectOption('map');
  await form().locator('[name=preset]').selectOption('sphere');
  assert.ok(await ground.isDisabled(), 'no ground with a preset');
});

test('the passes asked for each get a tab; the albedo pass of the diffuse sphere is one flat colour', async () => {
  const names = (await apiDocument(server)).components.schemas.RenderRequest.properties.passes.items.enum.filter((n) => n !== 'color');
  const choices = page.locator('#render-pass-choices [name=pass]');
  assert.deepEqual(await choices.evaluateAll((cs) => cs.map((c) => c.value)), names);
  for (const name of names) await page.locator(`#render-pass-choices [value=${name}]`).check();
  const { id, body } = await renderShown(page, { width: 32, height: 32, spp: 4 });
  assert.deepEqual(body.passes, names);

  const tabs = page.locator('#render-passes button');
  await tabs.first().waitFor();
  assert.deepEqual(await tabs.allInnerTexts(), ['color', ...names]);
  assert.equal(await page.locator('#render-passes [aria-pressed=true]').innerText(), 'color');
  const color = await pixelsOf(page, '#render-image');
  await page.locator('#render-passes [data-pass=albedo]').click();
  const albedo = await renderPixels(page, 'pass=albedo');
  assert.equal(await page.locator('#render-passes [aria-pressed=true]').innerText(), 'albedo');
  // The sphere's middle: one albedo everywhere (0.8 grey), while its shading varies in the colour pass.
  const block = (image) => {
    const out = [];
    for (let y = 12; y < 20; ++y) for (let x = 12; x < 20; ++x) out.push(image.data.slice(4 * (y * 32 + x), 4 * (y * 32 + x) + 3).join());
    return new Set(out);
  };
  assert.equal(block(albedo).size, 1, `albedo values ${[...block(albedo)]}`);
  assert.ok(block(color).size > 1);
  assert.match(await page.locator('#render-image-downloads a[data-format=exr]').getAttribute('href'), /pass=albedo/);
  for (const name of names.filter((n) => n !== 'albedo')) {
    await page.locator(`#render-passes [data-pass=${name}]`).click();
    await renderPixels(page, `pass=${name}`);
  }
  const job = await (await fetch(`${server.base}/api/v1/renders/${id}`)).json();
  assert.equal(job.status, 'done');
  await elementScreenshot(page, '#renders-panel', 'render-passes');
  for (const name of names) await page.locator(`#render-pass-choices [value=${name}]`).uncheck();
  assert.deepEqual(browser.errors, []);
});

// The mean difference of the green channel between horizontal neighbours: noise, and the edges.
function roughness(image) {
  let sum = 0;
  for (let y = 0; y < image.height; ++y)
    for (let x = 1; x < image.width; ++x) sum += Math.abs(image.data[4 * (y * image.width + x) + 1] - image.data[4 * (y * image.width + x - 1) + 1]);
  return sum / (image.height * (image.width - 1));
}

test('denoise: the finished render shows its denoised colour beside the raw one, smoother', async (t) => {
  await form().locator('[name=preset]').selectOption('sphere');
  await form().locator('[name=denoise]').check();
  const { id, body } = await renderShown(page, { width: 64, height: 64, spp: 2 });
  assert.equal(body.denoise, true);
  await waitForImage(page, '#render-denoised img', 64);
  assert.ok(await page.locator('#render-denoised').isVisible());
  assert.match(await page.locator('#render-denoised figcaption').textContent(), /^denoised · [\d.]+ s$/);
  const status = await (await fetch(`${server.base}/api/v1/renders/${id}`)).json();
  assert.equal(status.denoised.ready, true);
  assert.deepEqual(status.passes, ['albedo', 'normal']);
  const raw = await renderPixels(page, `/renders/${id}/image`);
  const denoised = await pixelsOf(page, '#render-denoised img');
  t.diagnostic(`neighbour difference of the 8-bit green: raw ${roughness(raw).toFixed(2)}, denoised ${roughness(denoised).toFixed(2)}`);
  assert.ok(roughness(denoised) < 0.5 * roughness(raw), `roughness raw ${roughness(raw)}, denoised ${roughness(denoised)}`);
  await elementScreenshot(page, '#renders-panel', 'render-denoised');
  await form().locator('[name=denoise]').uncheck();
  await renderShown(page, { width: 32, height: 32, spp: 1 });
  assert.ok(await page.locator('#render-denoised').isHidden(), 'a render without denoise shows none');
});
