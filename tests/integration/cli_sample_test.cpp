// `lightprobe sample`, the real tool on a committed map: its JSON is the server's answer to the same
// request byte for byte, its CSV and binary records hold the same samples, across chunk boundaries too,
// and bad parameters fail with the API's messages.
#include <gtest/gtest.h>

#include <cstring>
#include <nlohmann/json.hpp>
#include <sstream>
#include <vector>

#include "api/sample_request.hpp"
#include "support/cli_run.hpp"
#include "support/http_reply.hpp"
#include "support/server_process.hpp"
#include "support/test_data.hpp"

namespace lp {
namespace {

using nlohmann::json;

const std::string kForest = test::envmap_path("forest.exr").string();

test::CliRun sample(std::vector<std::string> args) {
  args.insert(args.begin(), {"sample", kForest});
  return test::run_cli(args);
}

test::Reply api_sample(const std::string& body) {
  return test::reply(
      test::shared_server().client()->Post("/api/v1/envmaps/forest_exr/samples", body, "application/json"));
}

std::vector<std::vector<double>> csv_rows(const std::string& text, std::string& header) {
  std::istringstream in(text);
  std::getline(in, header);
  std::vector<std::vector<double>> rows;
  for (std::string line; std::getline(in, line);) {
    std::vector<double> row;
    std::istringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) row.push_back(std::stod(cell));
    rows.push_back(row);
  }
  return rows;
}

std::vector<float> records(const std::string& bytes) {
  std::vector<float> values(bytes.size() / sizeof(float));
  std::memcpy(values.data(), bytes.data(), values.size() * sizeof(float));
  return values;
}

TEST(CliSample, JsonIsTheServersAnswerToTheSameRequest) {
  const test::CliRun run =
      sample({"--count", "500", "--seed", "7", "--strategy", "sobol", "--luminance", "rec709"});
  ASSERT_EQ(run.exit_status, 0) << run.err;
  const test::Reply api = api_sample(R"({"count":500,"seed":7,"strategy":"sobol","luminance":"rec709"})");
  ASSERT_EQ(api.status, 200) << api.body;
  EXPECT_EQ(run.out, api.body + "\n");
}

TEST(CliSample, JsonCsvAndBinaryHoldTheSameSamples) {
  const std::vector<std::string> request = {"--count", "1000", "--seed", "3", "--strategy", "stratified"};
  auto with_format = [&](const char* format) {
    auto args = request;
    args.insert(args.end(), {"--format", format});
    const test::CliRun run = sample(args);
    EXPECT_EQ(run.exit_status, 0) << run.err;
    return run.out;
  };
  const json j = json::parse(with_format("json"));
  std::string header;
  const auto rows = csv_rows(with_format("csv"), header);
  const auto bin = records(with_format("bin"));
  EXPECT_EQ(header, api::kSampleRecordLayout);
  ASSERT_EQ(j["samples"].size(), 1000u);
  ASSERT_EQ(rows.size(), 1000u);
  ASSERT_EQ(bin.size(), 1000u * api::kSampleRecordFloats);
  for (size_t i = 0; i < 1000; ++i) {
    const json& s = j["samples"][i];
    const std::vector<double> from_json = {
        s["pixel"][0],     s["pixel"][1],     s["uv"][0],      s["uv"][1], s["direction"][0],
        s["direction"][1], s["direction"][2], s["theta"],      s["phi"],   s["pdf"],
        s["radiance"][0],  s["radiance"][1],  s["radiance"][2]};
    ASSERT_EQ(rows[i].size(), from_json.size());
    for (size_t k = 0; k < from_json.size(); ++k) {
      // Both texts are the float's shortest round-trip form, and the record is the float itself.
      EXPECT_EQ(float(rows[i][k]), float(from_json[k])) << "sample " << i << " value " << k;
      EXPECT_EQ(bin[i * api::kSampleRecordFloats + k], float(from_json[k]))
          << "sample " << i << " value " << k;
    }
    EXPECT_GT(s["pdf"].get<double>(), 0.0) << "sample " << i;
  }
}

// 70,000 samples are encoded in two chunks of the stream (65,536 each): the records run on unbroken.
TEST(CliSample, LargeSetsAcrossChunksAgreeInCsvAndBinary) {
  const test::CliRun bin = sample({"--count", "70000", "--format", "bin"});
  const test::CliRun csv = sample({"--count", "70000", "--format", "csv"});
  ASSERT_EQ(bin.exit_status, 0) << bin.err;
  ASSERT_EQ(csv.exit_status, 0) << csv.err;
  const auto values = records(bin.out);
  std::string header;
  const auto rows = csv_rows(csv.out, header);
  ASSERT_EQ(values.size(), 70000u * api::kSampleRecordFloats);
  ASSERT_EQ(rows.size(), 70000u);
  for (size_t i : {size_t(0), size_t(65535), size_t(65536), size_t(69999)})
    for (size_t k = 0; k < size_t(api::kSampleRecordFloats); ++k)
      EXPECT_EQ(float(rows[i][k]), values[i * api::kSampleRecordFloats + k]) << "sample " << i;
  for (size_t i = 0; i < rows.size(); ++i) ASSERT_GT(rows[i][9], 0.0) << "pdf of sample " << i;
}

TEST(CliSample, BadParametersFailAsTheApiAnswersThem) {
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{}, R"({})"},
      {{"--count", "0"}, R"({"count":0})"},
      {{"--count", "abc"}, R"({"count":"abc"})"},
      {{"--count", "2.5"}, R"({"count":2.5})"},
      {{"--count", "10", "--strategy", "halton"}, R"({"count":10,"strategy":"halton"})"},
      {{"--count", "10", "--cout", "3"}, R"({"count":10,"cout":3})"},
  };
  for (const auto& [args, body] : cases) {
    SCOPED_TRACE(body);
    const test::CliRun run = sample(args);
    const test::Reply api = api_sample(body);
    EXPECT_EQ(api.status, 400);
    EXPECT_EQ(run.exit_status, 2);
    EXPECT_EQ(run.err, test::cli_error_line(api.body_json()));
    EXPECT_TRUE(run.out.empty());
  }
  const test::CliRun format = sample({"--count", "1", "--format", "xml"});
  EXPECT_EQ(format.exit_status, 2);
  EXPECT_EQ(format.err, "error: invalid_field: field 'format': 'xml' is not one of: json, csv, bin\n");
}

}  // namespace
}  // namespace lp
