// Images for the denoiser test: Portable Float Maps (RGB, float32) and a deterministic noisy scene with
// its first-hit albedo and normal, as a path tracer gives them.
import { readFileSync, writeFileSync } from "node:fs";

// An RGB float image: data holds width * height * 3 floats, rows top to bottom.
export function makeImage(width, height) {
  return { width, height, data: new Float32Array(width * height * 3) };
}

// PFM stores rows bottom to top; a negative scale means little-endian.
export function writePfm(path, image) {
  const { width, height, data } = image;
  const header = Buffer.from(`PF\n${width} ${height}\n-1.0\n`, "ascii");
  const body = Buffer.alloc(width * height * 12);
  for (let y = 0; y < height; ++y)
    for (let i = 0; i < width * 3; ++i)
      body.writeFloatLE(data[y * width * 3 + i], ((height - 1 - y) * width * 3 + i) * 4);
  writeFileSync(path, Buffer.concat([header, body]));
}

export function readPfm(path) {
  const bytes = readFileSync(path);
  const fields = [];
  let start = 0;
  let at = 0;
  while (fields.length < 4) {
    const whitespace = bytes[at] === 0x0a || bytes[at] === 0x20 || bytes[at] === 0x0d;
    if (whitespace) {
      if (at > start) fields.push(bytes.toString("ascii", start, at));
      start = at + 1;
    }
    ++at;
  }
  const [magic, w, h, scale] = fields;
  if (magic !== "PF" || Number(scale) >= 0) throw new Error(`${path}: not a little-endian RGB PFM`);
  const image = makeImage(Number(w), Number(h));
  const row = image.width * 3;
  for (let y = 0; y < image.height; ++y)
    for (let i = 0; i < row; ++i)
      image.data[y * row + i] = bytes.readFloatLE(at + ((image.height - 1 - y) * row + i) * 4);
  return image;
}

// mulberry32: a small seeded generator, so the scene is the same on every run.
function generator(seed) {
  let state = seed >>> 0;
  return () => {
    state = (state + 0x6d2b79f5) >>> 0;
    let t = state;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

// A lit bumpy wall seen head-on: coloured tiles (albedo), three spherical bumps and a groove (normals),
// a sun and a sky (radiance from under 0.01 to about 40 in the highlights), then Monte Carlo noise: each
// pixel of `color` is the mean of `spp` exponentially distributed estimates of its `clean` radiance.
export function noisyScene(width, height, { spp = 4, seed = 1 } = {}) {
  const random = generator(seed);
  const clean = makeImage(width, height);
  const color = makeImage(width, height);
  const albedo = makeImage(width, height);
  const normal = makeImage(width, height);
  const bumps = [
    { x: 0.3, y: 0.35, r: 0.2 },
    { x: 0.72, y: 0.3, r: 0.14 },
    { x: 0.55, y: 0.75, r: 0.22 },
  ];
  const sun = normalize([0.5, -0.6, 0.62]);
  for (let y = 0; y < height; ++y) {
    for (let x = 0; x < width; ++x) {
      const u = (x + 0.5) / width;
      const v = (y + 0.5) / height;
      let n = [0, 0, 1];
      for (const b of bumps) {
        const dx = (u - b.x) / b.r;
        const dy = (v - b.y) / b.r;
        const d2 = dx * dx + dy * dy;
        if (d2 < 1) n = [dx, -dy, Math.sqrt(1 - d2)];
      }
      if (Math.abs(u - 0.12 - 0.2 * v) < 0.02) n = normalize([0.8, 0.1, 0.6]);
      const tile = (Math.floor(u * 6) + Math.floor(v * 5)) % 3;
      const a = [
        [0.8, 0.25, 0.2],
        [0.2, 0.6, 0.3],
        [0.85, 0.85, 0.8],
      ][tile];
      const diffuse = Math.max(0, dot(n, sun)) * 3 + 0.15 * (1 + n[2]);
      const specular = 40 * Math.pow(Math.max(0, dot(reflect(sun, n), [0, 0, 1])), 400);
      const i = (y * width + x) * 3;
      for (let c = 0; c < 3; ++c) {
        clean.data[i + c] = a[c] * diffuse + specular;
        let sum = 0;
        for (let s = 0; s < spp; ++s) sum += -Math.log(1 - random()) * clean.data[i + c];
        color.data[i + c] = sum / spp;
        albedo.data[i + c] = a[c];
        normal.data[i + c] = n[c];
      }
    }
  }
  return { clean, color, albedo, normal };
}

// The scene squeezed into [0, 1] for the low dynamic range filters.
export function lowDynamicRange(image) {
  const out = makeImage(image.width, image.height);
  for (let i = 0; i < image.data.length; ++i) out.data[i] = Math.min(1, image.data[i] / (1 + image.data[i]));
  return out;
}

function dot(a, b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
function normalize(a) {
  const l = Math.sqrt(dot(a, a));
  return [a[0] / l, a[1] / l, a[2] / l];
}
function reflect(l, n) {
  const d = 2 * dot(l, n);
  return [d * n[0] - l[0], d * n[1] - l[1], d * n[2] - l[2]];
}
