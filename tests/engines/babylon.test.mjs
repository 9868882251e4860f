// The `babylon` target in Babylon.js (@babylonjs/core from npm) in Chromium: `lightprobe bake MAP --target
// babylon` of a map whose colour is a linear function of the direction, 0.5 + 0.4 w in each channel (every
// direction a colour of its own), loaded with CubeTexture.CreateFromPrefilteredData as the scene's
// environment. A unit sphere is rendered with Babylon's PBR material and every pixel's linear colour is
// compared with the closed form in the direction the manifest's frame gives:
// - a white metal (metallic 1, Babylon's energy conservation makes its split sum exactly 1) of roughness
//   r shows the GGX lobe of alpha = r^2 about the reflected direction R, filtered as Babylon's and our
//   prefilters do (N = V = R, weighted by n.l): 0.5 + 0.4 g(alpha) R, g the lobe's mean cosine;
// - a white surface without specular shows the polynomial's irradiance, E / pi = 0.5 + 0.4 (2/3) n.
// Tolerances, on values from 0.1 to 0.9: RGBD's 8 bits keep a texel to 0.6% of its brightest channel
// (0.006); Babylon mixes the two levels about its lod, where the closed form takes the lobe of the
// material's roughness (within 0.004 at roughness 0.5 and 0.01 at 1); and it samples the small faces of
// rough levels bilinearly in face coordinates, where a linear function of the direction sags between
// texel centres: 1.6% on 8x8 faces, 6% on 4x4, 18% on the 2x2 faces that roughness 1 reaches (its lod is
// 0.8 log2(size), on faces of size^0.2 texels whatever the size). Hence 0.02 for the mirror and the
// irradiance, 0.03 at roughness 0.5 and 0.07 at 1. A face swapped or mirrored is off by up to 0.8, a lod
// scale of 1 for 0.8 by 0.08 at roughness 0.5.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { copyFileSync, readFileSync, readdirSync, writeFileSync, mkdirSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { cliBin, freshDir, openBrowser, requireBinary, screenshot, serveFiles } from './support.mjs';

const here = path.dirname(fileURLToPath(import.meta.url));
const SIZE = 64;        // the cube's face, small enough to bake in a second
const PIXELS = 64;      // the float render target read back
const TOLERANCE = { mirror: 0.02, 0.5: 0.03, 1: 0.07, diffuse: 0.02 };

// A lat-long PFM (rows bottom to top) of radiance 0.5 + 0.4 w, w the world direction of the pixel
// (z up, phi from +x toward +y, u = phi / 2 pi, row 0 at the top).
function writeLinearMap(file, width, height) {
  const header = Buffer.from(`PF\n${width} ${height}\n-1.0\n`, 'ascii');
  const data = Buffer.alloc(width * height * 12);
  for (let row = 0; row < height; ++row) {
    const y = height - 1 - row;
    const theta = ((y + 0.5) / height) * Math.PI;
    for (let x = 0; x < width; ++x) {
      const phi = ((x + 0.5) / width) * 2 * Math.PI;
      const w = [Math.sin(theta) * Math.cos(phi), Math.sin(theta) * Math.sin(phi), Math.cos(theta)];
      for (let c = 0; c < 3; ++c) data.writeFloatLE(0.5 + 0.4 * w[c], (row * width + x) * 12 + c * 4);
    }
  }
  writeFileSync(file, Buffer.concat([header, data]));
}

// The mean of n.l over the GGX lobe of `alpha` about n = v, weighted by n.l (Karis's prefilter).
function lobeMeanCosine(alpha) {
  if (alpha === 0) return 1;
  let num = 0;
  let den = 0;
  const steps = 20000;
  for (let k = 0; k < steps; ++k) {
    const u = (k + 0.5) / steps;  // the half vector's cos^2 theta, inverted from GGX's D(h) cos(theta_h)
    const cos2 = (1 - u) / (1 + (alpha * alpha - 1) * u);
    const nl = 2 * cos2 - 1;
    if (nl > 0) {
      num += nl * nl;
      den += nl;
    }
  }
  return num / den;
}

// Every pixel within 0.8 of the sphere's centre: its normal and reflected direction in Babylon's frame.
// The camera is orthographic at (0, 0, -5) looking at +z, y up; Babylon reflects the direction from the
// eye position to the point.
function* spherePixels() {
  for (let j = 0; j < PIXELS; ++j) {
    for (let i = 0; i < PIXELS; ++i) {
      const x = ((i + 0.5) / PIXELS) * 2 - 1;
      const y = ((j + 0.5) / PIXELS) * 2 - 1;  // rows of readPixels bottom to top
      if (x * x + y * y > 0.64) continue;
      const n = [x, y, -Math.sqrt(1 - x * x - y * y)];
      const v = [n[0], n[1], n[2] + 5];
      const length = Math.hypot(...v);
      const dot = (v[0] * n[0] + v[1] * n[1] + v[2] * n[2]) / length;
      const r = v.map((c, k) => c / length - 2 * dot * n[k]);
      yield { index: (j * PIXELS + i) * 4, n, r };
    }
  }
}

// World direction of a Babylon direction: the transpose of the manifest's world-to-engine matrix.
const toWorld = (m, d) => [0, 1, 2].map((c) => m[0][c] * d[0] + m[1][c] * d[1] + m[2][c] * d[2]);

function largestError(pixels, matrix, direction, factor) {
  let worst = { error: 0 };
  for (const p of spherePixels()) {
    const w = toWorld(matrix, p[direction]);
    for (let c = 0; c < 3; ++c) {
      const expected = 0.5 + 0.4 * factor * w[c];
      const error = Math.abs(pixels[p.index + c] - expected);
      if (error > worst.error) worst = { error, got: pixels[p.index + c], expected, channel: c, at: p.n };
    }
  }
  return worst;
}

test('the babylon target renders in Babylon.js as the closed form says', async (t) => {
  const bin = requireBinary(cliBin, 'LIGHTPROBE_CLI_BIN');
  const dir = freshDir('babylon');
  writeLinearMap(path.join(dir, 'linear.pfm'), 128, 64);
  const out = path.join(dir, 'bake');
  execFileSync(bin, ['bake', path.join(dir, 'linear.pfm'), '--target', 'babylon', '--out', out,
    '--base-size', String(SIZE), '--samples', '512', '-q']);
  const manifest = JSON.parse(readFileSync(path.join(out, 'manifest.json'), 'utf8'));
  assert.ok(readdirSync(out).includes('linear.env'), readdirSync(out).join(', '));
  const matrix = manifest.frame.world_to_engine;
  for (const page of readdirSync(path.join(here, 'pages/babylon'))) {
    copyFileSync(path.join(here, 'pages/babylon', page), path.join(dir, page));
  }
  const files = await serveFiles(dir);
  const browser = await openBrowser({ width: 256, height: 256 });
  try {
    await browser.page.goto(`${files.base}/index.html`);
    await browser.page.waitForFunction(() => window.pageReady === true);
    const loaded = await browser.page.evaluate(() => window.loadEnvironment('/bake/linear.env'));
    assert.deepEqual(loaded, { lodGenerationScale: 0.8, size: SIZE });
    for (const roughness of [0, 0.5, 1]) {
      const pixels = await browser.page.evaluate(([r, n]) => window.renderSphere('metal', r, n), [roughness, PIXELS]);
      await screenshot(browser.page, `babylon-metal-roughness-${roughness}`);
      const worst = largestError(pixels, matrix, 'r', lobeMeanCosine(roughness * roughness));
      const tolerance = roughness === 0 ? TOLERANCE.mirror : TOLERANCE[roughness];
      t.diagnostic(`metal, roughness ${roughness}: largest error ${worst.error.toFixed(4)} (tolerance ${tolerance})`);
      assert.ok(worst.error <= tolerance, `metal, roughness ${roughness}: ${JSON.stringify(worst)}`);
    }
    const pixels = await browser.page.evaluate((n) => window.renderSphere('diffuse', 0, n), PIXELS);
    await screenshot(browser.page, 'babylon-diffuse');
    const worst = largestError(pixels, matrix, 'n', 2 / 3);
    t.diagnostic(`diffuse: largest error ${worst.error.toFixed(4)} (tolerance ${TOLERANCE.diffuse})`);
    assert.ok(worst.error <= TOLERANCE.diffuse, `diffuse: ${JSON.stringify(worst)}`);
    assert.deepEqual(browser.errors, []);
  } finally {
    await browser.close();
    await files.close();
  }
});
