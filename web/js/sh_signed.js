// The SH reconstruction with its signs: the mean of its red, green and blue sums at every pixel centre
// of a lat-long image, drawn with a diverging colour map symmetric about 0 (negative lobes blue), its
// scale, and where it is smallest and largest. The server's picture is tone mapped, so a negative lobe
// is black there; here it is computed from the API's coefficients with the same basis.
import { el, num } from './dom.js';
import { shReconstruct } from './sh_basis.js';
import { diverging, divergingGradient } from './diverging.js';

const MAX_WIDTH = 512;
const deg = (rad) => (rad * 180) / Math.PI;

// The mean of the coefficients' three channels (the API's `average` luminance).
const meanChannel = (coefficients) => coefficients.map((c) => (c.rgb[0] + c.rgb[1] + c.rgb[2]) / 3);

// The extremes of `values` (width x height) and the share of the sphere's solid angle below 0.
function extremes(values, width, height) {
  let [min, max, at, atMax, negative, total] = [Infinity, -Infinity, 0, 0, 0, 0];
  values.forEach((v, i) => {
    if (v < min) [min, at] = [v, i];
    if (v > max) [max, atMax] = [v, i];
    const w = Math.sin((Math.PI * (Math.floor(i / width) + 0.5)) / height);
    total += w;
    if (v < 0) negative += w;
  });
  const where = (i) => `θ ${num(deg((Math.PI * (Math.floor(i / width) + 0.5)) / height))}°, φ ${num(deg((2 * Math.PI * ((i % width) + 0.5)) / width))}°`;
  return { min, max, minAt: where(at), maxAt: where(atMax), negativeShare: negative / total };
}

function paint(canvas, values, width, height, scale) {
  canvas.width = width;
  canvas.height = height;
  const context = canvas.getContext('2d');
  const image = context.createImageData(width, height);
  values.forEach((v, i) => {
    image.data.set([...diverging(scale > 0 ? v / scale : 0), 255], 4 * i);
  });
  context.putImageData(image, 0, 0);
}

// The colour bar under the picture: the gradient with ticks at -scale, 0 and +scale.
function drawScale(bar, scale) {
  const ticks = [-1, -0.5, 0, 0.5, 1].map((t) =>
    el('span', { class: 'tick', style: `left: ${50 + 50 * t}%`, dataset: { value: t * scale } }, num(t * scale, 3)));
  bar.replaceChildren(el('div', { class: 'gradient', style: `background: ${divergingGradient()}` }), ...ticks);
  bar.hidden = false;
}

// Draws the coefficients (an ShCoefficientSet's list) for a map `mapWidth` wide into `parts` =
// {canvas, bar, stats}; the canvas keeps its values (canvas.values) and their scale.
export function drawSignedSh(parts, coefficients, mapWidth) {
  const width = Math.max(2, Math.min(MAX_WIDTH, mapWidth));
  const height = Math.max(1, Math.floor(width / 2));
  const values = shReconstruct(meanChannel(coefficients), width, height);
  const e = extremes(values, width, height);
  const scale = Math.max(Math.abs(e.min), Math.abs(e.max));
  paint(parts.canvas, values, width, height, scale);
  Object.assign(parts.canvas, { values });
  parts.canvas.dataset.scale = scale;
  drawScale(parts.bar, scale);
  const items = [
    ['smallest', `${num(e.min)} at ${e.minAt}`],
    ['largest', `${num(e.max)} at ${e.maxAt}`],
    ['below 0', e.min < 0 ? `${num(100 * e.negativeShare, 3)} % of the sphere` : 'nowhere'],
  ];
  parts.stats.replaceChildren(...items.flatMap(([k, v]) => [el('dt', {}, k), el('dd', {}, v)]));
}

export function clearSignedSh(parts) {
  parts.canvas.width = 0;
  parts.canvas.values = null;
  parts.bar.hidden = true;
  parts.stats.replaceChildren();
}
