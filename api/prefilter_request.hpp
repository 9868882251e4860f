#pragma once
// POST /envmaps/{id}/prefilter body: the chain's parameters and the files it is delivered as.
#include <string>

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

struct PrefilterRequest {
  PrefilterParams params;
  PrefilterFormat format = PrefilterFormat::Ktx2;
  PixelPrecision precision = PixelPrecision::Half;
  bool operator==(const PrefilterRequest&) const = default;
};

// {"levels":6,"base_size":256,"samples":1024,"projection":"latlong","format":"ktx2","precision":"half"},
// every field optional (defaults shown); an empty body means all defaults. Ranges from
// engine/core/limits.hpp (kPrefilter*), and the rest of PrefilterParams::validate.
PrefilterRequest parse_prefilter_request(const std::string& body);

}  // namespace lp::api
