// Parsing of prefilter requests (defaults, every field, refusals naming the field) and the files and
// description of a chain.
#include "api/prefilter_request.hpp"

#include <gtest/gtest.h>

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
    EXPECT_EQ(r.format, PrefilterFormat::Ktx2);
    EXPECT_EQ(r.precision, PixelPrecision::Half);
  }
  const PrefilterRequest r = parse_prefilter_request(
      R"({"levels":9,"base_size":512,"samples":64,"format":"exr","precision":"float"})");
  EXPECT_EQ(r.params.levels, 9);
  EXPECT_EQ(r.params.base_size, 512);
  EXPECT_EQ(r.params.samples, 64);
  EXPECT_EQ(r.format, PrefilterFormat::Exr);
  EXPECT_EQ(r.precision, PixelPrecision::Float);
}

TEST(PrefilterRequest, BadFieldsAreNamed) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {R"({"levels":0})", "'levels'"},
      {R"({"levels":12})", "'levels'"},
      {R"({"levels":9,"base_size":256})", "'levels': must be at most log2(base_size) = 8"},
      {R"({"base_size":4})", "'base_size'"},
      {R"({"base_size":4096})", "'base_size'"},
      {R"({"samples":8})", "'samples'"},
      {R"({"samples":1.5})", "'samples'"},
      {R"({"format":"png"})", "'format'"},
      {R"({"precision":"double"})", "'precision'"},
      {R"({"level":3})", "'level'"},
  };
  for (const auto& [body, field] : cases) EXPECT_NE(refusal(body).find(field), std::string::npos) << body;
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
}

}  // namespace
}  // namespace lp::api
