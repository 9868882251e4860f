// The figures of the dashboard drawn from the API's numbers, in Chromium against the real server: the
// median-cut lights over the map as discs of area proportional to their energy with a scale, the SH
// reconstruction with its signs (checked against the server's own picture and against the analytic
// reconstruction of a hemisphere map, whose second band dips below 0), the BRDF table's axes, and the
// spp fields wide enough for the largest value the server accepts.
// Run: LIGHTPROBE_SERVER_BIN=build/bin/lightprobe-server node --test
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { shReconstruct } from '../../web/js/sh_basis.js';
import { mapWidth, mapHeight, useDashboard, waitForImage, elementScreenshot, pixelsOf, flagMaximum, srgb8,
  latlongPfm } from './support.mjs';

let server, browser, page;
useDashboard({ ready: (s) => ({ server, browser, page } = s) });

const shown = (x) => String(Number(x.toPrecision(4))); // the page's num()
const api = async (path, init) => (await fetch(`${server.base}/api/v1${path}`, init)).json();

async function selectMap(id) {
  await page.locator(`#map-list tr[data-id="${id}"]`).waitFor();
  await page.locator('#map-select').selectOption(id);
  await page.locator(`#map-list tr.selected[data-id="${id}"]`).waitFor();
}

test('median cut: every light is a disc over the map where it lies, its area proportional to its energy, with a scale', async () => {
  await selectMap('forest');
  const form = page.locator('#median-cut-form');
  await form.locator('[name=split]').selectOption('variance'); // energies that differ
  await form.locator('[name=count]').fill('32');
  await page.locator('#median-cut-stats').filter({ hasText: '32 lights' }).waitFor();
  await page.waitForFunction(() => document.querySelectorAll('#median-cut-overlay circle.light').length === 32);
  await waitForImage(page, '#median-cut-image', mapWidth);
  const result = await api('/envmaps/forest/median-cut', { method: 'POST', headers: { 'Content-Type': 'application/json' }, body: '{"count":32,"split":"variance"}' });
  assert.ok(result.energy_max > 1.5 * result.energy_min, `energies ${result.energy_min} .. ${result.energy_max}`);

  const image = await page.locator('#median-cut-image').boundingBox();
  const discs = await page.$$eval('#median-cut-overlay circle.light', (cs) => cs.map((c) => {
    const box = c.getBoundingClientRect();
    return { x: box.x + box.width / 2, y: box.y + box.height / 2, r: box.width / 2, energy: Number(c.dataset.energy), fill: c.getAttribute('fill') };
  }));
  const scale = image.width / mapWidth; // screen pixels per map pixel
  const k = discs[0].r ** 2 / discs[0].energy;
  result.lights.forEach((light, i) => {
    const disc = discs[i];
    assert.equal(disc.energy, light.energy);
    assert.ok(Math.abs(disc.x - (image.x + light.uv[0] * image.width)) <= 0.5, `light ${i} x ${disc.x}`);
    assert.ok(Math.abs(disc.y - (image.y + light.uv[1] * image.height)) <= 0.5, `light ${i} y ${disc.y}`);
    assert.ok(Math.abs(disc.r ** 2 / light.energy - k) <= 2e-3 * k, `light ${i}: r² / energy ${disc.r ** 2 / light.energy} against ${k}`);
    const top = Math.max(...light.power);
    assert.equal(disc.fill, `rgb(${light.power.map((c) => Math.round((255 * c) / top)).join(' ')})`);
  });
  // The brightest disc: half the side of a region of the mean size (in map pixels).
  const brightest = Math.max(...discs.map((d) => d.r));
  assert.ok(Math.abs(brightest - (scale * Math.sqrt((mapWidth * mapHeight) / 32)) / 2) <= 0.05, `largest disc ${brightest}`);

  // The scale: discs of the largest and smallest energies at the same screen size per energy, labelled.
  const legend = await page.$$eval('#median-cut-legend circle', (cs) => cs.map((c) => ({ r: c.getBoundingClientRect().width / 2, energy: Number(c.dataset.energy) })));
  assert.deepEqual(legend.map((d) => d.energy), [result.energy_max, result.energy_min]);
  for (const d of legend) assert.ok(Math.abs(d.r ** 2 / d.energy - k) <= 2e-3 * k, `scale disc of ${d.energy}: r ${d.r}`);
  const text = await page.locator('#median-cut-legend').evaluate((svg) => svg.textContent);
  assert.equal(text, `disc area ∝ energy:largest ${shown(result.energy_max)}smallest ${shown(result.energy_min)}`);
  await elementScreenshot(page, '#median-cut-panel', 'median-cut-lights');
  await form.locator('[name=split]').selectOption('median');
});

test('the signed SH picture is the API\'s coefficients summed on the real basis: the server\'s picture where both show it', async () => {
  await selectMap('forest');
  await page.locator('#sh-form [name=bands]').selectOption('4');
  await page.locator('#sh-form [name=quantity]').selectOption('radiance');
  await page.locator('#sh-form [name=exposure]').fill('-3'); // the brightest lobes within the 8 bits
  await page.waitForFunction(() => /bands=4.*exposure=-3/.test(document.querySelector('#sh-image').src));
  await waitForImage(page, '#sh-image', mapWidth);
  await page.waitForFunction((n) => document.querySelector('#sh-signed').values?.length === n, mapWidth * mapHeight);
  const sh = await api('/envmaps/forest/sh?bands=4');
  // Each channel summed here with the page's basis, against the server's tone-mapped picture.
  const channels = [0, 1, 2].map((c) => shReconstruct(sh.radiance.coefficients.map((x) => x.rgb[c]), mapWidth, mapHeight));
  const png = await pixelsOf(page, '#sh-image');
  assert.deepEqual([png.width, png.height], [mapWidth, mapHeight]);
  let negative = 0;
  for (let i = 0; i < mapWidth * mapHeight; ++i) {
    for (let c = 0; c < 3; ++c) {
      const v = channels[c][i] / 8;
      if (v < 0) ++negative; // black in the tone-mapped picture
      const expected = srgb8(Math.min(1, Math.max(0, v)));
      assert.ok(Math.abs(expected - png.data[4 * i + c]) <= 1, `pixel ${i} channel ${c}: ${v} → ${expected}, server ${png.data[4 * i + c]}`);
    }
  }
  assert.ok(negative > 0.05 * 3 * mapWidth * mapHeight, `${negative} values below 0`); // what the signed picture shows
  // The page's signed picture holds the mean of the three channels.
  await page.locator('#sh-form [name=exposure]').fill('0');
  const values = await page.$eval('#sh-signed', (c) => [...c.values]);
  values.forEach((v, i) => {
    const mean = (channels[0][i] + channels[1][i] + channels[2][i]) / 3;
    assert.ok(Math.abs(v - mean) <= 1e-5 * (1 + Math.abs(mean)), `pixel ${i}: ${v} against ${mean}`);
  });
});

test('a hemisphere map\'s two-band SH dips to -1/4 at the nadir: blue in the signed picture, black in the tone-mapped one', async () => {
  const upload = await fetch(`${server.base}/api/v1/envmaps?name=hemisphere`, { method: 'POST', body: latlongPfm(mapWidth, ([, , z]) => Array(3).fill(z > 0 ? 1 : 0)) });
  assert.equal(upload.status, 201, await upload.text());
  await page.reload();
  await selectMap('hemisphere');
  await page.locator('#sh-form [name=bands]').selectOption('2');
  await page.waitForFunction(() => /hemisphere\/sh\.png\?bands=2/.test(document.querySelector('#sh-image').src));
  await waitForImage(page, '#sh-image', mapWidth);
  await page.locator('#sh-signed-stats').filter({ hasText: 'below 0' }).waitFor();
  await page.waitForFunction(() => document.querySelector('#sh-signed').values?.[0] > 1); // this map's, not the last one's

  // L(z) = [z > 0] has L00 Y00 = 1/2 and L10 Y10 = 3/4 z: the reconstruction is 1/2 + 3/4 cos theta.
  const values = await page.$eval('#sh-signed', (c) => [...c.values]);
  for (let y = 0; y < mapHeight; ++y) {
    const expected = 0.5 + 0.75 * Math.cos((Math.PI * (y + 0.5)) / mapHeight);
    for (let x = 0; x < mapWidth; x += 17) {
      const v = values[y * mapWidth + x];
      assert.ok(Math.abs(v - expected) <= 1e-3, `row ${y}: ${v} against ${expected}`);
    }
  }
  const [top, bottom] = [values[0], values[values.length - 1]];
  assert.ok(bottom < -0.249 && bottom > -0.251, `nadir ${bottom}`);
  // Scaled to the largest magnitude (the zenith): the top row warm, the bottom row cool.
  const scale = Number(await page.locator('#sh-signed').getAttribute('data-scale'));
  assert.equal(scale, Math.max(Math.abs(top), Math.abs(bottom)));
  const signed = await pixelsOf(page, '#sh-signed');
  const at = (x, y) => signed.data.slice(4 * (y * mapWidth + x), 4 * (y * mapWidth + x) + 3);
  const [warm, cool] = [at(mapWidth / 2, 0), at(mapWidth / 2, mapHeight - 1)];
  assert.ok(warm[0] > 150 && warm[2] < 60, `zenith ${warm}`);
  assert.ok(cool[2] > cool[0] + 20, `nadir ${cool} is blue`);
  // The row where the sum crosses 0 (cos theta = -2/3) is the map's middle grey.
  const zeroRow = Math.round((Math.acos(-2 / 3) / Math.PI) * mapHeight - 0.5);
  assert.ok(Math.abs(values[zeroRow * mapWidth]) < 0.02);
  for (const c of at(0, zeroRow)) assert.ok(Math.abs(c - 221) <= 3, `zero row ${at(0, zeroRow)}`);
  // The server's tone-mapped picture cannot show the dip: black there.
  const png = await pixelsOf(page, '#sh-image');
  assert.deepEqual(png.data.slice(4 * (mapWidth * mapHeight - 1), 4 * mapWidth * mapHeight - 1), [0, 0, 0]);

  // The colour bar: ticks from -scale to +scale, 0 in the middle; the figures name the dip.
  const ticks = await page.$$eval('#sh-signed-scale .tick', (ts) => ts.map((t) => [t.style.left, Number(t.dataset.value), t.textContent]));
  assert.deepEqual(ticks.map((t) => t[0]), ['0%', '25%', '50%', '75%', '100%']);
  assert.deepEqual(ticks.map((t) => t[1]), [-scale, -scale / 2, 0, scale / 2, scale]);
  const stats = await page.locator('#sh-signed-stats').innerText();
  assert.ok(stats.includes(`smallest\n${shown(bottom)} at θ 179.3°, φ 0.7031°`), stats);
  // Below 0 where cos theta < -2/3: 1/6 of the sphere, to the rows' resolution.
  const share = Number(/below 0\n([0-9.]+) %/.exec(stats)[1]);
  assert.ok(Math.abs(share - 100 / 6) < 0.5, `${share} % below 0`);
  await elementScreenshot(page, '#ibl-panel', 'sh-signed');
  await selectMap('forest');
});

test('the BRDF table has its axes: n·v across and roughness down, ticked at the picture\'s edges and quarters', async () => {
  await page.locator('#lut-form [name=size]').selectOption('32');
  await page.waitForFunction(() => document.querySelector('#lut-image').src.includes('size=32'));
  await waitForImage(page, '#lut-image', 32);
  const image = await page.locator('#lut-image').boundingBox();
  for (const [axis, along] of [['x', 'x'], ['y', 'y']]) {
    const ticks = await page.$$eval(`#lut-${axis}-axis .tick`, (ts) => ts.map((t) => {
      const mark = getComputedStyle(t, t.parentElement.classList.contains('x') ? '::before' : '::after');
      const box = t.getBoundingClientRect();
      return { value: Number(t.dataset.value), text: t.textContent, box: { x: box.x, y: box.y, width: box.width, height: box.height }, mark: mark.content };
    }));
    assert.deepEqual(ticks.map((t) => t.text), ['0', '0.25', '0.5', '0.75', '1']);
    for (const t of ticks) {
      const centre = along === 'x' ? t.box.x + t.box.width / 2 : t.box.y + t.box.height / 2;
      const expected = along === 'x' ? image.x + t.value * image.width : image.y + t.value * image.height;
      assert.ok(Math.abs(centre - expected) <= 0.5, `${axis} tick ${t.text} at ${centre}, the picture's ${expected}`);
      // Labels lie outside the picture: under it, or left of it.
      if (axis === 'x') assert.ok(t.box.y >= image.y + image.height, `tick ${t.text} under the picture`);
      else assert.ok(t.box.x + t.box.width <= image.x, `tick ${t.text} left of the picture`);
    }
  }
  assert.equal(await page.locator('#lut-x-axis .axis-title').innerText(), 'n·v');
  assert.equal(await page.locator('#lut-y-axis .axis-title').innerText(), 'roughness');
  assert.match(await page.locator('#lut-channels').innerText(), /^red: scale, green: bias/);
  // The axes read the picture right: at roughness 0 (the top row) scale + bias is 1 at every n·v, the
  // bias (green) above the scale at grazing n·v (top left); rough at n·v 1 (bottom right) far less.
  const lut = await pixelsOf(page, '#lut-image');
  const texel = (x, y) => lut.data.slice(4 * (y * 32 + x), 4 * (y * 32 + x) + 2);
  for (let x = 0; x < 32; ++x) assert.ok(Math.abs(texel(x, 0)[0] + texel(x, 0)[1] - 255) <= 3, `top row ${x}: ${texel(x, 0)}`);
  assert.ok(texel(0, 0)[1] > 2 * texel(0, 0)[0], `top left ${texel(0, 0)}`);
  assert.ok(texel(31, 31)[0] + texel(31, 31)[1] < 128, `bottom right ${texel(31, 31)}`);
  await page.locator('#lut-form [name=multiscatter]').selectOption('true');
  await page.locator('#lut-channels').filter({ hasText: 'red: bias, green: scale + bias' }).waitFor();
  await elementScreenshot(page, '#ibl-panel', 'brdf-table-axes');
  await page.locator('#lut-form [name=multiscatter]').selectOption('false');
});

test('the spp and size fields show the largest values the server can be allowed whole', async () => {
  const largest = { spp: flagMaximum('max-render-spp'), width: flagMaximum('max-render-width'), height: flagMaximum('max-render-height') };
  assert.deepEqual(largest, { spp: 16777216, width: 65536, height: 65536 });
  for (const form of ['#render-form', '#model-render-form']) {
    for (const [name, value] of Object.entries(largest)) {
      const field = page.locator(`${form} [name=${name}]`);
      const before = await field.inputValue();
      await field.fill(String(value));
      const [scroll, client] = await field.evaluate((i) => [i.scrollWidth, i.clientWidth]);
      assert.ok(scroll <= client, `${form} ${name}: ${value} needs ${scroll} px in a field ${client} px wide`);
      await field.fill(before);
    }
  }
  assert.deepEqual(browser.errors, []);
});
