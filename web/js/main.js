// Wires the panels to the shared map selection and loads the map list.
import { $, el } from './dom.js';
import { withdrawOffer } from './downloads.js';
import { state, on, selectMap, currentMap } from './state.js';
import { initMaps, refreshMaps } from './maps.js';
import { initSampling } from './sampling.js';
import { initMedianCut } from './median_cut.js';
import { initIbl } from './ibl.js';
import { initPrefilter } from './prefilter.js';
import { initSun } from './sun.js';
import { initFresnel } from './fresnel.js';
import { initRenders } from './renders.js';
import { initModels } from './models.js';
import { initHealth } from './health.js';

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
    if (id) return;
    ['#map-image', '#samples-image', '#median-cut-image', '#sh-image', '#sh-map-image'].forEach((s) => $(s).removeAttribute('src'));
    ['#map-image', '#samples-image', '#distribution', '#median-cut-image', '#median-cut-lights', '#sh-image',
      '#sh-coefficients']
      .forEach((s) => withdrawOffer($(`${s}-downloads`)));
  });
}

initMapSelect();
initMaps();
initSun();
initSampling();
initMedianCut();
initIbl();
initPrefilter();
initFresnel();
initRenders();
initModels();
initHealth();
refreshMaps();
