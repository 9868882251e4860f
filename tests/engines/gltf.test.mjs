// The gltf target (`lightprobe bake --target gltf`) through the Khronos glTF validator: the .gltf and
// the files it names, read as the validator reads them, carry no error.
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { test } from 'node:test';
import validator from 'gltf-validator';
import { cliBin, envmaps, freshDir, requireBinary } from './support.mjs';

test('the gltf target passes the Khronos glTF validator', async () => {
  requireBinary(cliBin, 'LIGHTPROBE_CLI_BIN');
  const out = freshDir('gltf-target');
  execFileSync(cliBin, ['bake', path.join(envmaps, 'sunrise.exr'), '--target', 'gltf', '--out', out,
    '--base-size', '16', '--samples', '64', '--quiet']);
  const manifest = JSON.parse(readFileSync(path.join(out, 'manifest.json'), 'utf8'));
  const gltfFile = manifest.import.gltf;
  const report = await validator.validateBytes(new Uint8Array(readFileSync(path.join(out, gltfFile))), {
    uri: gltfFile,
    externalResourceFunction: (uri) => Promise.resolve(new Uint8Array(readFileSync(path.join(out, uri)))),
  });
  const errors = report.issues.messages.filter((m) => m.severity === 0);
  assert.deepEqual(errors, [], JSON.stringify(report.issues.messages, null, 2));
  assert.equal(report.issues.numErrors, 0);
  // Every file the glTF names was read by the validator.
  const uris = report.info.resources.map((r) => r.uri).sort();
  assert.ok(uris.includes(manifest.files.find((f) => f.endsWith('.ktx2'))), JSON.stringify(report.info.resources));
});
