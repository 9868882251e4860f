// What the Filament pages share: an engine on the canvas, a scene, a 64 x 64 view without
// post-processing, and the linear colour at the middle of the canvas once Filament has drawn a frame.
window.filamentView = (canvas) => {
  const engine = Filament.Engine.create(canvas, { preserveDrawingBuffer: true });
  const scene = engine.createScene();
  const camera = engine.createCamera(Filament.EntityManager.get().create());
  const view = engine.createView();
  view.setCamera(camera);
  view.setScene(scene);
  view.setViewport([0, 0, 64, 64]);
  view.setPostProcessingEnabled(false);
  const renderer = engine.createRenderer();
  const swapChain = engine.createSwapChain();
  const gl = canvas.getContext('webgl2');
  const nextFrame = () => new Promise((done) => requestAnimationFrame(done));
  // Filament may skip a frame to pace itself: render a few, one an animation frame.
  const middle = async () => {
    for (let i = 0; i < 4; ++i) {
      await nextFrame();
      renderer.render(swapChain, view);
    }
    const pixel = new Uint8Array(4);
    gl.readPixels(32, 32, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
    return Array.from(pixel.slice(0, 3)).map((c) => c / 255);
  };
  return { engine, scene, camera, middle };
};
