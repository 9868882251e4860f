// The tone curves in the dashboard, in Chromium against the real server: the render panel's tone
// mapper goes with the request and changes the picture shown (standard is the sRGB curve of the linear
// image), and the map preview offers the image endpoint's curves. The selects take their choices from
// the API's document.
// Run: LIGHTPROBE_SERVER_BIN=build/bin/lightprobe-server node --test
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { useDashboard, renderShown, renderPixels, waitForImage, pixelsOf, pfmValues, srgb8, apiDocument, mapWidth, mapHeight } from './support.mjs';

let server, browser, page;
useDashboard({ ready: (s) => ({ server, browser, page } = s) });

const form = () => page.locator('#render-form');

test('the tone mapper select offers the API\'s curves, goes with the request and changes the picture', async () => {
  const schema = (await apiDocument(server)).components.schemas.RenderRequest.properties.tone_mapping;
  const select = form().locator('[name=tone_mapping]');
  await select.waitFor();
  assert.deepEqual(await select.evaluate((s) => [...s.options].map((o) => o.value)), schema.enum);
  assert.equal(await select.inputValue(), 'neutral');

  await select.selectOption('standard');
  const { id, body } = await renderShown(page, { width: 32, height: 32, spp: 4 });
  assert.equal(body.tone_mapping, 'standard');
  // Standard: the sRGB curve of the linear image at exposure 0.
  const linear = pfmValues(Buffer.from(await (await fetch(`${server.base}/api/v1/renders/${id}/image?format=pfm`)).arrayBuffer()));
  const standard = await renderPixels(page, 'tone_mapping=standard');
  for (let i = 0; i < 32 * 32; ++i) {
    const row = 31 - Math.floor(i / 32); // a PFM's rows run bottom to top
    for (let c = 0; c < 3; ++c) {
      const v = linear[3 * (row * 32 + (i % 32)) + c];
      assert.ok(Math.abs(standard.data[4 * i + c] - srgb8(v)) <= 1, `pixel ${i}: ${v} shown as ${standard.data[4 * i + c]}`);
    }
  }

  // Another curve shows the same render otherwise: the picture changes, the job does not.
  await select.selectOption('agx');
  const agx = await renderPixels(page, 'tone_mapping=agx');
  let difference = 0;
  for (let i = 0; i < agx.data.length; ++i) if (i % 4 !== 3) difference += Math.abs(agx.data[i] - standard.data[i]);
  assert.ok(difference / (3 * 32 * 32) > 2, `mean change ${difference / (3 * 32 * 32)} of 255`);
  assert.match(await page.locator('#render-status').innerText(), new RegExp(`^${id} · done`));
  await select.selectOption('neutral');
});

test('the map preview offers the image endpoint\'s tone curves, standard first chosen, and each changes the picture', async () => {
  const parameter = (await apiDocument(server)).components.parameters.ToneMapping.schema;
  const select = page.locator('#map-tone-mapping');
  await select.waitFor();
  assert.deepEqual(await select.evaluate((s) => [...s.options].map((o) => o.value)), parameter.enum);
  assert.equal(await select.inputValue(), 'standard');
  const shown = async (curve) => {
    await page.waitForFunction((c) => document.querySelector('#map-image').src.includes(`tone_mapping=${c}`), curve);
    await waitForImage(page, '#map-image', mapWidth);
    return pixelsOf(page, '#map-image');
  };
  await select.selectOption('reinhard');
  const reinhard = await shown('reinhard');
  await select.selectOption('standard');
  const standard = await shown('standard');
  // Reinhard's x / (1 + x) darkens every channel short of black.
  let darker = 0;
  for (let i = 0; i < standard.data.length; i += 4) if (reinhard.data[i] < standard.data[i]) ++darker;
  assert.ok(darker > 0.9 * mapWidth * mapHeight, `${darker} pixels darker`);
});
