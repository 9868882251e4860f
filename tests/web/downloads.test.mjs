// Every image and table of the dashboard can be saved: each download link or button gives a file,
// checked against what the API says. Run: LIGHTPROBE_SERVER_BIN=build/bin/lightprobe-server node --test
import { test, beforeEach, afterEach } from 'node:test';
import assert from 'node:assert/strict';
import { mapWidth, mapHeight, useDashboard, renderSphere, download, pngSize, isExr, csvRows, prefilterChain } from './support.mjs';

let server, browser, page;
useDashboard({ ready: (s) => ({ server, browser } = s) });
// Each test saves from a tab of its own: headless Chromium drops a document's eleventh download.
beforeEach(async () => {
  page = await browser.newTab();
});
afterEach(() => page.close());

const getJson = async (path, init) => (await fetch(`${server.base}/api/v1${path}`, init)).json();
const save = (bar, format) => download(page, page.locator(`#${bar}-downloads [data-format=${format}]`));

// Saves a table as JSON and CSV: both named NAME, the JSON equal to `expected` (up to what `stable`
// leaves out), the CSV one row per record with (at least) the columns `columns`; resolves with the
// CSV's rows as records of strings.
async function saveTable(bar, name, expected, columns, stable = (record) => record) {
  const json = await save(bar, 'json');
  assert.equal(json.name, `${name}.json`);
  assert.deepEqual(JSON.parse(json.bytes).map(stable), expected.map(stable));
  const csv = await save(bar, 'csv');
  assert.equal(csv.name, `${name}.csv`);
  const [header, ...rows] = csvRows(csv.bytes);
  for (const column of columns) assert.ok(header.includes(column), `no column ${column} in ${header}`);
  assert.equal(rows.length, expected.length);
  return rows.map((row) => Object.fromEntries(header.map((column, i) => [column, row[i]])));
}

async function savePng(bar, name, size) {
  const png = await save(bar, 'png');
  assert.equal(png.name, `${name}.png`);
  assert.deepEqual(pngSize(png.bytes), size);
}

async function saveExr(bar, name) {
  const exr = await save(bar, 'exr');
  assert.equal(exr.name, `${name}.exr`);
  assert.ok(isExr(exr.bytes), `${name}.exr is no OpenEXR file`);
}

const BARS = ['map-list', 'map-image', 'samples-image', 'distribution', 'median-cut-image', 'median-cut-lights', 'fresnel',
  'render-image', 'render-jobs', 'sh-image', 'sh-coefficients', 'lut-image', 'prefilter', 'model-list'];
// Shown once a model is rendered (models.test.mjs), and once its turntable is done (turntable.test.mjs).
const MODEL_BARS = ['model-render-image', 'turntable'];

const prefiltered = async (fields) => getJson(`/prefilters/${await prefilterChain(page, fields)}`);

test('the page offers every image and table for download once it shows them', async () => {
  await page.locator('#map-list tr[data-id=forest]').waitFor();
  const id = await renderSphere(page);
  await page.locator(`#render-jobs tr[data-id="${id}"][data-status=done]`).waitFor();
  await prefiltered({ levels: 2, base_size: 16, samples: 16 });
  for (const bar of BARS) await page.locator(`#${bar}-downloads`).waitFor();
  const all = await page.$$eval('.downloads', (bars) => bars.map((b) => b.id.replace(/-downloads$/, '')));
  // (the side-by-side renders' links: dashboard.test.mjs)
  assert.deepEqual(all.sort(), [...BARS, ...MODEL_BARS].sort());
});

test('the maps list as JSON and CSV, the map as PNG and EXR', async () => {
  const { envmaps } = await getJson('/envmaps');
  const withoutMemory = ({ memory_bytes: _, ...map }) => map; // grows as the panels ask for tables
  const [row] = await saveTable('map-list', 'envmaps', envmaps, ['id', 'width', 'height'], withoutMemory);
  assert.deepEqual([row.id, row.width, row['power.0'], row['power.2']], ['forest', '256', ...[0, 2].map((i) => String(envmaps[0].power[i]))]);
  await savePng('map-image', 'forest', [mapWidth, mapHeight]);
  await saveExr('map-image', 'forest');
});

test('the samples picture as PNG, the marginal distribution behind the charts as JSON and CSV', async () => {
  await savePng('samples-image', 'forest-samples-stratified-1024', [mapWidth, mapHeight]);
  const weighted = await getJson('/envmaps/forest/distribution?luminance=average&sin_weight=true');
  const plain = await getJson('/envmaps/forest/distribution?luminance=average&sin_weight=false');
  const expected = weighted.marginal_pdf.map((p, y) => ({
    row: y, theta_deg: ((y + 0.5) / mapHeight) * 180, row_luminance: weighted.row_luminance[y],
    pdf_sin_weighted: p, pdf_unweighted: plain.marginal_pdf[y],
    cdf_sin_weighted: weighted.marginal_cdf[y + 1], cdf_unweighted: plain.marginal_cdf[y + 1],
  }));
  const rows = await saveTable('distribution', 'forest-distribution-average', expected, Object.keys(expected[0]));
  const sum = rows.reduce((s, r) => s + Number(r.pdf_sin_weighted), 0);
  assert.ok(Math.abs(sum - 1) < 1e-9, `the pdf column sums to ${sum}`);
  assert.ok(Math.abs(Number(rows[mapHeight - 1].cdf_unweighted) - 1) < 1e-9);
});

test('the median-cut picture as PNG, all its lights as JSON and CSV', async () => {
  await savePng('median-cut-image', 'forest-median-cut-64', [mapWidth, mapHeight]);
  const { lights } = await getJson('/envmaps/forest/median-cut', { method: 'POST', headers: { 'Content-Type': 'application/json' }, body: '{"count":64}' });
  assert.equal(lights.length, 64);
  const rows = await saveTable('median-cut-lights', 'forest-median-cut-64-lights', lights, []);
  rows.forEach((row, i) => {
    assert.equal(row['power.1'], String(lights[i].power[1]));
    assert.equal(row['region.x1'], String(lights[i].region.x1));
  });
});

test('the SH reconstruction as PNG, the coefficients as JSON and CSV, the BRDF table as EXR and PNG', async () => {
  await savePng('sh-image', 'forest-sh3-radiance', [mapWidth, mapHeight]);
  const sh = await getJson('/envmaps/forest/sh?bands=3&window=none');
  const expected = sh.radiance.coefficients.map((c, i) => ({ l: c.l, m: c.m, radiance: c.rgb, irradiance: sh.irradiance.coefficients[i].rgb }));
  const rows = await saveTable('sh-coefficients', 'forest-sh3', expected, ['l', 'm', 'radiance.0', 'irradiance.2']);
  assert.equal(rows[0]['radiance.1'], String(sh.radiance.coefficients[0].rgb[1]));
  await saveExr('lut-image', 'brdf-lut-128');
  await savePng('lut-image', 'brdf-lut-128', [128, 128]);
});

test('the prefiltered chain\'s files under their own names: each level as EXR, or the chain as KTX2', async () => {
  const exr = await prefiltered({ levels: 3, base_size: 16, samples: 16, format: 'exr' });
  assert.deepEqual(exr.files.map((f) => f.name), ['level0.exr', 'level1.exr', 'level2.exr']);
  for (const file of exr.files) {
    const saved = await download(page, page.locator(`#prefilter-downloads a[download="${file.name}"]`));
    assert.equal(saved.name, file.name);
    assert.ok(isExr(saved.bytes), `${file.name} is no OpenEXR file`);
  }
  await prefiltered({ levels: 3, base_size: 16, samples: 16, format: 'ktx2' });
  const ktx2 = await save('prefilter', 'ktx2');
  assert.equal(ktx2.name, 'prefiltered.ktx2');
  assert.equal(ktx2.bytes.subarray(1, 7).toString('latin1'), 'KTX 20'); // «KTX 20» identifier
});

test('the Fresnel table as the API gives it, JSON and CSV', async () => {
  await page.locator('#fresnel-downloads [data-format=json]').waitFor();
  const json = await save('fresnel', 'json');
  assert.equal(json.name, 'fresnel-1-1.5.json');
  assert.deepEqual(JSON.parse(json.bytes), await getJson('/fresnel?eta_i=1&eta_t=1.5&step=0.25'));
  const csv = await save('fresnel', 'csv');
  assert.equal(csv.name, 'fresnel-1-1.5.csv');
  const lines = csv.bytes.toString('utf8').trimEnd().split(/\r?\n/);
  assert.equal(lines[0], 'angle_deg,rs,rp,unpolarized,schlick');
  assert.equal(lines.length, 1 + 361); // 0, 0.25, ... 90
});

test('the render as PNG and EXR, the jobs as JSON and CSV', async () => {
  const id = await renderSphere(page);
  await savePng('render-image', `render-${id}`, [32, 32]);
  await saveExr('render-image', `render-${id}`);
  const { renders } = await getJson('/renders');
  const row = (await saveTable('render-jobs', 'renders', renders, ['id', 'status'])).find((r) => r.id === id);
  assert.deepEqual([row.id, row.status, row.spp_done, row['scene.preset']], [id, 'done', '4', 'sphere']);
  assert.deepEqual(browser.errors, []);
});

test('the CSV quotes values holding commas, quotes or line breaks and names nested values by their path', async () => {
  const csv = await page.evaluate(async () => (await import('/js/downloads.js')).toCsv([
    { name: 'a,b', note: 'say "hi"', lines: 'one\ntwo', rgb: [1, 0.5, 0.25], error: null, region: { x0: 0 } },
    { name: 'c', error: { code: 'corrupt' }, done: true },
  ]));
  assert.equal(csv, [
    'name,note,lines,rgb.0,rgb.1,rgb.2,region.x0,error.code,done',
    '"a,b","say ""hi""","one\ntwo",1,0.5,0.25,0,,',
    'c,,,,,,,corrupt,true',
    '',
  ].join('\r\n'));
});
