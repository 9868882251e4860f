// The Median-cut panel: Debevec's regions and lights for the selected map, each light drawn over the
// picture with its energy, and the brightest lights' figures.
import { api, apiUrl, loadImage } from './api.js';
import { $, el, num, rgb, busy, formValues, latestOnly, autoUpdate, fillTable } from './dom.js';
import { state, on, currentMap } from './state.js';
import { offerLinks, offerTable } from './downloads.js';
import { drawLights, clearLights, anglesDeg } from './light_markers.js';

const panel = () => $('#median-cut-panel');

function showStats(result) {
  const spread = result.energy_min > 0 ? result.energy_max / result.energy_min : Infinity;
  const items = [
    ['lights', `${result.count} lights`],
    ['energy min / max', `${num(result.energy_min)} / ${num(result.energy_max)} (×${num(spread, 3)})`],
    ['total power', rgb(result.power)],
    ['time', `${num(result.elapsed_ms, 3)} ms${result.cached ? ' (cached)' : ''}`],
  ];
  $('#median-cut-stats').replaceChildren(...items.flatMap(([k, v]) => [el('dt', {}, k), el('dd', {}, v)]));
  const brightest = [...result.lights].sort((a, b) => b.energy - a.energy).slice(0, 5);
  fillTable($('#median-cut-lights'), brightest.map((l, i) => {
    const { theta, phi } = anglesDeg(l.direction);
    const r = l.region;
    return el('tr', {},
      el('td', {}, `#${i + 1}  (${l.pixel[0]}, ${l.pixel[1]})`),
      el('td', { class: 'num' }, num(theta, 3)),
      el('td', { class: 'num' }, num(phi, 3)),
      el('td', { class: 'num' }, rgb(l.power)),
      el('td', { class: 'num' }, `${r.x1 - r.x0}×${r.y1 - r.y0}`));
  }));
}

const update = latestOnly(async (current) => {
  if (!state.map) return;
  const { count, placement, split, luminance, style, exposure } = formValues($('#median-cut-form'));
  const id = encodeURIComponent(state.map);
  await busy(panel(), async () => {
    const result = await api(`/envmaps/${id}/median-cut`, { method: 'POST', json: { count, placement, split, luminance } });
    if (!current()) return;
    showStats(result);
    const map = currentMap();
    drawLights($('#median-cut-overlay'), $('#median-cut-legend'), result, map.width, map.height);
    const name = `${state.map}-median-cut-${count}`;
    offerTable($('#median-cut-lights-downloads'), `${name}-lights`, result.lights);
    const png = apiUrl(`/envmaps/${id}/median-cut.png`, { count, placement, split, luminance, style, exposure });
    await loadImage($('#median-cut-image'), png, current);
    if (current()) offerLinks($('#median-cut-image-downloads'), name, { png });
  });
});

export function initMedianCut() {
  on('map', () => {
    clearLights($('#median-cut-overlay'), $('#median-cut-legend'));
    update();
  });
  autoUpdate($('#median-cut-form'), () => update());
}
