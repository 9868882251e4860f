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
  // EXT_lights_image_based's faces: 6 RGBA PNGs per level of the 16-texel cube (16 down to 1), each read and
  // decoded by the validator at its level's size.
  const gltf = JSON.parse(readFileSync(path.join(out, gltfFile), 'utf8'));
  assert.ok(gltf.extensionsUsed.includes('EXT_lights_image_based'));
  const light = gltf.extensions.EXT_lights_image_based.lights[gltf.scenes[0].extensions.EXT_lights_image_based.light];
  assert.equal(light.specularImageSize, 16);
  assert.equal(light.specularImages.length, 5);
  assert.equal(light.irradianceCoefficients.length, 9);
  light.specularImages.forEach((faces, level) => {
    assert.equal(faces.length, 6);
    for (const index of faces) {
      const { uri } = gltf.images[index];
      const resource = report.info.resources.find((r) => r.uri === uri);
      assert.ok(resource, `${uri} was not read`);
      assert.equal(resource.mimeType, 'image/png');
      assert.equal(resource.image.format, 'rgba', JSON.stringify(resource));
      assert.equal(resource.image.width, 16 >> level);
      assert.equal(resource.image.height, 16 >> level);
      assert.ok(manifest.files.includes(uri));
    }
  });
});
