// Time to reach a given error, for comparing with other renderers (bench/cycles_compare.py runs the
// same scene in Blender Cycles): renders a converged reference, then 1, 2, 4, ... spp, and prints for
// each the render time and the RMSE against the reference (relative to the reference's mean), over the
// pixels the reference covers (the map is not visible to the camera, as a transparent film in Cycles).
// Usage: render_error_bench [preset=sphere] [mode=envmap] [size=64] [ref_spp=4096] [max_spp=256]
//                           [threads=2] [out_dir]   (out_dir: writes reference.exr and spp_<n>.exr)
// Arguments starting with "--" (Google Benchmark flags from bench/run_all.sh) are ignored. The Cycles
// comparison in the README used: render_error_bench sphere envmap 128 4096 1024 2
#include <tbb/task_arena.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "bench_data.hpp"
#include "engine/image/image_io.hpp"
#include "engine/render/renderer.hpp"

namespace lp::render {
namespace {

const std::map<std::string, LightingMode> kModes = {{"envmap", LightingMode::EnvMap},
                                                    {"uniform", LightingMode::Uniform},
                                                    {"bsdf", LightingMode::Bsdf},
                                                    {"median_cut", LightingMode::MedianCut},
                                                    {"median_cut_all", LightingMode::MedianCutAll}};

struct Timed {
  Image image;
  double seconds;
  RenderStats stats;
};

Timed render(const SceneDesc& scene, const Lighting& lighting, int size, int spp, uint64_t seed,
             tbb::task_arena& arena, const std::shared_ptr<const EnvMap>& map) {
  RenderSettings settings;
  settings.width = settings.height = size;
  settings.seed = seed;
  const auto t0 = std::chrono::steady_clock::now();
  Renderer renderer(scene, lighting, settings, map);  // scene build included, as in Cycles' timing
  std::atomic<bool> cancel{false};
  arena.execute([&] { renderer.render_pass(spp, cancel, {}); });
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return {renderer.image(), seconds, renderer.stats()};
}

double relative_rmse(const Image& a, const Image& ref) {
  double sq = 0, sum = 0;
  int64_t n = 0;
  for (int y = 0; y < ref.height(); ++y)
    for (int x = 0; x < ref.width(); ++x) {
      const Rgb r = ref.at(x, y);
      if (r.x + r.y + r.z <= 0) continue;  // not covered
      for (int k = 0; k < 3; ++k) {
        const double d = double(a.at(x, y)[k]) - r[k];
        sq += d * d;
        sum += r[k];
        ++n;
      }
    }
  return std::sqrt(sq / double(n)) / (sum / double(n));
}

int run(int argc, char** argv) {
  std::vector<std::string> args;
  for (int i = 1; i < argc; ++i)
    if (std::string(argv[i]).rfind("--", 0) != 0) args.emplace_back(argv[i]);
  const auto arg = [&](size_t i, const char* fallback) {
    return i < args.size() ? args[i] : std::string(fallback);
  };
  const std::string preset = arg(0, "sphere");
  const std::string mode = arg(1, "envmap");
  const int size = std::atoi(arg(2, "64").c_str());
  const int ref_spp = std::atoi(arg(3, "4096").c_str());
  const int max_spp = std::atoi(arg(4, "256").c_str());
  const int threads = std::atoi(arg(5, "2").c_str());
  const std::filesystem::path out_dir = arg(6, "");
  const auto scene = scene_preset(preset);
  if (!scene || !kModes.count(mode)) {
    std::fprintf(stderr, "unknown preset or mode\n");
    return 2;
  }
  Lighting lighting;
  lighting.mode = kModes.at(mode);
  lighting.lights = 64;
  lighting.visible = false;
  const auto map = std::make_shared<const EnvMap>(read_image_file(bench::envmap_path("forest.exr")).image);
  tbb::task_arena arena(threads);

  const Timed ref = render(*scene, lighting, size, ref_spp, 1000, arena, map);
  std::printf("# lightprobe %s %s %dx%d, %d threads; reference %d spp in %.2f s\n", preset.c_str(),
              mode.c_str(), size, size, threads, ref_spp, ref.seconds);
  if (!out_dir.empty()) write_file(out_dir / "reference.exr", write_exr(ref.image));
  std::printf("spp,seconds,relative_rmse,samples_per_s,rays_per_s\n");
  for (int spp = 1; spp <= max_spp; spp *= 2) {
    const Timed t = render(*scene, lighting, size, spp, 1, arena, map);
    std::printf("%d,%.4f,%.5f,%.0f,%.0f\n", spp, t.seconds, relative_rmse(t.image, ref.image),
                double(t.stats.samples) / t.seconds, double(t.stats.rays) / t.seconds);
    if (!out_dir.empty()) write_file(out_dir / ("spp_" + std::to_string(spp) + ".exr"), write_exr(t.image));
  }
  return 0;
}

}  // namespace
}  // namespace lp::render

int main(int argc, char** argv) {
  return lp::render::run(argc, argv);
}
