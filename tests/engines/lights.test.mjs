// The lights `lightprobe` writes for glTF (KHR_lights_punctual) pass the Khronos glTF validator with no
// error and no warning, and the sun's light points down its node's -Z from where the sun is.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import path from 'node:path';
import validator from 'gltf-validator';
import { cliBin, envmaps, requireBinary } from './support.mjs';

const run = (...args) => execFileSync(cliBin, args, { encoding: 'utf8' });

// v rotated by the unit quaternion [x, y, z, w] (glTF's order).
function rotate([x, y, z, w], v) {
  const t = [2 * (y * v[2] - z * v[1]), 2 * (z * v[0] - x * v[2]), 2 * (x * v[1] - y * v[0])];
  return [0, 1, 2].map((i) => v[i] + w * t[i] + [y * t[2] - z * t[1], z * t[0] - x * t[2], x * t[1] - y * t[0]][i]);
}

async function validate(text, name) {
  const report = await validator.validateString(text, { uri: name, format: 'gltf' });
  assert.equal(report.issues.numErrors, 0, JSON.stringify(report.issues.messages, null, 2));
  assert.equal(report.issues.numWarnings, 0, JSON.stringify(report.issues.messages, null, 2));
  assert.ok(report.info.extensionsUsed.includes('KHR_lights_punctual'));
  return JSON.parse(text);
}

test('the sun of sunrise.exr as a glTF directional light', async () => {
  requireBinary(cliBin, 'LIGHTPROBE_CLI_BIN');
  const map = path.join(envmaps, 'sunrise.exr');
  const sun = JSON.parse(run('sun', map));
  assert.equal(sun.found, true);
  const doc = await validate(run('sun', map, '--format', 'gltf'), 'sun.gltf');
  const [light] = doc.extensions.KHR_lights_punctual.lights;
  assert.equal(light.type, 'directional');
  for (let c = 0; c < 3; ++c) assert.ok(Math.abs(light.intensity * light.color[c] - sun.irradiance[c]) <= 1e-9 * sun.irradiance[c]);
  // Towards the scene from the sun, in glTF's frame: world (x, y, z) is (x, z, -y).
  const [x, y, z] = sun.direction;
  const travel = rotate(doc.nodes[0].rotation, [0, 0, -1]);
  [-x, -z, y].forEach((want, i) => assert.ok(Math.abs(travel[i] - want) < 1e-6, `${travel} against ${[-x, -z, y]}`));
  assert.equal(doc.asset.extras.upper_hemisphere_illuminance, JSON.parse(run('info', map)).illuminance);
});

test('64 median-cut lights as glTF, their irradiance the map\'s power', async () => {
  requireBinary(cliBin, 'LIGHTPROBE_CLI_BIN');
  const map = path.join(envmaps, 'forest.exr');
  const doc = await validate(run('median-cut', map, '--count', '64', '--format', 'gltf'), 'lights.gltf');
  const lights = doc.extensions.KHR_lights_punctual.lights;
  assert.equal(lights.length, 64);
  const power = JSON.parse(run('info', map)).power;
  for (let c = 0; c < 3; ++c) {
    const sum = lights.reduce((s, l) => s + l.intensity * l.color[c], 0);
    assert.ok(Math.abs(sum / power[c] - 1) < 1e-5, `channel ${c}: ${sum} against ${power[c]}`);
  }
});
