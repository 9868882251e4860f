// White metal spheres lit by a map through three.js's documented path (HDRLoader or UltraHDRLoader, then
// PMREMGenerator.fromEquirectangular), read back as linear floats; and the product's answer for the same
// pixels from its own prefiltered chain (EXR levels, read with three's EXRLoader).
import * as THREE from 'three';
import { HDRLoader } from 'three/addons/loaders/HDRLoader.js';
import { UltraHDRLoader } from 'three/addons/loaders/UltraHDRLoader.js';
import { EXRLoader } from 'three/addons/loaders/EXRLoader.js';

const canvas = document.getElementById('view');
const renderer = new THREE.WebGLRenderer({ canvas, antialias: false });
renderer.toneMapping = THREE.NoToneMapping;
renderer.outputColorSpace = THREE.LinearSRGBColorSpace;

async function loadMap(url) {
  const loader = url.endsWith('.jpg') ? new UltraHDRLoader() : new HDRLoader();
  loader.setDataType(THREE.FloatType);
  const texture = await loader.loadAsync(url);
  texture.mapping = THREE.EquirectangularReflectionMapping;
  return texture;
}

// The sphere of radius 1 fills an orthographic view from +z: pixel (i, j), j from the bottom, sees the
// point (x, y, sqrt(1 - x^2 - y^2)), which is also its normal; the view direction is +z everywhere.
function scene(envMap, roughness) {
  const s = new THREE.Scene();
  const material = new THREE.MeshStandardMaterial({ color: 0xffffff, metalness: 1, roughness, envMap });
  s.add(new THREE.Mesh(new THREE.SphereGeometry(1, 256, 128), material));
  return s;
}
const camera = new THREE.OrthographicCamera(-1, 1, 1, -1, 0.1, 10);
camera.position.set(0, 0, 5);
camera.lookAt(0, 0, 0);

// Renders one sphere per roughness into a float target; returns RGBA rows bottom to top.
window.renderSpheres = async ({ map, roughnesses, size }) => {
  const texture = await loadMap(map);
  const pmrem = new THREE.PMREMGenerator(renderer);
  const envMap = pmrem.fromEquirectangular(texture).texture;
  const target = new THREE.WebGLRenderTarget(size, size, { type: THREE.FloatType });
  renderer.setSize(size, size, false);
  const out = [];
  for (const roughness of roughnesses) {
    renderer.setRenderTarget(target);
    renderer.render(scene(envMap, roughness), camera);
    const pixels = new Float32Array(size * size * 4);
    renderer.readRenderTargetPixels(target, 0, 0, size, size, pixels);
    out.push(Array.from(pixels));
  }
  // The picture people look at: the spheres side by side, sRGB encoded.
  renderer.setRenderTarget(null);
  renderer.setSize(size * roughnesses.length, size, false);
  renderer.outputColorSpace = THREE.SRGBColorSpace;
  renderer.setScissorTest(true);
  roughnesses.forEach((roughness, i) => {
    renderer.setViewport(i * size, 0, size, size);
    renderer.setScissor(i * size, 0, size, size);
    renderer.render(scene(envMap, roughness), camera);
  });
  renderer.setScissorTest(false);
  renderer.outputColorSpace = THREE.LinearSRGBColorSpace;
  pmrem.dispose();
  return out;
};

// A float EXR as {width, height, data}, rows top to bottom as in the file (EXRLoader stores them bottom up).
async function loadExr(url) {
  const loader = new EXRLoader();
  loader.setDataType(THREE.FloatType);
  const { image } = await loader.loadAsync(url);
  return { width: image.width, height: image.height, data: image.data, rowOf: (y) => image.height - 1 - y };
}

function bilinear(img, fx, fy, wrap) {
  const x0 = Math.floor(fx), y0 = Math.floor(fy), tx = fx - x0, ty = fy - y0;
  const at = (x, y) => {
    x = wrap ? ((x % img.width) + img.width) % img.width : Math.min(Math.max(x, 0), img.width - 1);
    y = Math.min(Math.max(y, 0), img.height - 1);
    const i = (img.rowOf(y) * img.width + x) * 4;
    return [img.data[i], img.data[i + 1], img.data[i + 2]];
  };
  const a = at(x0, y0), b = at(x0 + 1, y0), c = at(x0, y0 + 1), d = at(x0 + 1, y0 + 1);
  return [0, 1, 2].map((k) => (a[k] * (1 - tx) + b[k] * tx) * (1 - ty) + (c[k] * (1 - tx) + d[k] * tx) * ty);
}

// The product's lat-long (z up): theta from +z, phi from +x towards +y, row 0 at the top.
function latlong(img, w) {
  const len = Math.hypot(w[0], w[1], w[2]);
  let u = Math.atan2(w[1], w[0]) / (2 * Math.PI);
  if (u < 0) u += 1;
  const v = Math.acos(Math.min(Math.max(w[2] / len, -1), 1)) / Math.PI;
  return bilinear(img, u * img.width - 0.5, v * img.height - 0.5, true);
}

// The engine direction e (y up) as a world direction: e = (x, z, -y) of the world.
const toWorld = (e) => [e[0], -e[2], e[1]];
const normalize = (v) => { const l = Math.hypot(...v); return v.map((c) => c / l); };

// The product's answer for each pixel: MeshStandardMaterial's split sum on the product's chain, with the
// product's DFG table (F0 = 1: scale + bias) and three.js's own choices of lookup direction (the reflection
// bent towards the normal by roughness^4) and of multiple scattering ((1 - E) x the roughness-1 level in
// the normal's direction). `levels[i]` is the chain's level of roughness `roughnesses[i]`, last at 1.
window.expectedSpheres = async ({ levels, lut, roughnesses, size }) => {
  const chain = await Promise.all(levels.map(loadExr));
  const dfg = await loadExr(lut);
  const rough = chain[chain.length - 1];
  return roughnesses.map((r, level) => {
    const out = new Float32Array(size * size * 4).fill(NaN);
    for (let j = 0; j < size; ++j)
      for (let i = 0; i < size; ++i) {
        const x = ((i + 0.5) / size) * 2 - 1, y = ((j + 0.5) / size) * 2 - 1, zz = 1 - x * x - y * y;
        if (zz <= 0) continue;
        const n = [x, y, Math.sqrt(zz)];
        const reflected = [2 * n[2] * n[0], 2 * n[2] * n[1], 2 * n[2] * n[2] - 1];
        const a2 = r ** 4;
        const bent = normalize(reflected.map((c, k) => c * (1 - a2) + n[k] * a2));
        const [scale, bias] = bilinear(dfg, n[2] * dfg.width - 0.5, r * dfg.height - 0.5, false);
        const e = scale + bias;
        const spec = latlong(chain[level], toWorld(bent)), diffuse = latlong(rough, toWorld(n));
        for (let k = 0; k < 3; ++k) out[(j * size + i) * 4 + k] = e * spec[k] + (1 - e) * diffuse[k];
      }
    return Array.from(out);
  });
};
window.pageReady = true;
