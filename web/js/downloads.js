// Every image and table on the page can be saved: files the API gives (images as PNG, and EXR where
// the API offers the linear values; the Fresnel table as JSON and CSV) as links, and the tables the
// page builds from API lists as JSON and as CSV written here from the same records.
import { el } from './dom.js';

const KEEP_BLOB_MS = 10000; // long enough for the browser to start saving it

function csvField(value) {
  if (value === null || value === undefined) return '';
  const text = String(value);
  return /[",\r\n]/.test(text) ? `"${text.replaceAll('"', '""')}"` : text;
}

// A record's values by column: nested objects and arrays become columns named by their path
// (power.0, region.x0).
function flatten(value, path, out) {
  if (value !== null && typeof value === 'object') {
    for (const [key, v] of Object.entries(value)) flatten(v, path ? `${path}.${key}` : key, out);
  } else {
    out[path] = value;
  }
  return out;
}

// RFC 4180 CSV with a header row: the columns of every record, in the order they first appear (a
// field that is null in one record and an object in another keeps only the object's columns).
export function toCsv(records) {
  const rows = records.map((r) => flatten(r, '', {}));
  const all = [...new Set(rows.flatMap((r) => Object.keys(r)))];
  const columns = all.filter((c) => !all.some((other) => other.startsWith(`${c}.`)));
  const lines = [columns, ...rows.map((r) => columns.map((c) => r[c]))];
  return lines.map((line) => line.map(csvField).join(',')).join('\r\n') + '\r\n';
}

function save(name, type, text) {
  const url = URL.createObjectURL(new Blob([text], { type }));
  el('a', { href: url, download: name }).click();
  setTimeout(() => URL.revokeObjectURL(url), KEEP_BLOB_MS);
}

function fill(bar, items) {
  bar.hidden = !items;
  bar.replaceChildren(...(items ? [el('span', { class: 'muted' }, 'save'), ...items] : []));
}

// Links in `bar` to files of the API, saved as NAME.FORMAT: urls = {png: url, exr: url}.
export function offerLinks(bar, name, urls) {
  fill(bar, Object.entries(urls).map(([format, href]) =>
    el('a', { href, download: `${name}.${format}`, dataset: { format } }, format.toUpperCase())));
}

// Links in `bar` to the files a job lists ([{name, url}]), each saved under its own name.
export function offerFiles(bar, files) {
  fill(bar, files.map((f) => el('a', { href: f.url, download: f.name, dataset: { format: f.name.split('.').pop() } }, f.name)));
}

// Buttons in `bar` saving `records` (an array of objects) as NAME.json and NAME.csv.
export function offerTable(bar, name, records) {
  const button = (format, type, text) =>
    el('button', { type: 'button', class: 'small', dataset: { format }, onclick: () => save(`${name}.${format}`, type, text()) },
      format.toUpperCase());
  fill(bar, [
    button('json', 'application/json', () => JSON.stringify(records, null, 2)),
    button('csv', 'text/csv', () => toCsv(records)),
  ]);
}

// Hides `bar` while there is nothing to save.
export const withdrawOffer = (bar) => fill(bar, null);
