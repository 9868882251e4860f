#pragma once
// KTX 1.1 (Khronos Texture, version 1) files of a cube map and its mip levels in GL_R11F_G11F_B10F, the
// container Filament loads an image-based light and a skybox from (Filament's Ktx1Bundle; its cmgen
// writes them). Little-endian; a level is its imageSize (the bytes of one face) and then its six faces
// in the order +X, -X, +Y, -Y, +Z, -Z, each face's rows from t = 0 (engine/projection/cube_face.hpp),
// 4 bytes a texel, so that no padding is ever needed.
#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "engine/image/image.hpp"
#include "engine/image/image_io.hpp"

namespace lp {

namespace ktx1 {
inline constexpr uint32_t kGlRgb = 0x1907;
inline constexpr uint32_t kGlR11fG11fB10f = 0x8C3A;
inline constexpr uint32_t kGlUnsignedInt10f11f11fRev = 0x8C3B;
inline constexpr uint32_t kEndianness = 0x04030201;
inline constexpr int kCubeFaces = 6;
}  // namespace ktx1

struct Ktx1Header {
  uint32_t gl_type = 0, gl_type_size = 0, gl_format = 0, gl_internal_format = 0, gl_base_internal_format = 0;
  uint32_t width = 0, height = 0, depth = 0, array_elements = 0, faces = 0, levels = 0;
};

struct Ktx1Texture {
  Ktx1Header header;
  std::vector<Image> levels;  // level 0 first, each its faces side by side (6N x N) in the file's order
  // The key/value data; a value that ends in NUL (a string) without it.
  std::map<std::string, std::string> metadata;
};

// A cube map: each level a strip of its six faces side by side (6N x N, Projection::Cube's layout),
// level p of faces max(1, N >> p), at most
// floor(log2(N)) + 1 levels. The header is the one Filament's cmgen writes and Filament's Ktx1Reader
// understands: glType and glInternalFormat GL_R11F_G11F_B10F (the reader maps only that glType to its
// UINT_10F_11F_11F_REV pixels; the KTX specification would have GL_UNSIGNED_INT_10F_11F_11F_REV),
// glTypeSize 1, glFormat GL_RGB, glBaseInternalFormat GL_R11F_G11F_B10F. `metadata` values are written as
// NUL-terminated strings, keys in their sorted order. Throws lp::Error(InvalidArgument) for levels that
// are not such a chain, or an empty key or one holding a NUL.
std::vector<uint8_t> write_ktx1_cube(std::span<const Image> levels,
                                     const std::map<std::string, std::string>& metadata = {});

// Reads a 2D texture or a cube map (no arrays, no volumes) in GL_R11F_G11F_B10F, with either glType.
// Throws lp::Error: Unsupported (not KTX 1.1, big-endian, or another format or kind of texture), Corrupt
// (sizes that disagree or leave the file), TooLarge (over `limits`).
Ktx1Texture read_ktx1(std::span<const uint8_t> bytes, const ImageLimits& limits);

}  // namespace lp
