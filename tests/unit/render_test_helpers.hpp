#pragma once
// Shared helpers of the render_*_test.cpp files.
#include <atomic>
#include <cmath>
#include <functional>
#include <memory>
#include <vector>

#include "engine/envmap/envmap.hpp"
#include "engine/render/renderer.hpp"

namespace lp::render::test {

// A map of radiance f(direction), `width` x width/2.
inline std::shared_ptr<const EnvMap> make_map(int width, const std::function<Rgb(Vec3)>& f) {
  Image image(width, width / 2);
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x)
      image.set(x, y,
                f(latlong::direction(
                    {(float(x) + 0.5f) / float(width), (float(y) + 0.5f) / float(image.height())})));
  return std::make_shared<const EnvMap>(std::move(image));
}

inline std::shared_ptr<const EnvMap> constant_map(float radiance) {
  return make_map(64, [=](Vec3) { return Rgb{radiance, radiance, radiance}; });
}

inline Lighting lighting(LightingMode mode, int lights = 64) {
  Lighting l;
  l.mode = mode;
  l.lights = lights;
  return l;
}

inline RenderSettings settings(int size, int max_depth = 8, uint64_t seed = 1) {
  RenderSettings s;
  s.width = s.height = size;
  s.max_depth = max_depth;
  s.seed = seed;
  return s;
}

// One pass of `spp` samples.
inline Image render(const SceneDesc& scene, const Lighting& l, const RenderSettings& s,
                    std::shared_ptr<const EnvMap> map, int spp) {
  RenderSettings one_pass = s;
  one_pass.spp = spp;  // the samples the footprints are shared among (sample_spread)
  Renderer renderer(scene, l, one_pass, std::move(map));
  std::atomic<bool> cancel{false};
  renderer.render_pass(spp, cancel, {});
  return renderer.image();
}

// Pixels (x, y) of a square image whose footprint lies on the unit sphere of the sphere / furnace
// presets (seen from distance 4 with a 40 degree field: silhouette radius 0.7094 of the half-size).
inline bool on_preset_sphere(int x, int y, int size) {
  const float c = 0.5f * float(size);
  const float radius = 0.70943f * c - 1.0f;  // one pixel inside the silhouette
  return std::hypot(float(x) + 0.5f - c, float(y) + 0.5f - c) < radius;
}

// Mean of all channels over the preset sphere's pixels.
inline double sphere_mean(const Image& image) {
  double sum = 0;
  int n = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x)
      if (on_preset_sphere(x, y, image.width())) {
        const Rgb p = image.at(x, y);
        sum += double(p.x) + p.y + p.z;
        n += 3;
      }
  return sum / n;
}

// Relative L1 difference over the preset sphere's pixels: sum |a - b| / sum b.
inline double sphere_relative_l1(const Image& a, const Image& b) {
  double diff = 0, total = 0;
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x)
      if (on_preset_sphere(x, y, a.width()))
        for (int k = 0; k < 3; ++k) {
          diff += std::abs(double(a.at(x, y)[k]) - b.at(x, y)[k]);
          total += b.at(x, y)[k];
        }
  return diff / total;
}

// Root-mean-square difference over the preset sphere's pixels, relative to b's mean.
inline double sphere_relative_rmse(const Image& a, const Image& b) {
  double sq = 0, total = 0;
  int n = 0;
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x)
      if (on_preset_sphere(x, y, a.width()))
        for (int k = 0; k < 3; ++k) {
          const double d = double(a.at(x, y)[k]) - b.at(x, y)[k];
          sq += d * d;
          total += b.at(x, y)[k];
          ++n;
        }
  return std::sqrt(sq / n) / (total / n);
}

}  // namespace lp::render::test
