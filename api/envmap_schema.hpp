#pragma once
// JSON shapes of environment-map resources.
#include <chrono>
#include <string>

#include "api/params.hpp"
#include "engine/envmap/envmap.hpp"
#include "engine/projection/projection.hpp"

namespace lp::api {

struct EnvMapInfo {
  std::string id, name, format, source;
  std::chrono::system_clock::time_point created;
  Projection source_projection = Projection::LatLong;
};

Json envmap_metadata(const EnvMapInfo& info, const EnvMap& map);
Json rgb_json(Rgb c);

// The data behind the marginal PDF/CDF figures: per-row mean luminance, row probabilities
// (weighted by sin theta of the row centre or not), and the CDF over rows (height + 1 entries).
Json distribution_json(const EnvMap& map, LuminanceMode mode, bool sin_weight);

}  // namespace lp::api
