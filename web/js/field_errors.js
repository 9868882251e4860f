// Messages next to the control they are about: the browser's own message for a value out of an
// input's range, and an API error naming a field ("field 'lighting.intensity': must be in ...").
const NAMED_FIELD = /^field '([^']+)':/;

// The control of `root` an API field stands for: the one of that name, else of its last part
// (the render form's `intensity` is the request's `lighting.intensity`).
function controlFor(root, field) {
  for (const name of [field, field.split('.').pop()]) {
    const control = root.querySelector(`[name="${CSS.escape(name)}"]`);
    if (control) return control;
  }
  return null;
}

// The message element of a control: right after the label holding it, gone once the value changes.
function messageOf(control, create) {
  const id = control.getAttribute('aria-describedby');
  const existing = id && document.getElementById(id);
  if (existing || !create) return existing || null;
  const box = document.createElement('span');
  box.className = 'field-error';
  box.id = `${control.form?.id || 'page'}-${control.name}-error`;
  box.setAttribute('role', 'alert');
  (control.closest('label') || control).after(box);
  control.setAttribute('aria-describedby', box.id);
  control.addEventListener('input', () => clearFieldError(control), { once: true });
  return box;
}

function showFieldError(control, message) {
  messageOf(control, true).textContent = message;
  control.setAttribute('aria-invalid', 'true');
}

function clearFieldError(control) {
  const box = messageOf(control, false);
  if (box) box.remove();
  control.removeAttribute('aria-describedby');
  control.removeAttribute('aria-invalid');
}

// Shows an API error next to the control of `root` it names; false when it names none there.
export function showApiFieldError(root, err) {
  const field = err && err.code === 'invalid_field' && NAMED_FIELD.exec(err.message);
  const control = field && controlFor(root, field[1]);
  if (!control) return false;
  showFieldError(control, err.message);
  return true;
}

// Shows the browser's message next to each control of `form` out of range; true when none is.
export function checkFields(form) {
  let valid = true;
  for (const control of form.elements) {
    if (!control.name || control.disabled) continue;
    if (control.validity.valid) {
      if (control.hasAttribute('aria-invalid')) clearFieldError(control);
    } else {
      showFieldError(control, control.validationMessage);
      valid = false;
    }
  }
  return valid;
}
