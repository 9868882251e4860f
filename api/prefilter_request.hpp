#pragma once
// POST /envmaps/{id}/prefilter body: the chain's parameters and the files it is delivered as.
#include <optional>
#include <string>

#include "api/bake/bake_target.hpp"
#include "api/params.hpp"
#include "engine/image/image_io.hpp"
#include "engine/prefilter/prefilter_params.hpp"

namespace lp::api {

// One EXR file per level, or the whole chain as one KTX2 texture with its mip levels (a cube map for the
// cube projection).
enum class PrefilterFormat { Exr, Ktx2 };
constexpr auto enum_entries(PrefilterFormat) {
  return std::to_array<EnumEntry<PrefilterFormat>>(
      {{PrefilterFormat::Exr, "exr"}, {PrefilterFormat::Ktx2, "ktx2"}});
}

// The most texel samples one chain may take (engine/prefilter: prefilter_work_units): the texels of the
// levels above 0 times `samples`, plus level 0's texels. It bounds what one job costs (a few CPU-minutes
// at most), which the fields' ranges alone do not: 11 levels from 2048 texels wide with 16384 samples
// would take 11.5e9.
inline constexpr Range<int64_t> kPrefilterTexelSamples{1, int64_t{1} << 30};

struct PrefilterRequest {
  PrefilterParams params;
  PrefilterFormat format = PrefilterFormat::Ktx2;
  PixelPrecision precision = PixelPrecision::Half;
  // A bake target: the job makes the target's chain (params as its chain_params sets them) and then its
  // files instead of the chain's own (format is then not asked).
  std::optional<BakeTarget> target;
  bool operator==(const PrefilterRequest&) const = default;
};

// {"levels":6,"base_size":256,"samples":1024,"projection":"latlong","level_roughness":"linear",
// "format":"ktx2","precision":"half","target":"gltf"}, every field optional (defaults shown, no target by
// default); an empty body means all defaults. With a target, a field the target fixes given another
// value is a 400 naming it (apply_bake_target). Ranges from
// engine/core/limits.hpp (kPrefilter*), the rest of PrefilterParams::validate, and at most
// kPrefilterTexelSamples texel samples (400 invalid_field naming the limit).
PrefilterRequest parse_prefilter_request(const std::string& body);

}  // namespace lp::api
