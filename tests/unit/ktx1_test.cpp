// KTX 1.1 files: the bytes write_ktx1_cube lays out, read field by field against the specification and
// against what Filament's cmgen writes (the header, NUL-terminated metadata with its padding, each
// level's imageSize of one face then the six faces), the round trip through read_ktx1, files written by
// Debian's cmgen 1.9.25 (tests/fuzz/corpus/ktx1), and refusals.
#include "engine/image/ktx1.hpp"

#include <gtest/gtest.h>

#include <cstring>

#include "engine/core/error.hpp"
#include "engine/image/packed_float.hpp"
#include "support/test_data.hpp"

namespace lp {
namespace {

uint32_t word(const std::vector<uint8_t>& bytes, size_t offset) {
  uint32_t v;
  std::memcpy(&v, bytes.data() + offset, 4);
  return v;
}

std::vector<uint8_t> with_word(std::vector<uint8_t> bytes, size_t offset, uint32_t value) {
  std::memcpy(bytes.data() + offset, &value, 4);
  return bytes;
}

// Face f of level p holds (f + 1, p + 1, x + 2 y) / 4 at texel (x, y): values R11F_G11F_B10F keeps exactly.
std::vector<Image> cube_chain(int size, int levels) {
  std::vector<Image> out;
  for (int p = 0; p < levels; ++p) {
    const int n = std::max(1, size >> p);
    Image image(6 * n, n);
    for (int f = 0; f < 6; ++f)
      for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x)
          image.set(f * n + x, y, {float(f + 1) / 4, float(p + 1) / 4, float(x + 2 * y) / 4});
    out.push_back(std::move(image));
  }
  return out;
}

TEST(Ktx1, HeaderMetadataAndLevelsAreWhereTheSpecificationPutsThem) {
  const auto bytes = write_ktx1_cube(cube_chain(8, 3), {{"sh", "1 2 3\n"}});
  const uint8_t identifier[12] = {0xAB, 'K', 'T', 'X', ' ', '1', '1', 0xBB, '\r', '\n', 0x1A, '\n'};
  ASSERT_GT(bytes.size(), 64u);
  EXPECT_EQ(std::memcmp(bytes.data(), identifier, 12), 0);
  EXPECT_EQ(word(bytes, 12), 0x04030201u);  // endianness
  EXPECT_EQ(word(bytes, 16), 0x8C3Au);      // glType as cmgen writes it
  EXPECT_EQ(word(bytes, 20), 1u);           // glTypeSize
  EXPECT_EQ(word(bytes, 24), 0x1907u);      // glFormat GL_RGB
  EXPECT_EQ(word(bytes, 28), 0x8C3Au);      // glInternalFormat GL_R11F_G11F_B10F
  EXPECT_EQ(word(bytes, 32), 0x8C3Au);      // glBaseInternalFormat
  EXPECT_EQ(word(bytes, 36), 8u);           // pixelWidth
  EXPECT_EQ(word(bytes, 40), 8u);           // pixelHeight
  EXPECT_EQ(word(bytes, 44), 0u);           // pixelDepth
  EXPECT_EQ(word(bytes, 48), 0u);           // numberOfArrayElements
  EXPECT_EQ(word(bytes, 52), 6u);           // numberOfFaces
  EXPECT_EQ(word(bytes, 56), 3u);           // numberOfMipmapLevels
  // "sh\0" + "1 2 3\n\0" = 10 bytes, padded to 12.
  EXPECT_EQ(word(bytes, 60), 16u);
  EXPECT_EQ(word(bytes, 64), 10u);
  EXPECT_EQ(std::memcmp(bytes.data() + 68, "sh\0001 2 3\n\0\0\0", 12), 0);
  // Level 0: imageSize of one 8 x 8 face, then the faces; texel (1, 2) of face 3 (-Y).
  EXPECT_EQ(word(bytes, 80), 8u * 8 * 4);
  EXPECT_EQ(word(bytes, 84 + (3 * 64 + 2 * 8 + 1) * 4), pack_r11g11b10f({1.0f, 0.25f, 5.0f / 4}));
  // Level 1 follows: 4 x 4 faces.
  const size_t level1 = 84 + 6 * 64 * 4;
  EXPECT_EQ(word(bytes, level1), 4u * 4 * 4);
  EXPECT_EQ(bytes.size(), level1 + 4 + 6 * 16 * 4 + 4 + 6 * 4 * 4);
}

TEST(Ktx1, RoundTripsThroughTheReader) {
  const auto levels = cube_chain(16, 5);
  const Ktx1Texture t = read_ktx1(write_ktx1_cube(levels, {{"sh", "0.5 0.25 1\n"}, {"a", ""}}), {});
  EXPECT_EQ(t.header.faces, 6u);
  EXPECT_EQ(t.header.width, 16u);
  ASSERT_EQ(t.levels.size(), 5u);
  for (size_t p = 0; p < levels.size(); ++p) {
    ASSERT_EQ(t.levels[p].width(), levels[p].width());
    ASSERT_EQ(t.levels[p].height(), levels[p].height());
    EXPECT_TRUE(std::equal(t.levels[p].data().begin(), t.levels[p].data().end(), levels[p].data().begin()));
  }
  EXPECT_EQ(t.metadata.at("sh"), "0.5 0.25 1\n");
  EXPECT_EQ(t.metadata.at("a"), "");
}

// Debian's cmgen 1.9.25: `cmgen --no-mirror --format=ktx --size=16 --ibl-samples=64 -x grid uv2`, its
// generated test map: a 2 x 2 checker on each face, the odd squares (x / 8 xor y / 8) of face f in the
// face's colour times 5 (+X white, -X red, +Y blue, -Y green, +Z yellow, -Z magenta), the rest black.
TEST(Ktx1, ReadsCmgensSkyboxFaceByFace) {
  const Ktx1Texture t =
      read_ktx1(test::read_bytes(test::fuzz_corpus_path("ktx1", "cmgen_uv2_16_skybox.ktx")), {});
  EXPECT_EQ(t.header.gl_type, ktx1::kGlR11fG11fB10f);
  EXPECT_EQ(t.header.gl_format, ktx1::kGlRgb);
  ASSERT_EQ(t.levels.size(), 1u);
  ASSERT_EQ(t.levels[0].width(), 96);
  ASSERT_EQ(t.levels[0].height(), 16);
  EXPECT_TRUE(t.metadata.empty());
  const Rgb colours[6] = {{1, 1, 1}, {1, 0, 0}, {0, 0, 1}, {0, 1, 0}, {1, 1, 0}, {1, 0, 1}};
  for (int f = 0; f < 6; ++f)
    for (int y = 0; y < 16; ++y)
      for (int x = 0; x < 16; ++x) {
        const Rgb want = ((x / 8) ^ (y / 8)) & 1 ? colours[f] * 5.0f : Rgb{};
        const Rgb got = t.levels[0].at(f * 16 + x, y);
        ASSERT_EQ(got.x, want.x) << f << " " << x << " " << y;
        ASSERT_EQ(got.y, want.y);
        ASSERT_EQ(got.z, want.z);
      }
}

TEST(Ktx1, ReadsCmgensIblWithItsShMetadata) {
  const Ktx1Texture t =
      read_ktx1(test::read_bytes(test::fuzz_corpus_path("ktx1", "cmgen_uv2_16_ibl.ktx")), {});
  ASSERT_EQ(t.levels.size(), 5u);  // 16 to 1
  EXPECT_EQ(t.levels[4].width(), 6);
  EXPECT_EQ(t.levels[4].height(), 1);
  const std::string& sh = t.metadata.at("sh");
  EXPECT_EQ(std::count(sh.begin(), sh.end(), '\n'), 9);
  EXPECT_TRUE(sh.starts_with("1.66667 1.25 1.25\n"));
}

TEST(Ktx1, WriterRefusesWhatIsNotACubeChain) {
  EXPECT_THROW(write_ktx1_cube({}), Error);
  EXPECT_THROW(write_ktx1_cube(std::vector<Image>{Image(8, 8)}), Error);  // not six faces
  auto levels = cube_chain(8, 2);
  levels[1] = Image(4, 4);  // a face, not a strip
  EXPECT_THROW(write_ktx1_cube(levels), Error);
  EXPECT_THROW(write_ktx1_cube(cube_chain(8, 5)), Error);  // 8 has 4 levels
  EXPECT_THROW(write_ktx1_cube(cube_chain(4, 1), {{"", "x"}}), Error);
  EXPECT_THROW(write_ktx1_cube(cube_chain(4, 1), {{"k", std::string("a\0b", 3)}}), Error);
}

void expect_refused(const std::vector<uint8_t>& bytes, ErrorKind kind, const ImageLimits& limits = {}) {
  try {
    read_ktx1(bytes, limits);
    ADD_FAILURE() << "read";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), kind) << e.what();
  }
}

TEST(Ktx1, ReaderRefusesBadFilesBeforeAllocating) {
  const auto good = write_ktx1_cube(cube_chain(8, 2), {{"sh", "1"}});
  expect_refused({}, ErrorKind::Corrupt);                                   // too short
  expect_refused(with_word(good, 0, 0), ErrorKind::Unsupported);            // identifier
  expect_refused(with_word(good, 12, 0x01020304), ErrorKind::Unsupported);  // big-endian
  expect_refused(with_word(good, 28, 0x881A), ErrorKind::Unsupported);      // RGBA16F
  expect_refused(with_word(good, 16, 0x1406), ErrorKind::Unsupported);      // glType FLOAT
  expect_refused(with_word(good, 52, 2), ErrorKind::Unsupported);           // two faces
  expect_refused(with_word(good, 48, 3), ErrorKind::Unsupported);           // an array
  expect_refused(with_word(good, 36, 16), ErrorKind::Corrupt);              // a cube of 16 x 8 faces
  expect_refused(with_word(good, 56, 5), ErrorKind::Corrupt);               // 8 x 8 has 4 levels
  expect_refused(with_word(good, 60, 1u << 30), ErrorKind::Corrupt);        // key/values past the end
  expect_refused(with_word(good, 64, 200), ErrorKind::Corrupt);             // a pair past its section
  expect_refused(with_word(good, 76, 12), ErrorKind::Corrupt);              // imageSize of another face
  expect_refused(std::vector<uint8_t>(good.begin(), good.end() - 4), ErrorKind::Corrupt);
  auto longer = good;
  longer.push_back(0);
  expect_refused(longer, ErrorKind::Corrupt);
  ImageLimits small;
  small.max_pixels = 8 * 8 * 6 - 1;  // the six faces of level 0 count
  expect_refused(good, ErrorKind::TooLarge, small);
  expect_refused(test::read_bytes(test::fuzz_corpus_path("ktx1", "truncated_level.ktx")), ErrorKind::Corrupt);
}

}  // namespace
}  // namespace lp
