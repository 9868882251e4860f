// Parsing of prefilter requests (defaults, every field, refusals naming the field) and the files and
// description of a chain.
#include "api/prefilter_request.hpp"

#include <gtest/gtest.h>

#include <tuple>

#include "api/api_error.hpp"
#include "api/prefilter_files.hpp"
#include "api/prefilter_schema.hpp"

namespace lp::api {
namespace {

std::string refusal(const std::string& body) {
  try {
    parse_prefilter_request(body);
  } catch (const ApiError& e) {
    EXPECT_EQ(e.status(), 400);
    return e.what();
  }
  return "accepted";
}

TEST(PrefilterRequest, EmptyBodyMeansDefaults) {
  for (const char* body : {"", " \n", "{}"}) {
    const PrefilterRequest r = parse_prefilter_request(body);
    EXPECT_EQ(r.params.levels, 6);
    EXPECT_EQ(r.params.base_size, 256);
    EXPECT_EQ(r.params.samples, 1024);
    EXPECT_EQ(r.params.projection, Projection::LatLong);
    EXPECT_EQ(r.format, PrefilterFormat::Ktx2);
    EXPECT_EQ(r.precision, PixelPrecision::Half);
  }
  const PrefilterRequest r = parse_prefilter_request(
      R"({"levels":9,"base_size":512,"samples":64,"projection":"equal-area","format":"exr","precision":"float"})");
  EXPECT_EQ(r.params.projection, Projection::EqualArea);
  EXPECT_EQ(r.params.levels, 9);
  EXPECT_EQ(r.params.base_size, 512);
  EXPECT_EQ(r.params.samples, 64);
  EXPECT_EQ(r.format, PrefilterFormat::Exr);
  EXPECT_EQ(r.precision, PixelPrecision::Float);
}

TEST(PrefilterRequest, BadFieldsAreNamed) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {R"({"levels":0})", "'levels'"},
      {R"({"levels":13})", "'levels'"},
      {R"({"levels":10,"base_size":256,"projection":"cube"})",
       "'levels': must be at most log2(base_size) + 1 = 9"},
      {R"({"level_roughness":"steep"})", "'level_roughness'"},
      {R"({"target":"maya"})", "'target': 'maya' is not one of: gltf, filament"},
      {R"({"levels":9,"base_size":256})", "'levels': must be at most log2(base_size) = 8"},
      {R"({"base_size":4})", "'base_size'"},
      {R"({"base_size":4096})", "'base_size'"},
      {R"({"samples":8})", "'samples'"},
      {R"({"samples":1.5})", "'samples'"},
      {R"({"format":"png"})", "'format'"},
      {R"({"precision":"double"})", "'precision'"},
      {R"({"projection":"sphere"})",
       "'projection': 'sphere' is not one of: latlong, cube, cross, octahedral, equal-area"},
      {R"({"projection":"cross","base_size":100})", "'base_size': must be a multiple of 2^(levels - 1) = 32"},
      {R"({"level":3})", "'level'"},
  };
  for (const auto& [body, field] : cases)
    EXPECT_NE(refusal(body).find(field), std::string::npos) << refusal(body);
  EXPECT_NE(refusal("[1]").find("JSON object"), std::string::npos);
}

TEST(PrefilterRequest, FilesAreOneExrPerLevelOrOneKtx2) {
  PrefilterRequest r;
  EXPECT_EQ(prefilter_file_names(r), std::vector<std::string>{"prefiltered.ktx2"});
  r.format = PrefilterFormat::Exr;
  r.params.levels = 3;
  EXPECT_EQ(prefilter_file_names(r), (std::vector<std::string>{"level0.exr", "level1.exr", "level2.exr"}));
  EXPECT_THROW(prefilter_file_bytes(r, "level3.exr"), ApiError);
  EXPECT_THROW(prefilter_file_bytes(r, "prefiltered.ktx2"), ApiError);
}

TEST(PrefilterRequest, TheDescriptionGivesEveryLevelsSizeAndRoughness) {
  const PrefilterRequest r = parse_prefilter_request(R"({"levels":5,"base_size":64})");
  Json out;
  describe_prefilter(out, r, {"forest", "/api/v1/prefilters/x/files", false, 0});
  ASSERT_EQ(out["level_info"].size(), 5u);
  EXPECT_EQ(out["level_info"][4]["width"], 4);
  EXPECT_EQ(out["level_info"][4]["height"], 2);
  EXPECT_DOUBLE_EQ(out["level_info"][2]["roughness"].get<double>(), 0.5);
  EXPECT_DOUBLE_EQ(out["level_info"][2]["alpha"].get<double>(), 0.25);
  EXPECT_EQ(out["files"][0]["url"], "/api/v1/prefilters/x/files/prefiltered.ktx2");
  EXPECT_EQ(out["files_available"], false);
  EXPECT_TRUE(out["source_width"].is_null());
  EXPECT_NE(out["convention"]["roughness"].get<std::string>().find("roughness^2"), std::string::npos);
  EXPECT_EQ(out["projection"], "latlong");
  EXPECT_FALSE(out["convention"].contains("cube_faces"));
}

// Sizes in the projection's terms: a cube's level of size n is the strip 6n x n, a cross 4n x 3n, a
// square n x n; the faces' frame is stated as cube_face.hpp declares it.
TEST(PrefilterRequest, TheDescriptionGivesSizesInTheProjectionsTerms) {
  const std::vector<std::tuple<std::string, int, int>> cases = {
      {"cube", 6 * 16, 16}, {"cross", 4 * 16, 3 * 16}, {"octahedral", 16, 16}, {"equal-area", 16, 16}};
  for (const auto& [projection, width, height] : cases) {
    const auto r =
        parse_prefilter_request(R"({"levels":4,"base_size":64,"projection":")" + projection + "\"}");
    Json out;
    describe_prefilter(out, r, {"forest", "/f", false, 0});
    EXPECT_EQ(out["projection"], projection);
    EXPECT_EQ(out["level_info"][2]["size"], 16) << projection;
    EXPECT_EQ(out["level_info"][2]["width"], width) << projection;
    EXPECT_EQ(out["level_info"][2]["height"], height) << projection;
  }
  const auto cube = parse_prefilter_request(R"({"projection":"cube"})");
  Json out;
  describe_prefilter(out, cube, {"forest", "/f", false, 0});
  const std::string faces = out["convention"]["cube_faces"];
  EXPECT_NE(faces.find("+X, -X, +Y, -Y, +Z, -Z"), std::string::npos) << faces;
  EXPECT_NE(faces.find("(x, y, z) is the cube direction (x, z, -y)"), std::string::npos) << faces;
  EXPECT_NE(faces.find("py looks at +z, right +x, down -y"), std::string::npos) << faces;
  EXPECT_NE(faces.find("pz looks at -y, right +x, down -z"), std::string::npos) << faces;
}

// The cost, texel samples, counted by hand for lat-long levels of width w and height w / 2: level 0 one
// sample a texel, the others `samples`; over kPrefilterTexelSamples a 400 naming the limit.
TEST(PrefilterRequest, TheChainsCostIsBoundedByTexelSamples) {
  const auto texel_samples = [](int levels, int base, int64_t samples) {
    int64_t total = int64_t(base) * (base / 2);
    for (int i = 1; i < levels; ++i) total += int64_t(base >> i) * ((base >> i) / 2) * samples;
    return total;
  };
  const auto ok = parse_prefilter_request(R"({"levels":11,"base_size":2048,"samples":1024})");
  Json out;
  describe_prefilter(out, ok, {"forest", "/f", false, 0});
  EXPECT_EQ(out["texel_samples"], texel_samples(11, 2048, 1024));
  EXPECT_EQ(out["texel_samples"], 717924352);
  try {
    parse_prefilter_request(R"({"levels":11,"base_size":2048,"samples":16384})");
    ADD_FAILURE() << "accepted";
  } catch (const ApiError& e) {
    EXPECT_EQ(e.code(), ErrorCode::InvalidField);
    const std::string what = e.what();
    EXPECT_NE(what.find(std::to_string(texel_samples(11, 2048, 16384)) + " texel samples"), std::string::npos)
        << what;
    EXPECT_NE(what.find("texel_samples <= 1073741824"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace lp::api
