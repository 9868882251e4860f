#include "api/prefilter_files.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <map>

#include "api/api_error.hpp"
#include "engine/image/encode_memory.hpp"
#include "engine/image/ktx2.hpp"

namespace lp::api {
namespace {

// The level a file holds: its index in the list of names.
size_t file_index(const PrefilterRequest& request, const std::string& name) {
  const auto names = prefilter_file_names(request);
  const auto it = std::find(names.begin(), names.end(), name);
  if (it == names.end())
    throw not_found("no file '" + excerpt(name) + "' in this chain; its files are " + join(names, ", "));
  return size_t(it - names.begin());
}

}  // namespace

std::vector<std::string> prefilter_file_names(const PrefilterRequest& request) {
  if (request.format == PrefilterFormat::Ktx2) return {"prefiltered.ktx2"};
  std::vector<std::string> names;
  for (int i = 0; i < request.params.levels; ++i) names.push_back("level" + std::to_string(i) + ".exr");
  return names;
}

const char* prefilter_file_mime_type(PrefilterFormat format) {
  return format == PrefilterFormat::Ktx2 ? "image/ktx2" : format_mime_type(ImageFormat::Exr);
}

std::vector<std::pair<std::string, std::string>> prefilter_conventions() {
  return {
      {"projection",
       "lat-long: texel (x, y) of a W x H level looks along theta = pi (y + 0.5) / H from +z, phi = 2 pi "
       "(x + 0.5) / W; row 0 at the top"},
      {"frame", "right-handed, z up: direction = (sin theta cos phi, sin theta sin phi, cos theta)"},
      {"roughness",
       "perceptual: level i of n has roughness i / (n - 1), GGX alpha = roughness^2 (the brdf-lut's)"},
      {"lobe",
       "GGX (Trowbridge-Reitz) with the split-sum assumption N = V = R: sum L(l) n.l / sum n.l over l = "
       "reflect(n, h), h ~ D(h) n.h, by filtered importance sampling (Krivanek and Colbert 2008)"},
      {"level0", "the map resampled to the base size, each texel the solid-angle mean it covers"},
  };
}

int64_t prefilter_file_bytes(const PrefilterRequest& request, const std::string& name) {
  const size_t index = file_index(request, name);
  const auto& p = request.params;
  if (request.format == PrefilterFormat::Exr) {
    const LevelSize s = latlong_level_size(p.base_size, int(index));
    return encode_bytes(ImageFormat::Exr, s.width, s.height);
  }
  // The texels at 16 bytes (RGBA float), the header and the metadata.
  return prefiltered_chain_bytes(p) * 16 / 12 + (1 << 16);
}

int prefilter_level_index(const PrefilterRequest& request, const std::string& text) {
  const int levels = request.params.levels;
  for (int i = 0; i < levels; ++i)
    if (text == std::to_string(i)) return i;
  throw not_found(
      fmt::format("no level '{}' in this chain; its levels are 0 to {}", excerpt(text), levels - 1));
}

std::vector<uint8_t> encode_prefilter_file(const PrefilteredChain& chain, const PrefilterRequest& request,
                                           const std::string& name) {
  const size_t index = file_index(request, name);
  if (request.format == PrefilterFormat::Exr)
    return write_exr(chain.levels[index], ExrCompression::Zip, request.precision);
  std::map<std::string, std::string> metadata;
  for (const auto& [key, text] : prefilter_conventions()) metadata["lightprobe." + key] = text;
  return write_ktx2(chain.levels, request.precision, metadata);
}

}  // namespace lp::api
