// OIDN's tensor archives: the vendored rt_hdr_alb_nrm.tza read tensor by tensor (names, shapes, a known
// value), float16 decoding, and every broken archive refused with DenoiseError.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>

#include "engine/denoise/denoiser.hpp"
#include "engine/denoise/tza.hpp"

namespace lp::denoise {
namespace {

std::vector<uint8_t> read_bytes(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

std::vector<uint8_t> vendored(const char* name) {
  return read_bytes(default_weights_dir() / name);
}

TEST(DenoiseTza, VendoredArchiveHasOidnsUNetLayers) {
  const TensorMap t = parse_tza(vendored("rt_hdr_alb_nrm.tza"));
  EXPECT_EQ(t.size(), 32u);  // 16 convolutions, weight and bias each
  const std::pair<const char*, std::vector<int>> expected[] = {{"enc_conv0.weight", {32, 9, 3, 3}},
                                                               {"enc_conv1.weight", {32, 32, 3, 3}},
                                                               {"enc_conv2.weight", {48, 32, 3, 3}},
                                                               {"enc_conv3.weight", {64, 48, 3, 3}},
                                                               {"enc_conv4.weight", {80, 64, 3, 3}},
                                                               {"enc_conv5a.weight", {96, 80, 3, 3}},
                                                               {"enc_conv5b.weight", {96, 96, 3, 3}},
                                                               {"dec_conv4a.weight", {112, 160, 3, 3}},
                                                               {"dec_conv4b.weight", {112, 112, 3, 3}},
                                                               {"dec_conv3a.weight", {96, 160, 3, 3}},
                                                               {"dec_conv3b.weight", {96, 96, 3, 3}},
                                                               {"dec_conv2a.weight", {64, 128, 3, 3}},
                                                               {"dec_conv2b.weight", {64, 64, 3, 3}},
                                                               {"dec_conv1a.weight", {64, 73, 3, 3}},
                                                               {"dec_conv1b.weight", {32, 64, 3, 3}},
                                                               {"dec_conv0.weight", {3, 32, 3, 3}},
                                                               {"dec_conv0.bias", {3}}};
  for (const auto& [name, dims] : expected) {
    ASSERT_TRUE(t.contains(name)) << name;
    EXPECT_EQ(t.at(name).dims, dims) << name;
    EXPECT_EQ(t.at(name).layout, dims.size() == 4 ? "oihw" : "x") << name;
    size_t count = 1;
    for (int d : dims) count *= size_t(d);
    EXPECT_EQ(t.at(name).values.size(), count) << name;
  }
  for (const auto& [name, tensor] : t)
    for (float v : tensor.values) ASSERT_TRUE(std::isfinite(v) && std::abs(v) < 100) << name << " " << v;
}

TEST(DenoiseTza, ColourOnlyArchiveReadsThreeChannels) {
  const TensorMap t = parse_tza(vendored("rt_ldr.tza"));
  EXPECT_EQ(t.at("enc_conv0.weight").dims, (std::vector<int>{32, 3, 3, 3}));
  EXPECT_EQ(t.at("dec_conv1a.weight").dims, (std::vector<int>{64, 67, 3, 3}));
}

TEST(DenoiseTza, HalfFloatsDecodeExactly) {
  EXPECT_EQ(half_to_float(0x3C00), 1.f);
  EXPECT_EQ(half_to_float(0xC000), -2.f);
  EXPECT_EQ(half_to_float(0x7BFF), 65504.f);
  EXPECT_EQ(half_to_float(0x3555), 0.333251953125f);
  EXPECT_EQ(half_to_float(0x0001), std::ldexp(1.f, -24));  // smallest subnormal
  EXPECT_EQ(half_to_float(0x03FF), std::ldexp(1023.f, -24));
  EXPECT_EQ(half_to_float(0x8000), -0.f);
  EXPECT_TRUE(std::isinf(half_to_float(0x7C00)));
  EXPECT_TRUE(std::isnan(half_to_float(0x7E00)));
}

// The small archive of the fuzz corpus: a half-float weight {2, 3, 3, 3} of values 0.5 i, a float bias.
std::vector<uint8_t> small_archive() {
  return read_bytes(std::filesystem::path(LIGHTPROBE_FUZZ_CORPUS) / "tza" / "two_tensors.tza");
}

TEST(DenoiseTza, SmallArchiveValues) {
  const TensorMap t = parse_tza(small_archive());
  ASSERT_EQ(t.size(), 2u);
  const Tensor& w = t.at("enc_conv0.weight");
  ASSERT_EQ(w.values.size(), 54u);
  for (size_t i = 0; i < 54; ++i) EXPECT_EQ(w.values[i], 0.5f * float(i));
  EXPECT_EQ(t.at("enc_conv0.bias").values, (std::vector<float>{1.f, -2.f}));
}

TEST(DenoiseTza, EveryTruncationIsRefused) {
  const std::vector<uint8_t> bytes = small_archive();
  for (size_t size = 0; size < bytes.size(); ++size)
    EXPECT_THROW(parse_tza(std::span(bytes.data(), size)), DenoiseError) << "size " << size;
}

TEST(DenoiseTza, BrokenHeadersAreRefused) {
  const std::vector<uint8_t> good = small_archive();
  const auto refused = [&](size_t at, uint8_t value, const char* what) {
    std::vector<uint8_t> bytes = good;
    bytes[at] = value;
    EXPECT_THROW(parse_tza(bytes), DenoiseError) << what;
  };
  refused(0, 0, "magic");
  refused(2, 1, "major version");
  refused(11, 0xFF, "table offset past the end");
  const size_t table = good[4] | size_t(good[5]) << 8;
  refused(table + 4 + 2 + 16, 9, "five dimensions or more");   // ndims of the first tensor
  refused(table + 4 + 2 + 16 + 1 + 16 + 1, 'q', "layout");     // first letter of "oihw"
  refused(table + 4 + 2 + 16 + 1 + 16 + 4, 'd', "data type");  // 'h'
  refused(table + 4 + 2 + 16 + 1 + 16 + 4 + 1 + 7, 0x7F, "data offset past the end");
}

}  // namespace
}  // namespace lp::denoise
