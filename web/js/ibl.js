// The image-based lighting panel: the selected map's spherical harmonics (the reconstruction beside the
// map, the coefficients) and the split-sum BRDF table.
import { api, apiUrl, loadImage } from './api.js';
import { $, el, rgb, busy, formValues, latestOnly, autoUpdate, fillTable } from './dom.js';
import { state, on } from './state.js';
import { offerLinks, offerTable } from './downloads.js';

const panel = () => $('#ibl-panel');

function coefficientRows(result) {
  const irradiance = result.irradiance?.coefficients ?? [];
  return result.radiance.coefficients.map((c, i) => ({
    l: c.l, m: c.m, radiance: c.rgb, irradiance: irradiance[i]?.rgb,
  }));
}

function showCoefficients(result) {
  fillTable($('#sh-coefficients'), coefficientRows(result).map((c) => el('tr', {},
    el('td', {}, `${c.l}, ${c.m}`),
    el('td', { class: 'num' }, rgb(c.radiance)),
    el('td', { class: 'num' }, c.irradiance ? rgb(c.irradiance) : '–'))));
}

const updateSh = latestOnly(async (current) => {
  if (!state.map) return;
  const { bands, quantity, window, exposure } = formValues($('#sh-form'));
  const id = encodeURIComponent(state.map);
  await busy(panel(), async () => {
    const result = await api(`/envmaps/${id}/sh?${new URLSearchParams({ bands, window })}`);
    if (!current()) return;
    showCoefficients(result);
    const name = `${state.map}-sh${bands}`;
    offerTable($('#sh-coefficients-downloads'), name, coefficientRows(result));
    const png = apiUrl(`/envmaps/${id}/sh.png`, { bands, quantity, window, exposure });
    await loadImage($('#sh-image'), png, current);
    if (current()) offerLinks($('#sh-image-downloads'), `${name}-${quantity}`, { png });
  });
});

const updateLut = latestOnly(async (current) => {
  const { size, multiscatter } = formValues($('#lut-form'));
  const params = { size, multiscatter };
  await busy(panel(), async () => {
    await loadImage($('#lut-image'), apiUrl('/brdf-lut', { ...params, format: 'png' }), current);
    if (!current()) return;
    const name = `brdf-lut-${size}${multiscatter === 'true' ? '-multiscatter' : ''}`;
    offerLinks($('#lut-image-downloads'), name, {
      exr: apiUrl('/brdf-lut', { ...params, format: 'exr' }),
      png: apiUrl('/brdf-lut', { ...params, format: 'png' }),
    });
  });
});

export function initIbl() {
  on('map', () => updateSh());
  autoUpdate($('#sh-form'), () => updateSh());
  autoUpdate($('#lut-form'), () => updateLut());
  updateLut();
}
