#pragma once
// KTX 2.0 (Khronos Texture) files of one 2D texture or one cube map with its mip levels, uncompressed
// RGBA floats (or a cube map in ASTC HDR blocks):
// VK_FORMAT_R16G16B16A16_SFLOAT (half) or VK_FORMAT_R32G32B32A32_SFLOAT (float), alpha 1, linear,
// BT.709 primaries, no supercompression, orientation "rd" (row 0 at the top), and key/value metadata.
#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "engine/image/astc.hpp"
#include "engine/image/image.hpp"
#include "engine/image/image_io.hpp"

namespace lp {

// A cube map's level is one image of its six N x N faces one below the other (N x 6N), in the file's order
// of faces (+X, -X, +Y, -Y, +Z, -Z): the bytes of the faces follow each other in a level just so.
struct Ktx2Texture {
  uint32_t vk_format = 0;
  uint32_t type_size = 0;  // bytes of one component
  PixelPrecision precision = PixelPrecision::Half;
  uint32_t faces = 1;         // 6 for a cube map
  std::vector<Image> levels;  // RGB (alpha dropped), level 0 first; a cube map's faces stacked
  // The key/value data; a value that ends in NUL (a string) without it.
  std::map<std::string, std::string> metadata;
};

// `levels` are a mip chain: level p is max(1, w0 >> p) x max(1, h0 >> p), at most
// floor(log2(max(w0, h0))) + 1 of them. `metadata` is written after KTXorientation and KTXwriter, each
// value as a NUL-terminated string; its keys must not begin with "KTX" or "ktx" (reserved). Throws
// lp::Error(InvalidArgument) otherwise.
std::vector<uint8_t> write_ktx2(std::span<const Image> levels, PixelPrecision precision,
                                const std::map<std::string, std::string>& metadata = {});
// A cube map (faceCount 6): each level its faces stacked (N x 6N), the faces square and a mip chain of
// level 0's (at most floor(log2(N)) + 1 levels).
std::vector<uint8_t> write_ktx2_cube(std::span<const Image> levels, PixelPrecision precision,
                                     const std::map<std::string, std::string>& metadata = {});
// A cube map in VK_FORMAT_ASTC_4x4_SFLOAT_BLOCK (ASTC HDR, engine/image/astc.hpp), the same chain of
// levels as write_ktx2_cube's compressed face by face with `options`; read_ktx2 does not read it back.
std::vector<uint8_t> write_ktx2_astc_cube(std::span<const Image> levels, const AstcOptions& options,
                                          const std::map<std::string, std::string>& metadata = {});
// Face `face` of a cube map's level (N x 6N), N x N.
Image ktx2_cube_face(const Image& level, int face);

// Reads what write_ktx2 and write_ktx2_cube write (the two formats, 2D or a cube map, no
// supercompression, the same Data Format Descriptor) and refuses the rest. Throws lp::Error: Unsupported (not
// KTX 2.0, or another kind of texture), Corrupt (sizes and offsets that disagree or leave the file), TooLarge
// (over `limits`).
Ktx2Texture read_ktx2(std::span<const uint8_t> bytes, const ImageLimits& limits);

}  // namespace lp
