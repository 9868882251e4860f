// The Sampling panel: where importance samples fall (samples.png) and the marginal distribution over
// rows, with and without the sin(theta) weighting, as pdf and cdf charts.
import { api, apiUrl, loadImage } from './api.js';
import { $, busy, formValues, latestOnly, autoUpdate } from './dom.js';
import { state, on } from './state.js';
import { lineChart } from './chart.js';
import { offerLinks, offerTable } from './downloads.js';

const panel = () => $('#sampling-panel');
const WEIGHTED = '#f5b942';
const PLAIN = '#5aa9ff';

async function showPicture(current) {
  const { count, strategy, seed, luminance, style, exposure } = formValues($('#sampling-form'));
  const src = apiUrl(`/envmaps/${encodeURIComponent(state.map)}/samples.png`, { count, strategy, seed, luminance, style, exposure });
  await loadImage($('#samples-image'), src, current);
  if (current()) offerLinks($('#samples-image-downloads'), `${state.map}-samples-${strategy}-${count}`, { png: src });
}

// Row y's centre as theta in degrees from +z.
const thetaOf = (y, h) => ((y + 0.5) / h) * 180;

// The charts' data, a record per row of the map: its pdf and its cdf at the row's far edge.
function rowsOf(weighted, plain) {
  return weighted.marginal_pdf.map((p, y) => ({
    row: y,
    theta_deg: thetaOf(y, weighted.height),
    row_luminance: weighted.row_luminance[y],
    pdf_sin_weighted: p,
    pdf_unweighted: plain.marginal_pdf[y],
    cdf_sin_weighted: weighted.marginal_cdf[y + 1],
    cdf_unweighted: plain.marginal_cdf[y + 1],
  }));
}

async function showDistribution(current) {
  const { luminance } = formValues($('#sampling-form'));
  const path = `/envmaps/${encodeURIComponent(state.map)}/distribution`;
  const [weighted, plain] = await Promise.all([
    api(`${path}?luminance=${luminance}&sin_weight=true`),
    api(`${path}?luminance=${luminance}&sin_weight=false`),
  ]);
  if (!current()) return;
  const h = weighted.height;
  // Rows as theta in degrees; pdf as a density in v (pdf * H), so a uniform map of rows reads 1.
  const theta = weighted.marginal_pdf.map((_, y) => thetaOf(y, h));
  const density = (d) => d.marginal_pdf.map((p) => p * h);
  const series = [
    { label: 'with sin θ', stroke: WEIGHTED },
    { label: 'without', stroke: PLAIN },
  ];
  lineChart($('#pdf-chart'), {
    xLabel: 'θ (degrees from +z)', xLegend: 'θ°', yLabel: 'p(v)', series, xRange: [0, 180],
    data: [theta, density(weighted), density(plain)],
  });
  const edges = weighted.marginal_cdf.map((_, y) => (y / h) * 180);
  lineChart($('#cdf-chart'), {
    xLabel: 'θ (degrees from +z)', xLegend: 'θ°', yLabel: 'P(v)', series, xRange: [0, 180], yRange: [0, 1],
    data: [edges, weighted.marginal_cdf, plain.marginal_cdf],
  });
  offerTable($('#distribution-downloads'), `${state.map}-distribution-${luminance}`, rowsOf(weighted, plain));
}

const update = latestOnly(async (current, { distribution = true } = {}) => {
  if (!state.map) return;
  await busy(panel(), () => Promise.all([showPicture(current), distribution ? showDistribution(current) : null]));
});

export function initSampling() {
  on('map', () => update());
  // Only the luminance mode changes the distribution; every control changes the picture.
  autoUpdate($('#sampling-form'), () => update(), (e) => update({ distribution: e.target.name === 'luminance' }));
}
