// A turntable of the selected model (POST /turntables): its frames orbit the framed model; the newest
// finished frame is shown while it renders, then its animated WebP plays; progress over all frames,
// cancel, and its files (the frames as a zip, the contact sheet, the animation). Offered when the
// server's document names the endpoint, its fields' ranges and defaults taken from there.
import { api, apiUrl, loadImage } from './api.js';
import { $, busy, formValues, showError } from './dom.js';
import { state } from './state.js';
import { checkFields } from './field_errors.js';
import { offerFiles, withdrawOffer } from './downloads.js';
import { ACTIVE, showProgress } from './jobs.js';
import { apiDocument, bodyFields, applyFields, schemaOf, queryParameter } from './openapi.js';

const POLL_MS = 400;
const form = () => $('#turntable-form');
const panel = () => $('#models-panel');

let followed = null; // {id, timer, shownFrame}

// A turntable's status with the field the page's job helpers read (`status`, as renders have it).
const asJob = (t) => ({ ...t, status: t.state ?? t.status });

const path = (id, tail = '') => `/turntables/${id}${tail}`;

function parts() {
  return { bar: $('#turntable-progress'), status: $('#turntable-status'), cancel: $('#turntable-cancel') };
}

async function showFrame(job, current) {
  const newest = job.frames_done - 1;
  if (newest < 0 || newest === followed.shownFrame) return;
  followed.shownFrame = newest;
  await loadImage($('#turntable-player'), apiUrl(path(job.id, `/frames/${newest}`), { format: 'png' }), current);
}

async function showAnimation(job, current) {
  const { fps } = formValues(form());
  const webp = apiUrl(path(job.id, '/animation.webp'), { fps });
  await loadImage($('#turntable-player'), webp, current);
  if (!current()) return;
  $('#turntable-player').dataset.animation = job.id;
  const name = `turntable-${job.id}`;
  offerFiles($('#turntable-downloads'), [
    { name: `${name}.webp`, url: webp },
    { name: `${name}-frames.zip`, url: apiUrl(path(job.id, '/frames.zip')) },
    { name: `${name}-contact-sheet.png`, url: apiUrl(path(job.id, '/contact-sheet'), { format: 'png' }) },
  ]);
}

function follow(id) {
  if (followed) clearTimeout(followed.timer);
  followed = { id, shownFrame: -1 };
  const current = () => followed?.id === id;
  const poll = async () => {
    if (!current()) return;
    try {
      const job = asJob(await api(path(id)));
      if (!current()) return;
      showProgress(job, parts());
      if (ACTIVE.has(job.status)) {
        await showFrame(job, current);
        followed.timer = setTimeout(poll, POLL_MS);
      } else if (job.status === 'done') {
        await showAnimation(job, current);
      }
    } catch (e) {
      showError(panel(), e);
    }
  };
  poll();
}

// The request: the model framed under the current map, the form's picture and turntable fields.
export async function startTurntable(modelPath) {
  if (!state.map) return showError(panel(), 'load a map first');
  if (!checkFields(form())) return undefined;
  const v = formValues(form());
  const body = {
    envmap: state.map, scene: { objects: [{ type: 'mesh', path: modelPath }] }, width: v.width, height: v.height, spp: v.spp,
    turntable: { frames: v.frames, azimuth_start_deg: v.azimuth_start_deg, elevation_deg: v.elevation_deg, elevation_sweep_deg: v.elevation_sweep_deg },
  };
  const job = await busy(panel(), () => api('/turntables', { method: 'POST', json: body }));
  if (!job) return undefined;
  $('#turntable-player').removeAttribute('src');
  delete $('#turntable-player').dataset.animation;
  withdrawOffer($('#turntable-downloads'));
  showProgress(asJob(job), parts());
  follow(job.id);
  return job;
}

async function cancel() {
  if (!followed) return;
  const job = await busy(panel(), () => api(path(followed.id), { method: 'DELETE' }));
  if (job) showProgress(asJob(job), parts());
}

// Shows the section when the server offers turntables; `modelPath()` names the selected model's
// path, or null while there is none.
export async function initTurntable(modelPath) {
  const doc = await apiDocument();
  if (!doc.paths['/api/v1/turntables']) return;
  const fields = bodyFields(doc, '/turntables');
  applyFields(form(), schemaOf(doc, fields.turntable)?.properties ?? {});
  applyFields(form(), { fps: queryParameter(doc, '/turntables/{id}/animation.webp', 'fps') ?? {} });
  $('#turntable-section').hidden = false;
  form().addEventListener('submit', (e) => {
    e.preventDefault();
    const model = modelPath();
    if (model) startTurntable(model);
  });
  $('#turntable-cancel').addEventListener('click', cancel);
}

// Enables the button while a model is selected.
export function turntableModel(selected) {
  $('#turntable-submit').disabled = !selected;
}
