// A program that uses the Lightprobe engine as a library: it loads an environment map, importance
// samples it, reduces it to median-cut lights and renders a small image lit by it.
//
//   lightprobe_tour [map.exr|map.pfm|map.hdr]
//
// Without a map it writes white_furnace.pfm (radiance 1 everywhere) and uses that, so every figure
// has a known answer: the map's power is 4 pi, the lights share it equally, and the diffuse sphere of
// albedo 0.5 in the render has radiance 0.5. The render is written to render.png.
#include <atomic>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "engine/core/error.hpp"
#include "engine/envmap/envmap.hpp"
#include "engine/envmap/envmap_sampler.hpp"
#include "engine/image/image_io.hpp"
#include "engine/mediancut/median_cut.hpp"
#include "engine/render/renderer.hpp"

namespace {

constexpr auto kMode = lp::LuminanceMode::Average;

std::filesystem::path write_white_furnace() {
  lp::Image image(64, 32);
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) image.set(x, y, {1, 1, 1});
  const std::filesystem::path path = "white_furnace.pfm";
  lp::write_file(path, lp::write_pfm(image));
  return path;
}

std::shared_ptr<const lp::EnvMap> load_map(const std::filesystem::path& path) {
  lp::DecodedImage decoded = lp::read_image_file(path);
  auto map = std::make_shared<const lp::EnvMap>(std::move(decoded.image));
  const lp::Rgb power = map->power();
  std::printf("map %s: %d x %d %s, power %.4f %.4f %.4f\n", path.string().c_str(), map->width(),
              map->height(), lp::enum_name(decoded.format), power.x, power.y, power.z);
  return map;
}

// A stratified n x n grid of importance samples: the mean of luminance / pdf estimates the power.
void sample(const lp::EnvMap& map, int n) {
  const auto sampler = map.sampler(kMode);
  double sum = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const lp::EnvSample s = sampler->sample((float(i) + 0.5f) / float(n), (float(j) + 0.5f) / float(n));
      sum += lp::luminance(s.radiance, kMode) / s.pdf;
    }
  std::printf("samples: %d, estimated power %.4f\n", n * n, sum / (n * n));
}

void median_cut(const lp::EnvMap& map, int count) {
  lp::MedianCutParams params;
  params.count = count;
  params.luminance = kMode;
  const lp::MedianCutResult result = lp::median_cut(map, params);
  const lp::Vec3 d = result.lights.front().direction;
  std::printf(
      "median cut: %zu lights, power %.4f, energy min %.4f max %.4f, first light towards %.3f %.3f %.3f\n",
      result.lights.size(), lp::power_luminance(result.power, kMode), result.energy_min, result.energy_max,
      d.x, d.y, d.z);
}

// The "furnace" preset: a diffuse sphere of albedo 0.5 filling the middle of the picture.
void render(std::shared_ptr<const lp::EnvMap> map, int size, int spp) {
  lp::render::RenderSettings settings;
  settings.width = settings.height = size;
  lp::render::Renderer renderer(*lp::render::scene_preset("furnace"), lp::render::Lighting{}, settings,
                                std::move(map));
  const std::atomic<bool> cancel{false};
  renderer.render_pass(spp, cancel, {});
  const lp::Image image = renderer.image();
  lp::write_file("render.png", lp::write_png(image));

  double centre = 0;
  const int lo = size * 3 / 8, hi = size * 5 / 8;
  for (int y = lo; y < hi; ++y)
    for (int x = lo; x < hi; ++x) centre += lp::luminance(image.at(x, y), kMode);
  std::printf("render: %d x %d, %d spp, centre radiance %.4f, %llu rays, written to render.png\n", size, size,
              spp, centre / ((hi - lo) * (hi - lo)), static_cast<unsigned long long>(renderer.stats().rays));
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const std::filesystem::path path = argc > 1 ? std::filesystem::path(argv[1]) : write_white_furnace();
    const auto map = load_map(path);
    sample(*map, 64);
    median_cut(*map, 16);
    render(map, 32, 16);
    return 0;
  } catch (const lp::Error& e) {
    std::fprintf(stderr, "lightprobe_tour: %s\n", e.what());
    return 1;
  }
}
