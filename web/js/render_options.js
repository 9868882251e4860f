// The picture options of a render that the server's own document names: the tone mapper, the
// background (the map, transparent, or a colour), a ground under an uploaded model (optionally a shadow
// catcher), the passes accumulated beside the colour, and the denoise (its result shown beside the raw
// render). A field the document does not name stays
// hidden and is never sent, so the page asks only what the server accepts.
import { el } from './dom.js';
import { apiDocument, componentFields, oneOfTypes, offerChoices, queryParameter, schemaOf } from './openapi.js';

const offered = { tone_mapping: false, background: false, ground: false, passes: false, denoise: false, imageToneMapping: false };

// sRGB (as a colour input gives it, #rrggbb) to linear RGB, the request's colours.
export function linearRgb(hex) {
  return [1, 3, 5].map((i) => {
    const c = parseInt(hex.slice(i, i + 2), 16) / 255;
    const linear = c <= 0.04045 ? c / 12.92 : ((c + 0.055) / 1.055) ** 2.4;
    return Number(linear.toPrecision(6));
  });
}

function show(form, field, on) {
  offered[field] = on;
  for (const box of form.querySelectorAll(`[data-field=${field}]`)) {
    box.hidden = !on;
    for (const control of box.querySelectorAll('input, select')) control.disabled = !on;
  }
}

// The passes' checkboxes, one per name the document lists (the colour pass is always there).
function passChoices(names) {
  return names.filter((n) => n !== 'color').map((name) =>
    el('label', {}, el('input', { type: 'checkbox', name: 'pass', value: name }), ` ${name}`));
}

// Shows the controls of the fields the server's document names; `sceneChanged()` after.
export async function offerRenderOptions(form) {
  const doc = await apiDocument();
  const fields = componentFields(doc, 'RenderRequest');
  const tone = schemaOf(doc, fields.tone_mapping);
  show(form, 'tone_mapping', Boolean(tone?.enum));
  if (tone?.enum) offerChoices(form.tone_mapping, tone);
  show(form, 'background', Boolean(fields.background));
  const passes = schemaOf(doc, schemaOf(doc, fields.passes)?.items)?.enum ?? [];
  document.querySelector('#render-pass-choices').replaceChildren(...passChoices(passes));
  show(form, 'passes', passes.length > 0);
  show(form, 'ground', oneOfTypes(doc, 'RenderObject').includes('ground'));
  show(form, 'denoise', schemaOf(doc, fields.denoise)?.type === 'boolean');
  offered.imageToneMapping = Boolean(queryParameter(doc, '/renders/{id}/image', 'tone_mapping'));
  return offered;
}

// Follows the form: the colour with a colour background, the ground with a scene of objects, the
// shadow catcher with a ground.
export function followRenderOptions(form, sceneHasObjects) {
  form.background_colour.disabled = !offered.background || form.background.value !== 'colour';
  form.ground.disabled = !offered.ground || !sceneHasObjects;
  form.shadow_catcher.disabled = form.ground.disabled || !form.ground.checked;
}

export const chosenPasses = (form) => [...form.querySelectorAll('[name=pass]:checked')].map((c) => c.value);

// The request's fields for the options offered.
export function renderOptionFields(form) {
  const out = {};
  if (offered.tone_mapping) out.tone_mapping = form.tone_mapping.value;
  if (offered.background) out.background = form.background.value === 'colour' ? linearRgb(form.background_colour.value) : form.background.value;
  const passes = chosenPasses(form);
  if (offered.passes && passes.length) out.passes = passes;
  if (offered.denoise && form.denoise.checked) out.denoise = true;
  return out;
}

// The ground object the form asks for under a scene of objects, or null.
export function groundObject(form) {
  if (!offered.ground || form.ground.disabled || !form.ground.checked) return null;
  return { type: 'ground', shadow_catcher: form.shadow_catcher.checked };
}

// The tone mapper the image of a render is shown with (a query parameter overriding the request's
// own), when the image endpoint takes one.
export const shownToneMapping = (form) => (offered.imageToneMapping && offered.tone_mapping ? form.tone_mapping.value : undefined);
