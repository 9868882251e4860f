// Two renders side by side: the same request with one option two ways (mipmaps or normal maps on and
// off, uniform or adaptive sampling), each followed to its end and shown with its render time.
import { api, apiUrl, loadImage } from './api.js';
import { $, el, num } from './dom.js';
import { offerLinks } from './downloads.js';
import { ACTIVE } from './jobs.js';

// Each option's label and its two values, with how a caption names them.
const OPTIONS = {
  mipmaps: { label: 'mipmaps', sides: [[true, 'on'], [false, 'off']] },
  normal_maps: { label: 'normal maps', sides: [[true, 'on'], [false, 'off']] },
  sampling: { label: 'sampling', sides: [['adaptive', 'adaptive'], ['uniform', 'uniform']] },
};

let comparison = 0; // the latest comparison; an older one stops updating the page

// A render's image (or one of its passes) as the page shows it (PNG at the exposure, with the tone
// mapper chosen if any) and in linear values (EXR).
export function renderImageUrls(id, { exposure = 0, tone_mapping: tone, pass = 'color' } = {}) {
  const which = pass === 'color' ? {} : { pass };
  return {
    png: apiUrl(`/renders/${id}/image`, { format: 'png', exposure, ...(tone ? { tone_mapping: tone } : {}), ...which }),
    exr: apiUrl(`/renders/${id}/image`, { format: 'exr', ...which }),
  };
}

async function follow(job, figure, label, current, picture) {
  const caption = $('figcaption', figure);
  for (;;) {
    if (!current()) return;
    caption.textContent = `${label} · ${job.status} · ${num(job.elapsed_s, 3)} s`;
    figure.dataset.status = job.status;
    if (!ACTIVE.has(job.status)) break;
    await new Promise((r) => setTimeout(r, 250));
    job = await api(`/renders/${job.id}`);
  }
  if (job.image_available) {
    const urls = renderImageUrls(job.id, picture);
    await loadImage($('img', figure), urls.png, current);
    if (current()) offerLinks($('.downloads', figure), `render-${job.id}`, urls);
  }
  if (job.error) caption.textContent += ` · ${job.error.code}: ${job.error.message}`;
}

// Submits `body` with `option` each of its two ways and, once both are accepted, shows both renders in
// `box`, at `picture` ({exposure, tone_mapping}). Resolves once both have ended; rejects with the
// API's error.
export async function compareRenders(box, body, option, picture) {
  const mine = ++comparison;
  const current = () => mine === comparison;
  const sides = OPTIONS[option].sides.map(([value, name]) => {
    const label = `${OPTIONS[option].label} ${name}`;
    const figure = el('figure', { dataset: { option, value: String(value) } },
      el('img', { alt: label }), el('figcaption', {}, label), el('div', { class: 'downloads', hidden: '' }));
    return { value, label, figure };
  });
  const jobs = [];
  for (const s of sides) jobs.push(await api('/renders', { method: 'POST', json: { ...body, [option]: s.value } }));
  if (!current()) return jobs;
  box.replaceChildren(...sides.map((s) => s.figure));
  box.hidden = false;
  await Promise.all(sides.map((s, i) => follow(jobs[i], s.figure, s.label, current, picture)));
  return jobs;
}
