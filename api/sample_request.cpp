#include "api/sample_request.hpp"

#include "api/api_error.hpp"
#include "api/preview_params.hpp"

namespace lp::api {
namespace {
const std::vector<std::string> kStrategies = {"independent", "stratified", "sobol"};
const std::vector<std::string> kLuminance = {"average", "rec709"};
constexpr int64_t kMaxSeed = int64_t{1} << 53;  // exact in a JSON number
}  // namespace

SampleRequest parse_sample_request(const Json& body, int64_t max_samples) {
  reject_unknown_fields(body, {"count", "seed", "strategy", "luminance"});
  if (!body.contains("count")) throw invalid_field("count", "is required");
  SampleRequest r;
  r.spec.count = uint64_t(json_int(body, "count", 0, 1, max_samples));
  r.spec.seed = uint64_t(json_int(body, "seed", 0, 0, kMaxSeed));
  r.spec.strategy = *parse_strategy(json_enum(body, "strategy", "independent", kStrategies));
  r.luminance = *parse_luminance_mode(json_enum(body, "luminance", "average", kLuminance));
  return r;
}

SampleImageRequest parse_sample_image_query(const Query& q, int64_t max_samples) {
  SampleImageRequest r;
  r.samples.spec.count = uint64_t(query_int(q, "count", 256, 1, max_samples));
  r.samples.spec.seed = uint64_t(query_int(q, "seed", 0, 0, kMaxSeed));
  r.samples.spec.strategy = *parse_strategy(query_enum(q, "strategy", "independent", kStrategies));
  r.samples.luminance = *parse_luminance_mode(query_enum(q, "luminance", "average", kLuminance));
  r.style = query_enum(q, "style", "marks", {"marks", "windows"}) == "marks" ? SampleImageStyle::Marks
                                                                              : SampleImageStyle::Windows;
  r.tone = parse_tone_map(q);
  return r;
}

}  // namespace lp::api
