// Small DOM and formatting helpers shared by the panels.
import { showApiFieldError, checkFields } from './field_errors.js';

export const $ = (sel, root = document) => root.querySelector(sel);
export const $$ = (sel, root = document) => [...root.querySelectorAll(sel)];

export function el(tag, attrs = {}, ...children) {
  const node = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) {
    if (k === 'class') node.className = v;
    else if (k.startsWith('on')) node.addEventListener(k.slice(2), v);
    else if (k === 'dataset') Object.assign(node.dataset, v);
    else node.setAttribute(k, v);
  }
  node.append(...children.flat().filter((c) => c !== null && c !== undefined));
  return node;
}

// 4 significant digits, exponent only when needed.
export function num(x, digits = 4) {
  if (x === null || x === undefined || Number.isNaN(x)) return '–';
  if (x === 0) return '0';
  const a = Math.abs(x);
  if (a >= 1e6 || a < 1e-3) return x.toExponential(digits - 1).replace('e+', 'e');
  return String(Number(x.toPrecision(digits)));
}

export const rgb = (v) => `[${v.map((x) => num(x)).join(', ')}]`;

export function bigNum(x) {
  if (x >= 1e9) return `${num(x / 1e9, 3)} G`;
  if (x >= 1e6) return `${num(x / 1e6, 3)} M`;
  if (x >= 1e3) return `${num(x / 1e3, 3)} k`;
  return num(x, 3);
}

// Reads a form's named controls as {name: value}, numbers as numbers.
export function formValues(form) {
  const out = {};
  for (const c of form.elements) {
    if (!c.name) continue;
    if (c.type === 'checkbox') out[c.name] = c.checked;
    else if (c.type === 'number' || c.type === 'range') out[c.name] = c.valueAsNumber;
    else out[c.name] = c.value;
  }
  return out;
}

// An error of the panel: next to the field it names (until that field changes), else on the panel's
// error line; null clears the line.
export function showError(panel, err) {
  const box = $('.error', panel);
  if (!err || showApiFieldError(panel, err)) {
    box.hidden = true;
    box.textContent = '';
    return;
  }
  box.textContent = String(err);
  box.hidden = false;
  if (!(err && err.code)) console.error(err);
}

// Runs an async task with the panel marked busy; shows its error, if any, on the panel.
export async function busy(panel, task) {
  panel.classList.add('busy');
  try {
    const result = await task();
    showError(panel, null);
    return result;
  } catch (e) {
    showError(panel, e);
    return undefined;
  } finally {
    panel.classList.remove('busy');
  }
}

export function debounce(fn, ms) {
  let t;
  return (...args) => {
    clearTimeout(t);
    t = setTimeout(() => fn(...args), ms);
  };
}

// Wraps an async update so that only the latest call applies its results: fn(current, ...args)
// gets current(), false once a newer call has started.
export function latestOnly(fn) {
  let seq = 0;
  return (...args) => {
    const mine = ++seq;
    return fn(() => mine === seq, ...args);
  };
}

// Re-runs `update` when a form's selects change or (debounced) when its numbers are typed; a number
// out of range gets its message and no update.
export function autoUpdate(form, update, onChange = update) {
  form.addEventListener('submit', (e) => {
    e.preventDefault();
    if (checkFields(form)) update();
  });
  form.addEventListener('change', (e) => { if (e.target.type !== 'number') onChange(e); });
  form.addEventListener('input', debounce((e) => { if (e.target.type === 'number' && checkFields(form)) onChange(e); }, 350));
}

// Fills a table's body with `rows`, each cell labelled with its column's heading (a narrow screen
// shows the rows as cards, each value after its label).
export function fillTable(table, rows) {
  const headings = $$('thead th', table).map((th) => th.textContent);
  for (const row of rows)
    [...row.cells].forEach((cell, i) => { if (cell.colSpan === 1 && headings[i]) cell.dataset.label = headings[i]; });
  $('tbody', table).replaceChildren(...rows);
}

// A button acting on its second click: the first arms it ("Sure?") for three seconds. Takes the
// click event (kept from the row under the button); true when the click is the second.
export function confirmClick(event) {
  event.stopPropagation();
  const button = event.currentTarget;
  if (button.classList.contains('armed')) return true;
  const text = button.textContent;
  button.classList.add('armed');
  button.textContent = 'Sure?';
  setTimeout(() => { button.classList.remove('armed'); button.textContent = text; }, 3000);
  return false;
}
