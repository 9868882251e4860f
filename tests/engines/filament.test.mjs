// The filament target in Filament's own web build (npm `filament` 1.53.4) in Chromium: the Skybox made
// from NAME_skybox.ktx shows, along each axis of Filament's y-up frame, the colour the map has in that
// world direction (world (x, y, z) is Filament's (x, z, -y), manifest.json's frame): face order and
// orientation as Filament samples them. The map is a lat-long PFM made here with one pure colour per
// world octant (red where x > 0, green where y > 0, blue where z > 0), and the camera looks at each face
// off its centre, towards each of its four quadrants, so that a face swapped or mirrored shows.
//
// Not here: spheres lit by the IndirectLight at roughness 0, 0.5 and 1. Filament's web build needs a
// compiled material for them; Debian's matc (libfilament-tools 1.9.25) compiles materials of version 10,
// which Filament 1.53.4 refuses, and the npm package ships none.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { copyFileSync, readFileSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { cliBin, freshDir, openBrowser, requireBinary, screenshot, serveFiles } from './support.mjs';

const here = path.dirname(fileURLToPath(import.meta.url));

const colour = (d) => d.map((c) => (c > 0 ? 1 : 0));

// A PFM lat-long (rows bottom to top in the file) in the product's convention: theta from +z, phi = 2 pi u.
function axesMap(width) {
  const height = width / 2;
  const data = new Float32Array(width * height * 3);
  for (let row = 0; row < height; ++row)
    for (let i = 0; i < width; ++i) {
      const theta = Math.PI * (row + 0.5) / height, phi = 2 * Math.PI * (i + 0.5) / width;
      const d = [Math.sin(theta) * Math.cos(phi), Math.sin(theta) * Math.sin(phi), Math.cos(theta)];
      const fileRow = height - 1 - row;
      data.set(colour(d), (fileRow * width + i) * 3);
    }
  return Buffer.concat([Buffer.from(`PF\n${width} ${height}\n-1.0\n`), Buffer.from(data.buffer)]);
}

test('Filament draws the filament target\'s skybox with each world direction where the manifest puts it', async () => {
  const cli = requireBinary(cliBin, 'LIGHTPROBE_CLI_BIN');
  const dir = freshDir('filament');
  writeFileSync(path.join(dir, 'axes.pfm'), axesMap(256));
  execFileSync(cli, ['bake', path.join(dir, 'axes.pfm'), '--target', 'filament', '--out', dir, '--base-size', '64',
    '--samples', '16', '-q']);
  copyFileSync(path.join(here, 'pages/filament/skybox.html'), path.join(dir, 'skybox.html'));
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
      const got = seen[n].map((c) => (c > 127 ? 255 : 0));
      assert.deepEqual(got, want, `looking along Filament's (${e}) (world (${world})): saw ${seen[n]}`);
    });
    assert.deepEqual(browser.errors, []);
  } finally {
    await browser.close();
    await files.close();
  }
});
