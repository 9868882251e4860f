// What the engine tests share: a static HTTP server on a loopback port for a test's files and this
// package's node_modules (so pages import three, @babylonjs/core or filament as their users do), Debian's
// Chromium with WebGL 2 on SwiftShader (no GPU), and the binaries under test.
import assert from 'node:assert/strict';
import { createServer } from 'node:http';
import { mkdtempSync, mkdirSync, rmSync, readFileSync, existsSync, statSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';

const here = path.dirname(fileURLToPath(import.meta.url));
export const envmaps = path.resolve(here, '../data/envmaps');
export const screenshots = process.env.LIGHTPROBE_SCREENSHOT_DIR || path.join(tmpdir(), 'lightprobe-engines');
export const cliBin = process.env.LIGHTPROBE_CLI_BIN;
export const serverBin = process.env.LIGHTPROBE_SERVER_BIN;

const TYPES = {
  '.html': 'text/html', '.js': 'text/javascript', '.mjs': 'text/javascript', '.json': 'application/json',
  '.wasm': 'application/wasm', '.png': 'image/png', '.jpg': 'image/jpeg', '.webp': 'image/webp',
  '.ktx': 'application/octet-stream', '.ktx2': 'image/ktx2', '.env': 'application/octet-stream',
  '.hdr': 'application/octet-stream', '.exr': 'application/octet-stream', '.gltf': 'model/gltf+json',
  '.glb': 'model/gltf-binary', '.bin': 'application/octet-stream',
};

// Serves `root` at / and this package's node_modules at /node_modules/. Resolves to {base, close}.
export function serveFiles(root) {
  const modules = path.join(here, 'node_modules');
  const server = createServer((req, res) => {
    const url = decodeURIComponent(new URL(req.url, 'http://x').pathname);
    if (url === '/favicon.ico') {
      res.writeHead(204).end();
      return;
    }
    const file = url.startsWith('/node_modules/')
      ? path.join(modules, url.slice('/node_modules/'.length))
      : path.join(root, url);
    const inside = file.startsWith(modules + path.sep) || file.startsWith(path.resolve(root) + path.sep);
    if (!inside || !existsSync(file) || !statSync(file).isFile()) {
      res.writeHead(404).end();
      return;
    }
    res.writeHead(200, { 'content-type': TYPES[path.extname(file)] ?? 'application/octet-stream' });
    res.end(readFileSync(file));
  });
  return new Promise((resolve) => server.listen(0, '127.0.0.1', () => resolve({
    base: `http://127.0.0.1:${server.address().port}`,
    close: () => new Promise((done) => server.close(done)),
  })));
}

// Chromium in a fresh profile, WebGL 2 through SwiftShader. Page errors and console errors are
// collected in `errors`.
export async function openBrowser(viewport = { width: 512, height: 512 }) {
  const profileDir = mkdtempSync(path.join(tmpdir(), 'lightprobe-chromium-'));
  const context = await chromium.launchPersistentContext(profileDir, {
    executablePath: '/usr/bin/chromium',
    headless: true,
    args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--ignore-gpu-blocklist',
      '--disable-quic', '--no-first-run', '--disable-background-networking', '--disable-component-update',
      '--disable-sync'],
    viewport,
  });
  const errors = [];
  const page = context.pages()[0] ?? (await context.newPage());
  page.setDefaultTimeout(60000);
  page.on('pageerror', (e) => errors.push(String(e)));
  page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
  const close = async () => {
    await context.close();
    rmSync(profileDir, { recursive: true, force: true });
  };
  return { context, page, errors, close };
}

// Saves a page's screenshot as screenshots/NAME.png (kept for people to look at).
export async function screenshot(page, name) {
  mkdirSync(screenshots, { recursive: true });
  await page.screenshot({ path: path.join(screenshots, `${name}.png`) });
}

export function requireBinary(bin, variable) {
  assert.ok(bin && existsSync(bin), `set ${variable} to the binary under test`);
  return bin;
}

export function freshDir(prefix) {
  return mkdtempSync(path.join(tmpdir(), `lightprobe-${prefix}-`));
}
