// Talks to /api/v1: JSON in and out, and every failure as an ApiError carrying the server's
// {"error": {"code", "message"}}.
export const API = '/api/v1';

export class ApiError extends Error {
  constructor(status, code, message) {
    super(message);
    this.status = status;
    this.code = code;
  }
  toString() {
    return this.status ? `${this.status} ${this.code}: ${this.message}` : `${this.code}: ${this.message}`;
  }
}

export async function errorOf(res) {
  try {
    const body = await res.json();
    if (body && body.error) return new ApiError(res.status, body.error.code, body.error.message);
  } catch { /* not JSON */ }
  return new ApiError(res.status, 'http_error', res.statusText || 'request failed');
}

// api('/envmaps'), api('/renders', {method: 'POST', json: {...}}), api(path, {method: 'POST', body: file});
// `fetch` adds options of fetch() itself (signal, cache).
export async function api(path, { method = 'GET', json, body, headers = {}, fetch: options = {} } = {}) {
  const init = { ...options, method, headers: { ...headers } };
  if (json !== undefined) {
    init.body = JSON.stringify(json);
    init.headers['Content-Type'] = 'application/json';
  } else if (body !== undefined) {
    init.body = body;
  }
  let res;
  try {
    res = await fetch(API + path, init);
  } catch (e) {
    throw new ApiError(0, 'network', `cannot reach the server (${e.message})`);
  }
  if (!res.ok) throw await errorOf(res);
  if (res.status === 204) return null;
  return (res.headers.get('Content-Type') || '').includes('json') ? res.json() : res.text();
}

export function apiUrl(path, params = {}) {
  const q = new URLSearchParams(params).toString();
  return API + path + (q ? `?${q}` : '');
}

// Shows `src` in `img` once it has loaded (no flicker), unless `current()` says a newer request has
// replaced this one; a failed load is fetched again to read the server's error message.
export function loadImage(img, src, current = () => true) {
  return new Promise((resolve, reject) => {
    const probe = new Image();
    probe.onload = () => {
      if (!current()) return resolve(img);
      img.src = src;
      img.decode().catch(() => {}).then(() => resolve(img));
    };
    probe.onerror = async () => {
      try {
        const res = await fetch(src);
        reject(res.ok ? new ApiError(res.status, 'bad_image', 'the image could not be decoded') : await errorOf(res));
      } catch (e) {
        reject(new ApiError(0, 'network', e.message));
      }
    };
    probe.src = src;
  });
}
