// The Renders panel: submit a preset scene or an uploaded model (optionally two renders side by side,
// an option on and off), follow the job through its server-sent events (progress
// bar, image refreshed after every pass), cancel it, and list every job.
import { api, errorOf, loadImage, API } from './api.js';
import { $, el, num, bigNum, busy, formValues, showError, fillTable } from './dom.js';
import { state } from './state.js';
import { compareRenders, renderImageUrls } from './render_compare.js';
import { offerLinks, offerTable, withdrawOffer } from './downloads.js';
import { checkFields } from './field_errors.js';
import { ACTIVE, showProgress } from './jobs.js';

const panel = () => $('#renders-panel');

let watched = null; // {id, source, poll, shownSpp}

function exposure() {
  return formValues($('#render-form')).exposure || 0;
}

function showImage(job, force = false) {
  if (!job.image_available || !watched || watched.id !== job.id) return;
  if (!force && watched.shownSpp === job.spp_done) return;
  watched.shownSpp = job.spp_done;
  const id = job.id;
  const current = () => watched && watched.id === id;
  const urls = renderImageUrls(id, exposure());
  showFreshImage($('#render-image'), urls.png, current)
    .then(() => { if (current()) offerLinks($('#render-image-downloads'), `render-${id}`, urls); })
    .catch((e) => showError(panel(), e));
}

// The image of a running render changes with every pass under the same URL: it is fetched past the
// browser's caches and shown from a blob URL (the one shown before is released).
let shownBlobUrl = null;
async function showFreshImage(img, src, current) {
  const res = await fetch(src, { cache: 'no-store' });
  if (!res.ok) throw await errorOf(res);
  const url = URL.createObjectURL(await res.blob());
  await loadImage(img, url, current);
  if (img.src !== url) return URL.revokeObjectURL(url);
  if (shownBlobUrl) URL.revokeObjectURL(shownBlobUrl);
  shownBlobUrl = url;
}

function showJob(job) {
  if (!watched || watched.id !== job.id) return;
  // A late answer (the DELETE's "cancelling") must not undo the end the event stream already told.
  if (watched.ended && ACTIVE.has(job.status)) return;
  showProgress(job, { bar: $('#render-progress'), status: $('#render-status'), cancel: $('#render-cancel') });
  const items = [
    ['passes', `${job.spp_done} / ${job.spp} spp`],
    ['time', `${num(job.elapsed_s, 3)} s`],
    ['camera samples/s', bigNum(job.samples_per_s)],
    ['rays/s', bigNum(job.rays_per_s)],
    ['scene', `${job.scene.preset ?? `${job.scene.objects} objects`} · ${job.lighting_mode} · ${job.envmap}`],
  ];
  if (job.error) items.push(['error', `${job.error.code}: ${job.error.message}`]);
  $('#render-stats').replaceChildren(...items.flatMap(([k, v]) => [el('dt', {}, k), el('dd', {}, v)]));
  showImage(job);
}

function stopWatching() {
  if (!watched) return;
  if (watched.source) watched.source.close();
  clearTimeout(watched.poll);
  watched = null;
}

// Polls the status when the event stream is refused (too many streams) or drops.
function poll(id) {
  if (!watched || watched.id !== id) return;
  api(`/renders/${id}`)
    .then((job) => {
      showJob(job);
      if (ACTIVE.has(job.status)) watched.poll = setTimeout(() => poll(id), 500);
      else ended(job);
    })
    .catch((e) => showError(panel(), e));
}

function ended(job) {
  if (watched && watched.id === job.id) watched.ended = true;
  showJob(job);
  showImage(job, true);
  refreshJobs();
}

function watch(job) {
  stopWatching();
  watched = { id: job.id, shownSpp: -1 };
  $('#render-image').removeAttribute('src');
  withdrawOffer($('#render-image-downloads'));
  showJob(job);
  if (!ACTIVE.has(job.status)) {
    ended(job);
    return;
  }
  const source = new EventSource(`${API}/renders/${job.id}/events`);
  watched.source = source;
  let throttle = 0;
  source.addEventListener('progress', (e) => {
    showJob(JSON.parse(e.data));
    if (Date.now() - throttle > 1000) {
      throttle = Date.now();
      refreshJobs();
    }
  });
  source.addEventListener('end', (e) => {
    source.close();
    ended(JSON.parse(e.data));
  });
  source.onerror = () => {
    source.close();
    if (watched && watched.source === source) poll(job.id);
  };
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
  watch(job);
  refreshJobs();
}

async function cancel() {
  if (!watched) return;
  const job = await busy(panel(), () => api(`/renders/${watched.id}`, { method: 'DELETE' }));
  if (job) showJob(job);
}

async function removeJob(event, job) {
  event.stopPropagation();
  if (watched && watched.id === job.id && !ACTIVE.has(job.status)) stopWatching();
  await busy(panel(), () => api(`/renders/${job.id}`, { method: 'DELETE' }));
  refreshJobs();
}

export async function refreshJobs() {
  const list = await busy(panel(), () => api('/renders'));
  if (!list) return;
  const rows = [...list.renders].reverse().map((j) =>
    el('tr', { class: watched && watched.id === j.id ? 'selected' : '', dataset: { id: j.id, status: j.status }, onclick: () => watch(j) },
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
  form.addEventListener('submit', submit);
  form.exposure.addEventListener('change', () => {
    if (watched) api(`/renders/${watched.id}`).then((job) => showImage(job, true)).catch((e) => showError(panel(), e));
  });
  form.mode.addEventListener('change', () => { form.lights.disabled = !form.mode.value.startsWith('median_cut'); });
  form.lights.disabled = true;
  $('#render-cancel').addEventListener('click', cancel);
  form.preset.addEventListener('focus', refreshAssets);
  refreshJobs();
  refreshAssets();
}
