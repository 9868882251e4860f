// The map every panel works on, and the list of loaded maps; panels subscribe to changes.
const listeners = { map: [], maps: [] };

export const state = { map: null, maps: [] };

export function on(what, fn) {
  listeners[what].push(fn);
}

export function setMaps(maps) {
  state.maps = maps;
  listeners.maps.forEach((fn) => fn(maps));
  if (!maps.some((m) => m.id === state.map)) selectMap(maps.length ? maps[0].id : null);
}

export function selectMap(id) {
  if (id === state.map) return;
  state.map = id;
  listeners.map.forEach((fn) => fn(id));
}

export const currentMap = () => state.maps.find((m) => m.id === state.map) || null;
