// A turntable of an uploaded model from the Models panel in Chromium against the real server: a short
// one runs to done and plays in the page as an animated WebP of as many frames as asked, its files
// offered; a long one shows its progress and is cancelled. The form's fields take their ranges and
// defaults from the API's document. Run: LIGHTPROBE_SERVER_BIN=build/bin/lightprobe-server node --test
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { useDashboard, fillForm, waitForImage, elementScreenshot, download, pngSize, apiDocument } from './support.mjs';

const boxGlb = '/usr/share/assimp/models/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb'; // assimp-testmodels

let server, browser, page;
useDashboard({ ready: (s) => ({ server, browser, page } = s) });

const isTurntablePost = (r) => r.request().method() === 'POST' && new URL(r.url()).pathname === '/api/v1/turntables';

// Starts a turntable of the selected model through the form; its id, once the status shows `state`.
async function turntable(values, state) {
  await fillForm(page, '#turntable-form', values);
  const [answer] = await Promise.all([page.waitForResponse(isTurntablePost), page.locator('#turntable-submit').click()]);
  assert.equal(answer.status(), 202, await answer.text());
  const { id } = await answer.json();
  await page.locator(`#turntable-status[data-status=${state}]`, { hasText: id }).waitFor({ timeout: 60000 });
  return id;
}

test('the turntable form has the API\'s fields and defaults', async () => {
  const upload = await fetch(`${server.base}/api/v1/assets?name=box`, { method: 'POST', body: readFileSync(boxGlb) });
  assert.equal(upload.status, 201, await upload.text());
  await page.reload();
  await page.locator('#model-list tr[data-id="box"].selected').waitFor();
  await page.locator('#turntable-section').waitFor();
  const doc = await apiDocument(server);
  const fields = doc.components.schemas.Turntable.properties;
  for (const name of ['frames', 'azimuth_start_deg', 'elevation_deg', 'elevation_sweep_deg']) {
    const input = page.locator(`#turntable-form [name=${name}]`);
    const [value, min, max] = await input.evaluate((i) => [i.value, i.min, i.max]);
    const schema = fields[name];
    if (schema.default !== undefined) assert.equal(value, String(schema.default), name);
    if (schema.minimum !== undefined) assert.equal(min, String(schema.minimum), name);
    if (schema.maximum !== undefined) assert.equal(max, String(schema.maximum), name);
  }
  assert.ok(await page.locator('#turntable-submit').isEnabled());
});

test('a turntable of eight frames runs to done and plays as an animation of eight frames, with its files', async () => {
  const id = await turntable({ frames: 8, width: 32, height: 32, spp: 2, elevation_sweep_deg: 20, fps: 8 }, 'done');
  assert.match(await page.locator('#turntable-status').innerText(), /done · 100%$/);
  assert.equal(await page.$eval('#turntable-progress', (bar) => bar.style.width), '100%');
  const status = await (await fetch(`${server.base}/api/v1/turntables/${id}`)).json();
  assert.deepEqual([status.frames, status.frames_done, status.cameras.length], [8, 8, 8]);

  await page.locator(`#turntable-player[data-animation="${id}"]`).waitFor({ state: 'attached' });
  await waitForImage(page, '#turntable-player', 32);
  const player = await page.$eval('#turntable-player', async (img) => {
    const blob = await (await fetch(img.src)).blob();
    const decoder = new ImageDecoder({ data: blob.stream(), type: 'image/webp' });
    await decoder.tracks.ready;
    const track = decoder.tracks.selectedTrack;
    const first = await decoder.decode({ frameIndex: 0 });
    const size = [first.image.displayWidth, first.image.displayHeight];
    first.image.close();
    return { src: img.src, type: blob.type, frames: track.frameCount, animated: track.animated, size };
  });
  assert.match(player.src, new RegExp(`/api/v1/turntables/${id}/animation\\.webp\\?fps=8$`));
  assert.equal(player.type, 'image/webp');
  assert.deepEqual([player.frames, player.animated, player.size], [8, true, [32, 32]]);

  const zip = await download(page, page.locator('#turntable-downloads a[data-format=zip]'));
  assert.equal(zip.name, `turntable-${id}-frames.zip`);
  assert.equal(zip.bytes.readUInt32LE(0), 0x04034b50, 'a zip');
  for (let i = 0; i < 8; ++i) assert.ok(zip.bytes.includes(`frame_000${i}.png`), `frame ${i} in the zip`);
  const sheet = await download(page, page.locator('#turntable-downloads a[data-format=png]'));
  assert.equal(sheet.name, `turntable-${id}-contact-sheet.png`);
  assert.deepEqual(pngSize(sheet.bytes), [3 * 32, 3 * 32], 'eight frames on a sheet of 3 x 3');
  await elementScreenshot(page, '#models-panel', 'turntable');
});

test('a long turntable shows its frames and progress while it runs and is cancelled', async () => {
  const id = await turntable({ frames: 720, width: 64, height: 64, spp: 64, elevation_sweep_deg: 0, fps: 12 }, 'running');
  assert.ok(await page.locator('#turntable-cancel').isEnabled());
  await page.waitForFunction(() => parseFloat(document.querySelector('#turntable-progress').style.width) > 0, null, { timeout: 60000 });
  await page.waitForFunction((t) => document.querySelector('#turntable-player').src.includes(`/turntables/${t}/frames/`), id, { timeout: 60000 });
  await page.locator('#turntable-cancel').click();
  await page.locator('#turntable-status[data-status=cancelled]').waitFor({ timeout: 30000 });
  const status = await (await fetch(`${server.base}/api/v1/turntables/${id}`)).json();
  assert.equal(status.status, 'cancelled');
  assert.ok(status.frames_done < 720 && status.progress < 1, `${status.frames_done} frames done`);
  assert.ok(await page.locator('#turntable-cancel').isDisabled());
  assert.ok(await page.locator('#turntable-downloads').isHidden());
  assert.deepEqual(browser.errors, []);
});
