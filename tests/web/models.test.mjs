// The Models panel in Chromium against the real server: real models uploaded through the page (a
// .glb, a self-contained .gltf, a tar.gz of a .gltf with its buffer, a broken .glb), their description
// checked against the API's record, their warnings, and renders of them framed and through a glTF
// camera checked against the map alone. Run: LIGHTPROBE_SERVER_BIN=build/bin/lightprobe-server node --test
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { execFileSync } from 'node:child_process';
import path from 'node:path';
import { useDashboard, waitForImage, elementScreenshot, isRenderPost, pfmValues, models } from './support.mjs';

const glTF2 = '/usr/share/assimp/models/glTF2'; // assimp-testmodels
const boxGlb = `${glTF2}/BoxTextured-glTF-Binary/BoxTextured.glb`;
const skinGltf = `${glTF2}/simple_skin/simple_skin.gltf`; // a skin and its animation
const quadGltf = path.join(models, 'quad_embedded.gltf');

let server, browser, page;
useDashboard({
  ready: (s) => ({ server, browser, page } = s),
  atEnd: (last) => elementScreenshot(last, '#models-panel', 'models-panel'),
});

const get = async (p) => (await fetch(`${server.base}/api/v1${p}`)).json();
const isAssetPost = (r) => r.request().method() === 'POST' && new URL(r.url()).pathname === '/api/v1/assets';
const panelError = () => page.locator('#models-panel .error');
const renderForm = () => page.locator('#model-render-form');

// Chooses `file` (a path, or {name, mimeType, buffer}) in the upload form and submits it under the name
// the form shows (the file's stem unless typed); the API's answer.
async function upload(file) {
  await page.locator('#model-file').setInputFiles(file);
  const [answer] = await Promise.all([page.waitForResponse(isAssetPost), page.locator('#model-upload-form button[type=submit]').click()]);
  return answer;
}

// The model description the panel shows, as {label: text}.
const shownMeta = () => page.$$eval('#model-meta dt', (dts) => Object.fromEntries(dts.map((dt) => [dt.textContent, dt.nextElementSibling.textContent])));
const shownRows = (table) => page.$$eval(`${table} tbody tr`, (rows) => rows.map((r) => [...r.cells].map((c) => c.textContent)));
const shownWarnings = (list) => page.$$eval(`${list} li`, (items) => items.map((li) => li.textContent));

// How the page writes a number (4 significant digits) and a point.
const num = (x) => String(Number(x.toPrecision(4)));
const vec = (v) => `(${v.map(num).join(', ')})`;
const shownBytes = (text) => {
  const [, value, unit] = /^([0-9.]+) ?([kMG]?)B$/.exec(text);
  return Number(value) * { '': 1, k: 1e3, M: 1e6, G: 1e9 }[unit];
};

// Renders the selected model with the form's values (and `values` typed first); the request the page
// sent and the job at its end, once the panel shows it done with its image.
async function renderModel(values) {
  for (const [name, value] of Object.entries(values)) await renderForm().locator(`[name=${name}]`).fill(String(value));
  const [request] = await Promise.all([page.waitForRequest(isRenderPost), page.locator('#model-render-submit').click()]);
  const { id } = await (await request.response()).json();
  await page.locator('#model-render-status[data-status=done]', { hasText: id }).waitFor({ timeout: 45000 });
  const job = await get(`/renders/${id}`);
  await waitForImage(page, '#model-render-image', job.width);
  return { body: request.postDataJSON(), job };
}

async function finished(id) {
  for (;;) {
    const job = await get(`/renders/${id}`);
    if (!['queued', 'running'].includes(job.status)) return job;
    await new Promise((r) => setTimeout(r, 100));
  }
}

// A render's linear pixels as luminance (mean of r, g, b).
async function luminance(id) {
  const bytes = Buffer.from(await (await fetch(`${server.base}/api/v1/renders/${id}/image?format=pfm`)).arrayBuffer());
  const v = pfmValues(bytes);
  return Array.from({ length: v.length / 3 }, (_, i) => (v[3 * i] + v[3 * i + 1] + v[3 * i + 2]) / 3);
}

test('a broken model is refused with the server\'s 422 invalid_model, and nothing is listed', async () => {
  const truncated = readFileSync(boxGlb).subarray(0, 300);
  const answer = await upload({ name: 'broken.glb', mimeType: 'model/gltf-binary', buffer: truncated });
  assert.equal(answer.status(), 422);
  assert.equal(new URL(answer.url()).searchParams.get('name'), 'broken');
  const { error } = await answer.json();
  assert.equal(error.code, 'invalid_model');
  await panelError().waitFor({ state: 'visible' });
  assert.equal(await panelError().innerText(), `422 invalid_model: ${error.message}`);
  assert.match(error.message, /model\.glb/);
  assert.deepEqual((await get('/assets')).assets, []);
  assert.deepEqual(await shownRows('#model-list'), [['no models: upload one above']]);
  assert.ok(await page.locator('#model-render-submit').isDisabled());
});

test('a .glb uploads under its file name and the panel shows the API\'s record of it', async () => {
  const answer = await upload(boxGlb);
  assert.equal(answer.status(), 201);
  await page.locator('#model-list tr[data-id="BoxTextured"].selected').waitFor();
  assert.ok(await panelError().isHidden());
  const record = await get('/assets/BoxTextured');
  assert.equal(record.triangles, 12);
  assert.deepEqual([record.bounds.min, record.bounds.max], [[-0.5, -0.5, -0.5], [0.5, 0.5, 0.5]]);

  const meta = await shownMeta();
  assert.equal(meta.triangles, String(record.triangles));
  assert.equal(meta.vertices, String(record.vertices));
  assert.equal(meta.meshes, String(record.meshes));
  assert.equal(meta.bounds, `${vec(record.bounds.min)} to ${vec(record.bounds.max)}`);
  assert.equal(meta.bounds, '(-0.5, -0.5, -0.5) to (0.5, 0.5, 0.5)');
  assert.equal(meta.centre, vec(record.bounds.centre));
  assert.equal(meta.radius, num(record.bounds.radius));
  assert.equal(meta.radius, '0.866'); // the half-diagonal of the unit box
  assert.equal(meta.frame, record.frame);
  assert.match(meta.model, /^model\.glb · 1 file · /);
  assert.deepEqual([meta.cameras, meta['extensions used']], ['none', 'none']);
  assert.deepEqual(await shownRows('#model-materials'), record.materials.map((m) => [m.name, m.features.join(', '), 'none']));
  assert.deepEqual(await shownRows('#model-materials'), [['Texture', 'base_color_texture', 'none']]);
  const [texture] = record.textures;
  const [[index, size, memory, space]] = await shownRows('#model-textures');
  assert.deepEqual([index, size, space], ['#0', `${texture.width}×${texture.height}`, texture.color_space]);
  assert.ok(Math.abs(shownBytes(memory) / texture.bytes - 1) < 0.005, `${memory} for ${texture.bytes} bytes`);
  assert.deepEqual([texture.width, texture.height, texture.color_space], [211, 211, 'srgb']);
  assert.ok(await page.locator('#model-warnings').isHidden());
  const [[name, format, triangles, bytes, warnings]] = await shownRows('#model-list');
  assert.deepEqual([name, format, triangles, warnings], ['BoxTextured', 'glb', '12', '']);
  assert.ok(Math.abs(shownBytes(bytes) / record.bytes - 1) < 0.005, `${bytes} for ${record.bytes} bytes`);
  // The Renders panel offers it in its scene menu.
  await page.locator('#render-assets option[value="asset:BoxTextured"]').waitFor({ state: 'attached' });
});

test('a framed render of the model under the map shows the model where the map alone shows the map', async () => {
  const { body, job } = await renderModel({ width: 64, height: 48, spp: 8, azimuth_deg: 30, elevation_deg: 20 });
  assert.deepEqual(body, {
    envmap: 'forest', width: 64, height: 48, spp: 8,
    scene: { objects: [{ type: 'mesh', path: 'assets/BoxTextured' }], camera: { fit: { azimuth_deg: 30, elevation_deg: 20 } } },
  });
  assert.equal(job.status, 'done');
  assert.deepEqual(job.warnings, []);
  assert.ok(await page.locator('#model-render-warnings').isHidden());
  // Framed at azimuth 30 (from -y towards +x) and elevation 20, at the distance where the bounding
  // sphere (radius 0.866 times the margin 1.05) fills the vertical field of 40 degrees.
  const rad = Math.PI / 180;
  const distance = (0.8660254 * 1.05) / Math.sin(20 * rad);
  const expected = [Math.sin(30 * rad) * Math.cos(20 * rad), -Math.cos(30 * rad) * Math.cos(20 * rad), Math.sin(20 * rad)].map((c) => c * distance);
  job.camera.position.forEach((x, i) => assert.ok(Math.abs(x - expected[i]) < 1e-4, `camera ${job.camera.position} against ${expected}`));
  assert.match(await page.locator('#model-render-stats').innerText(), /\ncamera\n\(1\.25, -2\.16, 0\.909\) → \(0, 0, 0\) · 40°$/);

  // The same request without the model, seen by the camera the server framed: the map alone.
  const answer = await fetch(`${server.base}/api/v1/renders`, {
    method: 'POST', headers: { 'Content-Type': 'application/json' },
    body: JSON.stringify({ ...body, scene: { objects: [], camera: job.camera } }),
  });
  assert.equal(answer.status, 202);
  const background = await finished((await answer.json()).id);
  assert.equal(background.status, 'done');
  const [model, map] = [await luminance(job.id), await luminance(background.id)];
  const differs = model.filter((v, i) => Math.abs(v - map[i]) > 0.02 + 0.1 * map[i]).length / model.length;
  assert.ok(differs > 0.2, `the model covers ${differs} of the image`);
  // The image's corners lie outside the framed sphere: there the map alone is seen.
  for (const i of [0, 63, 64 * 47, 64 * 48 - 1]) assert.ok(Math.abs(model[i] - map[i]) <= 1e-4 + 1e-3 * map[i], `pixel ${i}: ${model[i]} against ${map[i]}`);

  // The image the page shows is that render, not black: its middle is as bright as the render's.
  const shown = await page.$eval('#model-render-image', (img) => {
    const canvas = document.createElement('canvas');
    [canvas.width, canvas.height] = [img.naturalWidth, img.naturalHeight];
    const context = canvas.getContext('2d');
    context.drawImage(img, 0, 0);
    const { data } = context.getImageData(0, 0, canvas.width, canvas.height);
    let sum = 0;
    for (let i = 0; i < data.length; i += 4) sum += data[i] + data[i + 1] + data[i + 2];
    return { mean: sum / (3 * data.length / 4), width: canvas.width };
  });
  assert.equal(shown.width, 64);
  assert.ok(shown.mean > 20, `mean of the shown image ${shown.mean} of 255`);
  await page.locator('#model-render-image-downloads').waitFor(); // the image offered for download
});

test('a tar.gz of a .gltf with its buffer uploads, lists its cameras, and renders through its perspective camera', async () => {
  const archive = execFileSync('tar', ['-czf', '-', '-C', `${glTF2}/cameras`, 'Cameras.gltf', 'simpleSquare.bin']);
  const answer = await upload({ name: 'cameras.tar.gz', mimeType: 'application/gzip', buffer: archive });
  assert.equal(answer.status(), 201);
  await page.locator('#model-list tr[data-id="cameras"].selected').waitFor();
  const record = await get('/assets/cameras');
  assert.deepEqual([record.format, record.files], ['gltf', 2]);
  assert.equal((await shownMeta()).cameras, '0 perspective, 1 orthographic');
  const options = await renderForm().locator('[name=camera] option').evaluateAll((os) => os.map((o) => [o.value, o.disabled]));
  assert.deepEqual(options, [['', false], ['0', false], ['1', true]]); // an orthographic camera does not render
  await renderForm().locator('[name=camera]').selectOption('0');
  assert.ok(await renderForm().locator('[name=azimuth_deg]').isDisabled());
  const { body, job } = await renderModel({ width: 32, height: 32, spp: 2 });
  assert.deepEqual(body.scene.camera, { gltf: 0 });
  // The camera node at glTF (0.5, 0.5, 3) in the world frame (x, -z, y), looking along glTF -z (world +y).
  assert.deepEqual(job.camera.position, [0.5, -3, 0.5]);
  assert.deepEqual(job.camera.look_at, [0.5, -2, 0.5]);
  await renderForm().locator('[name=camera]').selectOption('');
});

// The embedded quad of tests/data with a material extension that is not read and a camera looking
// away from it.
function quadLookingAway() {
  const gltf = JSON.parse(readFileSync(quadGltf, 'utf8'));
  gltf.materials[0].extensions = { KHR_materials_anisotropy: { anisotropyStrength: 0.5 } };
  gltf.extensionsUsed.push('KHR_materials_anisotropy');
  gltf.cameras = [{ name: 'away', type: 'perspective', perspective: { yfov: 0.6, znear: 0.01 } }];
  // At z = 10 over the quad (at z = 3), turned half about y: looking along +z.
  gltf.nodes.push({ camera: 0, translation: [1, 2, 10], rotation: [0, 1, 0, 0] });
  gltf.scenes[0].nodes.push(gltf.nodes.length - 1);
  return Buffer.from(JSON.stringify(gltf));
}

test('what a model holds that is ignored is shown as its warnings, and a view missing the model says so', async () => {
  assert.equal((await upload(skinGltf)).status(), 201);
  await page.locator('#model-list tr[data-id="simple_skin"].selected').waitFor();
  const skin = await get('/assets/simple_skin');
  assert.equal(skin.warnings.length, 2);
  assert.ok(await page.locator('#model-warnings').isVisible());
  assert.deepEqual(await shownWarnings('#model-warnings'), skin.warnings);
  assert.match((await shownWarnings('#model-warnings')).join('\n'), /animation[\s\S]*skin/);
  assert.equal(await page.locator('#model-list tr[data-id="simple_skin"] .pill').innerText(), '2 warnings');

  assert.equal((await upload({ name: 'quad away.gltf', mimeType: 'model/gltf+json', buffer: quadLookingAway() })).status(), 201);
  await page.locator('#model-list tr[data-id="quad_away"].selected').waitFor();
  const quad = await get('/assets/quad_away');
  assert.ok(quad.warnings.includes('materials[0]: KHR_materials_anisotropy is not supported and is ignored'), quad.warnings.join('\n'));
  assert.deepEqual(await shownWarnings('#model-warnings'), quad.warnings);
  assert.match((await shownMeta())['extensions used'], /KHR_materials_anisotropy/);
  assert.match((await shownRows('#model-materials'))[0][2], /KHR_materials_anisotropy/);

  await renderForm().locator('[name=camera]').selectOption('0');
  const { job } = await renderModel({ width: 16, height: 16, spp: 1 });
  assert.ok(job.warnings.length > 0, 'the server warns of a view holding none of the objects');
  assert.ok(await page.locator('#model-render-warnings').isVisible());
  assert.deepEqual(await shownWarnings('#model-render-warnings'), job.warnings);
  await renderForm().locator('[name=camera]').selectOption('');
});

test('delete takes two clicks and removes the model from the list, the API and the render menu', async () => {
  const del = page.locator('#model-list tr[data-id="quad_away"] button');
  await del.click(); // arms
  assert.ok((await get('/assets')).assets.some((a) => a.name === 'quad_away'));
  await del.click(); // deletes
  await page.locator('#model-list tr[data-id="quad_away"]').waitFor({ state: 'detached' });
  assert.equal((await fetch(`${server.base}/api/v1/assets/quad_away`)).status, 404);
  await page.locator('#render-assets option[value="asset:quad_away"]').waitFor({ state: 'detached' });
  assert.ok(await page.locator('#model-list tr.selected').count() === 1);
  assert.deepEqual(browser.errors, []);
});
