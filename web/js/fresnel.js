// The Fresnel panel: rs, rp, unpolarised and Schlick reflectance against the incidence angle for a
// dielectric pair (Brewster and critical angles marked), or the per-channel curves of a metal.
import { api, apiUrl } from './api.js';
import { $, el, num, rgb, busy, formValues, latestOnly, autoUpdate } from './dom.js';
import { lineChart } from './chart.js';
import { offerLinks } from './downloads.js';

const panel = () => $('#fresnel-panel');
const COLORS = { rs: '#5aa9ff', rp: '#f5874f', unpolarized: '#e8ecf1', schlick: '#7bd88f', brewster: '#f5b942', critical: '#d77bf5' };

function stats(items) {
  $('#fresnel-stats').replaceChildren(...items.flatMap(([k, v]) => [el('dt', {}, k), el('dd', {}, v)]));
}

// Linear interpolation of a table column at angle a.
function at(angles, values, a) {
  const i = Math.max(1, angles.findIndex((x) => x >= a));
  const t = (a - angles[i - 1]) / (angles[i] - angles[i - 1] || 1);
  return values[i - 1] + t * (values[i] - values[i - 1]);
}

function showDielectric(t) {
  const markers = [{ x: t.brewster_deg, label: `Brewster ${t.brewster_deg.toFixed(1)}°`, color: COLORS.brewster }];
  if (t.critical_deg !== null) markers.push({ x: t.critical_deg, label: `critical ${t.critical_deg.toFixed(1)}°`, color: COLORS.critical });
  const errAngle = t.schlick_max_error_angle_deg;
  lineChart($('#fresnel-chart'), {
    xLabel: 'incidence angle (degrees)', xLegend: 'θ°', yLabel: 'reflectance', xRange: [0, 90], yRange: [0, 1], height: 260,
    series: [
      { label: 'rs', stroke: COLORS.rs },
      { label: 'rp', stroke: COLORS.rp },
      { label: 'unpolarized', stroke: COLORS.unpolarized, width: 2 },
      { label: 'Schlick', stroke: COLORS.schlick, dash: [6, 4] },
    ],
    data: [t.angles_deg, t.rs, t.rp, t.unpolarized, t.schlick],
    markers,
    points: [{ x: errAngle, y: at(t.angles_deg, t.schlick, errAngle), color: COLORS.schlick }],
  });
  stats([
    ['interface', `η ${num(t.eta_i)} → ${num(t.eta_t)}`],
    ['R0 (normal incidence)', num(t.r0)],
    ['Brewster angle', `${t.brewster_deg.toFixed(1)}° (rp = 0)`],
    ['critical angle', t.critical_deg === null ? 'none (η_i < η_t)' : `${t.critical_deg.toFixed(1)}° (total internal reflection past it)`],
    ['Schlick max |error|', `${num(t.schlick_max_abs_error)} at ${errAngle.toFixed(1)}°`],
  ]);
}

function showConductor(t) {
  lineChart($('#fresnel-chart'), {
    xLabel: 'incidence angle (degrees)', xLegend: 'θ°', yLabel: 'reflectance', xRange: [0, 90], yRange: [0, 1], height: 260,
    series: [
      { label: 'R red', stroke: '#ff6b6b', width: 2 },
      { label: 'R green', stroke: '#6bdc7b', width: 2 },
      { label: 'R blue', stroke: '#6ba4ff', width: 2 },
      { label: 'rs green', stroke: '#6bdc7b', dash: [2, 3], width: 1 },
      { label: 'rp green', stroke: '#6bdc7b', dash: [7, 4], width: 1 },
    ],
    data: [t.angles_deg, t.r, t.g, t.b, t.rs.g, t.rp.g],
  });
  const r0 = [t.r0.r, t.r0.g, t.r0.b];
  const c = r0.map((x) => Math.round(255 * Math.pow(x, 1 / 2.2)));
  const wl = t.wavelengths_nm;
  stats([
    ['conductor', t.metal ?? 'custom'],
    ['R0 (normal incidence)', el('span', {}, el('span', { class: 'swatch', style: `background: rgb(${c.join(',')})` }), rgb(r0))],
    ['η', rgb([t.eta.r, t.eta.g, t.eta.b])],
    ['k', rgb([t.k.r, t.k.g, t.k.b])],
    ['wavelengths', wl ? `${[wl.r, wl.g, wl.b].map((x) => x.toFixed(0)).join(' / ')} nm` : '–'],
  ]);
}

const update = latestOnly(async (current) => {
  const { preset, eta_i, eta_t } = formValues($('#fresnel-form'));
  const metal = preset.startsWith('metal:') ? preset.slice(6) : null;
  const query = { eta_i, step: 0.25, ...(metal ? { metal } : { eta_t }) };
  $('#fresnel-form [name=eta_t]').disabled = Boolean(metal);
  await busy(panel(), async () => {
    const table = await api(`/fresnel?${new URLSearchParams(query)}`);
    if (!current()) return;
    if (table.kind === 'conductor') showConductor(table);
    else showDielectric(table);
    const name = `fresnel-${metal ?? `${eta_i}-${eta_t}`}`;
    offerLinks($('#fresnel-downloads'), name, { json: apiUrl('/fresnel', query), csv: apiUrl('/fresnel', { ...query, format: 'csv' }) });
  });
});

function applyPreset() {
  const form = $('#fresnel-form');
  const preset = form.preset.value;
  if (preset.startsWith('metal:')) form.eta_i.value = 1;
  else if (preset !== 'custom') [form.eta_i.value, form.eta_t.value] = preset.split(',');
}

export function initFresnel() {
  const form = $('#fresnel-form');
  autoUpdate(form, () => update(), (e) => {
    if (e.target.name === 'preset') applyPreset();
    else if (!form.preset.value.startsWith('metal:')) form.preset.value = 'custom';
    update();
  });
  applyPreset();
  update();
}
