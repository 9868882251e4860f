// The axes of the split-sum BRDF table (GET /brdf-lut): n·v across from 0 to 1 and roughness down
// from 0 at the top to 1, texel x at n·v = (x + 0.5) / size, so the picture's edges are 0 and 1; and
// what its channels hold.
import { el, num } from './dom.js';

const TICKS = [0, 0.25, 0.5, 0.75, 1];

// Ticks along `axis` (its title kept): `side` 'left' places them across, 'top' down.
function ticks(axis, side) {
  const title = axis.querySelector('.axis-title');
  axis.replaceChildren(title, ...TICKS.map((t) => el('span', { class: 'tick', style: `${side}: ${100 * t}%`, dataset: { value: t } }, num(t))));
}

export function drawLutAxes({ xAxis, yAxis }) {
  ticks(xAxis, 'left');
  ticks(yAxis, 'top');
}

// The channels of the table as the API lays them out with or without multiscatter.
export const lutChannels = (multiscatter) => (multiscatter
  ? 'red: bias, green: scale + bias (specular = mix(red, green, F0)); blue 0'
  : 'red: scale, green: bias (specular = prefiltered × (F0 · scale + bias)); blue 0');
