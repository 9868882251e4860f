// ASTC HDR 4x4 through libastcenc: real maps compressed and decoded again stay within a stated error
// (log-space error of each pixel, relative RMS), constant blocks keep their value to half precision over a
// wide range, edge blocks of sizes that are not multiples of 4, and the KTX 2.0 cube of ASTC blocks read
// field by field against the KTX 2.0 specification (header, level index, alignment, the Data Format
// Descriptor of ASTC_4x4_SFLOAT) with its levels decoded and compared with the source.
#include "engine/image/astc.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstring>

#include "engine/core/error.hpp"
#include "engine/image/image_io.hpp"
#include "engine/image/ktx2.hpp"
#include "support/test_data.hpp"

namespace lp {
namespace {

struct Errors {
  double mean_log2 = 0;  // mean over channels of |log2((decoded + e) / (source + e))|
  double psnr_db = 0;    // 10 log10(peak^2 / mean squared error), peak the source's largest value
};

// e = 1e-3 of the mean keeps the log error of near-black pixels from dominating.
Errors compare(const Image& decoded, const Image& source) {
  const auto d = decoded.data(), s = source.data();
  double mean = 0;
  for (const float v : s) mean += v;
  const double e = 1e-3 * mean / double(s.size()) + 1e-12;
  Errors out;
  double diff2 = 0, peak = 0;
  for (size_t i = 0; i < s.size(); ++i) {
    out.mean_log2 += std::abs(std::log2((d[i] + e) / (s[i] + e)));
    diff2 += (d[i] - s[i]) * (d[i] - s[i]);
    peak = std::max(peak, double(s[i]));
  }
  out.mean_log2 /= double(s.size());
  out.psnr_db = 10 * std::log10(peak * peak * double(s.size()) / diff2);
  return out;
}

Image round_trip(const Image& image, float quality = 60.0f) {
  AstcHdrEncoder encoder({quality, 2});
  const std::vector<uint8_t> blocks = encoder.compress(image);
  EXPECT_EQ(blocks.size(), astc_bytes(image.width(), image.height()));
  return decompress_astc_hdr(blocks, image.width(), image.height());
}

TEST(Astc, BlockBytesCoverEdges) {
  EXPECT_EQ(astc_bytes(256, 128), size_t(64 * 32 * 16));
  EXPECT_EQ(astc_bytes(1, 1), size_t(16));
  EXPECT_EQ(astc_bytes(5, 3), size_t(2 * 1 * 16));
}

// Every real map (4 decades and more of radiance, a sun in sunrise.exr; reduced to 256x128, so detail
// fills every block) at the medium preset. Measured: PSNR to the peak 49.5 dB (courtyard) to 65.6 dB
// (city), as Debian's `astcenc -th ... 4x4 -medium` reports for the same files (49.7 to 65.6 dB); mean
// log2 error 0.015 (city) to 0.081 (forest's foliage, 5.8% a channel). Bounds: 2 dB under the worst PSNR,
// the worst log2 error plus a quarter.
TEST(Astc, RealMapsStayWithinStatedError) {
  for (const std::string& file : test::real_envmap_files()) {
    if (!file.ends_with(".exr")) continue;
    const Image source = read_image_file(test::envmap_path(file)).image;
    const Errors errors = compare(round_trip(source), source);
    SCOPED_TRACE(file);
    EXPECT_GT(errors.psnr_db, 47.5);
    EXPECT_LT(errors.mean_log2, 0.1);
  }
}

// A constant block is stored as four FP16 values: each level comes back to half precision (2^-11).
TEST(Astc, ConstantImagesKeepTheirValueOverTheHdrRange) {
  for (const float value : {1e-3f, 0.5f, 1.0f, 37.0f, 6.0e4f}) {
    Image image(8, 8);
    for (int y = 0; y < 8; ++y)
      for (int x = 0; x < 8; ++x) image.set(x, y, {value, value * 0.5f, value * 0.25f});
    const Image decoded = round_trip(image);
    for (int y = 0; y < 8; ++y)
      for (int x = 0; x < 8; ++x) {
        EXPECT_NEAR(decoded.at(x, y).x, value, value * 1e-3) << value;
        EXPECT_NEAR(decoded.at(x, y).z, value * 0.25f, value * 1e-3) << value;
      }
  }
}

TEST(Astc, SizesThatAreNotMultiplesOfTheBlockDecodeToTheirSize) {
  for (const auto& [w, h] : {std::pair{1, 1}, {2, 2}, {5, 3}, {7, 9}}) {
    Image image(w, h);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) image.set(x, y, {float(x + 1), float(y + 1), 2.0f});
    const Image decoded = round_trip(image);
    ASSERT_EQ(decoded.width(), w);
    ASSERT_EQ(decoded.height(), h);
    EXPECT_GT(compare(decoded, image).psnr_db, 35.0) << w << "x" << h;  // measured 39-41 dB
  }
}

TEST(Astc, RefusesBlocksOfTheWrongSize) {
  const std::vector<uint8_t> blocks(32);
  EXPECT_THROW(decompress_astc_hdr(blocks, 4, 4), Error);
  EXPECT_THROW(decompress_astc_hdr(blocks, 0, 4), Error);
}

template <class T>
T at(const std::vector<uint8_t>& bytes, size_t offset) {
  T v;
  std::memcpy(&v, bytes.data() + offset, sizeof(T));
  return v;
}

// A cube chain of size x size faces down to 1 x 1: face f smooth colour gradients scaled by 4^f (a
// decade and more between faces, so that a face in the wrong place shows).
std::vector<Image> cube_chain(int size) {
  std::vector<Image> levels;
  for (int n = size; n >= 1; n /= 2) {
    Image level(n, 6 * n);
    for (int f = 0; f < 6; ++f)
      for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
          const float u = (float(x) + 0.5f) / float(n), v = (float(y) + 0.5f) / float(n);
          const float scale = std::pow(4.0f, float(f));
          level.set(x, f * n + y, {scale * (0.2f + u), scale * (0.2f + v), scale * 0.3f});
        }
    levels.push_back(level);
  }
  return levels;
}

TEST(AstcKtx2, CubeFileIsLaidOutAsTheSpecificationSays) {
  const std::vector<Image> levels = cube_chain(16);
  const std::vector<uint8_t> file =
      write_ktx2_astc_cube(levels, {60.0f, 2}, {{"lightprobe.map", "gradients"}});
  const uint8_t identifier[12] = {0xAB, 0x4B, 0x54, 0x58, 0x20, 0x32, 0x30, 0xBB, 0x0D, 0x0A, 0x1A, 0x0A};
  ASSERT_EQ(std::memcmp(file.data(), identifier, 12), 0);
  EXPECT_EQ(at<uint32_t>(file, 12), 1000066000u);  // VK_FORMAT_ASTC_4x4_SFLOAT_BLOCK
  EXPECT_EQ(at<uint32_t>(file, 16), 1u);           // typeSize of a block-compressed format
  EXPECT_EQ(at<uint32_t>(file, 20), 16u);          // pixelWidth
  EXPECT_EQ(at<uint32_t>(file, 24), 16u);          // pixelHeight
  EXPECT_EQ(at<uint32_t>(file, 28), 0u);           // pixelDepth
  EXPECT_EQ(at<uint32_t>(file, 32), 0u);           // layerCount
  EXPECT_EQ(at<uint32_t>(file, 36), 6u);           // faceCount
  EXPECT_EQ(at<uint32_t>(file, 40), 5u);           // levelCount: 16, 8, 4, 2, 1
  EXPECT_EQ(at<uint32_t>(file, 44), 0u);           // supercompressionScheme

  // The Data Format Descriptor: one basic block with one 128-bit ASTC sample (Khronos Data Format
  // Specification 1.3, section "ASTC"; KTX-Software writes the same for this vkFormat).
  const uint32_t dfd_at = at<uint32_t>(file, 48), dfd_bytes = at<uint32_t>(file, 52);
  ASSERT_EQ(dfd_bytes, 44u);
  const uint32_t expected[11] = {44,
                                 0,                         // Khronos, basic descriptor
                                 2 | 40u << 16,             // version 2, block of 40 bytes
                                 162 | 1 << 8 | 1 << 16,    // KHR_DF_MODEL_ASTC, BT.709, linear, straight
                                 3 | 3 << 8,                // 4 x 4 texel blocks
                                 16,                        // bytesPlane0
                                 0,                         // bytesPlane4..7
                                 127u << 16 | 0xC0u << 24,  // 128 bits at 0, ASTC_DATA, float | signed
                                 0,                         // sample position
                                 std::bit_cast<uint32_t>(-1.0f),
                                 std::bit_cast<uint32_t>(1.0f)};
  for (uint32_t w = 0; w < 11; ++w)
    EXPECT_EQ(at<uint32_t>(file, dfd_at + 4 * w), expected[w]) << "word " << w;

  // Levels from the smallest, on 16-byte boundaries, each its six faces of blocks in the order +X, -X, +Y,
  // -Y, +Z, -Z; decoded each is its source face (measured: PSNR 34-47 dB, mean log2 error 0.01-0.04; a
  // face out of place is off by 2 or more).
  uint64_t previous_end = file.size() + 1;
  for (uint32_t p = 0; p < 5; ++p) {
    const size_t entry = 80 + 24 * p;
    const auto offset = at<uint64_t>(file, entry), length = at<uint64_t>(file, entry + 8);
    const int n = 16 >> p;
    EXPECT_EQ(offset % 16, 0u) << p;
    EXPECT_EQ(length, 6 * astc_bytes(n, n)) << p;
    EXPECT_EQ(at<uint64_t>(file, entry + 16), length) << p;  // uncompressedByteLength
    if (p > 0) {
      EXPECT_LE(offset + length, previous_end) << p;
    }
    previous_end = offset;
    ASSERT_LE(offset + length, file.size());
    for (int f = 0; f < 6; ++f) {
      const size_t face_bytes = astc_bytes(n, n);
      const Image face = decompress_astc_hdr(
          std::span<const uint8_t>(file.data() + offset + size_t(f) * face_bytes, face_bytes), n, n);
      const Errors errors = compare(face, ktx2_cube_face(levels[p], f));
      EXPECT_GT(errors.psnr_db, 30.0) << p << " " << f;
      EXPECT_LT(errors.mean_log2, 0.06) << p << " " << f;
    }
  }
  EXPECT_EQ(at<uint64_t>(file, 80) + at<uint64_t>(file, 88), file.size());  // level 0 ends the file
}

TEST(AstcKtx2, TheFloatReaderRefusesItCleanly) {
  const std::vector<uint8_t> file = write_ktx2_astc_cube(cube_chain(4), {10.0f, 1});
  try {
    read_ktx2(file, {});
    FAIL() << "read";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::Unsupported);
  }
}

TEST(AstcKtx2, RefusesLevelsThatAreNotACubeChain) {
  std::vector<Image> levels = cube_chain(8);
  levels[1] = Image(4, 4);
  EXPECT_THROW(write_ktx2_astc_cube(levels, {}), Error);
}

}  // namespace
}  // namespace lp
