// Wires the panels to the shared map selection and loads the map list.
import { api } from './api.js';
import { $, el } from './dom.js';
import { state, on, selectMap, currentMap } from './state.js';
import { initMaps, refreshMaps } from './maps.js';
import { initSampling } from './sampling.js';
import { initMedianCut } from './median_cut.js';
import { initFresnel } from './fresnel.js';
import { initRenders } from './renders.js';

function initMapSelect() {
  const select = $('#map-select');
  select.addEventListener('change', () => selectMap(select.value));
  on('maps', (maps) => {
    select.replaceChildren(...maps.map((m) => el('option', { value: m.id }, m.id)));
    select.value = state.map ?? '';
  });
  on('map', (id) => {
    select.value = id ?? '';
    const m = currentMap();
    $('#map-summary').textContent = m ? `${m.width}×${m.height} ${m.format}` : 'no map loaded';
    if (!id) ['#map-image', '#samples-image', '#median-cut-image'].forEach((s) => $(s).removeAttribute('src'));
  });
}

async function checkHealth() {
  const badge = $('#health');
  try {
    const h = await api('/health');
    badge.textContent = `server ${h.version}`;
    badge.className = 'health ok';
  } catch (e) {
    badge.textContent = 'server unreachable';
    badge.title = String(e);
    badge.className = 'health bad';
  }
}

initMapSelect();
initMaps();
initSampling();
initMedianCut();
initFresnel();
initRenders();
checkHealth();
refreshMaps();
