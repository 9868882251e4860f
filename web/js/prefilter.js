// The prefiltered GGX chain of the selected map, in the IBL panel: a job started from the form (its
// fields, defaults and ranges those of the API's document), its progress, cancel, and once done every
// level side by side at one display height with its roughness, and the chain's files.
import { api, apiUrl, loadImage } from './api.js';
import { $, el, num, busy, formValues, showError } from './dom.js';
import { state } from './state.js';
import { checkFields } from './field_errors.js';
import { offerFiles, withdrawOffer } from './downloads.js';
import { ACTIVE, showProgress } from './jobs.js';
import { apiDocument, bodyFields, applyFields } from './openapi.js';

const panel = () => $('#ibl-panel');
const form = () => $('#prefilter-form');
const POLL_MS = 200;

let watched = null; // {id, timer, job}

const jobView = () => ({ bar: $('#prefilter-progress'), status: $('#prefilter-status'), cancel: $('#prefilter-cancel') });

// One figure per level, each as wide as its aspect asks so that all stand at the same height.
function showStrip(job) {
  const exposure = formValues(form()).exposure || 0;
  const figures = job.level_info.map((level) => el('figure', { dataset: { level: level.level }, style: `flex-grow: ${level.width / level.height}` },
    el('img', { alt: `level ${level.level}, roughness ${level.roughness}`, width: level.width, height: level.height }),
    el('figcaption', { title: `GGX alpha ${num(level.alpha)}; ${level.width}×${level.height}` }, `r ${num(level.roughness, 3)}`)));
  $('#prefilter-strip').replaceChildren(...figures);
  const current = () => watched && watched.job === job;
  return Promise.all(figures.map((figure, i) =>
    loadImage($('img', figure), apiUrl(`/prefilters/${job.id}/levels/${i}.png`, { exposure }), current)));
}

function showStats(job) {
  const [top] = job.level_info;
  const items = [
    ['chain', `${job.envmap} · ${job.levels} levels from ${top.width}×${top.height} · ${job.samples} samples`],
    ['time', `${num(job.elapsed_s, 3)} s`],
  ];
  if (job.source_width) items.push(['lobes read', `the map reduced to ${job.source_width} texels wide`]);
  $('#prefilter-stats').replaceChildren(...items.flatMap(([k, v]) => [el('dt', {}, k), el('dd', {}, v)]));
}

function showJob(job) {
  if (!watched || watched.id !== job.id) return;
  watched.job = job;
  showProgress(job, jobView());
  showStats(job);
  if (job.error) showError(panel(), `${job.error.code}: ${job.error.message}`);
  if (job.status !== 'done') return;
  offerFiles($('#prefilter-downloads'), job.files);
  showStrip(job).catch((e) => showError(panel(), e));
}

function poll() {
  if (!watched) return;
  const { id } = watched;
  api(`/prefilters/${id}`)
    .then((job) => {
      showJob(job);
      if (ACTIVE.has(job.status) && watched && watched.id === id) watched.timer = setTimeout(poll, POLL_MS);
    })
    .catch((e) => showError(panel(), e));
}

function watch(job) {
  if (watched) clearTimeout(watched.timer);
  watched = { id: job.id };
  $('#prefilter-strip').replaceChildren();
  withdrawOffer($('#prefilter-downloads'));
  showJob(job);
  if (ACTIVE.has(job.status)) watched.timer = setTimeout(poll, POLL_MS);
}

async function submit(event) {
  event.preventDefault();
  if (!state.map) {
    showError(panel(), 'load a map first');
    return;
  }
  if (!checkFields(form())) return;
  const { levels, base_size, samples, format, precision } = formValues(form());
  const body = { levels, base_size, samples, format, precision };
  const job = await busy(panel(), () => api(`/envmaps/${encodeURIComponent(state.map)}/prefilter`, { method: 'POST', json: body }));
  if (job) watch(job);
}

async function cancel() {
  if (!watched) return;
  const job = await busy(panel(), () => api(`/prefilters/${watched.id}`, { method: 'DELETE' }));
  if (job) showJob(job);
}

export async function initPrefilter() {
  form().addEventListener('submit', submit);
  $('#prefilter-cancel').addEventListener('click', cancel);
  form().exposure.addEventListener('change', () => {
    if (watched?.job?.status === 'done') showStrip(watched.job).catch((e) => showError(panel(), e));
  });
  await busy(panel(), async () => applyFields(form(), bodyFields(await apiDocument(), '/envmaps/{id}/prefilter')));
}
