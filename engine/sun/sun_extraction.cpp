#include "engine/sun/sun_extraction.hpp"

#include <chrono>

#include "engine/mediancut/median_cut.hpp"
#include "engine/sun/sun_core.hpp"
#include "engine/sun/sun_detection.hpp"
#include "engine/sun/sun_disc.hpp"

namespace lp {
namespace {

Power power_of(Rgb p) {
  return {double(p.x), double(p.y), double(p.z)};
}

std::shared_ptr<const SunDetection> detection(const EnvMap& map, const SunParams& params, bool& hit) {
  return map.derived<SunDetection>("sun:" + params.key(), SunDetection::kMemoryBytes, [&] {
    hit = false;
    const auto tables = split_tables(map, kSunLuminance, SplitRule::Median);
    const MemoryReservation scratch =
        map.memory_budget().reserve(sun_core_scratch_bytes(map.width(), map.height()) +
                                        sun_detection_scratch_bytes(map.width(), map.height()),
                                    MemoryUse::Transient, "finding the sun of a map");
    return std::make_shared<const SunDetection>(detect_sun(map.image(), *tables.weight, params));
  });
}

std::shared_ptr<const EnvMap> residual(const EnvMap& map, const SunParams& params, const Sun& sun,
                                       bool& hit) {
  const int64_t bytes = EnvMap::image_bytes(map.width(), map.height()) + int64_t(sizeof(EnvMap));
  return map.derived<EnvMap>("sun_residual:" + params.key(), bytes, [&] {
    hit = false;
    Image image = map.image();
    fill_disc(image, sun.axis, sun.removed_radius, sun.fill);
    auto out = std::make_shared<EnvMap>(std::move(image));
    out->account_memory(map.memory_budget(), MemoryReservation());
    return std::shared_ptr<const EnvMap>(std::move(out));
  });
}

}  // namespace

SunExtraction extract_sun(const EnvMap& map, const SunParams& params, bool* cached) {
  params.validate();
  const auto start = std::chrono::steady_clock::now();
  bool hit = true;
  const auto found = detection(map, params, hit);
  SunExtraction out;
  out.params = params;
  out.reason = found->reason;
  out.map_power = out.residual_power = power_of(map.power());
  if (found->sun) {
    out.residual = residual(map, params, *found->sun, hit);
    out.residual_power = power_of(out.residual->power());
    Sun sun = *found->sun;
    Power power{};
    for (int c = 0; c < 3; ++c) power[c] = out.map_power[c] - out.residual_power[c];
    set_sun_power(sun, power, power_luminance(out.map_power, kSunLuminance));
    out.sun = sun;
  }
  if (cached) *cached = hit;
  out.elapsed_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace lp
