// The dashboard in a real browser (Debian's Chromium through playwright-core) against the real
// server binary ($LIGHTPROBE_SERVER_BIN) holding a real map: every panel is used as a person would and
// checked against what the API says. Run: LIGHTPROBE_SERVER_BIN=build/bin/lightprobe-server node --test
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { spawn } from 'node:child_process';
import { mkdtempSync, rmSync, existsSync, readFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';

const here = path.dirname(fileURLToPath(import.meta.url));
const envmaps = path.resolve(here, '../../../shared/data/envmaps');
const serverBin = process.env.LIGHTPROBE_SERVER_BIN;
const boxGlb = '/usr/share/assimp/models/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb'; // assimp-testmodels
const screenshot = process.env.LIGHTPROBE_SCREENSHOT || '/tmp/lightprobe-dashboard.png';
const CHROMIUM_ARGS = ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
  '--disable-background-networking', '--disable-component-update', '--disable-sync'];

let server; // {proc, base, log}
let profileDir;
let stateDir; // the server's own --state-dir, removed after the tests
let context;
let page;
const pageErrors = [];

// Starts the server on a free port and resolves with its base URL once it logs that it listens.
function startServer() {
  assert.ok(serverBin, 'set LIGHTPROBE_SERVER_BIN to the lightprobe-server binary');
  assert.ok(existsSync(path.join(envmaps, 'forest.exr')), `no test map in ${envmaps}`);
  stateDir = mkdtempSync(path.join(tmpdir(), 'lightprobe-state-'));
  const proc = spawn(serverBin, ['--port', '0', '--threads', '2', '--data-dir', envmaps,
    '--state-dir', stateDir, '--load', `forest=${path.join(envmaps, 'forest.exr')}`], { stdio: ['ignore', 'pipe', 'pipe'] });
  const log = [];
  return new Promise((resolve, reject) => {
    const timer = setTimeout(() => reject(new Error(`server did not start in 30 s:\n${log.join('')}`)), 30000);
    const onData = (chunk) => {
      log.push(chunk.toString());
      const m = log.join('').match(/listening on (http:\/\/127\.0\.0\.1:\d+)/);
      if (m) {
        clearTimeout(timer);
        resolve({ proc, base: m[1], log });
      }
    };
    proc.stdout.on('data', onData);
    proc.stderr.on('data', onData);
    proc.on('exit', (code, signal) => {
      clearTimeout(timer);
      const message = `server exited (${code ?? signal}):\n${log.join('').slice(-4000)}`;
      reject(new Error(message));
      if (server) console.error(message); // died during the tests
    });
  });
}

// Polls a condition of the test process itself (the server's log) until it holds.
async function eventually(what, check, ms = 10000) {
  for (const end = Date.now() + ms; !check(); await new Promise((r) => setTimeout(r, 50)))
    if (Date.now() > end) assert.fail(`timed out waiting for ${what}`);
}

const naturalWidth = (selector) => page.$eval(selector, (img) => (img.complete ? img.naturalWidth : 0));
const waitForImage = (selector, width) =>
  page.waitForFunction(([s, w]) => {
    const img = document.querySelector(s);
    return img && img.complete && img.naturalWidth === w;
  }, [selector, width]);

before(async () => {
  server = await startServer();
  profileDir = mkdtempSync(path.join(tmpdir(), 'lightprobe-chromium-'));
  context = await chromium.launchPersistentContext(profileDir, {
    executablePath: '/usr/bin/chromium',
    headless: true,
    args: CHROMIUM_ARGS,
    viewport: { width: 1440, height: 900 },
  });
  page = context.pages()[0] ?? (await context.newPage());
  page.setDefaultTimeout(20000);
  page.on('pageerror', (e) => pageErrors.push(String(e)));
  await page.goto(`${server.base}/`);
});

after(async () => {
  if (page && !page.isClosed()) {
    // The whole page in one viewport (a full-page capture would repeat the sticky header mid-page).
    const height = await page.evaluate(() => document.documentElement.scrollHeight).catch(() => 900);
    await page.setViewportSize({ width: 1440, height }).catch(() => {});
    await page.screenshot({ path: screenshot }).catch(() => {});
  }
  if (context) await context.close();
  if (profileDir) rmSync(profileDir, { recursive: true, force: true });
  if (server && server.proc.exitCode === null && server.proc.signalCode === null) {
    server.proc.removeAllListeners('exit'); // the start-up listener reports deaths during the tests
    const exited = new Promise((resolve) => server.proc.once('exit', resolve));
    server.proc.kill('SIGTERM');
    await exited;
  }
  if (stateDir) rmSync(stateDir, { recursive: true, force: true });
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
  assert.match(await row.innerText(), /forest\s+1024×512\s+exr/);
  assert.equal(await page.locator('#map-select').inputValue(), 'forest');
  await waitForImage('#map-image', 1024);
  const shown = await page.locator('#map-meta').innerText();
  assert.match(shown, /1024 × 512/);
  assert.ok(shown.includes(String(Number(meta.max_luminance.toPrecision(4)))), `max luminance ${meta.max_luminance} in:\n${shown}`);

  // The exposure slider asks the server for a brighter picture.
  await page.locator('#map-exposure').fill('2');
  await page.waitForFunction(() => document.querySelector('#map-image').src.includes('exposure=2'));
  await waitForImage('#map-image', 1024);
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
  await waitForImage('#samples-image', 1024);
  // Both series of the pdf chart are densities in v over the map's 512 rows: each integrates to 1.
  const sums = await page.waitForFunction(() => {
    const plot = document.querySelector('#pdf-chart')?.chart?.plot;
    if (!plot || plot.data[0].length !== 512) return null;
    return plot.data.slice(1).map((ys) => ys.reduce((a, b) => a + b, 0) / ys.length);
  });
  for (const s of await sums.jsonValue()) assert.ok(Math.abs(s - 1) < 1e-6, `pdf integrates to ${s}`);
  const cdfEnd = await page.$eval('#cdf-chart', (c) => c.chart.plot.data.slice(1).map((ys) => ys[ys.length - 1]));
  for (const v of cdfEnd) assert.ok(Math.abs(v - 1) < 1e-6, `cdf ends at ${v}`);
  assert.ok(await page.locator('#pdf-chart canvas').isVisible());
  assert.match(await page.locator('#pdf-chart .u-legend').innerText(), /with sin θ[\s\S]*without/);

  await page.locator('#sampling-form [name=strategy]').selectOption('sobol');
  await page.locator('#sampling-form [name=style]').selectOption('windows');
  await page.waitForFunction(() => /strategy=sobol.*style=windows/.test(document.querySelector('#samples-image').src));
  assert.equal(await naturalWidth('#samples-image'), 1024);
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
  await waitForImage('#median-cut-image', 1024);
  const api = await (await fetch(`${server.base}/api/v1/envmaps/forest/median-cut`, { method: 'POST', headers: { 'Content-Type': 'application/json' }, body: '{"count":16}' })).json();
  const stats = await page.locator('#median-cut-stats').innerText();
  assert.ok(stats.includes(`${Number(api.energy_min.toPrecision(4))} / ${Number(api.energy_max.toPrecision(4))}`), stats);
  assert.equal(await page.locator('#median-cut-lights tbody tr').count(), 5);
});

test('a small render streams its progress to done and shows its image', async () => {
  const form = page.locator('#render-form');
  await form.locator('[name=preset]').selectOption('sphere');
  await form.locator('[name=width]').fill('32');
  await form.locator('[name=height]').fill('32');
  await form.locator('[name=spp]').fill('4');
  await page.locator('#render-submit').click();
  await page.locator('#render-status[data-status=done]').waitFor({ timeout: 45000 });
  await waitForImage('#render-image', 32);
  assert.match(await page.locator('#render-status').innerText(), /done · 100%/);
  assert.match(await page.locator('#render-stats').innerText(), /4 \/ 4 spp/);
  assert.equal(await page.$eval('#render-progress', (bar) => bar.style.width), '100%');
  const id = (await page.locator('#render-status').innerText()).split(' ')[0];
  const job = await (await fetch(`${server.base}/api/v1/renders/${id}`)).json();
  assert.equal(job.status, 'done');
  assert.equal(job.spp_done, 4);
  // The page followed the job through its event stream (the server logs it when the stream ends).
  await eventually('the events stream in the server log', () => server.log.join('').includes(`GET /api/v1/renders/${id}/events 200`));
  await page.locator(`#render-jobs tr[data-id="${id}"][data-status=done]`).waitFor();
  assert.ok(await page.locator('#renders-panel .error').isHidden());
});

// Both figures of the side-by-side view end done with a 48-pixel-wide image and a caption naming the
// option's state and the render time; the two newest jobs are the request with the option on and off.
async function expectComparison(option, label) {
  for (const on of ['true', 'false']) {
    const figure = page.locator(`#render-compare figure[data-option=${option}][data-on=${on}]`);
    await figure.and(page.locator('[data-status=done]')).waitFor({ timeout: 45000 });
    await waitForImage(`#render-compare figure[data-on=${on}] img`, 48);
    assert.match(await figure.locator('figcaption').innerText(), new RegExp(`^${label} ${on === 'true' ? 'on' : 'off'} · done · [0-9.e-]+ s$`));
  }
  const { renders } = await (await fetch(`${server.base}/api/v1/renders`)).json();
  const [first, second] = renders.slice(-2);
  assert.deepEqual([first[option], second[option], first.status, second.status], [true, false, 'done', 'done']);
  return [first, second];
}

test('two renders side by side: the textured preset with mipmaps on and off, an uploaded model with normal maps on and off', async () => {
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

  // Back to one render of the sphere for the next test.
  await form.locator('[name=compare]').selectOption('');
  await form.locator('[name=preset]').selectOption('sphere');
});

test('a long render shows its passes while running and can be cancelled', async () => {
  const form = page.locator('#render-form');
  await form.locator('[name=width]').fill('128');
  await form.locator('[name=height]').fill('96');
  await form.locator('[name=spp]').fill('65536');
  await page.locator('#render-submit').click();
  await page.locator('#render-status[data-status=running]').waitFor();
  await waitForImage('#render-image', 128); // a finished pass, long before the end
  const id = (await page.locator('#render-status').innerText()).split(' ')[0];
  await page.locator('#render-cancel').click();
  await page.locator('#render-status[data-status=cancelled]').waitFor();
  const job = await (await fetch(`${server.base}/api/v1/renders/${id}`)).json();
  assert.equal(job.status, 'cancelled');
  assert.ok(job.spp_done >= 1 && job.spp_done < 65536, `spp_done ${job.spp_done}`);
  assert.equal(await naturalWidth('#render-image'), 128);
  assert.ok(await page.locator('#render-cancel').isDisabled());
  await page.locator(`#render-jobs tr[data-id="${id}"][data-status=cancelled]`).waitFor();
  // Back to the small render for the screenshot, and nothing threw in the page all along.
  await form.locator('[name=spp]').fill('4');
  assert.deepEqual(pageErrors, []);
});
