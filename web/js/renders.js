// The Renders panel: submit a preset scene or an uploaded model (optionally two renders side by side,
// an option on and off), follow the job through its server-sent events (progress
// bar, image refreshed after every pass), cancel it, and list every job.
import { api } from './api.js';
import { $, el, num, busy, formValues, showError, fillTable } from './dom.js';
import { state } from './state.js';
import { compareRenders } from './render_compare.js';
import { offerTable } from './downloads.js';
import { checkFields } from './field_errors.js';
import { ACTIVE } from './jobs.js';
import { renderView } from './render_view.js';

const panel = () => $('#renders-panel');

let view = null; // the job followed (renderView)

function exposure() {
  return formValues($('#render-form')).exposure || 0;
}

// The scene a choice of the scene menu names: a preset, or "asset:NAME" for an uploaded model.
function sceneOf(choice) {
  if (!choice.startsWith('asset:')) return { preset: choice };
  return { objects: [{ type: 'mesh', path: `assets/${choice.slice('asset:'.length)}` }] };
}

// Lists the uploaded assets in the scene menu, keeping the choice when it is still there.
export async function refreshAssets() {
  const list = await busy(panel(), () => api('/assets'));
  if (!list) return;
  const select = $('#render-form').preset;
  const chosen = select.value;
  $('#render-assets').replaceChildren(...list.assets.map((a) => el('option', { value: `asset:${a.name}` }, a.name)));
  select.value = [...select.options].some((o) => o.value === chosen) ? chosen : select.options[0].value;
}

async function submit(event) {
  event.preventDefault();
  if (!state.map) {
    showError(panel(), 'load a map first');
    return;
  }
  if (!checkFields($('#render-form'))) return;
  const v = formValues($('#render-form'));
  const lighting = { mode: v.mode, rotation_deg: v.rotation_deg, intensity: v.intensity, visible: v.visible };
  if (v.mode.startsWith('median_cut')) lighting.lights = v.lights;
  const body = { envmap: state.map, scene: sceneOf(v.preset), lighting, width: v.width, height: v.height, spp: v.spp,
    sampling: v.sampling, max_depth: v.max_depth, mipmaps: v.mipmaps, normal_maps: v.normal_maps };
  if (v.compare) {
    await busy(panel(), () => compareRenders($('#render-compare'), body, v.compare, exposure()));
    refreshJobs();
    return;
  }
  $('#render-compare').hidden = true;
  const job = await busy(panel(), () => api('/renders', { method: 'POST', json: body }));
  if (!job) return;
  view.watch(job);
  refreshJobs();
}

async function removeJob(event, job) {
  event.stopPropagation();
  if (view.id() === job.id && !ACTIVE.has(job.status)) view.stop();
  await busy(panel(), () => api(`/renders/${job.id}`, { method: 'DELETE' }));
  refreshJobs();
}

export async function refreshJobs() {
  const list = await busy(panel(), () => api('/renders'));
  if (!list) return;
  const rows = [...list.renders].reverse().map((j) =>
    el('tr', { class: view.id() === j.id ? 'selected' : '', dataset: { id: j.id, status: j.status }, onclick: () => view.watch(j) },
      el('td', { class: 'mono' }, j.id.slice(0, 8)),
      el('td', {}, el('span', { class: `pill ${j.status}` }, ACTIVE.has(j.status) ? `${j.status} ${Math.round(j.progress * 100)}%` : j.status)),
      el('td', {}, j.scene.preset ?? `${j.scene.objects} objects`),
      el('td', {}, j.lighting_mode),
      el('td', {}, `${j.width}×${j.height}`),
      el('td', { class: 'num' }, `${j.spp_done}/${j.spp}`),
      el('td', { class: 'num' }, `${num(j.elapsed_s, 3)} s`),
      el('td', {}, el('button', { type: 'button', class: 'small', title: ACTIVE.has(j.status) ? 'cancel' : 'remove job and image', onclick: (e) => removeJob(e, j) },
        ACTIVE.has(j.status) ? 'Cancel' : 'Remove'))));
  if (!rows.length) rows.push(el('tr', {}, el('td', { colspan: 8, class: 'muted' }, 'no jobs yet')));
  fillTable($('#render-jobs'), rows);
  offerTable($('#render-jobs-downloads'), 'renders', list.renders);
}

export function initRenders() {
  const form = $('#render-form');
  view = renderView({
    panel: panel(), image: $('#render-image'), downloads: $('#render-image-downloads'), bar: $('#render-progress'),
    status: $('#render-status'), cancel: $('#render-cancel'), stats: $('#render-stats'), warnings: $('#render-warnings'),
  }, { exposure, changed: refreshJobs });
  form.addEventListener('submit', submit);
  form.exposure.addEventListener('change', () => view.refresh());
  form.mode.addEventListener('change', () => { form.lights.disabled = !form.mode.value.startsWith('median_cut'); });
  form.lights.disabled = true;
  form.preset.addEventListener('focus', refreshAssets);
  refreshJobs();
  refreshAssets();
}
