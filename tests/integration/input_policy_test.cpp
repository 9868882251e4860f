// Real-world and hostile input over real HTTP: maps with lossy-codec noise, NaN/Inf and huge values
// load under the default policy (or give 422 under ?invalid=reject), every JSON answer stays valid
// JSON with finite numbers, and the decoder reproducers in tests/fuzz/corpus get a clean 4xx.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>

#include "engine/image/image_io.hpp"
#include "support/http_reply.hpp"
#include "support/process_status.hpp"
#include "support/server_process.hpp"
#include "support/test_data.hpp"

namespace lp {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test::Reply;

constexpr double kPiD = 3.14159265358979323846;

Reply upload(const test::ServerProcess& s, const std::string& query, const std::vector<uint8_t>& bytes) {
  return test::reply(s.client()->Post(("/api/v1/envmaps?" + query).c_str(),
                                      reinterpret_cast<const char*>(bytes.data()), bytes.size(),
                                      "application/octet-stream"));
}

Reply post_json(const test::ServerProcess& s, const std::string& path, const json& body) {
  return test::reply(s.client()->Post(path.c_str(), body.dump(), "application/json"));
}

// A 64 x 32 map of mean radiance about 0.13 (a night sky), with `bad` values written over some pixels.
Image night_map(const std::vector<std::pair<std::pair<int, int>, Rgb>>& bad) {
  Image img(64, 32);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 64; ++x) {
      const float v = 0.13f + 0.05f * std::sin(0.3f * float(x)) * std::cos(0.2f * float(y));
      img.set(x, y, {v, 0.9f * v, 1.1f * v});
    }
  for (const auto& [at, value] : bad) img.set(at.first, at.second, value);
  return img;
}

// What the server must report as power: the exact solid-angle sum over the map with negatives set
// to 0 and non-finite or huge pixels black, computed here in double.
std::array<double, 3> clamped_power(const Image& img) {
  std::array<double, 3> p{};
  const int w = img.width(), h = img.height();
  for (int y = 0; y < h; ++y) {
    const double omega = 2.0 * kPiD / w * (std::cos(kPiD * y / h) - std::cos(kPiD * (y + 1) / h));
    for (int x = 0; x < w; ++x) {
      const Rgb c = img.at(x, y);
      const float v[3] = {c.x, c.y, c.z};
      bool usable = true;
      for (float f : v) usable = usable && std::isfinite(f) && std::abs(f) <= 1e24f;
      for (int k = 0; k < 3 && usable; ++k) p[size_t(k)] += omega * std::max(0.0f, v[k]);
    }
  }
  return p;
}

void expect_power(const json& meta, const Image& img) {
  const auto want = clamped_power(img);
  for (size_t k = 0; k < 3; ++k)
    EXPECT_NEAR(meta["power"][k].get<double>(), want[k], 1e-5 * want[k]) << meta.dump();
}

// Every number in the document is finite (nlohmann writes null for NaN and Inf; a raw -nan token
// would not parse at all).
void expect_finite_json(const std::string& body) {
  const json j = json::parse(body, nullptr, false);
  ASSERT_FALSE(j.is_discarded()) << body.substr(0, 200);
  std::function<void(const json&)> walk = [&](const json& v) {
    if (v.is_null()) ADD_FAILURE() << "null in " << body.substr(0, 200);
    if (v.is_number_float()) {
      EXPECT_TRUE(std::isfinite(v.get<double>())) << body.substr(0, 200);
    }
    if (v.is_structured())
      for (const auto& e : v) walk(e);
  };
  walk(j);
}

test::ServerProcess& server() {
  static test::ServerProcess s;
  return s;
}

TEST(InputPolicy, SmallNegativesLoadClampedByDefaultWithTheClampedPower) {
  const Image noisy = night_map({{{3, 1}, {-0.0033f, 0.1f, 0.1f}}, {{10, 5}, {0.1f, -0.002f, -0.001f}}});
  const Reply r = upload(server(), "name=night_noise", write_pfm(noisy));
  ASSERT_EQ(r.status, 201) << r.body;
  const json meta = r.body_json();
  EXPECT_EQ(meta["clamped_negative_values"], 3);
  EXPECT_FLOAT_EQ(meta["most_negative_value"].get<float>(), -0.0033f);
  EXPECT_EQ(meta["non_finite_pixels"], 0);
  expect_power(meta, noisy);
  // The stored map is the clamped one: its image has no negative value left.
  const Reply image = test::reply(server().client()->Get("/api/v1/envmaps/night_noise/image?format=pfm"));
  ASSERT_EQ(image.status, 200);
  const Image back = read_image(std::vector<uint8_t>(image.body.begin(), image.body.end())).image;
  EXPECT_EQ(back.at(3, 1), (Rgb{0.0f, 0.1f, 0.1f}));
  EXPECT_EQ(back.at(10, 5), (Rgb{0.1f, 0.0f, 0.0f}));
}

TEST(InputPolicy, NanAndInfPixelsLoadBlackByDefaultAndAreCounted) {
  const Image bad = night_map(
      {{{7, 2}, {NAN, 0.1f, 0.1f}}, {{8, 2}, {0.1f, INFINITY, 0.1f}}, {{9, 30}, {-INFINITY, 0, 0}}});
  const Reply r = upload(server(), "name=night_nan&invalid=clamp", write_pfm(bad));
  ASSERT_EQ(r.status, 201) << r.body;
  const json meta = r.body_json();
  EXPECT_EQ(meta["non_finite_pixels"], 3);
  EXPECT_EQ(meta["clamped_negative_values"], 0);
  expect_power(meta, bad);
}

TEST(InputPolicy, RejectGives422NamingTheFirstBadPixel) {
  const Image noisy = night_map({{{5, 4}, {0.1f, 0.1f, -0.004f}}, {{2, 9}, {NAN, 0, 0}}});
  const Reply r = upload(server(), "name=night_strict&invalid=reject", write_pfm(noisy));
  EXPECT_EQ(r.status, 422) << r.body;
  EXPECT_EQ(r.body_json()["error"]["code"], "invalid_image_data");
  EXPECT_NE(r.body.find("pixel (5, 4) has a negative value (-0.004) in channel B"), std::string::npos)
      << r.body;
  EXPECT_EQ(test::reply(server().client()->Get("/api/v1/envmaps/night_strict")).status, 404);

  const Reply bad_value = upload(server(), "name=night_strict&invalid=zero", write_pfm(noisy));
  EXPECT_EQ(bad_value.status, 400) << bad_value.body;
  EXPECT_NE(bad_value.body.find("invalid"), std::string::npos) << bad_value.body;
}

TEST(InputPolicy, LoadByPathTakesThePolicyToo) {
  test::TempDir dir;
  const Image noisy = night_map({{{1, 1}, {-0.001f, 0.1f, 0.1f}}});
  write_file(dir.path() / "noisy.pfm", write_pfm(noisy));
  test::ServerProcess s({"--data-dir", dir.path().string()});
  const Reply strict = post_json(s, "/api/v1/envmaps?invalid=reject", {{"name", "a"}, {"path", "noisy.pfm"}});
  EXPECT_EQ(strict.status, 422) << strict.body;
  EXPECT_NE(strict.body.find("pixel (1, 1)"), std::string::npos) << strict.body;
  const Reply loaded = post_json(s, "/api/v1/envmaps", {{"name", "a"}, {"path", "noisy.pfm"}});
  ASSERT_EQ(loaded.status, 201) << loaded.body;
  EXPECT_EQ(loaded.body_json()["clamped_negative_values"], 1);
  expect_power(loaded.body_json(), noisy);
}

TEST(InputPolicy, HugeValuesLoadAndEveryJsonAnswerStaysFinite) {
  // Near FLT_MAX (PFM) and a Radiance pixel with exponent 255 (about 1.7e38), beside ordinary values.
  const Image pfm = night_map({{{20, 10}, {FLT_MAX, FLT_MAX, FLT_MAX}}, {{21, 10}, {3e38f, 1, 1}}});
  std::string hdr = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 2\n";
  hdr += std::string("\xff\xff\xff\xff\x80\x80\x80\x81\x40\x80\x80\x81\x80\x40\x80\x81", 16);
  struct Case {
    std::string name;
    std::vector<uint8_t> bytes;
    int non_finite;
  };
  for (const auto& [name, bytes, non_finite] :
       std::vector<Case>{{"huge_pfm", write_pfm(pfm), 2}, {"huge_hdr", {hdr.begin(), hdr.end()}, 1}}) {
    const Reply r = upload(server(), "name=" + name, bytes);
    ASSERT_EQ(r.status, 201) << r.body;
    expect_finite_json(r.body);
    EXPECT_EQ(r.body_json()["non_finite_pixels"], non_finite) << name;
    const std::string base = "/api/v1/envmaps/" + name;
    expect_finite_json(test::reply(server().client()->Get(base.c_str())).body);
    expect_finite_json(test::reply(server().client()->Get((base + "/distribution").c_str())).body);
    const Reply samples = post_json(server(), base + "/samples", {{"count", 200}, {"seed", 3}});
    ASSERT_EQ(samples.status, 200) << samples.body.substr(0, 200);
    expect_finite_json(samples.body);
    const Reply cut = post_json(server(), base + "/median-cut", {{"count", 2}});
    ASSERT_EQ(cut.status, 200) << cut.body.substr(0, 200);
    expect_finite_json(cut.body);
  }
  expect_power(upload(server(), "name=huge_pfm_again", write_pfm(pfm)).body_json(), pfm);

  const Reply strict = upload(server(), "name=huge_strict&invalid=reject", write_pfm(pfm));
  EXPECT_EQ(strict.status, 422) << strict.body;
  EXPECT_NE(strict.body.find("pixel (20, 10)"), std::string::npos) << strict.body;
}

TEST(InputPolicy, RadianceHeaderThatHungTheDecoderIsRefused) {
  const auto bytes = test::read_bytes(test::fuzz_corpus_path("hdr", "hdr_nul_header_line_hang.hdr"));
  for (int i = 0; i < 20; ++i) {  // more than the HTTP workers: a hang in any would show
    const Reply r = upload(server(), "name=hang" + std::to_string(i), bytes);
    ASSERT_EQ(r.status, 422) << r.body;
    EXPECT_EQ(r.body_json()["error"]["code"], "corrupt");
  }
  EXPECT_EQ(test::reply(server().client()->Get("/api/v1/health")).status, 200);
}

TEST(InputPolicy, ExrThatCannotHoldItsPixelsIsRefusedWithoutTheirMemory) {
  // 569 bytes claiming 65536 x 512 pixels: allocating them would take 400 MB.
  test::ServerProcess s({"--max-pixels", std::to_string(65536 * 512)});
  const auto bytes = test::read_bytes(test::fuzz_corpus_path("exr", "claims_65536x512_without_pixels.exr"));
  for (int i = 0; i < 8; ++i) {
    const Reply r = upload(s, "name=claims" + std::to_string(i), bytes);
    EXPECT_EQ(r.status, 422) << r.body;
    EXPECT_NE(r.body.find("cannot hold"), std::string::npos) << r.body;
  }
  const double peak = test::peak_rss_mib(s.pid());
  EXPECT_GT(peak, 0);
  EXPECT_LT(peak, 200.0) << "peak resident memory of the server in MiB";
}

TEST(InputPolicy, ObjInputThatOverflowsTheParserIsRefusedAt400) {
  test::TempDir dir;
  for (const std::string file : {"vw_huge_joint_id.obj", "huge_exponent.obj", "index_over_int.obj"})
    fs::copy_file(test::fuzz_corpus_path("obj_model", file), dir.path() / file);
  test::ServerProcess s({"--data-dir", dir.path().string()});
  for (const std::string file : {"vw_huge_joint_id.obj", "huge_exponent.obj", "index_over_int.obj"}) {
    const json scene = {{"objects", json::array({{{"type", "mesh"}, {"path", file}}})}};
    const Reply r =
        post_json(s, "/api/v1/renders",
                  {{"envmap", "default"}, {"scene", scene}, {"width", 16}, {"height", 16}, {"spp", 1}});
    EXPECT_EQ(r.status, 400) << r.body;
    EXPECT_NE(r.body.find("scene.objects[0].path"), std::string::npos) << r.body;
    EXPECT_NE(r.body.find("mesh " + file + " line "), std::string::npos) << r.body;
  }
  EXPECT_TRUE(s.alive());
}

}  // namespace
}  // namespace lp
