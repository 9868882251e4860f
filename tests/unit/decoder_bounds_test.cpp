// Decoders on hostile input: every reproducer found by fuzzing (tests/fuzz/corpus) is refused cleanly,
// and nothing a file claims is allocated before the file is shown to hold it.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <set>
#include <string>
#include <tuple>

#include "engine/core/error.hpp"
#include "engine/envmap/envmap.hpp"
#include "engine/image/image_io.hpp"
#include "engine/model/model_loader.hpp"
#include "engine/model/obj_prescan.hpp"
#include "support/test_data.hpp"

namespace lp {
namespace {

using namespace std::string_literals;

std::vector<uint8_t> bytes_of(const std::string& s) {
  return {s.begin(), s.end()};
}

std::string error_of(ErrorKind kind, const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), kind) << e.what();
    return e.what();
  }
  ADD_FAILURE() << "no error thrown";
  return "";
}

// A Radiance file: the usual header, then the resolution line and pixel data given.
std::vector<uint8_t> hdr(const std::string& resolution_and_data) {
  std::vector<uint8_t> b = bytes_of("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n");
  b.insert(b.end(), resolution_and_data.begin(), resolution_and_data.end());
  return b;
}

TEST(DecoderBounds, RadianceHeaderWithANulLineIsCorrupt) {
  // stb_image ended this header at the NUL line and then spun forever on the data that followed.
  const auto bytes = test::read_bytes(test::fuzz_corpus_path("hdr", "hdr_nul_header_line_hang.hdr"));
  const std::string message = error_of(ErrorKind::Corrupt, [&] { read_image(bytes); });
  EXPECT_NE(message.find("NUL"), std::string::npos) << message;
}

TEST(DecoderBounds, RadianceRunLengthDataIsChecked) {
  const std::string scanline_start = "\x02\x02\x00\x08"s;
  // A zero-length run never advances: refused instead of looping.
  error_of(ErrorKind::Corrupt,
           [&] { read_image(hdr("-Y 1 +X 8\n"s + scanline_start + std::string(40, '\0'))); });
  // A run past the end of the scanline.
  error_of(ErrorKind::Corrupt,
           [&] { read_image(hdr("-Y 1 +X 8\n" + scanline_start + "\x89" + std::string(40, '\x01'))); });
  // Truncated inside a scanline.
  error_of(ErrorKind::Corrupt, [&] { read_image(hdr("-Y 1 +X 8\n" + scanline_start + "\x88\x01")); });
}

TEST(DecoderBounds, RadianceSizeMustFitTheBytesBeforeAllocation) {
  // 30000 x 30000 pixels claimed by a few bytes: refused by size, whatever the limits allow.
  ImageLimits generous;
  generous.max_pixels = int64_t{1} << 32;
  const std::string message =
      error_of(ErrorKind::Corrupt, [&] { read_image(hdr("-Y 30000 +X 30000\n\x02\x02"), generous); });
  EXPECT_NE(message.find("cannot hold"), std::string::npos) << message;
  error_of(ErrorKind::TooLarge, [&] { read_image(hdr("-Y 99999999999 +X 8\n")); });
  error_of(ErrorKind::Corrupt, [&] { read_image(hdr("+Y 1 +X 1\n\x80\x80\x80\x80")); });
  error_of(ErrorKind::Unsupported, [&] {
    read_image(bytes_of("#?RADIANCE\nFORMAT=32-bit_rle_xyze\n\n-Y 1 +X 1\n\x80\x80\x80\x80"));
  });
}

TEST(DecoderBounds, RadianceFlatAndRunLengthScanlinesDecode) {
  // 1 x 1 flat: (128, 64, 32) * 2^(129 - 136).
  const Image flat = read_image(hdr("-Y 1 +X 1\n\x80\x40\x20\x81")).image;
  EXPECT_EQ(flat.at(0, 0), (Rgb{1.0f, 0.5f, 0.25f}));
  // 8 x 1 run-length: R a run of 8 x 128, G literal 0..7, B a run of 0, E a run of 129.
  const std::string rle =
      "\x02\x02\x00\x08"s + "\x88\x80"s + "\x08\x00\x01\x02\x03\x04\x05\x06\x07"s + "\x88\x00"s + "\x88\x81"s;
  const Image img = read_image(hdr("-Y 1 +X 8\n" + rle)).image;
  for (int x = 0; x < 8; ++x) EXPECT_EQ(img.at(x, 0), (Rgb{1.0f, float(x) / 128.0f, 0.0f})) << x;
}

TEST(DecoderBounds, RadianceExponent255IsHugeAndBecomesBlackUnderClamp) {
  const Image raw = read_image(hdr("-Y 1 +X 2\n\xff\xff\xff\xff\x80\x80\x80\x81")).image;
  EXPECT_EQ(raw.at(0, 0).x, 255.0f * std::ldexp(1.0f, 119));  // finite, about 1.7e38
  const EnvMap map{Image(raw)};
  EXPECT_EQ(map.invalid_pixels().non_finite_pixels, 1u);
  EXPECT_TRUE(std::isfinite(map.power().x) && map.power().x > 0);
  error_of(ErrorKind::InvalidData, [&] { EnvMap(Image(raw), InvalidPixelPolicy::Reject); });
}

TEST(DecoderBounds, PfmNearFltMaxLoadsWithFiniteDerivedValues) {
  Image img(4, 2);
  img.set(1, 1, {FLT_MAX, FLT_MAX, FLT_MAX});
  img.set(2, 1, {1.0f, 2.0f, 3.0f});
  const EnvMap map(read_image(write_pfm(img)).image);
  EXPECT_EQ(map.invalid_pixels().non_finite_pixels, 1u);
  EXPECT_EQ(map.power().x, EnvMap(read_image(write_pfm([&] {
                                    Image clean = img;
                                    clean.set(1, 1, {});
                                    return clean;
                                  }()))
                                      .image)
                               .power()
                               .x);
}

TEST(DecoderBounds, ExrThatCannotHoldItsPixelsIsRefusedBeforeAllocation) {
  // 569 bytes whose header claims 65536 x 512 (the old pixel limit): the 400 MB buffer used to be
  // allocated and zeroed before the missing data was noticed.
  const auto bytes = test::read_bytes(test::fuzz_corpus_path("exr", "claims_65536x512_without_pixels.exr"));
  ImageLimits limits;
  limits.max_pixels = int64_t{65536} * 512;
  const std::string message = error_of(ErrorKind::Corrupt, [&] { read_image(bytes, limits); });
  EXPECT_NE(message.find("cannot hold"), std::string::npos) << message;
}

TEST(DecoderBounds, ExrAttributeLargerThanTheFileIsRefusedBeforeTheLibraryAllocatesIt) {
  // Found by fuzzing: 918 bytes whose header, as the library's C++ reader walks it, has an unknown
  // attribute of 1.8 GB, which that reader allocated before reading.
  const auto bytes = test::read_bytes(test::fuzz_corpus_path("exr", "opaque_attribute_claims_1_8_gb.exr"));
  const std::string message = error_of(ErrorKind::Corrupt, [&] { read_image(bytes); });
  EXPECT_NE(message.find("an attribute of 1851877475 bytes"), std::string::npos) << message;
}

TEST(DecoderBounds, ExrTilesFarLargerThanTheImageAreRefused) {
  // Found by fuzzing: a 16 x 8 image declaring 8 x 8388616 tiles; the library sized its tile-row
  // buffer from the declared tile before finding the data did not match.
  const auto bytes = test::read_bytes(test::fuzz_corpus_path("exr", "tile_taller_than_image.exr"));
  const std::string message = error_of(ErrorKind::Corrupt, [&] { read_image(bytes); });
  EXPECT_NE(message.find("tiles of 8 x 8388616 for 16 x 8 pixels"), std::string::npos) << message;
}

TEST(DecoderBounds, ExrAttributeGivenTwiceIsRefused) {
  // Found by fuzzing: two dataWindow attributes. The core reader keeps one, the C++ reader the other
  // (6029327 pixels wide), and sized its line buffers from it.
  const auto bytes = test::read_bytes(test::fuzz_corpus_path("exr", "data_window_twice.exr"));
  const std::string message = error_of(ErrorKind::Corrupt, [&] { read_image(bytes); });
  EXPECT_NE(message.find("attribute 'dataWindow' appears twice"), std::string::npos) << message;
}

TEST(DecoderBounds, ExrAttributeWhoseValueIsNotItsDeclaredSizeIsRefused) {
  // Found by fuzzing: a channel list declared as 55 bytes whose entries run on for 189. The C++ reader
  // reads the entries, not the declared size, so it read the rest of the header at another offset
  // than the core reader (and met an attribute claiming 1.8 GB there).
  const auto bytes = test::read_bytes(test::fuzz_corpus_path("exr", "chlist_longer_than_declared.exr"));
  const std::string message = error_of(ErrorKind::Corrupt, [&] { read_image(bytes); });
  EXPECT_NE(message.find("of type chlist declares 55 bytes but holds 189"), std::string::npos) << message;
}

TEST(DecoderBounds, ExrWithADataWindowFarFromTheOriginDecodes) {
  // Data window (1e9, -1e9) .. (1e9 + 7, -1e9 + 3), half RGB with the generator's pattern 0.01 * (i % 97).
  const Image img = read_image(test::read_bytes(test::fuzz_corpus_path("exr", "far_window.exr"))).image;
  ASSERT_EQ(img.width(), 8);
  ASSERT_EQ(img.height(), 4);
  EXPECT_NEAR(img.at(1, 0).x, 0.03f, 1e-3f);
  EXPECT_NEAR(img.at(7, 3).z, 0.01f * float((3 * 8 + 7) * 3 + 2), 2e-3f);
}

TEST(DecoderBounds, EveryCorpusExrCompressionDecodes) {
  for (const std::string file :
       {"none.exr", "rle_half.exr", "zips.exr", "piz_half.exr", "pxr24.exr", "b44_half.exr", "b44a_half.exr",
        "dwaa_half.exr", "dwab.exr", "tiled_zip.exr", "grey_y.exr"}) {
    const Image img = read_image(test::read_bytes(test::fuzz_corpus_path("exr", file))).image;
    EXPECT_EQ(img.width(), 16) << file;
    EXPECT_EQ(img.height(), 8) << file;
  }
}

Model obj(const std::string& file) {
  const auto bytes = test::read_bytes(test::fuzz_corpus_path("obj_model", file));
  return load_obj_memory(std::string(bytes.begin(), bytes.end()), "", file, {});
}

TEST(DecoderBounds, ObjInputThatOverflowsTheParserIsRefused) {
  EXPECT_NE(error_of(ErrorKind::Corrupt, [] { obj("vw_huge_joint_id.obj"); }).find("line 4: joint id '1e10'"),
            std::string::npos);
  EXPECT_NE(error_of(ErrorKind::Corrupt, [] { obj("huge_exponent.obj"); })
                .find("line 1: '1e2147483648' has an exponent"),
            std::string::npos);
  EXPECT_NE(
      error_of(ErrorKind::Corrupt, [] { obj("index_over_int.obj"); }).find("line 4: '99999999999' is out of"),
      std::string::npos);
  const std::string polygon = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf" + [] {
    std::string s;
    for (int i = 0; i <= obj::kMaxObjFaceVertices; ++i) s += (i % 3 == 0 ? " 1" : i % 3 == 1 ? " 2" : " 3");
    return s;
  }();
  error_of(ErrorKind::Corrupt, [&] { load_obj_memory(polygon, "", "poly.obj", {}); });
  ModelLimits few;
  few.max_triangles = 1;
  error_of(ErrorKind::TooLarge, [&] { load_obj_memory("v 0 0 0\nf 1 1 1\nf 1 1 1\n", "", "two.obj", few); });
}

TEST(DecoderBounds, ObjWithEveryStatementTheLibraryReadsLoads) {
  const Model cube = obj("cube.obj");
  // Every corner is read (a corner may be several vertices: with and without a texture coordinate).
  std::set<std::tuple<float, float, float>> corners;
  for (const Vec3& p : cube.positions) corners.insert({p.x, p.y, p.z});
  EXPECT_EQ(corners.size(), 8u);
  EXPECT_EQ(cube.triangle_count(), 12u);
}

}  // namespace
}  // namespace lp
