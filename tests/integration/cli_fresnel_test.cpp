// `lightprobe fresnel`, the real tool: values against the textbook (normal incidence ((n1 - n2) /
// (n1 + n2))^2, Brewster's angle atan(n2 / n1) where rp vanishes), JSON and CSV agreeing, the server's
// answers, and bad parameters failing with the API's messages.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>
#include <vector>

#include "support/cli_run.hpp"
#include "support/http_reply.hpp"
#include "support/server_process.hpp"

namespace lp {
namespace {

using nlohmann::json;

std::string fresnel(const std::vector<std::string>& options) {
  std::vector<std::string> args = {"fresnel"};
  args.insert(args.end(), options.begin(), options.end());
  const test::CliRun run = test::run_cli(args);
  EXPECT_EQ(run.exit_status, 0) << run.err;
  return run.out;
}

std::vector<std::vector<double>> csv_rows(const std::string& text) {
  std::istringstream in(text);
  std::string line;
  std::getline(in, line);  // the header
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::istringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) row.push_back(std::stod(cell));
    rows.push_back(row);
  }
  return rows;
}

TEST(CliFresnel, NormalIncidenceIsTheSquaredIndexRatio) {
  for (const auto& [n1, n2] : std::vector<std::pair<double, double>>{{1.0, 1.5}, {1.33, 1.0}, {1.0, 2.4}}) {
    const double r0 = std::pow((n1 - n2) / (n1 + n2), 2);
    const auto rows = csv_rows(fresnel(
        {"--eta-i", std::to_string(n1), "--eta-t", std::to_string(n2), "--step", "5", "--format", "csv"}));
    ASSERT_EQ(rows.size(), 19u);  // 0, 5, ..., 90 degrees
    EXPECT_EQ(rows[0][0], 0.0);
    for (size_t k = 1; k <= 3; ++k)
      EXPECT_NEAR(rows[0][k], r0, 1e-12) << "column " << k;  // rs, rp, unpolarised
  }
}

TEST(CliFresnel, RpVanishesAtBrewstersAngle) {
  const double brewster = std::atan(1.5) * 180 / std::numbers::pi;  // 56.3099 degrees
  const json j = json::parse(fresnel({"--eta-t", "1.5", "--step", "0.01"}));
  EXPECT_NEAR(j["brewster_deg"].get<double>(), brewster, 1e-9);
  const auto& angles = j["angles_deg"];
  const auto& rp = j["rp"];
  size_t lowest = 0;
  for (size_t i = 0; i < rp.size(); ++i)
    if (rp[i].get<double>() < rp[lowest].get<double>()) lowest = i;
  EXPECT_NEAR(angles[lowest].get<double>(), brewster, 0.01);
  EXPECT_LT(rp[lowest].get<double>(), 1e-8);
}

TEST(CliFresnel, CsvAndJsonAreTheServersTables) {
  const json cli = json::parse(fresnel({"--metal", "gold", "--step", "10"}));
  const json api =
      test::reply(test::shared_server().client()->Get("/api/v1/fresnel?metal=gold&step=10")).body_json();
  EXPECT_EQ(cli, api);
  const std::string csv = fresnel({"--eta-i", "1.45", "--eta-t", "1", "--step", "2", "--format", "csv"});
  const test::Reply api_csv = test::reply(
      test::shared_server().client()->Get("/api/v1/fresnel?eta_i=1.45&eta_t=1&step=2&format=csv"));
  EXPECT_EQ(csv, api_csv.body);
  // Beyond the critical angle asin(1 / 1.45) = 43.6 degrees, everything is reflected.
  for (const auto& row : csv_rows(csv))
    if (row[0] > 43.6) {
      EXPECT_EQ(row[3], 1.0) << row[0];
    }
}

TEST(CliFresnel, BadParametersFailAsTheApiAnswersThem) {
  for (const auto& [options, query] : std::vector<std::pair<std::vector<std::string>, std::string>>{
           {{}, ""},
           {{"--eta-t", "-1"}, "eta_t=-1"},
           {{"--eta-t", "1.5", "--step", "0"}, "eta_t=1.5&step=0"},
           {{"--metal", "unobtainium"}, "metal=unobtainium"},
           {{"--metal", "gold", "--eta-t", "1.5"}, "metal=gold&eta_t=1.5"},
           {{"--eta-t", "1.5", "--colour", "red"}, "eta_t=1.5&colour=red"},
           {{"--eta-t", "1.5", "--format", "xml"}, "eta_t=1.5&format=xml"}}) {
    SCOPED_TRACE(query);
    std::vector<std::string> args = {"fresnel"};
    args.insert(args.end(), options.begin(), options.end());
    const test::CliRun run = test::run_cli(args);
    const test::Reply api =
        test::reply(test::shared_server().client()->Get(("/api/v1/fresnel?" + query).c_str()));
    EXPECT_EQ(api.status, 400);
    EXPECT_EQ(run.exit_status, 2);
    EXPECT_EQ(run.err, test::cli_error_line(api.body_json()));
  }
}

}  // namespace
}  // namespace lp
