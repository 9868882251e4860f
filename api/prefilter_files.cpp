#include "api/prefilter_files.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <map>

#include "api/api_error.hpp"
#include "api/projection_conventions.hpp"
#include "engine/image/encode_memory.hpp"
#include "engine/image/ktx2.hpp"
#include "engine/projection/cube_face.hpp"

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

// A strip of six N x N faces side by side (6N x N) as KTX2 lays out a cube map's level: the faces one
// below the other (N x 6N).
Image stacked_faces(const Image& strip) {
  const int size = strip.height();
  Image out(size, kCubeFaces * size);
  for (int face = 0; face < kCubeFaces; ++face)
    for (int j = 0; j < size; ++j)
      std::copy_n(strip.row(j) + 3 * face * size, 3 * size, out.row(face * size + j));
  return out;
}

std::vector<uint8_t> encode_ktx2(const PrefilteredChain& chain, const PrefilterRequest& request) {
  std::map<std::string, std::string> metadata;
  for (const auto& [key, text] : prefilter_conventions(request)) metadata["lightprobe." + key] = text;
  if (request.params.projection != Projection::Cube)
    return write_ktx2(chain.levels, request.precision, metadata);
  std::vector<Image> levels;
  for (const Image& strip : chain.levels) levels.push_back(stacked_faces(strip));
  return write_ktx2_cube(levels, request.precision, metadata);
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

std::vector<std::pair<std::string, std::string>> prefilter_conventions(const PrefilterRequest& request) {
  const Projection projection = request.params.projection;
  std::vector<std::pair<std::string, std::string>> conventions = {
      {"projection", projection_convention(projection)},
      {"frame", "right-handed, z up: direction = (sin theta cos phi, sin theta sin phi, cos theta)"},
      {"roughness", fmt::format("perceptual, GGX alpha = roughness^2 (the brdf-lut's): {}",
                                level_roughness_formula(request.params.level_roughness))},
      {"lobe",
       "GGX (Trowbridge-Reitz) with the split-sum assumption N = V = R: sum L(l) n.l / sum n.l over l = "
       "reflect(n, h), h ~ D(h) n.h, by filtered importance sampling (Krivanek and Colbert 2008), at each "
       "texel's own direction"},
      {"level0", "the map resampled to the base size, each texel the solid-angle mean it covers"},
  };
  if (projection == Projection::Cube || projection == Projection::Cross)
    conventions.emplace_back("cube_faces", cube_faces_convention());
  return conventions;
}

int64_t prefilter_file_bytes(const PrefilterRequest& request, const std::string& name) {
  const size_t index = file_index(request, name);
  const auto& p = request.params;
  if (request.format == PrefilterFormat::Exr) {
    const ImageShape s = prefilter_level_shape(p, int(index));
    return encode_bytes(ImageFormat::Exr, s.width, s.height);
  }
  // The texels at 16 bytes (RGBA float), the header and the metadata; a cube map's faces restacked too.
  const int64_t restacked = p.projection == Projection::Cube ? prefiltered_chain_bytes(p) : 0;
  return prefiltered_chain_bytes(p) * 16 / 12 + restacked + (1 << 16);
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
  return encode_ktx2(chain, request);
}

}  // namespace lp::api
