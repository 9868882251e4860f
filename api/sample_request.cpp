#include "api/sample_request.hpp"

#include <algorithm>

#include "api/api_error.hpp"
#include "api/preview_params.hpp"

namespace lp::api {
namespace {

int64_t count(int64_t given, const NumberField& f, const RequestLimits& limits) {
  return std::min<int64_t>(given, std::min<int64_t>(int64_t(f.range.max), limits.max_samples));
}

}  // namespace

SampleRequest parse_sample_request(const Json& body, const RequestLimits& limits) {
  reject_unknown_fields(body, {"count", "seed", "strategy", "luminance"});
  if (!body.contains(kSampleCount.name)) throw invalid_field(kSampleCount.name, "is required");
  const auto& c = kSampleCount;
  const auto& s = kSampleSeed;
  SampleRequest r;
  r.spec.count =
      uint64_t(json_int(body, c.name, 0, int64_t(c.range.min), count(limits.max_samples, c, limits)));
  r.spec.seed =
      uint64_t(json_int(body, s.name, int64_t(*s.fallback), int64_t(s.range.min), int64_t(s.range.max)));
  r.spec.strategy = json_enum(body, "strategy", SampleStrategy::Independent);
  r.luminance = json_enum(body, "luminance", LuminanceMode::Average);
  return r;
}

SampleImageRequest parse_sample_image_query(const Query& q, const RequestLimits& limits) {
  const auto& c = kSampleImageCount;
  const auto& s = kSampleSeed;
  SampleImageRequest r;
  r.samples.spec.count = uint64_t(
      query_int(q, c.name, int64_t(*c.fallback), int64_t(c.range.min), count(limits.max_samples, c, limits)));
  r.samples.spec.seed =
      uint64_t(query_int(q, s.name, int64_t(*s.fallback), int64_t(s.range.min), int64_t(s.range.max)));
  r.samples.spec.strategy = query_enum(q, "strategy", SampleStrategy::Independent);
  r.samples.luminance = query_enum(q, "luminance", LuminanceMode::Average);
  r.style = query_enum(q, "style", SampleImageStyle::Marks);
  r.tone = parse_tone_map(q);
  return r;
}

}  // namespace lp::api
