#pragma once
// Image files as textures: PNG and JPEG through stb_image, OpenEXR, Radiance HDR and PFM through the
// engine's readers. Colour textures (base colour, emissive) are stored sRGB-encoded in 8- and 16-bit
// files and decoded to linear; data textures (normals, metallic-roughness) are used as stored. Float
// formats are linear already and read as they are in both cases.
#include <array>
#include <cstdint>
#include <span>
#include <string>

#include "engine/core/enum_table.hpp"
#include "engine/image/image_io.hpp"
#include "engine/texture/texture.hpp"

namespace lp {

enum class ColorSpace { Srgb, Linear };

constexpr auto enum_entries(ColorSpace) {
  return std::to_array<EnumEntry<ColorSpace>>({{ColorSpace::Srgb, "srgb"}, {ColorSpace::Linear, "linear"}});
}

// The size is checked against `limits` (and limits.before_allocation called) before any pixel is
// decoded. Throws lp::Error: Unsupported (not one of the formats), Corrupt, TooLarge; `name` appears in
// messages.
Texture decode_texture(std::span<const uint8_t> bytes, ColorSpace space, const ImageLimits& limits,
                       const std::string& name);

// The most memory decode_texture holds at once for the width x height image in `bytes` (the texture
// with its mip levels, and the decoder's own buffer), from the file's header; 0 when the header cannot
// be read (decoding then fails before it allocates).
int64_t texture_decode_bytes(std::span<const uint8_t> bytes, int64_t width, int64_t height);

}  // namespace lp
