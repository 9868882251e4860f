// The image-based lighting panel: the selected map's spherical harmonics (the reconstruction beside the
// map, tone mapped and with its signs, the coefficients) and the split-sum BRDF table with its axes.
import { api, apiUrl, loadImage } from './api.js';
import { $, el, rgb, busy, formValues, latestOnly, autoUpdate, fillTable } from './dom.js';
import { state, on, currentMap } from './state.js';
import { offerLinks, offerTable } from './downloads.js';
import { drawSignedSh, clearSignedSh } from './sh_signed.js';
import { drawLutAxes, lutChannels } from './lut_axes.js';

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

const signedParts = () => ({ canvas: $('#sh-signed'), bar: $('#sh-signed-scale'), stats: $('#sh-signed-stats') });

const updateSh = latestOnly(async (current) => {
  if (!state.map) return;
  const { bands, quantity, window, exposure } = formValues($('#sh-form'));
  const id = encodeURIComponent(state.map);
  await busy(panel(), async () => {
    const result = await api(`/envmaps/${id}/sh?${new URLSearchParams({ bands, window })}`);
    if (!current()) return;
    showCoefficients(result);
    const map = currentMap();
    drawSignedSh(signedParts(), result[quantity].coefficients, map.width);
    const name = `${state.map}-sh${bands}`;
    offerTable($('#sh-coefficients-downloads'), name, coefficientRows(result));
    const png = apiUrl(`/envmaps/${id}/sh.png`, { bands, quantity, window, exposure });
    await Promise.all([loadImage($('#sh-image'), png, current),
      loadImage($('#sh-map-image'), apiUrl(`/envmaps/${id}/image`, { format: 'png', exposure }), current)]);
    if (current()) offerLinks($('#sh-image-downloads'), `${name}-${quantity}`, { png });
  });
});

const updateLut = latestOnly(async (current) => {
  const { size, multiscatter } = formValues($('#lut-form'));
  const params = { size, multiscatter };
  await busy(panel(), async () => {
    await loadImage($('#lut-image'), apiUrl('/brdf-lut', { ...params, format: 'png' }), current);
    if (!current()) return;
    $('#lut-channels').textContent = lutChannels(multiscatter === 'true');
    const name = `brdf-lut-${size}${multiscatter === 'true' ? '-multiscatter' : ''}`;
    offerLinks($('#lut-image-downloads'), name, {
      exr: apiUrl('/brdf-lut', { ...params, format: 'exr' }),
      png: apiUrl('/brdf-lut', { ...params, format: 'png' }),
    });
  });
});

export function initIbl() {
  on('map', () => {
    clearSignedSh(signedParts());
    updateSh();
  });
  autoUpdate($('#sh-form'), () => updateSh());
  autoUpdate($('#lut-form'), () => updateLut());
  drawLutAxes({ xAxis: $('#lut-x-axis'), yAxis: $('#lut-y-axis') });
  updateLut();
}
