// One render job followed on the page: through its server-sent events (polling when the stream is
// refused or drops), its progress bar, status and figures, the camera it resolved and its warnings,
// the image refreshed after every pass, the passes it accumulates beside the colour (one shown at a
// time), its denoised colour beside the raw one once it is ready, and Cancel. The Renders and Models
// panels each have one.
import { api, errorOf, loadImage, API } from './api.js';
import { el, num, bigNum, busy, showError } from './dom.js';
import { renderImageUrls } from './render_compare.js';
import { offerLinks, withdrawOffer } from './downloads.js';
import { ACTIVE, showProgress } from './jobs.js';

const vec = (v) => `(${v.map((x) => num(x, 3)).join(', ')})`;

// The figures of a job as [label, text] pairs.
function figures(job) {
  const items = [
    ['passes', `${job.spp_done} / ${job.spp} spp`],
    ['time', `${num(job.elapsed_s, 3)} s`],
    ['camera samples/s', bigNum(job.samples_per_s)],
    ['rays/s', bigNum(job.rays_per_s)],
    ['scene', `${job.scene.preset ?? `${job.scene.objects} objects`} · ${job.lighting_mode} · ${job.envmap}`],
  ];
  if (job.denoised) items.push(['denoise', job.denoised.ready ? `${num(job.denoised.seconds, 3)} s` : 'after the last pass']);
  if (job.camera) items.push(['camera', `${vec(job.camera.position)} → ${vec(job.camera.look_at)} · ${num(job.camera.fov_deg, 3)}°`]);
  if (job.error) items.push(['error', `${job.error.code}: ${job.error.message}`]);
  return items;
}

// Shows `warnings` (strings) as the items of the list `box`, hidden while there are none.
export function showWarnings(box, warnings = []) {
  box.replaceChildren(...warnings.map((w) => el('li', {}, w)));
  box.hidden = !warnings.length;
}

// `parts`: the elements it fills ({panel, image, downloads, bar, status, cancel, stats, warnings, and
// optionally passes: the pass tabs, and denoised: a figure with an img and a figcaption}), `picture()` how the image is shown ({exposure, tone_mapping}),
// `passesOf(job)` the passes a job accumulates beside the colour, `changed()` called as the job
// advances (at most once a second) and when it ends.
export function renderView(parts, { picture, passesOf = () => [], changed = () => {} }) {
  let watched = null; // {id, source, poll, shownSpp, ended, pass}
  let shownBlobUrl = null;
  const fail = (e) => showError(parts.panel, e);

  // The image of a running render changes with every pass under the same URL: it is fetched past the
  // browser's caches and shown from a blob URL (the one shown before is released).
  async function showFreshImage(src, current) {
    const res = await fetch(src, { cache: 'no-store' });
    if (!res.ok) throw await errorOf(res);
    const url = URL.createObjectURL(await res.blob());
    await loadImage(parts.image, url, current);
    if (parts.image.src !== url) return URL.revokeObjectURL(url);
    if (shownBlobUrl) URL.revokeObjectURL(shownBlobUrl);
    shownBlobUrl = url;
    parts.image.dataset.source = src; // the API's URL of the picture shown
  }

  function showImage(job, force = false) {
    if (!job.image_available || !watched || watched.id !== job.id) return;
    if (!force && watched.shownSpp === job.spp_done) return;
    watched.shownSpp = job.spp_done;
    const { id } = job;
    const current = () => watched && watched.id === id;
    const urls = renderImageUrls(id, { ...picture(), pass: watched.pass });
    showFreshImage(urls.png, current)
      .then(() => { if (current()) offerLinks(parts.downloads, `render-${id}`, urls); })
      .catch(fail);
  }

  // The denoised colour beside the raw image, once the job has it; hidden otherwise.
  function showDenoised(job) {
    const figure = parts.denoised;
    if (!figure) return;
    const ready = Boolean(job.denoised?.ready) && watched && watched.id === job.id;
    figure.hidden = !ready;
    if (!ready) return figure.querySelector('img').removeAttribute('src');
    const { png } = renderImageUrls(job.id, { ...picture(), pass: 'denoised' });
    figure.querySelector('figcaption').textContent = `denoised · ${num(job.denoised.seconds, 3)} s`;
    const img = figure.querySelector('img');
    if (img.dataset.source === png) return;
    img.dataset.source = png;
    const current = () => watched && watched.id === job.id;
    loadImage(img, png, current).catch(fail);
  }

  // A tab per pass of the job (the colour first), the one shown pressed; hidden without passes.
  function showPassTabs(job) {
    if (!parts.passes) return;
    const passes = passesOf(job);
    const ready = job.image_available && !ACTIVE.has(job.status);
    parts.passes.hidden = !passes.length || !ready;
    if (parts.passes.hidden) return parts.passes.replaceChildren();
    parts.passes.replaceChildren(el('span', { class: 'muted' }, 'pass'), ...['color', ...passes].map((name) =>
      el('button', { type: 'button', class: 'small', 'aria-pressed': String(name === watched.pass), dataset: { pass: name },
        onclick: () => showPass(job, name) }, name)));
  }

  function showPass(job, name) {
    if (!watched || watched.id !== job.id) return;
    watched.pass = name;
    showPassTabs(job);
    showImage(job, true);
  }

  function showJob(job) {
    if (!watched || watched.id !== job.id) return;
    // A late answer (the DELETE's "cancelling") must not undo the end the event stream already told.
    if (watched.ended && ACTIVE.has(job.status)) return;
    showProgress(job, parts);
    parts.stats.replaceChildren(...figures(job).flatMap(([k, v]) => [el('dt', {}, k), el('dd', {}, v)]));
    showWarnings(parts.warnings, job.warnings);
    showPassTabs(job);
    showImage(job);
    showDenoised(job);
  }

  function stop() {
    if (!watched) return;
    if (watched.source) watched.source.close();
    clearTimeout(watched.poll);
    watched = null;
  }

  function ended(job) {
    if (watched && watched.id === job.id) watched.ended = true;
    showJob(job);
    showImage(job, true);
    changed();
  }

  function poll(id) {
    if (!watched || watched.id !== id) return;
    api(`/renders/${id}`)
      .then((job) => {
        showJob(job);
        if (ACTIVE.has(job.status)) watched.poll = setTimeout(() => poll(id), 500);
        else ended(job);
      })
      .catch(fail);
  }

  function watch(job) {
    stop();
    watched = { id: job.id, shownSpp: -1, pass: 'color' };
    parts.image.removeAttribute('src');
    delete parts.image.dataset.source;
    withdrawOffer(parts.downloads);
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
        changed();
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

  async function cancel() {
    if (!watched) return;
    const job = await busy(parts.panel, () => api(`/renders/${watched.id}`, { method: 'DELETE' }));
    if (job) showJob(job);
  }

  // The image again at the current exposure and tone mapper.
  function refresh() {
    if (watched) api(`/renders/${watched.id}`).then((job) => { showImage(job, true); showDenoised(job); }).catch(fail);
  }

  // Follows no job and shows none.
  function clear() {
    stop();
    parts.image.removeAttribute('src');
    withdrawOffer(parts.downloads);
    parts.bar.style.width = '0';
    parts.bar.className = '';
    parts.status.textContent = 'no render yet';
    delete parts.status.dataset.status;
    parts.cancel.disabled = true;
    parts.stats.replaceChildren();
    showWarnings(parts.warnings);
    if (parts.passes) {
      parts.passes.hidden = true;
      parts.passes.replaceChildren();
    }
    if (parts.denoised) parts.denoised.hidden = true;
  }

  parts.cancel.addEventListener('click', cancel);
  return { watch, stop, clear, refresh, id: () => watched?.id ?? null };
}
