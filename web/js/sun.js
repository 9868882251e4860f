// The sun of the selected map (POST /envmaps/{id}/sun): a marker over the lat-long map where it lies,
// as large as its cone, with its figures beside the map; or why the map has none.
import { api } from './api.js';
import { apiDocument, applyFields, componentFields } from './openapi.js';
import { $, el, num, rgb, busy } from './dom.js';
import { state, on } from './state.js';
import { refreshMaps } from './maps.js';

const panel = () => $('#maps-panel');
const form = () => $('#sun-form');
const deg = (rad) => (rad * 180) / Math.PI;

// Where a direction lies on a lat-long image, as fractions of its width and height: u = phi / 2 pi,
// v = theta / pi, row 0 at the top (engine/envmap/latlong.hpp).
export const latlongUv = (theta, phi) => [phi / (2 * Math.PI), theta / Math.PI];

// The marker: centred on the direction, as tall as the cone (2 r / pi of the map's height) and as wide
// as the cone spreads along its row (2 r / sin theta of 2 pi), never smaller than a mark one can see.
function placeMarker(sun) {
  const [u, v] = latlongUv(sun.theta, sun.phi);
  const r = sun.angular_radius;
  const width = Math.min(1, r / (Math.PI * Math.max(Math.sin(sun.theta), 1e-6)));
  const height = (2 * r) / Math.PI;
  const marker = $('#sun-marker');
  Object.assign(marker.style, {
    left: `${100 * u}%`, top: `${100 * v}%`, width: `max(14px, ${100 * width}%)`, height: `max(14px, ${100 * height}%)`,
  });
  Object.assign(marker.dataset, { u, v });
  marker.title = `the sun: θ ${num(deg(sun.theta))}°, φ ${num(deg(sun.phi))}°, radius ${num(deg(r))}°`;
}

function showFigures(sun) {
  const figures = $('#sun-figures');
  figures.dataset.found = sun.found;
  const items = sun.found ? [
    ['sun direction', `θ ${num(deg(sun.theta))}°, φ ${num(deg(sun.phi))}° (pixel ${sun.pixel[0]}, ${sun.pixel[1]})`],
    ['angular radius', `${num(deg(sun.angular_radius))}°`],
    ['irradiance', rgb(sun.irradiance)],
    ['share of power', `${num(100 * sun.share, 3)} %`],
    ['residual map', sun.residual],
  ] : [['sun', `none in this map: ${sun.reason}`]];
  items.push(['sun parameters', `threshold ${num(sun.parameters.min_contrast)} times the sky around it, least share ${num(sun.parameters.min_share)}`]);
  figures.replaceChildren(...items.flatMap(([k, v]) => [el('dt', {}, k), el('dd', {}, v)]));
  figures.hidden = false;
}

function clear() {
  $('#sun-marker').hidden = true;
  $('#sun-figures').hidden = true;
  $('#sun-figures').replaceChildren();
}

async function findSun() {
  const id = state.map;
  if (!id) return;
  // The threshold and least share the form holds (the API's defaults and ranges, from its document).
  const json = {};
  for (const name of ['min_contrast', 'min_share']) {
    const value = form().elements.namedItem(name).value;
    if (value !== '') json[name] = Number(value);
  }
  const sun = await busy(panel(), () => api(`/envmaps/${encodeURIComponent(id)}/sun`, { method: 'POST', json }));
  if (!sun || id !== state.map) return;
  showFigures(sun);
  $('#sun-marker').hidden = !sun.found;
  if (!sun.found) return;
  placeMarker(sun);
  await refreshMaps(); // the residual map is listed beside the others
}

export async function initSun() {
  $('#sun-find').addEventListener('click', findSun);
  form().addEventListener('submit', (event) => { event.preventDefault(); findSun(); });
  applyFields(form(), componentFields(await apiDocument(), 'SunParameters'));
  on('map', clear);
}
