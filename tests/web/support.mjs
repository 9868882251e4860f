// What every browser test of the dashboard shares: the real server binary ($LIGHTPROBE_SERVER_BIN)
// holding a real map, Debian's Chromium through playwright-core, and waits on the page.
import { before, after } from 'node:test';
import assert from 'node:assert/strict';
import { spawn, spawnSync } from 'node:child_process';
import { mkdtempSync, mkdirSync, rmSync, existsSync, readFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';
import { load } from '../../web/vendor/js-yaml.min.js';

const here = path.dirname(fileURLToPath(import.meta.url));
export const envmaps = path.resolve(here, '../data/envmaps');
export const models = path.resolve(here, '../data/models');
export const [mapWidth, mapHeight] = [256, 128]; // every map in tests/data/envmaps
export const screenshots = process.env.LIGHTPROBE_SCREENSHOT_DIR || path.join(tmpdir(), 'lightprobe-dashboard');
const serverBin = process.env.LIGHTPROBE_SERVER_BIN;
const CHROMIUM_ARGS = ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
  '--disable-background-networking', '--disable-component-update', '--disable-sync'];

// Starts a server holding the map `forest` (on a free port unless `port` is given; in a fresh state
// directory unless `stateDir` is given) and resolves once it logs that it listens. A death before
// stop() is reported; remove() stops it and deletes its state directory.
export function startServer({ port = 0, stateDir = mkdtempSync(path.join(tmpdir(), 'lightprobe-state-')) } = {}) {
  assert.ok(serverBin, 'set LIGHTPROBE_SERVER_BIN to the lightprobe-server binary');
  assert.ok(existsSync(path.join(envmaps, 'forest.exr')), `no test map in ${envmaps}`);
  const proc = spawn(serverBin, ['--port', String(port), '--threads', '2', '--data-dir', envmaps,
    '--state-dir', stateDir, '--load', `forest=${path.join(envmaps, 'forest.exr')}`], { stdio: ['ignore', 'pipe', 'pipe'] });
  const log = [];
  let started = false;
  let stopping = false;
  const exited = new Promise((resolve) => proc.once('exit', resolve));
  const stop = async (signal = 'SIGTERM') => {
    stopping = true;
    if (proc.exitCode === null && proc.signalCode === null) {
      proc.kill(signal);
      proc.kill('SIGCONT'); // a stopped process acts on the signal once it runs
    }
    await exited;
  };
  const remove = async () => {
    await stop();
    rmSync(stateDir, { recursive: true, force: true });
  };
  return new Promise((resolve, reject) => {
    const timer = setTimeout(() => reject(new Error(`server did not start in 30 s:\n${log.join('')}`)), 30000);
    const onData = (chunk) => {
      log.push(chunk.toString());
      const m = !started && log.join('').match(/listening on (http:\/\/127\.0\.0\.1:(\d+))/);
      if (m) {
        clearTimeout(timer);
        started = true;
        resolve({ proc, base: m[1], port: Number(m[2]), log, stateDir, stop, remove });
      }
    };
    proc.stdout.on('data', onData);
    proc.stderr.on('data', onData);
    proc.on('exit', (code, signal) => {
      clearTimeout(timer);
      const message = `server exited (${code ?? signal}):\n${log.join('').slice(-4000)}`;
      reject(new Error(message));
      if (started && !stopping) console.error(message); // died during the tests
    });
  });
}

// Chromium in a fresh profile with one page at `url`; page errors are collected in `errors`.
export async function openBrowser(url, viewport = { width: 1440, height: 900 }) {
  const profileDir = mkdtempSync(path.join(tmpdir(), 'lightprobe-chromium-'));
  const context = await chromium.launchPersistentContext(profileDir, {
    executablePath: '/usr/bin/chromium',
    headless: true,
    args: CHROMIUM_ARGS,
    viewport,
  });
  const errors = [];
  const watch = async (page) => {
    page.setDefaultTimeout(20000);
    page.on('pageerror', (e) => errors.push(String(e)));
    await page.goto(url);
    return page;
  };
  const page = await watch(context.pages()[0] ?? (await context.newPage()));
  // Another tab on the dashboard, its errors counted with the first's.
  const newTab = async () => watch(await context.newPage());
  const close = async () => {
    await context.close();
    rmSync(profileDir, { recursive: true, force: true });
  };
  return { context, page, errors, newTab, close };
}

// The before and after hooks of a test file that uses the dashboard: a server of its own, and
// Chromium on its page. `ready({server, browser, page})` gets them before the tests; `atEnd(page)`
// runs before the browser closes.
export function useDashboard({ ready, atEnd = async () => {} }) {
  const session = {};
  before(async () => {
    session.server = await startServer();
    session.browser = await openBrowser(`${session.server.base}/`);
    session.page = session.browser.page;
    ready(session);
  });
  after(async () => {
    if (session.page && !session.page.isClosed()) await atEnd(session.page).catch(() => {});
    if (session.browser) await session.browser.close();
    if (session.server) await session.server.remove();
  });
}

// Polls a condition of the test process itself (the server's log) until it holds.
export async function eventually(what, check, ms = 10000) {
  for (const end = Date.now() + ms; !check(); await new Promise((r) => setTimeout(r, 50)))
    if (Date.now() > end) assert.fail(`timed out waiting for ${what}`);
}

export const naturalWidth = (page, selector) => page.$eval(selector, (img) => (img.complete ? img.naturalWidth : 0));

export const waitForImage = (page, selector, width) =>
  page.waitForFunction(([s, w]) => {
    const img = document.querySelector(s);
    return img && img.complete && img.naturalWidth === w;
  }, [selector, width]);

// Saves the page as NAME.png in the screenshot directory: the viewport, or with `wholePage` the whole
// page in one viewport of the same width (a full-page capture would repeat the sticky header mid-page).
export async function screenshot(page, name, { wholePage = false } = {}) {
  mkdirSync(screenshots, { recursive: true });
  const viewport = page.viewportSize();
  if (wholePage) {
    const height = await page.evaluate(() => document.documentElement.scrollHeight);
    await page.setViewportSize({ width: viewport.width, height });
  }
  await page.screenshot({ path: path.join(screenshots, `${name}.png`) });
  await page.setViewportSize(viewport);
}

// Saves one element (a panel) as NAME.png in the screenshot directory, the sticky header kept off it.
export async function elementScreenshot(page, selector, name) {
  mkdirSync(screenshots, { recursive: true });
  await page.locator(selector).screenshot({ path: path.join(screenshots, `${name}.png`), style: '.top { position: static !important; }', animations: 'disabled' });
}

// Types values into the named fields of a form: fillForm(page, '#prefilter-form', { levels: 3 }).
export async function fillForm(page, form, values) {
  for (const [name, value] of Object.entries(values)) await page.locator(`${form} [name=${name}]`).fill(String(value));
}

// A prefiltered chain of the selected map through the IBL panel, followed to `status` (done by
// default); its job id.
export async function prefilterChain(page, { format = 'ktx2', status = 'done', ...numbers }) {
  await fillForm(page, '#prefilter-form', numbers);
  await page.locator('#prefilter-form [name=format]').selectOption(format);
  const [answer] = await Promise.all([
    page.waitForResponse((r) => r.request().method() === 'POST' && new URL(r.url()).pathname.endsWith('/prefilter')),
    page.locator('#prefilter-submit').click(),
  ]);
  assert.equal(answer.status(), 202);
  const { id } = await answer.json();
  await page.locator(`#prefilter-status[data-status=${status}]`, { hasText: id }).waitFor({ timeout: 30000 });
  return id;
}

export const isRenderPost = (request) => request.method() === 'POST' && new URL(request.url()).pathname === '/api/v1/renders';

// A small render of the sphere through the render panel, followed to `status` (done by default).
export async function renderSphere(page, { width = 32, height = 32, spp = 4, sampling = 'uniform', status = 'done' } = {}) {
  const form = page.locator('#render-form');
  await form.locator('[name=preset]').selectOption('sphere');
  await form.locator('[name=compare]').selectOption('');
  await form.locator('[name=sampling]').selectOption(sampling);
  await form.locator('[name=width]').fill(String(width));
  await form.locator('[name=height]').fill(String(height));
  await form.locator('[name=spp]').fill(String(spp));
  const [answer] = await Promise.all([
    page.waitForResponse((r) => isRenderPost(r.request())),
    page.locator('#render-submit').click(),
  ]);
  const { id } = await answer.json();
  await page.locator(`#render-status[data-status=${status}]`, { hasText: id }).waitFor({ timeout: 45000 });
  return id;
}

// Clicks a download link or button and resolves with the file the browser saved: {name, bytes}.
export async function download(page, control) {
  const [saved] = await Promise.all([page.waitForEvent('download'), control.click()]);
  assert.equal(await saved.failure(), null);
  return { name: saved.suggestedFilename(), bytes: readFileSync(await saved.path()) };
}

// A PNG's [width, height] (from its IHDR chunk).
export function pngSize(bytes) {
  assert.ok(bytes.subarray(0, 8).equals(Buffer.from([0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a])), 'not a PNG');
  return [bytes.readUInt32BE(16), bytes.readUInt32BE(20)];
}

export const isExr = (bytes) => bytes.length > 8 && bytes.readUInt32LE(0) === 20000630; // OpenEXR magic

// A PFM image (the API writes little-endian float32, scale -1): its values, 3 per pixel.
export function pfmValues(bytes) {
  let offset = 0;
  const header = [];
  while (header.length < 3) {
    const end = bytes.indexOf(0x0a, offset);
    header.push(bytes.subarray(offset, end).toString('latin1'));
    offset = end + 1;
  }
  assert.equal(header[0], 'PF');
  assert.ok(Number(header[2]) < 0, 'little-endian');
  const [width, height] = header[1].split(' ').map(Number);
  return Array.from({ length: width * height * 3 }, (_, i) => bytes.readFloatLE(offset + 4 * i));
}

// The rows of a CSV file the page wrote (CRLF line ends; its values here hold no commas or quotes).
export function csvRows(bytes) {
  const text = bytes.toString('utf8');
  assert.ok(text.endsWith('\r\n') && !/[^\r]\n/.test(text), 'CSV lines end in CRLF');
  assert.ok(!text.includes('"'), 'no quoted values expected');
  return text.slice(0, -2).split('\r\n').map((line) => line.split(','));
}

// The RGBA bytes of what an <img> (at its natural size) or a <canvas> shows: {width, height, data}.
export const pixelsOf = (page, selector) => page.$eval(selector, (source) => {
  const canvas = document.createElement('canvas');
  [canvas.width, canvas.height] = source instanceof HTMLImageElement ? [source.naturalWidth, source.naturalHeight] : [source.width, source.height];
  const context = canvas.getContext('2d');
  context.drawImage(source, 0, 0);
  return { width: canvas.width, height: canvas.height, data: [...context.getImageData(0, 0, canvas.width, canvas.height).data] };
});

// The largest value the server accepts for one of its integer flags (--NAME), as its refusal of a
// value past the flag's range states it.
export function flagMaximum(flag) {
  const answer = spawnSync(serverBin, [`--${flag}`, '0'], { encoding: 'utf8', timeout: 10000 });
  const range = new RegExp(`--${flag} takes an integer in \\[(\\d+), (\\d+)\\]`).exec(answer.stderr + answer.stdout);
  assert.ok(range, `no range in: ${answer.stderr}`);
  return Number(range[2]);
}

// The sRGB encoding of a linear value in 8 bits, as the server's `standard` pictures at exposure 0.
export const srgb8 = (x) => Math.round(255 * (x <= 0.0031308 ? 12.92 * x : 1.055 * Math.min(1, x) ** (1 / 2.4) - 0.055));

// The API's document, parsed.
export async function apiDocument(server) {
  return load(await (await fetch(`${server.base}/api/v1/openapi.yaml`)).text());
}

// A render of the sphere through the render panel shown in the page: its id and the request's body.
export async function renderShown(page, options) {
  const posted = page.waitForRequest(isRenderPost);
  const id = await renderSphere(page, options);
  await waitForImage(page, '#render-image', options.width ?? 32);
  return { id, body: (await posted).postDataJSON() };
}

// The pixels of the render image once the API URL it shows matches `pattern` (a newer picture).
export async function renderPixels(page, pattern) {
  await page.waitForFunction((p) => new RegExp(p).test(document.querySelector('#render-image').dataset.source ?? ''), pattern);
  return pixelsOf(page, '#render-image');
}

// A lat-long PFM (rows bottom to top) of width x width / 2 with radiance f(direction) at pixel centres.
export function latlongPfm(width, f) {
  const height = width / 2;
  const header = Buffer.from(`PF\n${width} ${height}\n-1.0\n`, 'latin1');
  const data = Buffer.alloc(width * height * 12);
  for (let y = 0; y < height; ++y) {
    const theta = (Math.PI * (y + 0.5)) / height;
    const row = height - 1 - y;
    for (let x = 0; x < width; ++x) {
      const phi = (2 * Math.PI * (x + 0.5)) / width;
      const d = [Math.sin(theta) * Math.cos(phi), Math.sin(theta) * Math.sin(phi), Math.cos(theta)];
      f(d).forEach((v, c) => data.writeFloatLE(v, 12 * (row * width + x) + 4 * c));
    }
  }
  return Buffer.concat([header, data]);
}
