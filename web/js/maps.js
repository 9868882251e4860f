// The Maps panel: the loaded maps, the selected one's metadata and preview, upload and delete.
import { api, apiUrl, loadImage } from './api.js';
import { $, el, num, rgb, busy, debounce, latestOnly, fillTable, confirmClick } from './dom.js';
import { state, on, setMaps, selectMap, currentMap } from './state.js';
import { offerLinks, offerTable } from './downloads.js';
import { uploadForm } from './upload.js';
import { apiDocument, queryParameter, offerChoices } from './openapi.js';

const panel = () => $('#maps-panel');

export async function refreshMaps() {
  await busy(panel(), async () => {
    const { envmaps } = await api('/envmaps');
    setMaps(envmaps);
  });
}

function swatch(color) {
  const max = Math.max(...color, 1e-30);
  const c = color.map((x) => Math.round(255 * Math.pow(x / max, 1 / 2.2)));
  return el('span', { class: 'swatch', style: `background: rgb(${c.join(',')})`, title: 'hue of the mean radiance' });
}

function renderList(maps) {
  const rows = maps.map((m) =>
    el('tr', { class: m.id === state.map ? 'selected' : '', dataset: { id: m.id }, onclick: () => selectMap(m.id) },
      el('td', {}, swatch(m.mean_radiance), m.id),
      el('td', {}, `${m.width}×${m.height}`),
      el('td', {}, m.format),
      el('td', { class: 'num' }, rgb(m.power)),
      el('td', {}, el('button', { type: 'button', class: 'danger small', title: `unload ${m.id}`, onclick: (e) => askDelete(e, m.id) }, 'Delete'))));
  if (!rows.length) rows.push(el('tr', {}, el('td', { colspan: 5, class: 'muted' }, 'no maps loaded: upload one below')));
  fillTable($('#map-list'), rows);
  offerTable($('#map-list-downloads'), 'envmaps', maps);
}

async function askDelete(event, id) {
  if (!confirmClick(event)) return;
  await busy(panel(), () => api(`/envmaps/${encodeURIComponent(id)}`, { method: 'DELETE' }));
  await refreshMaps();
}

function renderMeta() {
  const m = currentMap();
  const meta = $('#map-meta');
  if (!m) {
    meta.replaceChildren();
    $('#map-image').removeAttribute('src');
    return;
  }
  const items = [
    ['map', m.id], ['size', `${m.width} × ${m.height} (${m.format})`], ['source', m.source],
    ['power', rgb(m.power)], ['mean radiance', rgb(m.mean_radiance)], ['max luminance', num(m.max_luminance)],
  ];
  if (m.clamped_negative_values) items.push(['clamped negatives', String(m.clamped_negative_values)]);
  meta.replaceChildren(...items.flatMap(([k, v]) => [el('dt', {}, k), el('dd', {}, v)]));
}

// The map in the chosen projection (lat-long as held, or resampled by the server).
const showPreview = latestOnly(async (current) => {
  if (!state.map) return;
  const exposure = $('#map-exposure').valueAsNumber;
  $('#map-exposure-value').textContent = exposure > 0 ? `+${exposure}` : String(exposure);
  const projection = $('#map-projection').value || 'latlong';
  const tone = $('#map-tone-mapping-field').hidden ? {} : { tone_mapping: $('#map-tone-mapping').value };
  const id = state.map;
  const path = `/envmaps/${encodeURIComponent(id)}/image`;
  const png = apiUrl(path, { format: 'png', exposure, projection, ...tone });
  await busy(panel(), async () => {
    await loadImage($('#map-image'), png, current);
    if (!current()) return;
    $('#map-view').dataset.projection = projection;
    const name = projection === 'latlong' ? id : `${id}-${projection}`;
    offerLinks($('#map-image-downloads'), name, { png, exr: apiUrl(path, { format: 'exr', projection }) });
  });
});

// The projections (and tone curves, when it takes one) the image endpoint offers, named as its
// document names them.
async function offerProjections() {
  await busy(panel(), async () => {
    const doc = await apiDocument();
    offerChoices($('#map-projection'), queryParameter(doc, '/envmaps/{id}/image', 'projection'));
    const tone = queryParameter(doc, '/envmaps/{id}/image', 'tone_mapping');
    if (tone?.enum) offerChoices($('#map-tone-mapping'), tone);
    $('#map-tone-mapping-field').hidden = !tone?.enum;
  });
}

export function initMaps() {
  on('maps', (maps) => { renderList(maps); renderMeta(); });
  on('map', () => { renderList(state.maps); renderMeta(); showPreview(); });
  $('#map-exposure').addEventListener('input', debounce(() => showPreview(), 120));
  $('#map-projection').addEventListener('change', () => showPreview());
  $('#map-tone-mapping').addEventListener('change', () => showPreview());
  offerProjections();
  uploadForm($('#upload-form'), panel(), {
    path: '/envmaps',
    missing: 'choose an EXR, PFM or Radiance HDR file first',
    done: async (map) => {
      await refreshMaps();
      selectMap(map.id);
    },
  });
}
