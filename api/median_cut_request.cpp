#include "api/median_cut_request.hpp"

#include <algorithm>

#include "api/api_error.hpp"
#include "api/engine_validation.hpp"
#include "api/preview_params.hpp"

namespace lp::api {
namespace {

int64_t max_count(const RequestLimits& limits) {
  return std::min<int64_t>(limits.max_lights, int64_t(kLightCount.range.max));
}

}  // namespace

MedianCutParams parse_median_cut_request(const std::string& body, const RequestLimits& limits) {
  const Json j = parse_optional_json_object(body);
  reject_unknown_fields(j, {"count", "placement", "split", "luminance"});
  const auto& c = kLightCount;
  MedianCutParams p;
  p.count = int(json_int(j, c.name, int64_t(*c.fallback), int64_t(c.range.min), max_count(limits)));
  p.placement = json_enum(j, "placement", LightPlacement::Centroid);
  p.split = json_enum(j, "split", SplitRule::Median);
  p.luminance = json_enum(j, "luminance", LuminanceMode::Average);
  return p;
}

MedianCutImageRequest parse_median_cut_image_query(const Query& q, const RequestLimits& limits) {
  const auto& c = kLightCount;
  MedianCutImageRequest r;
  r.params.count = int(query_int(q, c.name, int64_t(*c.fallback), int64_t(c.range.min), max_count(limits)));
  r.params.placement = query_enum(q, "placement", LightPlacement::Centroid);
  r.params.split = query_enum(q, "split", SplitRule::Median);
  r.params.luminance = query_enum(q, "luminance", LuminanceMode::Average);
  r.style = query_enum(q, "style", MedianCutStyle::Regions);
  r.tone = parse_tone_map(q);
  return r;
}

void check_count_fits(const MedianCutParams& params, int64_t pixel_count) {
  as_invalid_field([&] { params.validate(pixel_count); });
}

}  // namespace lp::api
