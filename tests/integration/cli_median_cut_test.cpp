// `lightprobe median-cut`, the real tool on committed maps: the lights are the server's, they add up to
// the map's power, and the CSV, pbrt-v4 and Mitsuba 3 light lists read back to the same lights.
#include <gtest/gtest.h>

#include <array>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <vector>

#include "engine/envmap/envmap.hpp"
#include "engine/image/image_io.hpp"
#include "support/cli_run.hpp"
#include "support/http_reply.hpp"
#include "support/server_process.hpp"
#include "support/test_data.hpp"

namespace lp {
namespace {

using nlohmann::json;

const std::string kStudio = test::envmap_path("studio.exr").string();

// A light read back from a list: the direction it comes from, and its RGB value.
struct Light {
  std::array<double, 3> from{}, power{};
};

std::string median_cut(const std::vector<std::string>& options) {
  std::vector<std::string> args = {"median-cut", kStudio};
  args.insert(args.end(), options.begin(), options.end());
  const test::CliRun run = test::run_cli(args);
  EXPECT_EQ(run.exit_status, 0) << run.err;
  return run.out;
}

std::array<double, 3> numbers(const std::string& text) {
  std::array<double, 3> v{};
  std::istringstream in(std::regex_replace(text, std::regex(","), " "));
  for (double& x : v) in >> x;
  return v;
}

std::vector<Light> json_lights(const json& j) {
  std::vector<Light> lights;
  for (const json& l : j["lights"])
    lights.push_back({{l["direction"][0], l["direction"][1], l["direction"][2]},
                      {l["power"][0], l["power"][1], l["power"][2]}});
  return lights;
}

// pbrt-v4: `LightSource "distant" "point3 from" [x y z] "point3 to" [0 0 0] "rgb L" [r g b] "float scale" s`.
std::vector<Light> pbrt_lights(const std::string& text) {
  const std::regex light(
      R"re(LightSource "distant" "point3 from" \[([^\]]*)\] "point3 to" \[0 0 0\]\s+"rgb L" \[([^\]]*)\] "float scale" ([-0-9.e+]+))re");
  std::vector<Light> lights;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), light); it != std::sregex_iterator(); ++it) {
    Light l{numbers((*it)[1]), numbers((*it)[2])};
    for (double& c : l.power) c *= std::stod((*it)[3]);
    lights.push_back(l);
  }
  return lights;
}

// Mitsuba 3: <emitter type="directional"> with <vector name="direction"> (the way light travels) and
// <rgb name="irradiance">.
std::vector<Light> mitsuba_lights(const std::string& text) {
  const std::regex emitter(
      R"re(<emitter type="directional" id="[^"]*">\s*<vector name="direction" value="([^"]*)"/>\s*<rgb name="irradiance" value="([^"]*)"/>\s*</emitter>)re");
  std::vector<Light> lights;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), emitter); it != std::sregex_iterator();
       ++it) {
    Light l{numbers((*it)[1]), numbers((*it)[2])};
    for (double& c : l.from) c = -c;
    lights.push_back(l);
  }
  return lights;
}

size_t count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// Each list holds the JSON's lights in order: directions to float precision, powers to the printed
// doubles' precision; together they carry the map's power (float sums against double sums: 1e-6).
void expect_same_lights(const std::vector<Light>& got, const std::vector<Light>& want, const EnvMap& map) {
  ASSERT_EQ(got.size(), want.size());
  std::array<double, 3> total{};
  for (size_t i = 0; i < got.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(got[i].from[c], want[i].from[c], 1e-7) << "light " << i;
      EXPECT_DOUBLE_EQ(got[i].power[c], want[i].power[c]) << "light " << i;
      total[c] += got[i].power[c];
    }
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(total[c], map.power()[c], 1e-6 * map.power()[c]) << "channel " << c;
}

TEST(CliMedianCut, LightsAreTheServersAndAddUpToTheMapsPower) {
  const EnvMap map(read_image_file(kStudio).image);
  const json cli =
      json::parse(median_cut({"--count", "32", "--split", "variance", "--placement", "centroid_squared"}));
  const json api = test::reply(test::shared_server().client()->Post(
                                   "/api/v1/envmaps/studio_exr/median-cut",
                                   R"({"count":32,"split":"variance","placement":"centroid_squared"})",
                                   "application/json"))
                       .body_json();
  EXPECT_EQ(cli["lights"], api["lights"]);
  EXPECT_EQ(cli["power"], api["power"]);
  EXPECT_EQ(cli["count"], 32);
  expect_same_lights(json_lights(cli), json_lights(api), map);
}

TEST(CliMedianCut, PbrtAndMitsubaListsReadBackToTheSameLights) {
  const EnvMap map(read_image_file(kStudio).image);
  const auto lights = json_lights(json::parse(median_cut({"--count", "64"})));
  ASSERT_EQ(lights.size(), 64u);

  const std::string pbrt = median_cut({"--count", "64", "--format", "pbrt"});
  EXPECT_EQ(count(pbrt, "LightSource "), 64u);
  EXPECT_EQ(count(pbrt, "AttributeBegin\n"), 1u);
  EXPECT_EQ(count(pbrt, "AttributeEnd\n"), 1u);
  expect_same_lights(pbrt_lights(pbrt), lights, map);

  const std::string mitsuba = median_cut({"--count", "64", "--format", "mitsuba", "--frame", "world"});
  EXPECT_EQ(mitsuba.rfind("<scene version=\"3.0.0\">\n", 0), 0u);
  EXPECT_TRUE(mitsuba.ends_with("</scene>\n"));
  EXPECT_EQ(count(mitsuba, "<scene"), 1u);
  EXPECT_EQ(count(mitsuba, "<emitter "), 64u);
  EXPECT_EQ(count(mitsuba, "</emitter>"), 64u);
  EXPECT_EQ(count(mitsuba, "<!--"), count(mitsuba, "-->"));
  expect_same_lights(mitsuba_lights(mitsuba), lights, map);
}

TEST(CliMedianCut, CsvRowsAreTheLights) {
  const EnvMap map(read_image_file(kStudio).image);
  const auto lights = json_lights(json::parse(median_cut({"--count", "16"})));
  std::istringstream csv(median_cut({"--count", "16", "--format", "csv"}));
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header, "dir_x,dir_y,dir_z,pixel_x,pixel_y,u,v,x0,y0,x1,y1,power_r,power_g,power_b,energy");
  std::vector<Light> rows;
  for (std::string line; std::getline(csv, line);) {
    std::vector<double> cells;
    std::istringstream in(line);
    for (std::string cell; std::getline(in, cell, ',');) cells.push_back(std::stod(cell));
    ASSERT_EQ(cells.size(), 15u);
    rows.push_back({{cells[0], cells[1], cells[2]}, {cells[11], cells[12], cells[13]}});
  }
  expect_same_lights(rows, lights, map);
}

TEST(CliMedianCut, BadParametersFailAsTheApiAnswersThem) {
  for (const auto& [options, body] : std::vector<std::pair<std::vector<std::string>, std::string>>{
           {{"--count", "0"}, R"({"count":0})"},
           {{"--count", "100000"}, R"({"count":100000})"},
           {{"--split", "mean"}, R"({"split":"mean"})"},
           {{"--lights", "4"}, R"({"lights":4})"}}) {
    SCOPED_TRACE(body);
    std::vector<std::string> args = {"median-cut", kStudio};
    args.insert(args.end(), options.begin(), options.end());
    const test::CliRun run = test::run_cli(args);
    const test::Reply api = test::reply(test::shared_server().client()->Post(
        "/api/v1/envmaps/studio_exr/median-cut", body, "application/json"));
    EXPECT_EQ(api.status, 400);
    EXPECT_EQ(run.exit_status, 2);
    EXPECT_EQ(run.err, test::cli_error_line(api.body_json()));
  }
  // More lights than the map has pixels: refused with the API's message, as for a map of 32768 pixels.
  const test::CliRun run = test::run_cli({"median-cut", kStudio, "--count", "40000"});
  EXPECT_EQ(run.exit_status, 2);
  EXPECT_EQ(run.err.rfind("error: invalid_field: field 'count': ", 0), 0u) << run.err;
}

}  // namespace
}  // namespace lp
