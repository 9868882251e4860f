// api/openapi.yaml is a valid OpenAPI 3.0 document (checked by swagger-parser against the official
// schema, with every $ref resolved), and every operation has a unique operationId.
import { test } from "node:test";
import assert from "node:assert/strict";
import { fileURLToPath } from "node:url";
import SwaggerParser from "@apidevtools/swagger-parser";

const documentPath = fileURLToPath(new URL("../../api/openapi.yaml", import.meta.url));
const methods = ["get", "put", "post", "delete", "options", "head", "patch", "trace"];

function operations(api) {
  const found = [];
  for (const [path, item] of Object.entries(api.paths))
    for (const method of methods) if (item[method]) found.push({ path, method, operation: item[method] });
  return found;
}

test("the document validates against the OpenAPI 3.0 schema", async () => {
  const api = await SwaggerParser.validate(documentPath);
  assert.match(api.openapi, /^3\.0\./);
});

test("every operation has a unique operationId", async () => {
  const api = await SwaggerParser.parse(documentPath);
  const seen = new Map();
  for (const { path, method, operation } of operations(api)) {
    assert.ok(operation.operationId, `${method.toUpperCase()} ${path} has no operationId`);
    assert.ok(!seen.has(operation.operationId), `operationId ${operation.operationId} is used twice`);
    seen.set(operation.operationId, `${method} ${path}`);
  }
  assert.ok(seen.size > 0);
});
