// The engine tests' precondition: Debian's Chromium gives pages WebGL 2 with the float render targets and
// filtering that three.js's PMREM, Babylon's and Filament's IBL need, without a GPU.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { writeFileSync } from 'node:fs';
import { openBrowser, serveFiles, freshDir } from './support.mjs';

test('Chromium renders WebGL 2 with float colour buffers on SwiftShader', async () => {
  const dir = freshDir('webgl');
  writeFileSync(`${dir}/index.html`, '<canvas id="c"></canvas>');
  const files = await serveFiles(dir);
  const browser = await openBrowser();
  try {
    await browser.page.goto(`${files.base}/index.html`);
    const gl = await browser.page.evaluate(() => {
      const context = document.getElementById('c').getContext('webgl2');
      return context && {
        version: context.getParameter(context.VERSION),
        floatColour: context.getExtension('EXT_color_buffer_float') !== null,
        floatLinear: context.getExtension('OES_texture_float_linear') !== null,
      };
    });
    assert.ok(gl, 'no WebGL 2 context');
    assert.match(gl.version, /^WebGL 2\.0/);
    assert.ok(gl.floatColour && gl.floatLinear, JSON.stringify(gl));
    const three = await browser.page.evaluate(async () => (await import('/node_modules/three/build/three.module.js')).REVISION);
    assert.equal(three, '187');
    assert.deepEqual(browser.errors, []);
  } finally {
    await browser.close();
    await files.close();
  }
});
