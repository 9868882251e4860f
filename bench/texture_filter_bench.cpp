// Texture filters side by side on the `textured` preset (a brick-textured, normal-mapped sphere on a
// checkerboard ground seen at a low angle) on forest.exr: relMSE = mean((a - b)^2) / mean(b)^2 of a
// render with anisotropic footprints, with one isotropic level, and at level 0 (mipmaps off), each at
// the same spp, against a many-spp render at level 0 (the texture integrated over each pixel by the
// samples themselves). Path-tracing noise at the compared spp is common to all three.
// Run: ./build/bin/texture_filter_bench [size=96] [reference spp=512] [spp=4]
#include <tbb/task_arena.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <memory>

#include "bench_data.hpp"
#include "engine/image/image_io.hpp"
#include "engine/render/renderer.hpp"

namespace lp::render {
namespace {

Image render(const RenderSettings& settings, int spp) {
  static const auto map =
      std::make_shared<const EnvMap>(read_image_file(lp::bench::envmap_path("forest.exr")).image);
  Renderer renderer(preset_scene(ScenePreset::Textured), Lighting{}, settings, map);
  std::atomic<bool> cancel{false};
  tbb::task_arena(2).execute([&] { renderer.render_pass(spp, cancel, {}); });
  return renderer.image();
}

double rel_mse(const Image& a, const Image& b) {
  double sq = 0, sum = 0;
  int n = 0;
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x) {
      const Rgb p = a.at(x, y), q = b.at(x, y);
      const Rgb d{p.x - q.x, p.y - q.y, p.z - q.z};
      sq += double(d.x) * d.x + double(d.y) * d.y + double(d.z) * d.z;
      sum += double(q.x) + q.y + q.z;
      n += 3;
    }
  const double mean = sum / n;
  return sq / n / (mean * mean);
}

int run(int size, int reference_spp, int spp) {
  RenderSettings anisotropic;
  anisotropic.width = anisotropic.height = size;
  RenderSettings isotropic = anisotropic, level0 = anisotropic;
  isotropic.texture_anisotropy = 1;
  level0.mipmaps = false;
  RenderSettings reference = level0;
  reference.seed = 7;
  const Image truth = render(reference, reference_spp);
  std::printf("textured preset %dx%d, relMSE at %d spp against %d spp at level 0:\n", size, size, spp,
              reference_spp);
  std::printf("  anisotropic %.5f\n", rel_mse(render(anisotropic, spp), truth));
  std::printf("  isotropic   %.5f\n", rel_mse(render(isotropic, spp), truth));
  std::printf("  level 0     %.5f\n", rel_mse(render(level0, spp), truth));
  return 0;
}

}  // namespace
}  // namespace lp::render

int main(int argc, char** argv) {
  const int size = argc > 1 ? std::atoi(argv[1]) : 96;
  const int reference_spp = argc > 2 ? std::atoi(argv[2]) : 512;
  const int spp = argc > 3 ? std::atoi(argv[3]) : 4;
  return lp::render::run(size, reference_spp, spp);
}
