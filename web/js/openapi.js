// The API's own document (GET /api/v1/openapi.yaml), read once: forms take the defaults, ranges and
// choices of their fields from it instead of repeating them.
import { load } from '../vendor/js-yaml.min.js';
import { API, ApiError, errorOf } from './api.js';

let loaded = null;

export function apiDocument() {
  loaded ??= fetch(`${API}/openapi.yaml`)
    .catch((e) => { throw new ApiError(0, 'network', `cannot reach the server (${e.message})`); })
    .then(async (res) => {
      if (!res.ok) throw await errorOf(res);
      return load(await res.text());
    });
  loaded.catch(() => { loaded = null; }); // asked again next time
  return loaded;
}

// The node a local reference ("#/components/parameters/Exposure") points to, or the node itself.
function resolve(doc, node) {
  if (!node || typeof node.$ref !== 'string') return node;
  return node.$ref.slice(2).split('/').reduce((at, key) => at?.[key], doc);
}

// A schema with its references followed: a $ref, or an allOf of one schema whose own keys (a
// default, a description) override the referenced schema's.
export function schemaOf(doc, node) {
  const schema = resolve(doc, node);
  if (!schema?.allOf || schema.allOf.length !== 1) return schema;
  const { allOf, ...own } = schema;
  return { ...schemaOf(doc, allOf[0]), ...own };
}

const operation = (doc, path, method) => doc.paths[API + path]?.[method];

// The schemas of the fields of an operation's JSON body: {levels: {type, minimum, ...}, ...}.
export function bodyFields(doc, path, method = 'post') {
  const body = operation(doc, path, method)?.requestBody?.content?.['application/json']?.schema;
  return resolve(doc, body)?.properties ?? {};
}

// The schemas of the fields of a component schema, or of an object field inside it:
// componentFields(doc, 'RenderCamera', 'fit') is {object: {...}, azimuth_deg: {...}, ...}.
export function componentFields(doc, name, ...fields) {
  let schema = resolve(doc, doc.components.schemas[name]);
  for (const field of fields) schema = resolve(doc, schema?.properties?.[field]);
  return schema?.properties ?? {};
}

// The schema of a query parameter of an operation.
export function queryParameter(doc, path, name, method = 'get') {
  const parameters = (operation(doc, path, method)?.parameters ?? []).map((p) => resolve(doc, p));
  return resolve(doc, parameters.find((p) => p.name === name && p.in === 'query')?.schema);
}

// A select offering the schema's enum, its default chosen (the current choice kept if still offered).
export function offerChoices(select, schema) {
  const chosen = select.value;
  select.replaceChildren(...schema.enum.map((name) => new Option(name, name)));
  select.value = schema.enum.includes(chosen) ? chosen : (schema.default ?? schema.enum[0]);
}

// Gives the controls of `form` named as fields their range and default, or their choices.
export function applyFields(form, fields) {
  for (const [name, schema] of Object.entries(fields)) {
    const control = form.elements.namedItem(name);
    if (!control) continue;
    if (control.tagName === 'SELECT' && schema.enum) {
      offerChoices(control, schema);
    } else if (control.type === 'number') {
      if (schema.minimum !== undefined) control.min = schema.minimum;
      if (schema.maximum !== undefined) control.max = schema.maximum;
      if (schema.default !== undefined) control.value = schema.default;
      if (schema.type === 'integer') control.step = 1;
      if (schema.description) control.title = schema.description;
    }
  }
}

// The `type` names of the object schemas a oneOf component lists: ['sphere', 'plane', 'mesh', ...].
export function oneOfTypes(doc, name) {
  const schema = resolve(doc, doc.components.schemas[name]);
  return (schema?.oneOf ?? []).flatMap((s) => resolve(doc, resolve(doc, s)?.properties?.type)?.enum ?? []);
}
