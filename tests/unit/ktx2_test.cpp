// KTX 2.0 files: the bytes write_ktx2 lays out, read field by field against the specification (header,
// index, level index from the largest level with the data from the smallest, alignment, the Data Format
// Descriptor of RGBA16F, sorted metadata), the round trip through read_ktx2 of 2D textures and cube
// maps, and refusals.
#include "engine/image/ktx2.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cstring>

#include "engine/core/error.hpp"
#include "support/test_data.hpp"

namespace lp {
namespace {

template <class T>
T at(const std::vector<uint8_t>& bytes, size_t offset) {
  T v;
  std::memcpy(&v, bytes.data() + offset, sizeof(T));
  return v;
}

template <class T>
std::vector<uint8_t> with(std::vector<uint8_t> bytes, size_t offset, T value) {
  std::memcpy(bytes.data() + offset, &value, sizeof(T));
  return bytes;
}

// A mip chain of w x h: level p holds value (p + 1) * (x + 2 y + 1) / 64 in red, twice it in green, -it in
// blue.
std::vector<Image> chain(int w, int h, int levels) {
  std::vector<Image> out;
  for (int p = 0; p < levels; ++p) {
    Image image(std::max(1, w >> p), std::max(1, h >> p));
    for (int y = 0; y < image.height(); ++y)
      for (int x = 0; x < image.width(); ++x) {
        const float v = float(p + 1) * float(x + 2 * y + 1) / 64.0f;
        image.set(x, y, {v, 2 * v, -v});
      }
    out.push_back(std::move(image));
  }
  return out;
}

TEST(Ktx2, HeaderIndexAndLevelsAreWhereTheSpecificationPutsThem) {
  const auto levels = chain(16, 8, 4);
  const auto bytes = write_ktx2(levels, PixelPrecision::Half);
  const uint8_t identifier[12] = {0xAB, 'K', 'T', 'X', ' ', '2', '0', 0xBB, '\r', '\n', 0x1A, '\n'};
  ASSERT_GT(bytes.size(), 80u);
  EXPECT_EQ(std::memcmp(bytes.data(), identifier, 12), 0);
  EXPECT_EQ(at<uint32_t>(bytes, 12), 97u);  // VK_FORMAT_R16G16B16A16_SFLOAT
  EXPECT_EQ(at<uint32_t>(bytes, 16), 2u);   // typeSize
  EXPECT_EQ(at<uint32_t>(bytes, 20), 16u);  // pixelWidth
  EXPECT_EQ(at<uint32_t>(bytes, 24), 8u);   // pixelHeight
  EXPECT_EQ(at<uint32_t>(bytes, 28), 0u);   // pixelDepth
  EXPECT_EQ(at<uint32_t>(bytes, 32), 0u);   // layerCount
  EXPECT_EQ(at<uint32_t>(bytes, 36), 1u);   // faceCount
  EXPECT_EQ(at<uint32_t>(bytes, 40), 4u);   // levelCount
  EXPECT_EQ(at<uint32_t>(bytes, 44), 0u);   // supercompressionScheme
  const uint32_t dfd_offset = at<uint32_t>(bytes, 48), dfd_length = at<uint32_t>(bytes, 52);
  const uint32_t kvd_offset = at<uint32_t>(bytes, 56), kvd_length = at<uint32_t>(bytes, 60);
  EXPECT_EQ(at<uint64_t>(bytes, 64), 0u);  // sgdByteOffset
  EXPECT_EQ(at<uint64_t>(bytes, 72), 0u);  // sgdByteLength
  EXPECT_EQ(dfd_offset, 80u + 4 * 24);     // right after the level index
  EXPECT_EQ(kvd_offset, dfd_offset + dfd_length);

  // The level index starts with level 0; the data starts with the smallest level, 8-byte aligned.
  uint64_t previous_offset = bytes.size();
  for (size_t p = 0; p < 4; ++p) {
    const uint64_t offset = at<uint64_t>(bytes, 80 + 24 * p), length = at<uint64_t>(bytes, 88 + 24 * p);
    EXPECT_EQ(length, uint64_t(levels[p].pixel_count()) * 8) << p;
    EXPECT_EQ(at<uint64_t>(bytes, 96 + 24 * p), length) << p;
    EXPECT_EQ(offset % 8, 0u) << p;
    EXPECT_LT(offset, previous_offset) << p;
    EXPECT_GE(offset, uint64_t(kvd_offset) + kvd_length);
    previous_offset = offset;
  }
  EXPECT_EQ(at<uint64_t>(bytes, 80) + at<uint64_t>(bytes, 88), bytes.size());  // level 0 ends the file

  // Level 0's first texel is (1/64, 2/64, -1/64, 1) in halves, little-endian.
  const uint64_t level0 = at<uint64_t>(bytes, 80);
  EXPECT_EQ(at<uint16_t>(bytes, level0), 0x2400);      // 2^-6
  EXPECT_EQ(at<uint16_t>(bytes, level0 + 2), 0x2800);  // 2^-5
  EXPECT_EQ(at<uint16_t>(bytes, level0 + 4), 0xA400);  // -2^-6
  EXPECT_EQ(at<uint16_t>(bytes, level0 + 6), 0x3C00);  // 1
}

TEST(Ktx2, TheDataFormatDescriptorIsLinearRgba16f) {
  const auto bytes = write_ktx2(chain(4, 2, 1), PixelPrecision::Half);
  const uint32_t dfd = at<uint32_t>(bytes, 48);
  const auto word = [&](size_t i) { return at<uint32_t>(bytes, dfd + 4 * i); };
  EXPECT_EQ(word(0), 92u);                      // dfdTotalSize: 4 + 24 + 4 * 16
  EXPECT_EQ(word(1), 0u);                       // vendorId Khronos, descriptorType basic
  EXPECT_EQ(word(2), 2u | 88u << 16);           // versionNumber 2, descriptorBlockSize 88
  EXPECT_EQ(word(3), 1u | 1u << 8 | 1u << 16);  // RGBSDA, BT709, linear, straight alpha
  EXPECT_EQ(word(4), 0u);                       // 1 x 1 x 1 x 1 texel blocks
  EXPECT_EQ(word(5), 8u);                       // bytesPlane0
  EXPECT_EQ(word(6), 0u);
  const uint32_t channels[4] = {0, 1, 2, 15};
  for (uint32_t c = 0; c < 4; ++c) {
    const size_t s = 7 + 4 * c;
    EXPECT_EQ(word(s) & 0xffff, 16 * c) << c;                  // bitOffset
    EXPECT_EQ((word(s) >> 16) & 0xff, 15u) << c;               // bitLength - 1
    EXPECT_EQ(word(s) >> 24, channels[c] | 0x80 | 0x40) << c;  // channel, FLOAT | SIGNED
    EXPECT_EQ(word(s + 1), 0u);
    EXPECT_EQ(word(s + 2), std::bit_cast<uint32_t>(-1.0f));
    EXPECT_EQ(word(s + 3), std::bit_cast<uint32_t>(1.0f));
  }
}

TEST(Ktx2, RoundTripsHalfAndFloatWithTheMetadata) {
  const auto levels = chain(32, 16, 5);
  for (const auto precision : {PixelPrecision::Half, PixelPrecision::Float}) {
    const auto bytes = write_ktx2(levels, precision, {{"lightprobe.roughness", "i / (n - 1)"}});
    const Ktx2Texture t = read_ktx2(bytes, {});
    EXPECT_EQ(t.precision, precision);
    EXPECT_EQ(t.vk_format, precision == PixelPrecision::Half ? 97u : 109u);
    EXPECT_EQ(t.type_size, precision == PixelPrecision::Half ? 2u : 4u);
    ASSERT_EQ(t.levels.size(), levels.size());
    for (size_t p = 0; p < levels.size(); ++p) {
      ASSERT_EQ(t.levels[p].width(), levels[p].width());
      ASSERT_EQ(t.levels[p].height(), levels[p].height());
      for (size_t i = 0; i < levels[p].data().size(); ++i) {
        const float want = levels[p].data()[i];
        // A half keeps 11 significant bits: within 2^-11 relative.
        const float tolerance = precision == PixelPrecision::Half ? std::abs(want) * 0x1p-11f : 0.0f;
        EXPECT_NEAR(t.levels[p].data()[i], want, tolerance);
      }
    }
    EXPECT_EQ(t.metadata.at("KTXorientation"), "rd");
    EXPECT_EQ(t.metadata.at("KTXwriter").rfind("Lightprobe ", 0), 0u);
    EXPECT_EQ(t.metadata.at("lightprobe.roughness"), "i / (n - 1)");
  }
}

TEST(Ktx2, MetadataIsSortedByKeyAndPadded) {
  const auto bytes = write_ktx2(chain(4, 2, 1), PixelPrecision::Half, {{"b", "x"}, {"a", "yy"}});
  const uint32_t kvd = at<uint32_t>(bytes, 56), kvd_length = at<uint32_t>(bytes, 60);
  std::vector<std::string> keys;
  for (size_t p = kvd; p < kvd + kvd_length;) {
    const uint32_t length = at<uint32_t>(bytes, p);
    keys.emplace_back(reinterpret_cast<const char*>(bytes.data() + p + 4));
    p += 4 + (length + 3) / 4 * 4;
  }
  EXPECT_EQ(keys, (std::vector<std::string>{"KTXorientation", "KTXwriter", "a", "b"}));
  EXPECT_EQ(kvd_length % 4, 0u);
}

TEST(Ktx2, WriterRefusesWhatIsNotAMipChainAndReservedKeys) {
  auto bad = chain(16, 8, 3);
  bad[2] = Image(3, 1);
  EXPECT_THROW(write_ktx2(bad, PixelPrecision::Half), Error);
  EXPECT_THROW(write_ktx2(chain(4, 2, 4), PixelPrecision::Half), Error);  // 4 x 2 has 3 levels
  EXPECT_THROW(write_ktx2({}, PixelPrecision::Half), Error);
  EXPECT_THROW(write_ktx2(chain(4, 2, 1), PixelPrecision::Half, {{"KTXswizzle", "rgba"}}), Error);
}

// A file of the fuzz corpus written by a separate writer (a short Python script following the
// specification): level p, texel i (row-major) holds (p + 1)(i + 1) / 16 and twice and minus that.
TEST(Ktx2, ReadsAFileOfAnotherWriter) {
  const Ktx2Texture t =
      read_ktx2(test::read_bytes(test::fuzz_corpus_path("ktx2", "half_16x8_5_levels.ktx2")), {});
  ASSERT_EQ(t.levels.size(), 5u);
  for (size_t p = 0; p < t.levels.size(); ++p) {
    const Image& level = t.levels[p];
    ASSERT_EQ(level.width(), 16 >> p);
    ASSERT_EQ(level.height(), std::max(1, 8 >> int(p)));
    for (int i = 0; i < int(level.pixel_count()); ++i) {
      const float v = float(p + 1) * float(i + 1) / 16.0f;
      const Rgb got = level.at(i % level.width(), i / level.width());
      EXPECT_NEAR(got.x, v, v * 0x1p-11f);
      EXPECT_NEAR(got.y, 2 * v, v * 0x1p-10f);
      EXPECT_NEAR(got.z, -v, v * 0x1p-11f);
    }
  }
  EXPECT_EQ(t.metadata.at("lightprobe.roughness"), "i / (n - 1)");
  EXPECT_THROW(read_ktx2(test::read_bytes(test::fuzz_corpus_path("ktx2", "cube_face_count.ktx2")), {}),
               Error);
}

// Six faces of size x size, face f of level p holding (f + 1) (p + 1) (x + 2 y + 1) / 64: a cube map's
// levels, the faces stacked.
std::vector<Image> cube_chain(int size, int levels) {
  std::vector<Image> out;
  for (int p = 0; p < levels; ++p) {
    const int n = size >> p;
    Image image(n, 6 * n);
    for (int f = 0; f < 6; ++f)
      for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
          const float v = float((f + 1) * (p + 1) * (x + 2 * y + 1)) / 64.0f;
          image.set(x, f * n + y, {v, 2 * v, -v});
        }
    out.push_back(std::move(image));
  }
  return out;
}

TEST(Ktx2, ACubeMapHasSixFacesAfterEachOtherInEveryLevel) {
  const auto levels = cube_chain(8, 4);
  const auto bytes = write_ktx2_cube(levels, PixelPrecision::Float, {{"lightprobe.faces", "px nx"}});
  EXPECT_EQ(at<uint32_t>(bytes, 20), 8u);  // pixelWidth: a face
  EXPECT_EQ(at<uint32_t>(bytes, 24), 8u);  // pixelHeight
  EXPECT_EQ(at<uint32_t>(bytes, 36), 6u);  // faceCount
  EXPECT_EQ(at<uint32_t>(bytes, 40), 4u);  // levelCount
  // Level 1: 6 faces of 4 x 4 texels of 16 bytes, face 2 (+Y) starting 2 faces in.
  const auto level1 = at<uint64_t>(bytes, 80 + 24);
  EXPECT_EQ(at<uint64_t>(bytes, 80 + 24 + 8), 6u * 4 * 4 * 16);
  EXPECT_EQ(at<float>(bytes, size_t(level1) + 2 * 4 * 4 * 16), 3.0f * 2 * 1 / 64);

  const Ktx2Texture t = read_ktx2(bytes, {});
  EXPECT_EQ(t.faces, 6u);
  ASSERT_EQ(t.levels.size(), 4u);
  for (size_t p = 0; p < t.levels.size(); ++p) {
    ASSERT_EQ(t.levels[p].width(), 8 >> p);
    ASSERT_EQ(t.levels[p].height(), 6 * (8 >> p));
    EXPECT_EQ(t.levels[p].data().size(), levels[p].data().size());
    EXPECT_TRUE(std::equal(t.levels[p].data().begin(), t.levels[p].data().end(), levels[p].data().begin()));
  }
  const Image nz = ktx2_cube_face(t.levels[0], 5);
  EXPECT_EQ(nz.width(), 8);
  EXPECT_EQ(nz.at(1, 2).x, 6.0f * 6 / 64);
  EXPECT_EQ(t.metadata.at("lightprobe.faces"), "px nx");
  EXPECT_EQ(read_ktx2(write_ktx2(chain(4, 2, 1), PixelPrecision::Half), {}).faces, 1u);
}

// A cube map of the fuzz corpus written by a short Python script following the specification: face f of
// level p holds the values of cube_chain.
TEST(Ktx2, ReadsACubeMapOfAnotherWriter) {
  const Ktx2Texture t =
      read_ktx2(test::read_bytes(test::fuzz_corpus_path("ktx2", "cube_half_4x4_3_levels.ktx2")), {});
  EXPECT_EQ(t.faces, 6u);
  const auto want = cube_chain(4, 3);
  ASSERT_EQ(t.levels.size(), want.size());
  for (size_t p = 0; p < want.size(); ++p) {
    ASSERT_EQ(t.levels[p].width(), want[p].width());
    ASSERT_EQ(t.levels[p].height(), want[p].height());
    for (size_t i = 0; i < want[p].data().size(); ++i)
      EXPECT_NEAR(t.levels[p].data()[i], want[p].data()[i], std::abs(want[p].data()[i]) * 0x1p-10f);
  }
}

TEST(Ktx2, CubeMapsAreSquareFacesInAMipChain) {
  EXPECT_THROW(write_ktx2_cube(chain(8, 8, 1), PixelPrecision::Half), Error);  // not six faces
  auto levels = cube_chain(8, 2);
  levels[1] = Image(4, 4);
  EXPECT_THROW(write_ktx2_cube(levels, PixelPrecision::Half), Error);
  EXPECT_THROW(write_ktx2_cube(cube_chain(8, 5), PixelPrecision::Half), Error);  // 8 x 8 has 4 levels
  EXPECT_THROW(ktx2_cube_face(Image(8, 8), 0), Error);
  ImageLimits small;
  small.max_pixels = 8 * 8 * 6 - 1;  // the six faces of level 0 count
  EXPECT_THROW(read_ktx2(write_ktx2_cube(cube_chain(8, 1), PixelPrecision::Half), small), Error);
}

void expect_refused(const std::vector<uint8_t>& bytes, ErrorKind kind) {
  try {
    read_ktx2(bytes, {});
    ADD_FAILURE() << "read";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), kind) << e.what();
  }
}

TEST(Ktx2, ReaderRefusesBrokenFiles) {
  const auto good = write_ktx2(chain(16, 8, 3), PixelPrecision::Half);
  expect_refused({good.begin(), good.begin() + 40}, ErrorKind::Corrupt);
  expect_refused({good.begin(), good.end() - 1}, ErrorKind::Corrupt);
  expect_refused(with<uint8_t>(good, 5, '1'), ErrorKind::Unsupported);           // "KTX 10"
  expect_refused(with<uint32_t>(good, 12, 37), ErrorKind::Unsupported);          // VK_FORMAT_R8G8B8A8_UNORM
  expect_refused(with<uint32_t>(good, 36, 2), ErrorKind::Unsupported);           // two faces
  expect_refused(with<uint32_t>(good, 36, 6), ErrorKind::Corrupt);               // a cube of 16 x 8 faces
  expect_refused(with<uint32_t>(good, 44, 2), ErrorKind::Unsupported);           // Zstandard
  expect_refused(with<uint32_t>(good, 40, 6), ErrorKind::Corrupt);               // a 16 x 8 base has 5 levels
  expect_refused(with<uint64_t>(good, 80, good.size()), ErrorKind::Corrupt);     // level 0 past the end
  expect_refused(with<uint64_t>(good, 88, 16 * 8 * 8 - 8), ErrorKind::Corrupt);  // a texel short
  expect_refused(with<uint32_t>(good, 60, at<uint32_t>(good, 60) + 4), ErrorKind::Corrupt);  // metadata
  ImageLimits small;
  small.max_pixels = 100;
  EXPECT_THROW(read_ktx2(good, small), Error);
}

}  // namespace
}  // namespace lp
