// The Models panel: upload a model (a .glb, a self-contained .gltf, or an archive of a model with its
// files), the uploaded models with delete, the selected one's description as the server read it
// (frame, bounds, counts, materials, textures, cameras, extensions) with its warnings, and a render of
// it framed (or through one of its glTF cameras) under the current map, and a turntable of it.
import { api } from './api.js';
import { $, el, num, bigNum, busy, formValues, showError, fillTable, confirmClick } from './dom.js';
import { state } from './state.js';
import { checkFields } from './field_errors.js';
import { offerTable } from './downloads.js';
import { uploadForm } from './upload.js';
import { apiDocument, componentFields, applyFields } from './openapi.js';
import { renderView, showWarnings } from './render_view.js';
import { refreshAssets, refreshJobs } from './renders.js';
import { initTurntable, turntableModel } from './turntable.js';

const panel = () => $('#models-panel');
const renderForm = () => $('#model-render-form');

let models = [];
let selected = null; // the name of the model shown
let view = null; // its render (renderView)

const current = () => models.find((m) => m.name === selected) || null;
const vec = (v) => `(${v.map((x) => num(x)).join(', ')})`;
const bytes = (n) => `${bigNum(n)}B`;
const plural = (n, word) => `${n} ${word}${n === 1 ? '' : 's'}`;
const listed = (names) => (names.length ? names.join(', ') : 'none');

// Lists the models again, showing `name` (by default the one shown, else the first).
export async function refreshModels(name = selected) {
  const list = await busy(panel(), () => api('/assets'));
  if (!list) return;
  models = list.assets;
  select(models.some((m) => m.name === name) ? name : (models[0]?.name ?? null));
}

// Shows model `name`; the render of another model is no longer followed here.
function select(name) {
  if (name !== selected) view.clear();
  selected = name;
  showList();
  showModel();
}

function showList() {
  const rows = models.map((m) =>
    el('tr', { class: m.name === selected ? 'selected' : '', dataset: { id: m.name }, onclick: () => select(m.name) },
      el('td', {}, m.name),
      el('td', {}, m.format),
      el('td', { class: 'num' }, m.triangles === undefined ? '–' : String(m.triangles)),
      el('td', { class: 'num' }, bytes(m.bytes)),
      el('td', {}, m.warnings?.length ? el('span', { class: 'pill warned' }, plural(m.warnings.length, 'warning')) : ''),
      el('td', {}, el('button', { type: 'button', class: 'danger small', title: `delete ${m.name}`, onclick: (e) => remove(e, m.name) }, 'Delete'))));
  if (!rows.length) rows.push(el('tr', {}, el('td', { colspan: 6, class: 'muted' }, 'no models: upload one above')));
  fillTable($('#model-list'), rows);
  offerTable($('#model-list-downloads'), 'assets', models);
}

async function remove(event, name) {
  if (!confirmClick(event)) return;
  await busy(panel(), () => api(`/assets/${encodeURIComponent(name)}`, { method: 'DELETE' }));
  await refreshModels();
  refreshAssets();
}

// The model's description as [label, text] pairs (an asset stored by an earlier server has none).
function description(m) {
  const items = [['model', `${m.model} · ${plural(m.files, 'file')} · ${bytes(m.bytes)} · ${m.path}`]];
  if (!m.bounds) return items;
  items.push(
    ['frame', m.frame],
    ['bounds', `${vec(m.bounds.min)} to ${vec(m.bounds.max)}`],
    ['centre', vec(m.bounds.centre)],
    ['radius', num(m.bounds.radius)],
    ['triangles', String(m.triangles)],
    ['vertices', String(m.vertices)],
    ['meshes', String(m.meshes)],
    ['cameras', listed(m.cameras.map((c) => `${c.index}${c.name ? ` “${c.name}”` : ''} ${c.type}`))],
    ['extensions used', listed(m.extensions_used)],
  );
  return items;
}

function showMaterials(m) {
  const rows = (m.materials ?? []).map((mat, i) => el('tr', {},
    el('td', {}, mat.name || `#${i}`), el('td', {}, listed(mat.features)), el('td', {}, listed(mat.extensions))));
  fillTable($('#model-materials'), rows);
  $('#model-materials').hidden = !rows.length;
}

function showTextures(m) {
  const rows = (m.textures ?? []).map((t, i) => el('tr', {},
    el('td', {}, `#${i}`), el('td', { class: 'num' }, `${t.width}×${t.height}`), el('td', { class: 'num' }, bytes(t.bytes)),
    el('td', {}, t.color_space)));
  fillTable($('#model-textures'), rows);
  $('#model-textures').hidden = !rows.length;
}

// The camera menu: framed, or each perspective camera of the model (an orthographic one is listed,
// not offered: only perspective cameras render).
function offerCameras(m) {
  const select = renderForm().camera;
  const cameras = (m?.cameras ?? []).map((c) =>
    el('option', { value: String(c.index), ...(c.type === 'perspective' ? {} : { disabled: '' }) },
      `glTF camera ${c.index}${c.name ? ` “${c.name}”` : ''}${c.type === 'perspective' ? '' : ` (${c.type})`}`));
  select.replaceChildren(el('option', { value: '' }, 'framed'), ...cameras);
  followCamera();
}

// Azimuth and elevation place a framed camera only.
function followCamera() {
  const form = renderForm();
  for (const name of ['azimuth_deg', 'elevation_deg']) form.elements.namedItem(name).disabled = form.camera.value !== '';
}

function showModel() {
  const m = current();
  $('#model-meta').replaceChildren(...(m ? description(m) : []).flatMap(([k, v]) => [el('dt', {}, k), el('dd', {}, v)]));
  showWarnings($('#model-warnings'), m?.warnings);
  showMaterials(m ?? {});
  showTextures(m ?? {});
  offerCameras(m);
  $('#model-render-submit').disabled = !m;
  turntableModel(m);
}

// The scene's camera: a glTF camera by index, or the fit at the form's angles.
function cameraOf(v) {
  if (v.camera !== '') return { gltf: Number(v.camera) };
  return { fit: { azimuth_deg: v.azimuth_deg, elevation_deg: v.elevation_deg } };
}

async function render(event) {
  event.preventDefault();
  const m = current();
  if (!m) return;
  if (!state.map) {
    showError(panel(), 'load a map first');
    return;
  }
  if (!checkFields(renderForm())) return;
  const v = formValues(renderForm());
  const scene = { objects: [{ type: 'mesh', path: m.path }], camera: cameraOf(v) };
  const body = { envmap: state.map, scene, width: v.width, height: v.height, spp: v.spp };
  const job = await busy(panel(), () => api('/renders', { method: 'POST', json: body }));
  if (!job) return;
  view.watch(job);
  refreshJobs();
}

// The fit's angles take their ranges and defaults from the API's document.
async function offerAngles() {
  await busy(panel(), async () => applyFields(renderForm(), componentFields(await apiDocument(), 'RenderCamera', 'fit')));
}

export function initModels() {
  const form = renderForm();
  view = renderView({
    panel: panel(), image: $('#model-render-image'), downloads: $('#model-render-image-downloads'),
    bar: $('#model-render-progress'), status: $('#model-render-status'), cancel: $('#model-render-cancel'),
    stats: $('#model-render-stats'), warnings: $('#model-render-warnings'),
  }, { picture: () => ({ exposure: formValues(form).exposure || 0 }), changed: refreshJobs });
  uploadForm($('#model-upload-form'), panel(), {
    path: '/assets',
    missing: 'choose a .glb or .gltf file, or a zip or tar archive of a model, first',
    done: async (asset) => {
      await refreshModels(asset.name);
      refreshAssets();
    },
  });
  form.addEventListener('submit', render);
  form.camera.addEventListener('change', followCamera);
  form.exposure.addEventListener('change', () => view.refresh());
  offerAngles();
  busy(panel(), () => initTurntable(() => current()?.path ?? null));
  refreshModels();
}
