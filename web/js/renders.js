// The Renders panel: submit a preset scene or an uploaded model (optionally two renders side by side,
// an option on and off) with the picture options the server offers (tone mapper, background, ground,
// passes), follow the job through its server-sent events (progress bar, image refreshed after every
// pass, then each pass), cancel it, and list every job.
import { api } from './api.js';
import { $, el, num, busy, formValues, showError, fillTable } from './dom.js';
import { state } from './state.js';
import { compareRenders } from './render_compare.js';
import { offerTable } from './downloads.js';
import { checkFields } from './field_errors.js';
import { ACTIVE } from './jobs.js';
import { renderView } from './render_view.js';
import { offerRenderOptions, followRenderOptions, renderOptionFields, groundObject, shownToneMapping } from './render_options.js';

const panel = () => $('#renders-panel');

let view = null; // the job followed (renderView)
const requestedPasses = new Map(); // job id -> the passes its request named

// How the render's image is shown: the exposure, and the tone mapper chosen (overriding the request's).
function picture() {
  const form = $('#render-form');
  return { exposure: formValues(form).exposure || 0, tone_mapping: shownToneMapping(form) };
}

const isAsset = (choice) => choice.startsWith('asset:');

// The scene a choice of the scene menu names: a preset, or "asset:NAME" for an uploaded model (with
// the ground the form asks for).
function sceneOf(choice, form) {
  if (!isAsset(choice)) return { preset: choice };
  const ground = groundObject(form);
  return { objects: [{ type: 'mesh', path: `assets/${choice.slice('asset:'.length)}` }, ...(ground ? [ground] : [])] };
}

const follow = (form) => followRenderOptions(form, isAsset(form.preset.value));

// Lists the uploaded assets in the scene menu, keeping the choice when it is still there.
export async function refreshAssets() {
  const list = await busy(panel(), () => api('/assets'));
  if (!list) return;
  const select = $('#render-form').preset;
  const chosen = select.value;
  $('#render-assets').replaceChildren(...list.assets.map((a) => el('option', { value: `asset:${a.name}` }, a.name)));
  select.value = [...select.options].some((o) => o.value === chosen) ? chosen : select.options[0].value;
  follow($('#render-form'));
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
  const form = $('#render-form');
  const body = { envmap: state.map, scene: sceneOf(v.preset, form), lighting, width: v.width, height: v.height, spp: v.spp,
    sampling: v.sampling, max_depth: v.max_depth, mipmaps: v.mipmaps, normal_maps: v.normal_maps, ...renderOptionFields(form) };
  if (v.compare) {
    await busy(panel(), () => compareRenders($('#render-compare'), body, v.compare, picture()));
    refreshJobs();
    return;
  }
  $('#render-compare').hidden = true;
  const job = await busy(panel(), () => api('/renders', { method: 'POST', json: body }));
  if (!job) return;
  requestedPasses.set(job.id, body.passes ?? []);
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
    passes: $('#render-passes'), denoised: $('#render-denoised'),
  }, { picture, passesOf: (job) => (Array.isArray(job.passes) ? job.passes.filter((p) => p !== 'color') : requestedPasses.get(job.id) ?? []), changed: refreshJobs });
  form.addEventListener('submit', submit);
  form.exposure.addEventListener('change', () => view.refresh());
  form.tone_mapping.addEventListener('change', () => view.refresh());
  form.addEventListener('change', () => follow(form));
  busy(panel(), async () => {
    await offerRenderOptions(form);
    follow(form);
  });
  form.mode.addEventListener('change', () => { form.lights.disabled = !form.mode.value.startsWith('median_cut'); });
  form.lights.disabled = true;
  form.preset.addEventListener('focus', refreshAssets);
  refreshJobs();
  refreshAssets();
}
