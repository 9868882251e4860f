#pragma once
// The parts of a KTX 2.0 file that its writer and reader share (KTX File Format Specification 2.0 and
// the Khronos Data Format Specification 1.3): the identifier, the sizes of the fixed sections, the
// formats written and their Data Format Descriptor.
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "engine/image/image_io.hpp"

namespace lp::ktx2 {

inline constexpr std::array<uint8_t, 12> kIdentifier = {0xAB, 0x4B, 0x54, 0x58, 0x20, 0x32,
                                                        0x30, 0xBB, 0x0D, 0x0A, 0x1A, 0x0A};
// The identifier and nine UInt32 header fields, then the index (four UInt32 and two UInt64).
inline constexpr size_t kHeaderEnd = 12 + 9 * 4;
inline constexpr size_t kIndexEnd = kHeaderEnd + 4 * 4 + 2 * 8;
inline constexpr size_t kLevelIndexEntryBytes = 3 * 8;  // byteOffset, byteLength, uncompressedByteLength
inline constexpr int kChannels = 4;
inline constexpr int kCubeFaces = 6;

inline constexpr uint32_t kVkFormatRgba16Sfloat = 97;           // VK_FORMAT_R16G16B16A16_SFLOAT
inline constexpr uint32_t kVkFormatRgba32Sfloat = 109;          // VK_FORMAT_R32G32B32A32_SFLOAT
inline constexpr uint32_t kVkFormatAstc4x4Sfloat = 1000066000;  // VK_FORMAT_ASTC_4x4_SFLOAT_BLOCK(_EXT)

inline uint32_t vk_format(PixelPrecision p) {
  return p == PixelPrecision::Half ? kVkFormatRgba16Sfloat : kVkFormatRgba32Sfloat;
}
inline uint32_t component_bytes(PixelPrecision p) {
  return p == PixelPrecision::Half ? 2 : 4;
}
inline uint32_t texel_bytes(PixelPrecision p) {
  return kChannels * component_bytes(p);
}
// Levels start on a multiple of lcm(texel block size, 4): the texel size itself, 8 or 16 bytes.
inline uint32_t level_alignment(PixelPrecision p) {
  return texel_bytes(p);
}

// dfdTotalSize and one basic descriptor block: colour model RGBSDA, BT.709 primaries, linear transfer,
// straight alpha, 1 x 1 texel blocks, and one sample per channel (R, G, B, A = 0, 1, 2, 15), each a
// signed float of its bits over [-1, 1] (the bounds of a float sample).
std::vector<uint32_t> data_format_descriptor(PixelPrecision p);
// The descriptor of ASTC 4x4 SFLOAT (as the KTX 2.0 specification and the Khronos Data Format
// Specification's ASTC section give it): colour model ASTC, BT.709 primaries, linear transfer, 4 x 4 texel
// blocks of 16 bytes, one sample of 128 bits of ASTC data, qualified signed float over [-1, 1].
std::vector<uint32_t> astc_4x4_sfloat_descriptor();

}  // namespace lp::ktx2
