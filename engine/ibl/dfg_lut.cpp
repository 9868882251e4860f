#include "engine/ibl/dfg_lut.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>

#include "engine/bsdf/microfacet.hpp"
#include "engine/bsdf/visible_normal_quadrature.hpp"

namespace lp {
namespace {

// Tables kept at once: a few sizes are in use at a time, and each takes at most 1 MiB.
constexpr size_t kCachedTables = 8;

}  // namespace

DfgValue dfg(double n_dot_v, double roughness, bool multiscatter) {
  const float mu = float(std::clamp(n_dot_v, 0.0, 1.0));
  const float alpha = float(roughness * roughness);
  const auto schlick = [](double cos_theta) { return std::pow(1 - std::clamp(cos_theta, 0.0, 1.0), 5); };
  double total = 0, bias = 0;
  if (alpha < render::kDeltaLobeAlpha) {
    total = 1;
    bias = schlick(mu);
  } else {
    render::visible_normal_quadrature(mu, alpha, [&](float cos_theta, double weight) {
      total += weight;
      bias += schlick(cos_theta) * weight;
    });
  }
  return multiscatter ? DfgValue{bias, total} : DfgValue{total - bias, bias};
}

DfgLut make_dfg_lut(int size, bool multiscatter) {
  DfgLut lut{size, multiscatter, std::vector<DfgValue>(size_t(size) * size_t(size))};
  tbb::parallel_for(0, size, [&](int y) {
    for (int x = 0; x < size; ++x)
      lut.texels[size_t(y) * size_t(size) + size_t(x)] =
          dfg((x + 0.5) / size, (y + 0.5) / size, multiscatter);
  });
  return lut;
}

std::shared_ptr<const DfgLut> dfg_lut_cached(int size, bool multiscatter) {
  static std::mutex mutex;
  static std::map<std::pair<int, bool>, std::shared_ptr<const DfgLut>> cache;
  const std::lock_guard lock(mutex);  // a table takes well under a second: callers may wait for it
  if (cache.size() >= kCachedTables && !cache.contains({size, multiscatter})) cache.clear();
  auto& entry = cache[{size, multiscatter}];
  if (!entry) entry = std::make_shared<const DfgLut>(make_dfg_lut(size, multiscatter));
  return entry;
}

}  // namespace lp
