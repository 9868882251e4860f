#include "api/median_cut_request.hpp"

#include <algorithm>
#include <cctype>

#include <fmt/format.h>

#include "api/api_error.hpp"
#include "api/preview_params.hpp"

namespace lp::api {
namespace {
const std::vector<std::string> kPlacements = {"centroid", "centroid_squared", "center"};
const std::vector<std::string> kSplits = {"median", "variance"};
const std::vector<std::string> kLuminance = {"average", "rec709"};
const std::vector<std::string> kStyles = {"regions", "lights"};
constexpr int kDefaultCount = 64;

int checked_max(int64_t max_lights) { return int(std::clamp<int64_t>(max_lights, 1, int64_t{1} << 30)); }
}  // namespace

MedianCutParams parse_median_cut_request(const std::string& body, int64_t max_lights) {
  const bool empty = std::all_of(body.begin(), body.end(), [](unsigned char c) { return std::isspace(c); });
  const Json j = empty ? Json::object() : parse_json_object(body);
  reject_unknown_fields(j, {"count", "placement", "split", "luminance"});
  MedianCutParams p;
  p.count = int(json_int(j, "count", kDefaultCount, 1, checked_max(max_lights)));
  p.placement = *parse_light_placement(json_enum(j, "placement", "centroid", kPlacements));
  p.split = *parse_split_rule(json_enum(j, "split", "median", kSplits));
  p.luminance = *parse_luminance_mode(json_enum(j, "luminance", "average", kLuminance));
  return p;
}

MedianCutImageRequest parse_median_cut_image_query(const Query& q, int64_t max_lights) {
  MedianCutImageRequest r;
  r.params.count = int(query_int(q, "count", kDefaultCount, 1, checked_max(max_lights)));
  r.params.placement = *parse_light_placement(query_enum(q, "placement", "centroid", kPlacements));
  r.params.split = *parse_split_rule(query_enum(q, "split", "median", kSplits));
  r.params.luminance = *parse_luminance_mode(query_enum(q, "luminance", "average", kLuminance));
  r.style = *parse_median_cut_style(query_enum(q, "style", "regions", kStyles));
  r.tone = parse_tone_map(q);
  return r;
}

void check_count_fits(const MedianCutParams& params, int64_t pixel_count) {
  if (params.count > pixel_count)
    throw invalid_field("count", fmt::format("must be at most the map's {} pixels, got {}", pixel_count, params.count));
}

}  // namespace lp::api
