// Sun extraction in renders: relative RMSE against a converged reference at equal time, with the sun
// left in the map (lighting.sun none) and taken out as a cone light (extract). The scene: a diffuse
// sphere, a glossy plastic one and rough gold on a diffuse plane, camera not seeing the map. Maps: a
// synthetic sunny sky (support/sunny_map.hpp: 1024 x 512, a sun of 0.5 degrees carrying about 80% of the
// power) and sunrise.exr. For each, a reference of `ref_spp` with the sun left in the map (the map's
// own lighting), then 1, 2, 4, ... `max_spp` spp in each mode: seconds and RMSE (relative to the
// reference's mean); then the RMSE of extract interpolated (log-log) at the times none took. The
// extract reference's RMSE against the none reference is the bias a cone of uniform radiance has
// against the sun's own pixels (with both references' noise). Time is the process's CPU time (all its
// threads, the scene's build included), steadier than wall time on a shared machine.
// Usage: sun_error_bench [size=64] [ref_spp=4096] [max_spp=256] [threads=2]
// Arguments starting with "--" (Google Benchmark flags from bench/run_all.sh) are ignored.
#include <tbb/task_arena.h>

#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <vector>

#include "bench_data.hpp"
#include "engine/core/constants.hpp"
#include "engine/image/image_io.hpp"
#include "engine/render/renderer.hpp"
#include "engine/sun/sun_extraction.hpp"
#include "support/sunny_map.hpp"

namespace lp::render {
namespace {

struct Timed {
  Image image;
  double seconds;
};

Timed render(const SceneDesc& scene, SunMode sun, int size, int spp, uint64_t seed, tbb::task_arena& arena,
             const std::shared_ptr<const EnvMap>& map) {
  Lighting lighting;
  lighting.sun = sun;
  lighting.visible = false;
  RenderSettings settings;
  settings.width = settings.height = size;
  settings.seed = seed;
  const std::clock_t t0 = std::clock();
  Renderer renderer(scene, lighting, settings, map);  // the extraction is cached on the map
  std::atomic<bool> cancel{false};
  arena.execute([&] { renderer.render_pass(spp, cancel, {}); });
  return {renderer.image(), double(std::clock() - t0) / CLOCKS_PER_SEC};
}

double relative_rmse(const Image& a, const Image& ref) {
  double sq = 0, sum = 0;
  const auto pa = a.data(), pr = ref.data();
  for (size_t i = 0; i < pr.size(); ++i) {
    const double d = double(pa[i]) - pr[i];
    sq += d * d;
    sum += pr[i];
  }
  return std::sqrt(sq / double(pr.size())) / (sum / double(pr.size()));
}

struct Point {
  int spp;
  double seconds, rmse;
};

// log(rmse) interpolated linearly in log(seconds); NaN outside the measured times.
double rmse_at(const std::vector<Point>& curve, double seconds) {
  for (size_t i = 1; i < curve.size(); ++i)
    if (curve[i - 1].seconds <= seconds && seconds <= curve[i].seconds) {
      const double t =
          std::log(seconds / curve[i - 1].seconds) / std::log(curve[i].seconds / curve[i - 1].seconds);
      return std::exp(std::log(curve[i - 1].rmse) + t * std::log(curve[i].rmse / curve[i - 1].rmse));
    }
  return NAN;
}

void compare(const std::string& name, const std::shared_ptr<const EnvMap>& map, int size, int ref_spp,
             int max_spp, tbb::task_arena& arena) {
  const SunExtraction e = extract_sun(*map, SunParams{});
  if (!e.sun) {
    std::printf("# %s: no sun (%s)\n", name.c_str(), e.reason.c_str());
    return;
  }
  std::printf("# %s %dx%d: sun radius %.3f deg, %.1f%% of the power\n", name.c_str(), map->width(),
              map->height(), e.sun->angular_radius * 180 / kPi, 100 * e.sun->share);
  const SceneDesc scene = bench::diffuse_and_glossy();
  const Timed ref = render(scene, SunMode::None, size, ref_spp, 1000, arena, map);
  const Timed ref_extract = render(scene, SunMode::Extract, size, ref_spp, 1000, arena, map);
  std::printf(
      "# reference %d spp: none %.1f cpu s, extract %.1f cpu s; extract reference against none: %.4f\n",
      ref_spp, ref.seconds, ref_extract.seconds, relative_rmse(ref_extract.image, ref.image));
  std::printf("sun,spp,cpu_seconds,relative_rmse\n");
  std::vector<Point> curves[2];
  for (int m = 0; m < 2; ++m) {
    const SunMode sun = m == 0 ? SunMode::None : SunMode::Extract;
    for (int spp = 1; spp <= max_spp; spp *= 2) {
      const Timed t = render(scene, sun, size, spp, 1, arena, map);
      curves[m].push_back({spp, t.seconds, relative_rmse(t.image, ref.image)});
      std::printf("%s,%d,%.4f,%.5f\n", enum_name(sun), spp, t.seconds, curves[m].back().rmse);
    }
  }
  std::printf("equal time: cpu_seconds,rmse_none,rmse_extract,ratio\n");
  for (const Point& p : curves[0]) {
    const double x = rmse_at(curves[1], p.seconds);
    if (std::isfinite(x)) std::printf("%.4f,%.5f,%.5f,%.3f\n", p.seconds, p.rmse, x, x / p.rmse);
  }
}

int run(int argc, char** argv) {
  std::vector<std::string> args;
  for (int i = 1; i < argc; ++i)
    if (std::string(argv[i]).rfind("--", 0) != 0) args.emplace_back(argv[i]);
  const auto arg = [&](size_t i, int fallback) {
    return i < args.size() ? std::atoi(args[i].c_str()) : fallback;
  };
  const int size = arg(0, 64), ref_spp = arg(1, 4096), max_spp = arg(2, 256), threads = arg(3, 2);
  tbb::task_arena arena(threads);

  Image sky = test::latlong_image(1024, test::smooth_sky);
  test::add_sun(sky, 50, 230, 0.5, Rgb{1.0f, 0.9f, 0.75f} * 1.5e5f);
  compare("synthetic sunny sky", std::make_shared<const EnvMap>(std::move(sky)), size, ref_spp, max_spp,
          arena);
  compare("sunrise.exr",
          std::make_shared<const EnvMap>(read_image_file(bench::envmap_path("sunrise.exr")).image), size,
          ref_spp, max_spp, arena);
  return 0;
}

}  // namespace
}  // namespace lp::render

int main(int argc, char** argv) {
  return lp::render::run(argc, argv);
}
