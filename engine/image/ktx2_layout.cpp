#include "engine/image/ktx2_layout.hpp"

#include <bit>

namespace lp::ktx2 {
namespace {

constexpr uint32_t kVersionNumber = 2;
constexpr uint32_t kColorModelRgbsda = 1, kColorModelAstc = 162, kPrimariesBt709 = 1, kTransferLinear = 1;
constexpr uint32_t kQualifierFloat = 0x80, kQualifierSigned = 0x40;
constexpr uint32_t kChannelIds[kChannels] = {0, 1, 2, 15};
constexpr uint32_t kChannelAstcData = 0;
constexpr uint32_t kBlockHeaderWords = 6, kSampleWords = 4;

}  // namespace

std::vector<uint32_t> data_format_descriptor(PixelPrecision p) {
  const uint32_t bits = 8 * component_bytes(p);
  const uint32_t block_bytes = 4 * (kBlockHeaderWords + kChannels * kSampleWords);
  std::vector<uint32_t> words = {
      4 + block_bytes,                     // dfdTotalSize
      0,                                   // vendorId 0 (Khronos), descriptorType 0 (basic)
      kVersionNumber | block_bytes << 16,  // versionNumber, descriptorBlockSize
      kColorModelRgbsda | kPrimariesBt709 << 8 | kTransferLinear << 16,  // flags 0: straight alpha
      0,                                         // texelBlockDimension0..3: 1 x 1 x 1 x 1
      uint32_t(kChannels) * component_bytes(p),  // bytesPlane0; planes 1..3 empty
      0,                                         // bytesPlane4..7
  };
  for (int c = 0; c < kChannels; ++c) {
    const uint32_t channel_type = kChannelIds[c] | kQualifierFloat | kQualifierSigned;
    words.push_back(uint32_t(c) * bits | (bits - 1) << 16 | channel_type << 24);  // offset, length - 1
    words.push_back(0);                                                           // sample position
    words.push_back(std::bit_cast<uint32_t>(-1.0f));                              // sampleLower
    words.push_back(std::bit_cast<uint32_t>(1.0f));                               // sampleUpper
  }
  return words;
}

std::vector<uint32_t> astc_4x4_sfloat_descriptor() {
  const uint32_t block_bytes = 4 * (kBlockHeaderWords + kSampleWords);
  const uint32_t block_edge = 4, bits = 128;
  return {
      4 + block_bytes,
      0,
      kVersionNumber | block_bytes << 16,
      kColorModelAstc | kPrimariesBt709 << 8 | kTransferLinear << 16,
      (block_edge - 1) | (block_edge - 1) << 8,  // texelBlockDimension0..3: 4 x 4 (x 1 x 1)
      bits / 8,                                  // bytesPlane0
      0,
      (bits - 1) << 16 | (kChannelAstcData | kQualifierFloat | kQualifierSigned) << 24,  // bit offset 0
      0,
      std::bit_cast<uint32_t>(-1.0f),
      std::bit_cast<uint32_t>(1.0f),
  };
}

}  // namespace lp::ktx2
