// Time to reach a given error, for comparing with other renderers (bench/cycles_compare.py runs the
// same scene in Blender Cycles) and with earlier builds of this one (bench/speedup_compare.sh): renders a
// converged reference, then 1, 2, 4, ... spp, and prints for each the render time and the RMSE against
// the reference (relative to the reference's mean), over the pixels the reference covers (the map is not
// visible to the camera, as a transparent film in Cycles). Then the time each error level takes.
// Usage: render_error_bench [scene=sphere] [mode=envmap] [size=64] [ref_spp=4096] [max_spp=256]
//                           [threads=2] [out_dir] [--map=FILE] [--seeds=K]
//                           [--mis-compensation=0|1] [--adaptive=0|1] [--repeats=R]
//   scene: a preset, or `glossy` (bench_data.hpp: diffuse_and_glossy, no mirror or glass);
//   out_dir: writes reference.exr and spp_<n>.exr (and .pfm);  --map: the map (default forest.exr);
//   --seeds: K independent renders at each spp, whose squared errors are averaged (default 1);
//   --mis-compensation=0: light samples from the map's plain distribution (envmap.hpp, SamplerWeights);
//   --adaptive=1: each render spends the same samples in all (spp x pixels) in one adaptive pass
//   (Renderer::render_adaptive_pass: a uniform warm-up, then samples where the neighbours' variance is);
//   the reference stays uniform;
//   --reference=FILE: the reference image (an EXR of this scene at this size), instead of rendering one;
//   --reference-out=FILE: writes the reference rendered;
//   scene `glass`: bench_data.hpp's glass_on_plane;
//   --repeats: each render is run R times and timed by its fastest run (default 1). Renders are
//   deterministic, so the repeats change no error, and interference from other work on the machine
//   only ever adds time: the least of a few runs is the steadiest figure.
// Each line also gives the error without the worst 1% of pixels (trimmed_rmse, not corrected for the
// reference's noise) and the share of the squared error those pixels hold (top_share).
// The reference's own noise is taken out of each error: for independent unbiased renders of n and N
// spp, E|I_n - R_N|^2 = (s^2/n)(1 + n/N), so the error of I_n against the expectation is the measured
// one over sqrt(1 + n/N). Time is the render's wall time and the process's CPU time (all threads, scene
// build included); the CPU time is steadier on a shared machine.
// Other arguments starting with "--" (Google Benchmark flags from bench/run_all.sh) are ignored. The
// Cycles comparison in the README used: render_error_bench sphere envmap 128 4096 1024 2
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
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
const double kErrorLevels[] = {0.02, 0.01, 0.005};

struct Timed {
  Image image;
  double seconds, cpu_seconds;
  RenderStats stats;
};

// An adaptive pass where the engine has them; builds from before them render uniformly, so
// bench/speedup_compare.sh can build this file against them.
template <class R>
void render_pass(R& renderer, int spp, bool adaptive, const std::atomic<bool>& cancel) {
  if constexpr (requires { renderer.render_adaptive_pass(spp, cancel, {}); })
    if (adaptive) {
      renderer.render_adaptive_pass(spp, cancel, {});
      return;
    }
  renderer.render_pass(spp, cancel, {});
}

Timed render(const SceneDesc& scene, const Lighting& lighting, int size, int spp, uint64_t seed,
             tbb::task_arena& arena, const std::shared_ptr<const EnvMap>& map, bool adaptive = false) {
  RenderSettings settings;
  settings.width = settings.height = size;
  settings.seed = seed;
  const auto t0 = std::chrono::steady_clock::now();
  const std::clock_t c0 = std::clock();
  Renderer renderer(scene, lighting, settings, map);  // scene build included, as in Cycles' timing
  std::atomic<bool> cancel{false};
  arena.execute([&] { render_pass(renderer, spp, adaptive, cancel); });
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return {renderer.image(), seconds, double(std::clock() - c0) / CLOCKS_PER_SEC, renderer.stats()};
}

// The relative MSE without the 1% of covered pixels of largest squared error, and the share of the
// squared error those pixels hold: where fireflies (caustics, glints) carry the error, the trimmed
// error still shows how the rest of the image converges.
struct Trimmed {
  double relative_mse, top_share;
};
Trimmed trimmed_relative_mse(const Image& a, const Image& ref) {
  std::vector<double> errors;
  double sum = 0;
  for (int y = 0; y < ref.height(); ++y)
    for (int x = 0; x < ref.width(); ++x) {
      const Rgb r = ref.at(x, y);
      if (r.x + r.y + r.z <= 0) continue;
      double e = 0;
      for (int k = 0; k < 3; ++k) e += (double(a.at(x, y)[k]) - r[k]) * (double(a.at(x, y)[k]) - r[k]);
      errors.push_back(e);
      sum += double(r.x) + r.y + r.z;
    }
  std::sort(errors.begin(), errors.end());
  const size_t kept = errors.size() - errors.size() / 100;
  double low = 0, all = 0;
  for (size_t i = 0; i < errors.size(); ++i) (i < kept ? low : all) += errors[i];
  all += low;
  const double mean = sum / (3.0 * double(errors.size()));
  return {low / (3.0 * double(kept)) / (mean * mean), all > 0 ? 1 - low / all : 0};
}

double relative_mse(const Image& a, const Image& ref) {
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
  const double mean = sum / double(n);
  return sq / double(n) / (mean * mean);
}

// NAME.exr, and NAME.pfm for scripts that read it with numpy alone.
void write_images(const std::filesystem::path& dir, const std::string& name, const Image& image) {
  write_file(dir / (name + ".exr"), write_exr(image));
  write_file(dir / (name + ".pfm"), write_pfm(image));
}

double mean_of(const Image& image) {
  double sum = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) {
      const Rgb c = image.at(x, y);
      sum += double(c.x) + c.y + c.z;
    }
  return sum / (3.0 * double(image.width()) * image.height());
}

struct Point {
  int spp;
  double seconds, cpu_seconds, rmse;
  double trimmed_rmse = 0, top_share = 0;
};

// The time at which the error reaches `level`: log(time) linear in log(error) between the two measured
// points around it; past the last point, the last one's time scaled by (error / level)^2.
std::pair<double, bool> time_to(const std::vector<Point>& curve, double level, double Point::*time) {
  for (size_t i = 1; i < curve.size(); ++i) {
    const Point &a = curve[i - 1], &b = curve[i];
    if (a.rmse >= level && level >= b.rmse && a.rmse > b.rmse) {
      const double t = std::log(a.rmse / level) / std::log(a.rmse / b.rmse);
      return {a.*time * std::pow(b.*time / (a.*time), t), false};
    }
  }
  const Point& last = curve.back();
  return {last.*time * (last.rmse / level) * (last.rmse / level), last.rmse > level};
}

// Builds of the engine from before the option render with the plain distribution and ignore it, so
// bench/speedup_compare.sh can build this file against them.
template <class L>
void set_mis_compensation(L& lighting, bool on) {
  if constexpr (requires { lighting.mis_compensation; }) lighting.mis_compensation = on;
}

struct Options {
  std::vector<std::string> args;
  std::filesystem::path map = bench::envmap_path("forest.exr");
  int seeds = 1;
  bool mis_compensation = true;
  bool adaptive = false;
  int repeats = 1;
  std::filesystem::path reference, reference_out;
};

Options parse_options(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a.rfind("--map=", 0) == 0)
      o.map = a.substr(6);
    else if (a.rfind("--seeds=", 0) == 0)
      o.seeds = std::max(1, std::atoi(a.c_str() + 8));
    else if (a.rfind("--mis-compensation=", 0) == 0)
      o.mis_compensation = a.back() != '0';
    else if (a.rfind("--adaptive=", 0) == 0)
      o.adaptive = a.back() != '0';
    else if (a.rfind("--reference=", 0) == 0)
      o.reference = a.substr(12);
    else if (a.rfind("--reference-out=", 0) == 0)
      o.reference_out = a.substr(16);
    else if (a.rfind("--repeats=", 0) == 0)
      o.repeats = std::max(1, std::atoi(a.c_str() + 10));
    else if (a.rfind("--", 0) != 0)
      o.args.push_back(a);
  }
  return o;
}

int run(int argc, char** argv) {
  const Options o = parse_options(argc, argv);
  const auto arg = [&](size_t i, const char* fallback) {
    return i < o.args.size() ? o.args[i] : std::string(fallback);
  };
  const std::string preset = arg(0, "sphere");
  const std::string mode = arg(1, "envmap");
  const int size = std::atoi(arg(2, "64").c_str());
  const int ref_spp = std::atoi(arg(3, "4096").c_str());
  const int max_spp = std::atoi(arg(4, "256").c_str());
  const int threads = std::atoi(arg(5, "2").c_str());
  const std::filesystem::path out_dir = arg(6, "");
  const auto scene = preset == "glossy"  ? bench::diffuse_and_glossy()
                     : preset == "glass" ? bench::glass_on_plane()
                                         : scene_preset(preset);
  if (!scene || !kModes.count(mode)) {
    std::fprintf(stderr, "unknown preset or mode\n");
    return 2;
  }
  Lighting lighting;
  lighting.mode = kModes.at(mode);
  lighting.lights = 64;
  lighting.visible = false;
  set_mis_compensation(lighting, o.mis_compensation);
  const auto map = std::make_shared<const EnvMap>(read_image_file(o.map).image);
  tbb::task_arena arena(threads);

  const Timed ref = o.reference.empty() ? render(*scene, lighting, size, ref_spp, 1000, arena, map)
                                        : Timed{read_image_file(o.reference).image, 0, 0, {}};
  if (!o.reference_out.empty()) write_file(o.reference_out, write_exr(ref.image));
  std::printf(
      "# lightprobe %s %s %dx%d on %s, %d threads, %d seeds%s, fastest of %d; reference %s in "
      "%.2f s, mean %.6f\n",
      preset.c_str(), mode.c_str(), size, size, o.map.filename().c_str(), threads, o.seeds,
      o.adaptive ? ", adaptive" : "", o.repeats,
      o.reference.empty() ? (std::to_string(ref_spp) + " spp").c_str() : o.reference.c_str(), ref.seconds,
      mean_of(ref.image));
  if (!out_dir.empty()) write_images(out_dir, "reference", ref.image);
  std::printf("spp,seconds,cpu_seconds,relative_rmse,samples_per_s,rays_per_s,trimmed_rmse,top_share\n");
  std::vector<Point> curve;
  for (int spp = 1; spp <= max_spp; spp *= 2) {
    Point p{spp, 0, 0, 0};
    RenderStats stats;
    for (int k = 0; k < o.seeds; ++k) {
      Timed t = render(*scene, lighting, size, spp, 1 + uint64_t(k), arena, map, o.adaptive);
      for (int r = 1; r < o.repeats; ++r) {
        const Timed again = render(*scene, lighting, size, spp, 1 + uint64_t(k), arena, map, o.adaptive);
        t.seconds = std::min(t.seconds, again.seconds);
        t.cpu_seconds = std::min(t.cpu_seconds, again.cpu_seconds);
      }
      p.seconds += t.seconds / o.seeds;
      p.cpu_seconds += t.cpu_seconds / o.seeds;
      p.rmse += relative_mse(t.image, ref.image) / o.seeds;
      const Trimmed trimmed = trimmed_relative_mse(t.image, ref.image);
      p.trimmed_rmse += trimmed.relative_mse / o.seeds;
      p.top_share += trimmed.top_share / o.seeds;
      stats.samples += t.stats.samples;
      stats.rays += t.stats.rays;
      if (!out_dir.empty() && k == 0) write_images(out_dir, "spp_" + std::to_string(spp), t.image);
    }
    p.rmse = std::sqrt(p.rmse / (1 + double(spp) / ref_spp));
    p.trimmed_rmse = std::sqrt(p.trimmed_rmse);
    curve.push_back(p);
    std::printf("%d,%.4f,%.4f,%.5f,%.0f,%.0f,%.5f,%.3f\n", spp, p.seconds, p.cpu_seconds, p.rmse,
                double(stats.samples) / (p.seconds * o.seeds), double(stats.rays) / (p.seconds * o.seeds),
                p.trimmed_rmse, p.top_share);
  }
  std::printf("relative_rmse,seconds,cpu_seconds,extrapolated\n");
  for (const double level : kErrorLevels) {
    const auto [wall, extrapolated] = time_to(curve, level, &Point::seconds);
    std::printf("%.3f,%.4f,%.4f,%s\n", level, wall, time_to(curve, level, &Point::cpu_seconds).first,
                extrapolated ? "yes" : "no");
  }
  return 0;
}

}  // namespace
}  // namespace lp::render

int main(int argc, char** argv) {
  return lp::render::run(argc, argv);
}
