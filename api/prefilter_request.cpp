#include "api/prefilter_request.hpp"

#include <fmt/format.h>

#include "api/api_error.hpp"
#include "api/bake/bake_request.hpp"
#include "api/engine_validation.hpp"
#include "engine/core/limits.hpp"
#include "engine/prefilter/prefilter_chain.hpp"

namespace lp::api {
namespace {

template <class T>
int json_in(const Json& j, const char* name, int fallback, const Range<T>& range) {
  return int(json_int(j, name, fallback, range.min, range.max));
}

}  // namespace

PrefilterRequest parse_prefilter_request(const std::string& body) {
  const Json j = parse_json_object_or_empty(body);
  reject_unknown_fields(j, {"levels", "base_size", "samples", "projection", "level_roughness", "format",
                            "precision", "target"});
  PrefilterRequest r;
  PrefilterParams& p = r.params;
  p.levels = json_in(j, "levels", p.levels, limits::kPrefilterLevels);
  p.base_size = json_in(j, "base_size", p.base_size, limits::kPrefilterBaseSize);
  p.samples = json_in(j, "samples", p.samples, limits::kPrefilterSamples);
  p.projection = json_enum(j, "projection", p.projection);
  p.level_roughness = json_enum(j, "level_roughness", p.level_roughness);
  r.format = json_enum(j, "format", r.format);
  r.precision = json_enum(j, "precision", r.precision);
  apply_bake_target(r, j);
  as_invalid_field([&] { p.validate(); });
  const int64_t texel_samples = prefilter_work_units(p);
  if (texel_samples > kPrefilterTexelSamples.max)
    throw ApiError(ErrorCode::InvalidField,
                   fmt::format("the chain would take {} texel samples (the texels of levels 1 to {} times "
                               "'samples' {}, plus level 0's), over the limit texel_samples <= {}: ask "
                               "fewer 'samples' or 'levels', or a smaller 'base_size'",
                               texel_samples, p.levels - 1, p.samples, kPrefilterTexelSamples.max));
  return r;
}

}  // namespace lp::api
