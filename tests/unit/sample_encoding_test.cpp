// The JSON and CSV encodings of a sample: valid JSON, every float read back exactly, the largest values
// fit; a CSV row holds the binary record's values in its order.
#include "api/sample_encoding.hpp"

#include <gtest/gtest.h>

#include <cfloat>
#include <climits>
#include <cmath>
#include <cstring>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace lp::api {
namespace {

EnvSample sample_with(float value, int pixel) {
  EnvSample s;
  s.pixel_x = pixel;
  s.pixel_y = -pixel;
  s.u = s.v = s.theta = s.phi = s.pdf = value;
  s.direction = {value, -value, value};
  s.radiance = {value, value, -value};
  return s;
}

TEST(SampleEncoding, FloatsReadBackExactly) {
  for (float value : {0.0f, 1.0f, 0.1f, -0.0033f, 3.14159265f, 1e-45f, FLT_MIN, -FLT_MIN, FLT_MAX, -FLT_MAX,
                      1.17549421e-38f, 123456789.0f, 2.5e-7f}) {
    std::string out;
    append_sample_json(out, sample_with(value, INT_MAX));
    const auto json = nlohmann::json::parse(out);
    EXPECT_EQ(json["pixel"][0].get<int>(), INT_MAX) << out;
    EXPECT_EQ(json["pixel"][1].get<int>(), -INT_MAX) << out;
    for (const char* key : {"theta", "phi", "pdf"}) EXPECT_EQ(json[key].get<float>(), value) << out;
    EXPECT_EQ(json["uv"][1].get<float>(), value) << out;
    EXPECT_EQ(json["direction"][1].get<float>(), -value) << out;
    EXPECT_EQ(json["radiance"][2].get<float>(), -value) << out;
  }
}

TEST(SampleEncoding, AppendsOneObjectPerSample) {
  std::string out = "[";
  append_sample_json(out, sample_with(0.5f, 3));
  out += ",";
  append_sample_json(out, sample_with(0.25f, 4));
  out += "]";
  const auto json = nlohmann::json::parse(out);
  ASSERT_EQ(json.size(), 2u);
  EXPECT_EQ(json[1]["pdf"].get<float>(), 0.25f);
  EXPECT_EQ(json[0].size(), 7u);  // pixel, uv, direction, theta, phi, pdf, radiance
}

TEST(SampleEncoding, RefusesNonFiniteValues) {
  std::string out;
  EXPECT_THROW(append_sample_json(out, sample_with(NAN, 1)), std::logic_error);
  EXPECT_THROW(append_sample_json(out, sample_with(INFINITY, 1)), std::logic_error);
  EXPECT_THROW(append_sample_csv(out, sample_with(NAN, 1)), std::logic_error);
  EXPECT_TRUE(out.empty());
}

TEST(SampleEncoding, CsvRowIsTheBinaryRecordAsText) {
  EnvSample s = sample_with(0.1f, INT_MAX);
  s.pdf = FLT_MAX;
  std::string csv, binary;
  append_sample_csv(csv, s);
  append_sample_binary(binary, s);
  ASSERT_TRUE(csv.ends_with("\n"));
  ASSERT_EQ(binary.size(), sizeof(float) * kSampleRecordFloats);
  std::vector<std::string> cells;
  for (size_t start = 0, comma; start < csv.size(); start = comma + 1) {
    comma = csv.find_first_of(",\n", start);
    cells.push_back(csv.substr(start, comma - start));
  }
  ASSERT_EQ(cells.size(), size_t(kSampleRecordFloats));
  EXPECT_EQ(cells[0], "2147483647");
  EXPECT_EQ(cells[1], "-2147483647");
  for (int k = 2; k < kSampleRecordFloats; ++k) {
    float value;
    std::memcpy(&value, binary.data() + k * sizeof(float), sizeof(float));
    EXPECT_EQ(std::stof(cells[size_t(k)]), value) << "value " << k << ": " << cells[size_t(k)];
  }
}

}  // namespace
}  // namespace lp::api
