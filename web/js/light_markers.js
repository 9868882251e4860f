// The median-cut lights drawn over the map: a disc per light centred where it lies, its area
// proportional to its energy (the luminance of its power), filled with its power's colour; and a
// scale of discs of the largest and smallest energies with their values. Both are SVGs in the map's
// pixels, so they scale with the picture under them.
import { num, rgb } from './dom.js';

const SVG = 'http://www.w3.org/2000/svg';
const deg = (rad) => (rad * 180) / Math.PI;

function svgEl(tag, attrs = {}, ...children) {
  const node = document.createElementNS(SVG, tag);
  for (const [k, v] of Object.entries(attrs)) node.setAttribute(k, v);
  node.append(...children);
  return node;
}

// The power's colour at full brightness (its largest channel at 255).
function chromaticity(power) {
  const top = Math.max(...power);
  return top > 0 ? `rgb(${power.map((c) => Math.round((255 * c) / top)).join(' ')})` : 'rgb(0 0 0)';
}

// The radius in map pixels of the disc of energy `energy`: the brightest light's disc is half as wide
// as a region of the average size, and no wider than a quarter of the map's height.
export function discScale(result, width, height) {
  const largest = Math.min(Math.sqrt((width * height) / result.count), height / 4) / 2;
  return (energy) => (result.energy_max > 0 ? largest * Math.sqrt(energy / result.energy_max) : 0);
}

// A unit direction's polar angle from +z and azimuth from +x toward +y, in degrees.
export function anglesDeg([x, y, z]) {
  return { theta: deg(Math.acos(Math.max(-1, Math.min(1, z)))), phi: (deg(Math.atan2(y, x)) + 360) % 360 };
}

function lightDisc(light, index, radius) {
  const [u, v] = light.uv;
  const { theta, phi } = anglesDeg(light.direction);
  const where = `θ ${num(theta, 3)}°, φ ${num(phi, 3)}°`;
  return svgEl('circle', { class: 'light', cx: u * light.mapWidth, cy: v * light.mapHeight, r: radius(light.energy),
    fill: chromaticity(light.power), 'data-index': index, 'data-energy': light.energy },
  svgEl('title', {}, `light ${index + 1}: energy ${num(light.energy)}, power ${rgb(light.power)}, ${where}`));
}

// Draws `result` (POST /envmaps/{id}/median-cut) over a map of width x height in `overlay`, and its
// scale in `legend`.
export function drawLights(overlay, legend, result, width, height) {
  const radius = discScale(result, width, height);
  overlay.setAttribute('viewBox', `0 0 ${width} ${height}`);
  overlay.replaceChildren(...result.lights.map((l, i) => lightDisc({ ...l, mapWidth: width, mapHeight: height }, i, radius)));

  const font = width / 48;
  const largest = radius(result.energy_max);
  const rows = Math.max(2 * largest, font) + font;
  const entries = [['largest', result.energy_max], ['smallest', result.energy_min]];
  let x = font / 2;
  const items = [svgEl('text', { x, y: rows / 2, 'font-size': font, 'dominant-baseline': 'middle' }, 'disc area ∝ energy:')];
  x += font * 11;
  for (const [name, energy] of entries) {
    const r = radius(energy);
    items.push(svgEl('circle', { class: 'scale', cx: x + largest, cy: rows / 2, r, 'data-energy': energy }));
    items.push(svgEl('text', { x: x + 2 * largest + font / 2, y: rows / 2, 'font-size': font, 'dominant-baseline': 'middle' },
      `${name} ${num(energy)}`));
    x += 2 * largest + font * 9;
  }
  legend.setAttribute('viewBox', `0 0 ${width} ${rows}`);
  legend.replaceChildren(...items);
  legend.hidden = false;
}

export function clearLights(overlay, legend) {
  overlay.replaceChildren();
  legend.replaceChildren();
  legend.hidden = true;
}

