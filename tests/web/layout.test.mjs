// The dashboard on a desktop screen (1280 x 800) and on a phone (390 x 844): the page never scrolls
// sideways and every control, image and chart lies within the viewport's width. Screenshots are saved
// in $LIGHTPROBE_SCREENSHOT_DIR. Run: LIGHTPROBE_SERVER_BIN=build/bin/lightprobe-server node --test
import { test } from 'node:test';
import assert from 'node:assert/strict';
import path from 'node:path';
import { useDashboard, renderSphere, waitForImage, screenshot, prefilterChain, models } from './support.mjs';

const SCREENS = [
  { name: 'desktop', width: 1280, height: 800 },
  { name: 'phone', width: 390, height: 844 },
];

let browser, page;
useDashboard({ ready: (s) => ({ browser, page } = s) });

// Everything a person reads or uses that does not fit in the viewport's width, with where it lies.
const outside = () => page.evaluate(() => {
  const width = document.documentElement.clientWidth;
  const things = document.querySelectorAll('button, input, select, textarea, a[href], #health, img[src], canvas');
  return [...things]
    .filter((e) => e.checkVisibility())
    .map((e) => ({ e, box: e.getBoundingClientRect() }))
    .filter(({ box }) => box.left < -0.5 || box.right > width + 0.5)
    .map(({ e, box }) => `${e.outerHTML.slice(0, 120)} at x ${Math.round(box.left)}..${Math.round(box.right)} of ${width}`);
});

// A model with warnings, then one whose material lists every extension read (the longest rows of the
// Models panel), rendered framed at 640 pixels wide.
async function fillModels() {
  for (const [file, name] of [['/usr/share/assimp/models/glTF2/simple_skin/simple_skin.gltf', 'simple_skin'], [path.join(models, 'quad_lobes.gltf'), 'quad_lobes']]) {
    await page.locator('#model-file').setInputFiles(file);
    await page.locator('#model-upload-form button[type=submit]').click();
    await page.locator(`#model-list tr[data-id="${name}"].selected`).waitFor();
  }
  const form = page.locator('#model-render-form');
  await form.locator('[name=width]').fill('640');
  await form.locator('[name=height]').fill('480');
  await form.locator('[name=spp]').fill('1');
  await page.locator('#model-render-submit').click();
  await page.locator('#model-render-status[data-status=done]').waitFor({ timeout: 45000 });
  await waitForImage(page, '#model-render-image', 640);
}

// Fills the page with what makes it wide: the map list with its Delete button, the sun marked on the
// map, a prefiltered chain's strip of seven levels, the Models panel with a model and its render, a
// render wider than a phone still running (its Cancel button in the job list), a side-by-side pair,
// messages beside fields.
async function fillPage() {
  await page.locator('#map-list tr[data-id=forest] button').waitFor();
  await page.locator('#sun-find').click();
  await page.locator('#sun-marker').waitFor();
  await prefilterChain(page, { levels: 7, base_size: 128, samples: 16 });
  await page.locator('#prefilter-strip figure[data-level="6"] img[src]').waitFor();
  await fillModels();
  const running = await renderSphere(page, { width: 640, height: 480, spp: 65536, status: 'running' });
  await waitForImage(page, '#render-image', 640);
  const form = page.locator('#render-form');
  await form.locator('[name=compare]').selectOption('mipmaps');
  await form.locator('[name=width]').fill('96');
  await form.locator('[name=height]').fill('64');
  await form.locator('[name=spp]').fill('1');
  await page.locator('#render-submit').click();
  for (const on of [true, false]) await page.locator(`#render-compare figure[data-value=${on}][data-status=done]`).waitFor({ timeout: 45000 });
  await page.locator(`#render-jobs tr[data-id="${running}"] button`, { hasText: 'Cancel' }).waitFor();
  await page.locator('#sampling-form [name=count]').fill('0');
  await page.locator('#sampling-form [aria-invalid]').waitFor();
  await form.locator('[name=spp]').fill('10000000');
  await page.locator('#render-submit').click();
  await form.locator('[name=spp][aria-invalid]').waitFor();
  return running;
}

test('nothing lies beyond the viewport at 1280 and at 390 pixels wide, the render image included', async () => {
  const running = await fillPage();
  for (const screen of SCREENS) {
    await page.setViewportSize({ width: screen.width, height: screen.height });
    // The charts follow their panel's width on the next frames.
    await page.waitForFunction(() => [...document.querySelectorAll('.chart')].every((c) => c.chart?.plot.width <= c.clientWidth + 1));
    await screenshot(page, `dashboard-${screen.name}`);
    await screenshot(page, `dashboard-${screen.name}-whole`, { wholePage: true });
    const scroll = await page.evaluate(() => [document.documentElement.scrollWidth, document.documentElement.clientWidth]);
    assert.equal(scroll[0], scroll[1], `${screen.name}: the page is ${scroll[0]} px wide in a ${scroll[1]} px viewport`);
    assert.deepEqual(await outside(), [], screen.name);
    // The renders are shown whole: within their frames, scaled down to fit if need be.
    for (const id of ['#render-image', '#model-render-image']) {
      const [frame, image] = await Promise.all([page.locator(id).locator('xpath=..'), page.locator(id)].map((l) => l.boundingBox()));
      assert.ok(image.width > 0 && image.x >= frame.x && image.x + image.width <= frame.x + frame.width, `${screen.name} ${id}: ${JSON.stringify({ frame, image })}`);
    }
    assert.ok(await page.locator('#health').isVisible());
  }
  await page.locator(`#render-jobs tr[data-id="${running}"] button`).click();
  await page.locator(`#render-jobs tr[data-id="${running}"][data-status=cancelled]`).waitFor();
  assert.deepEqual(browser.errors, []);
});
