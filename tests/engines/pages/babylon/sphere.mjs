// A unit sphere under a .env as Babylon.js's users load one (CubeTexture.CreateFromPrefilteredData as
// scene.environmentTexture), seen by an orthographic camera from Babylon's -z looking at +z (y up), so
// that the pixel at (x, y) in [-1, 1]^2 shows the normal (x, y, -sqrt(1 - x^2 - y^2)). window.renderSphere
// draws it with a PBR material and answers the linear colour of every pixel, read from a float render
// target (the material writes linear values when image processing is left to a post-process).
import {
  Engine, Scene, Color3, Color4, Vector3, FreeCamera, Camera, MeshBuilder, PBRMaterial, CubeTexture,
  RenderTargetTexture, Constants,
} from '/node_modules/@babylonjs/core/index.js';

const canvas = document.getElementById('c');
const engine = new Engine(canvas, false, { preserveDrawingBuffer: true, antialias: false });
const scene = new Scene(engine);
scene.clearColor = new Color4(0, 0, 0, 1);
const camera = new FreeCamera('camera', new Vector3(0, 0, -5), scene);
camera.setTarget(Vector3.Zero());
camera.mode = Camera.ORTHOGRAPHIC_CAMERA;
camera.orthoLeft = -1;
camera.orthoRight = 1;
camera.orthoTop = 1;
camera.orthoBottom = -1;
const sphere = MeshBuilder.CreateSphere('sphere', { diameter: 2, segments: 96 }, scene);
const material = new PBRMaterial('material', scene);
material.albedoColor = Color3.White();
sphere.material = material;

function whenReady(isReady) {
  return new Promise((resolve) => {
    const check = () => (isReady() ? resolve() : setTimeout(check, 20));
    check();
  });
}

// Loads the .env at `url` as the scene's environment; answers its lodGenerationScale and size.
window.loadEnvironment = async (url) => {
  const texture = CubeTexture.CreateFromPrefilteredData(url, scene);
  scene.environmentTexture = texture;
  await whenReady(() => texture.isReady());
  return { lodGenerationScale: texture.lodGenerationScale, size: texture.getSize().width };
};

// kind: 'metal' (metallic 1, white: the prefiltered radiance in the reflected direction) or 'diffuse'
// (specular-glossiness with black reflectivity: no specular at all, the irradiance of the polynomial).
window.renderSphere = async (kind, roughness, size) => {
  if (kind === 'metal') {
    material.metallic = 1;
    material.roughness = roughness;
    material.reflectivityColor = Color3.White();
    // Babylon blends rough reflections toward the irradiance by default; the chain alone is compared.
    material.brdf.mixIblRadianceWithIrradiance = false;
  } else {
    material.metallic = null;
    material.roughness = null;
    material.reflectivityColor = Color3.Black();
    material.microSurface = 0;
  }
  scene.imageProcessingConfiguration.applyByPostProcess = true;
  const target = new RenderTargetTexture('linear', { width: size, height: size }, scene, {
    type: Constants.TEXTURETYPE_FLOAT, generateMipMaps: false,
  });
  target.renderList = [sphere];
  target.activeCamera = camera;
  target.clearColor = new Color4(0, 0, 0, 0);
  scene.customRenderTargets.push(target);
  await scene.whenReadyAsync();
  await whenReady(() => material.isReady(sphere));
  scene.render();
  const pixels = Array.from(await target.readPixels());
  scene.customRenderTargets.length = 0;
  target.dispose();
  scene.imageProcessingConfiguration.applyByPostProcess = false;  // the canvas: as users see it
  scene.render();
  return pixels;
};
window.pageReady = true;
