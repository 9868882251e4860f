// The filament target in Filament's own web build (npm `filament` 1.53.4) in Chromium: the Skybox made
// from NAME_skybox.ktx shows, along each axis of Filament's y-up frame, the colour the map has in that
// world direction (world (x, y, z) is Filament's (x, z, -y), manifest.json's frame): face order and
// orientation as Filament samples them. The map is a lat-long PFM made here with one pure colour per
// world octant (red where x > 0, green where y > 0, blue where z > 0), and the camera looks at each face
// off its centre, towards each of its four quadrants, so that a face swapped or mirrored shows.
//
// And a metallic white sphere lit by the IndirectLight made from NAME_ibl.ktx, at roughness 0, 0.5 and 1
// (gltfio's materials: Debian's matc, of libfilament-tools 1.9.25, compiles materials of version 10,
// which Filament 1.53.4 refuses, and the npm package ships no .filamat): seen from +Z, the middle pixel
// reflects +Z, and for a white metal Filament's split sum with its multiple-scattering compensation is
// the prefiltered radiance itself, so the pixel must be the product's own level at lod = 4 r (2 - r),
// read from the file in that direction (the middle of face +Z), within 3% and 2/255 (8-bit output,
// R11F_G11F_B10F rounding, the GPU's filtering). And independently of the file: the map is linear in
// the direction, so a lobe of roughness r about +Z (world -y) sees blue 0.2 + 0.15 (1 + c(r)), c(r) the
// n.l-weighted mean of n.l over the GGX lobe (N = V = R, alpha = r^2); Filament's blue must be that within
// 3.5% (the chain reads its source through filtered importance sampling, which shrinks a gradient by up
// to 3% at roughness 1), which a chain of the wrong roughness schedule misses (5% at roughness 0.5).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { copyFileSync, readFileSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { cliBin, freshDir, openBrowser, requireBinary, screenshot, serveFiles } from './support.mjs';

const here = path.dirname(fileURLToPath(import.meta.url));

const colour = (d) => d.map((c) => (c > 0 ? 1 : 0));

// A PFM lat-long (rows bottom to top in the file) in the product's convention, theta from +z and
// phi = 2 pi u, of radiance(world direction).
function latlongPfm(width, radiance) {
  const height = width / 2;
  const data = new Float32Array(width * height * 3);
  for (let row = 0; row < height; ++row)
    for (let i = 0; i < width; ++i) {
      const theta = Math.PI * (row + 0.5) / height, phi = 2 * Math.PI * (i + 0.5) / width;
      const d = [Math.sin(theta) * Math.cos(phi), Math.sin(theta) * Math.sin(phi), Math.cos(theta)];
      data.set(radiance(d), ((height - 1 - row) * width + i) * 3);
    }
  return Buffer.concat([Buffer.from(`PF\n${width} ${height}\n-1.0\n`), Buffer.from(data.buffer)]);
}

// The page `name` and its shared script, with the files of `dir`.
function copyPage(name, dir) {
  for (const file of [name, 'view.js']) copyFileSync(path.join(here, 'pages/filament', file), path.join(dir, file));
}

test('Filament draws the filament target\'s skybox with each world direction where the manifest puts it', async () => {
  const cli = requireBinary(cliBin, 'LIGHTPROBE_CLI_BIN');
  const dir = freshDir('filament');
  writeFileSync(path.join(dir, 'axes.pfm'), latlongPfm(256, colour));
  execFileSync(cli, ['bake', path.join(dir, 'axes.pfm'), '--target', 'filament', '--out', dir, '--base-size', '64',
    '--samples', '16', '-q']);
  copyPage('skybox.html', dir);
  const manifest = JSON.parse(readFileSync(path.join(dir, 'manifest.json'), 'utf8'));
  const toEngine = manifest.frame.world_to_engine;
  const files = await serveFiles(dir);
  const browser = await openBrowser();
  try {
    await browser.page.goto(`${files.base}/skybox.html`);
    // Each face (its axis 1, the other two +-0.5): 24 directions of Filament's frame.
    const directions = [];
    for (let axis = 0; axis < 3; ++axis)
      for (const sign of [1, -1])
        for (const a of [0.5, -0.5])
          for (const b of [0.5, -0.5]) {
            const d = [0, 0, 0];
            d[axis] = sign;
            d[(axis + 1) % 3] = a;
            d[(axis + 2) % 3] = b;
            directions.push(d);
          }
    const seen = await browser.page.evaluate(([url, ds]) => window.run(url, ds), ['/axes_skybox.ktx', directions]);
    await screenshot(browser.page, 'filament-skybox');
    directions.forEach((e, n) => {
      // The world direction of engine direction e: the transpose of world_to_engine applied to e.
      const world = [0, 1, 2].map((k) => toEngine[0][k] * e[0] + toEngine[1][k] * e[1] + toEngine[2][k] * e[2]);
      const want = colour(world).map((c) => (c ? 255 : 0));
      const got = seen[n].map((c) => (c > 0.5 ? 255 : 0));
      assert.deepEqual(got, want, `looking along Filament's (${e}) (world (${world})): saw ${seen[n]}`);
    });
    assert.deepEqual(browser.errors, []);
  } finally {
    await browser.close();
    await files.close();
  }
});

// The texel value of a level of a KTX1 R11F_G11F_B10F cube at the middle of face `face`: the mean of the
// four central texels (what bilinear filtering gives there).
function unpackFloat(bits, mantissa) {
  const e = bits >> mantissa, m = bits & ((1 << mantissa) - 1);
  return e === 0 ? (m / (1 << mantissa)) * 2 ** -14 : (1 + m / (1 << mantissa)) * 2 ** (e - 15);
}
function faceMiddle(bytes, level, face) {
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const size = view.getUint32(36, true);
  let at = 64 + view.getUint32(60, true);
  for (let p = 0; p < level; ++p) at += 4 + 6 * view.getUint32(at, true);
  const n = Math.max(1, size >> level);
  at += 4 + face * n * n * 4;
  const sum = [0, 0, 0];
  const middle = n === 1 ? [[0, 0]] : [[n / 2 - 1, n / 2 - 1], [n / 2, n / 2 - 1], [n / 2 - 1, n / 2], [n / 2, n / 2]];
  for (const [i, j] of middle) {
    const t = view.getUint32(at + 4 * (j * n + i), true);
    const c = [unpackFloat(t & 0x7ff, 6), unpackFloat((t >>> 11) & 0x7ff, 6), unpackFloat(t >>> 22, 5)];
    for (let k = 0; k < 3; ++k) sum[k] += c[k] / middle.length;
  }
  return sum;
}

// A smooth map, linear in the world direction d.
const gradient = (d) => [0.2 + 0.15 * (1 + d[0]), 0.2 + 0.15 * (1 + d[2]), 0.2 + 0.15 * (1 - d[1])];

// The n.l-weighted mean of n.l over the GGX lobe of perceptual roughness r, by a quadrature in
// u = the GGX CDF of cos^2 theta_h.
function lobeMeanCosine(r) {
  if (r === 0) return 1;
  const a2 = r ** 4, n = 20000;
  let num = 0, den = 0;
  for (let i = 0; i < n; ++i) {
    const u = (i + 0.5) / n, cos2 = (1 - u) / (1 + (a2 - 1) * u), nl = 2 * cos2 - 1;
    if (nl > 0) num += nl * nl, den += nl;
  }
  return num / den;
}

// A glTF sphere of radius 1, metallic white of roughness r.
function sphereGltf(r) {
  const rows = 32, columns = 64, positions = [], indices = [];
  for (let j = 0; j <= rows; ++j)
    for (let i = 0; i <= columns; ++i) {
      const theta = Math.PI * j / rows, phi = 2 * Math.PI * i / columns;
      positions.push(Math.sin(theta) * Math.cos(phi), Math.cos(theta), Math.sin(theta) * Math.sin(phi));
    }
  for (let j = 0; j < rows; ++j)
    for (let i = 0; i < columns; ++i) {
      const a = j * (columns + 1) + i, b = a + columns + 1;
      indices.push(a, a + 1, b, a + 1, b + 1, b);
    }
  const p = Buffer.from(new Float32Array(positions).buffer), ix = Buffer.from(new Uint16Array(indices).buffer);
  const data = Buffer.concat([p, p, ix]);
  const count = positions.length / 3;
  return JSON.stringify({
    asset: { version: '2.0' }, scene: 0, scenes: [{ nodes: [0] }], nodes: [{ mesh: 0 }],
    meshes: [{ primitives: [{ attributes: { POSITION: 0, NORMAL: 1 }, indices: 2, material: 0 }] }],
    materials: [{ pbrMetallicRoughness: { baseColorFactor: [1, 1, 1, 1], metallicFactor: 1, roughnessFactor: r } }],
    buffers: [{ byteLength: data.length, uri: `data:application/octet-stream;base64,${data.toString('base64')}` }],
    bufferViews: [{ buffer: 0, byteOffset: 0, byteLength: p.length }, { buffer: 0, byteOffset: p.length, byteLength: p.length },
      { buffer: 0, byteOffset: 2 * p.length, byteLength: ix.length }],
    accessors: [
      { bufferView: 0, componentType: 5126, count, type: 'VEC3', min: [-1, -1, -1], max: [1, 1, 1] },
      { bufferView: 1, componentType: 5126, count, type: 'VEC3' },
      { bufferView: 2, componentType: 5123, count: indices.length, type: 'SCALAR' }],
  });
}

test('Filament lights a metal sphere with the filament target\'s IBL as the product\'s own levels say', async () => {
  const cli = requireBinary(cliBin, 'LIGHTPROBE_CLI_BIN');
  const dir = freshDir('filament-ibl');
  writeFileSync(path.join(dir, 'gradient.pfm'), latlongPfm(256, gradient));
  execFileSync(cli, ['bake', path.join(dir, 'gradient.pfm'), '--target', 'filament', '--out', dir, '--samples', '64', '-q']);
  copyPage('sphere.html', dir);
  const ibl = readFileSync(path.join(dir, 'gradient_ibl.ktx'));
  const files = await serveFiles(dir);
  const browser = await openBrowser();
  try {
    await browser.page.goto(`${files.base}/sphere.html`);
    const roughness = [0, 0.5, 1];
    const seen = await browser.page.evaluate(([url, g]) => window.run(url, g), ['/gradient_ibl.ktx', roughness.map(sphereGltf)]);
    await screenshot(browser.page, 'filament-sphere-roughness-1');
    roughness.forEach((r, n) => {
      const lod = 4 * r * (2 - r);  // an integer here: 0, 3, 4
      const want = faceMiddle(ibl, lod, 4);
      console.log(`roughness ${r}: Filament ${seen[n].map((c) => c.toFixed(4))}, level ${lod} ${want.map((c) => c.toFixed(4))}`);
      for (let k = 0; k < 3; ++k)
        assert.ok(Math.abs(seen[n][k] - want[k]) <= 0.03 * want[k] + 2 / 255,
          `roughness ${r} channel ${k}: Filament ${seen[n][k]}, the product's level ${lod} ${want[k]}`);
      const blue = 0.2 + 0.15 * (1 + lobeMeanCosine(r));
      assert.ok(Math.abs(seen[n][2] - blue) <= 0.035 * blue, `roughness ${r}: Filament's blue ${seen[n][2]}, the lobe's ${blue}`);
    });
    assert.deepEqual(browser.errors, []);
  } finally {
    await browser.close();
    await files.close();
  }
});
