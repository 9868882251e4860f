// An upload form of a panel: a file input, a name that defaults to the file's stem (unless typed), and
// a submit that sends the file as it is to a collection of the API (POST PATH?name=NAME).
import { api } from './api.js';
import { busy, showError } from './dom.js';
import { checkFields } from './field_errors.js';

// A file name's stem (an archive's ".tar.gz" gone as a whole), made a valid resource name.
export const nameFromFile = (file) =>
  file.name.replace(/(\.tar)?\.[^.]*$/i, '').replace(/[^A-Za-z0-9._-]/g, '_').replace(/^\./, '_').slice(0, 64);

// `missing` is the message for a submit without a file; `done(record)` gets the API's answer.
export function uploadForm(form, panel, { path, missing, done }) {
  const file = form.querySelector('input[type=file]');
  const name = form.elements.namedItem('name');
  // The name follows the file chosen until one is typed.
  file.addEventListener('change', () => {
    if (!file.files[0] || (name.value && !name.dataset.fromFile)) return;
    name.value = nameFromFile(file.files[0]);
    name.dataset.fromFile = 'true';
  });
  name.addEventListener('input', () => delete name.dataset.fromFile);
  form.addEventListener('submit', async (event) => {
    event.preventDefault();
    if (!checkFields(form)) return;
    const chosen = file.files[0];
    if (!chosen) {
      showError(panel, missing);
      return;
    }
    const as = name.value.trim() || nameFromFile(chosen);
    const record = await busy(panel, () => api(`${path}?name=${encodeURIComponent(as)}`,
      { method: 'POST', body: chosen, headers: { 'Content-Type': 'application/octet-stream' } }));
    if (!record) return;
    form.reset();
    delete name.dataset.fromFile;
    await done(record);
  });
}
