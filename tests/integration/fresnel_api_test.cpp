// GET /api/v1/fresnel on the real server: dielectric and conductor tables as JSON and CSV, and every
// kind of bad input. Expected numbers are worked out by hand here, independently of the engine.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "support/http_reply.hpp"
#include "support/server_process.hpp"

namespace lp {
namespace {

using nlohmann::json;

using test::Reply;

Reply get(const std::string& query) {
  return test::reply(test::shared_server().client()->Get(("/api/v1/fresnel" + query).c_str()));
}

json get_json(const std::string& query) {
  const Reply r = get(query);
  EXPECT_EQ(r.status, 200) << query << ": " << r.body;
  EXPECT_EQ(r.type().rfind("application/json", 0), 0u) << r.type();
  return json::parse(r.body);
}

std::vector<std::vector<std::string>> parse_csv(const std::string& body) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(body);
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::istringstream cols(line);
    std::string cell;
    while (std::getline(cols, cell, ',')) cells.push_back(cell);
    rows.push_back(cells);
  }
  return rows;
}

// Unpolarised dielectric reflectance written out again from the textbook formulas (Hecht).
double fresnel_by_hand(double deg, double ni, double nt) {
  const double th = deg * std::numbers::pi / 180, st = ni / nt * std::sin(th);
  if (st >= 1) return 1;
  const double ci = std::cos(th), ct = std::sqrt(1 - st * st);
  const double rs = (ni * ci - nt * ct) / (ni * ci + nt * ct), rp = (nt * ci - ni * ct) / (nt * ci + ni * ct);
  return (rs * rs + rp * rp) / 2;
}

TEST(FresnelApi, AirToGlassJson) {
  const json j = get_json("?eta_i=1.0&eta_t=1.45&step=1");
  EXPECT_EQ(j["kind"], "dielectric");
  EXPECT_EQ(j["eta_i"].get<double>(), 1.0);
  EXPECT_EQ(j["eta_t"].get<double>(), 1.45);
  for (const char* key : {"angles_deg", "rs", "rp", "unpolarized", "schlick"})
    ASSERT_EQ(j[key].size(), 91u) << key;
  for (int i = 0; i <= 90; ++i) EXPECT_EQ(j["angles_deg"][i].get<double>(), i);
  // R0 = (0.45 / 2.45)^2 = 0.2025 / 6.0025.
  EXPECT_NEAR(j["r0"].get<double>(), 0.2025 / 6.0025, 1e-15);
  EXPECT_NEAR(j["rs"][0].get<double>(), 0.0337359433569346, 1e-15);
  EXPECT_NEAR(j["rp"][0].get<double>(), 0.0337359433569346, 1e-15);
  EXPECT_NEAR(j["schlick"][0].get<double>(), 0.0337359433569346, 1e-15);
  // Brewster atan(1.45) = 55.4077 degrees; no critical angle going into the denser medium.
  EXPECT_NEAR(j["brewster_deg"].get<double>(), 55.40771131, 1e-8);
  EXPECT_TRUE(j["critical_deg"].is_null());
  // 45 degrees by hand: a = sqrt(2 * 1.45^2 - 1) = sqrt(3.205); r_s = (1 - a)/(1 + a) = -0.2832187.
  const double a = std::sqrt(3.205), rs45 = (1 - a) / (1 + a);
  EXPECT_NEAR(j["rs"][45].get<double>(), rs45 * rs45, 1e-14);
  EXPECT_NEAR(j["rp"][45].get<double>(), rs45 * rs45 * rs45 * rs45, 1e-14);  // R_p = R_s^2 at 45 degrees
  for (int i = 0; i <= 90; ++i) {
    const double rs = j["rs"][i], rp = j["rp"][i], r = j["unpolarized"][i];
    EXPECT_EQ(r, 0.5 * (rs + rp));
    EXPECT_GE(rs, rp);
    EXPECT_NEAR(r, fresnel_by_hand(i, 1.0, 1.45), 1e-12) << i;
  }
  EXPECT_EQ(j["rs"][90].get<double>(), 1.0);
  EXPECT_EQ(j["unpolarized"][90].get<double>(), 1.0);
  EXPECT_EQ(j["schlick"][90].get<double>(), 1.0);
  // Schlick's worst error: 0.0398185 near 84.69 degrees (a separate scan every 0.001 degree).
  EXPECT_NEAR(j["schlick_max_abs_error"].get<double>(), 0.0398185089, 1e-8);
  EXPECT_NEAR(j["schlick_max_error_angle_deg"].get<double>(), 84.691, 0.002);
}

TEST(FresnelApi, GlassToAirTotalInternalReflection) {
  const json j = get_json("?eta_i=1.45&eta_t=1.0&step=1");
  EXPECT_NEAR(j["critical_deg"].get<double>(), 43.60281897, 1e-8);  // asin(1 / 1.45)
  EXPECT_NEAR(j["brewster_deg"].get<double>(), 34.59228869, 1e-8);  // atan(1 / 1.45)
  EXPECT_NEAR(j["rp"][35].get<double>(), 0.0, 1e-4);                // one degree off Brewster
  for (int i = 0; i <= 90; ++i) {
    const double r = j["unpolarized"][i], s = j["schlick"][i];
    if (i >= 44) {
      EXPECT_EQ(r, 1.0) << i;
      EXPECT_EQ(s, 1.0) << i;
    } else {
      EXPECT_LT(r, 1.0) << i;
      EXPECT_NEAR(r, fresnel_by_hand(i, 1.45, 1.0), 1e-12) << i;
    }
  }
  // The worst Schlick error is the same as from air, at the angle Snell's law relates to 84.69.
  EXPECT_NEAR(j["schlick_max_abs_error"].get<double>(), 0.0398185089, 1e-8);
  EXPECT_NEAR(j["schlick_max_error_angle_deg"].get<double>(), 43.369, 0.002);
}

TEST(FresnelApi, StepsAndDefaults) {
  json j = get_json("?eta_i=1&eta_t=1.5&step=7");
  EXPECT_EQ(j["angles_deg"], json::parse("[0,7,14,21,28,35,42,49,56,63,70,77,84,90]"));
  EXPECT_EQ(j["rs"].size(), 14u);
  j = get_json("?eta_i=1&eta_t=1.5&step=0.1");
  ASSERT_EQ(j["angles_deg"].size(), 901u);
  EXPECT_EQ(j["angles_deg"][3].get<double>(), 0.3);
  EXPECT_EQ(j["angles_deg"][900].get<double>(), 90.0);
  j = get_json("?eta_i=1&eta_t=1.5&step=90");
  EXPECT_EQ(j["angles_deg"], json::parse("[0,90]"));
  j = get_json("?eta_t=1.45");  // eta_i defaults to air, step to 1 degree
  EXPECT_EQ(j["eta_i"].get<double>(), 1.0);
  EXPECT_EQ(j["angles_deg"].size(), 91u);
  // Matched media: no interface, R = 0 everywhere; Brewster formally 45.
  j = get_json("?eta_i=1.3&eta_t=1.3&step=10");
  for (const auto& r : j["unpolarized"]) EXPECT_EQ(r.get<double>(), 0.0);
  EXPECT_NEAR(j["brewster_deg"].get<double>(), 45.0, 1e-12);
  EXPECT_TRUE(j["critical_deg"].is_null());
}

TEST(FresnelApi, DielectricCsvIsTheSameTable) {
  const json j = get_json("?eta_i=1.45&eta_t=1.0&step=2.5");
  const Reply r = get("?eta_i=1.45&eta_t=1.0&step=2.5&format=csv");
  ASSERT_EQ(r.status, 200) << r.body;
  EXPECT_EQ(r.type().rfind("text/csv", 0), 0u) << r.type();
  const auto rows = parse_csv(r.body);
  ASSERT_EQ(rows.size(), 1 + j["angles_deg"].size());
  EXPECT_EQ(rows[0], (std::vector<std::string>{"angle_deg", "rs", "rp", "unpolarized", "schlick"}));
  for (size_t i = 1; i < rows.size(); ++i) {
    ASSERT_EQ(rows[i].size(), 5u);
    EXPECT_EQ(std::stod(rows[i][0]), j["angles_deg"][i - 1].get<double>());
    EXPECT_EQ(std::stod(rows[i][1]), j["rs"][i - 1].get<double>());
    EXPECT_EQ(std::stod(rows[i][2]), j["rp"][i - 1].get<double>());
    EXPECT_EQ(std::stod(rows[i][3]), j["unpolarized"][i - 1].get<double>());
    EXPECT_EQ(std::stod(rows[i][4]), j["schlick"][i - 1].get<double>());
  }
  EXPECT_EQ(rows.back()[0], "90");
}

TEST(FresnelApi, GoldPreset) {
  const json j = get_json("?metal=gold&step=5");
  EXPECT_EQ(j["kind"], "conductor");
  EXPECT_EQ(j["metal"], "gold");
  EXPECT_EQ(j["eta_i"].get<double>(), 1.0);
  EXPECT_EQ(j["eta"]["r"].get<double>(), 0.166);
  EXPECT_EQ(j["k"]["r"].get<double>(), 3.15);
  EXPECT_TRUE(j["wavelengths_nm"].is_object());
  ASSERT_EQ(j["angles_deg"].size(), 19u);
  for (const char* ch : {"r", "g", "b"}) {
    ASSERT_EQ(j[ch].size(), 19u) << ch;
    ASSERT_EQ(j["rs"][ch].size(), 19u) << ch;
    ASSERT_EQ(j["rp"][ch].size(), 19u) << ch;
    const double n = j["eta"][ch], k = j["k"][ch];
    // Normal incidence: ((n - 1)^2 + k^2) / ((n + 1)^2 + k^2).
    const double r0 = ((n - 1) * (n - 1) + k * k) / ((n + 1) * (n + 1) + k * k);
    EXPECT_NEAR(j[ch][0].get<double>(), r0, 1e-14) << ch;
    EXPECT_NEAR(j["r0"][ch].get<double>(), r0, 1e-14) << ch;
    EXPECT_NEAR(j[ch][18].get<double>(), 1.0, 1e-15) << ch;  // 90 degrees
    for (size_t i = 0; i < 19; ++i) {
      EXPECT_NEAR(j[ch][i].get<double>(), 0.5 * (j["rs"][ch][i].get<double>() + j["rp"][ch][i].get<double>()),
                  1e-15);
      EXPECT_GE(j["rs"][ch][i].get<double>(), j["rp"][ch][i].get<double>() - 1e-15);
    }
  }
  // Gold reflects red far better than blue: 10.618056 / 11.282056 = 0.9411 against 0.3856.
  EXPECT_NEAR(j["r"][0].get<double>(), 10.618056 / 11.282056, 1e-12);
  EXPECT_GT(j["r"][0].get<double>(), j["b"][0].get<double>() + 0.5);
  // Under water (eta_i = 1.33) the contrast, and so the reflectance, is lower.
  const json water = get_json("?metal=gold&eta_i=1.33&step=5");
  EXPECT_LT(water["r"][0].get<double>(), j["r"][0].get<double>());
  EXPECT_EQ(water["eta_i"].get<double>(), 1.33);
}

TEST(FresnelApi, EveryMetalPreset) {
  for (const char* name : {"gold", "silver", "copper", "aluminium"}) {
    const json j = get_json(std::string("?metal=") + name);
    EXPECT_EQ(j["metal"], name);
    EXPECT_EQ(j["r"].size(), 91u);
    for (const char* ch : {"r", "g", "b"}) {
      EXPECT_GT(j["r0"][ch].get<double>(), 0.3) << name;
      EXPECT_LT(j["r0"][ch].get<double>(), 1.0) << name;
    }
  }
}

TEST(FresnelApi, SingleChannelConductorWithZeroKIsTheDielectric) {
  const json m = get_json("?eta=1.45&k=0&step=3");
  const json d = get_json("?eta_i=1&eta_t=1.45&step=3");
  EXPECT_TRUE(m["metal"].is_null());
  EXPECT_TRUE(m["wavelengths_nm"].is_null());
  EXPECT_EQ(m["eta"], json::parse(R"({"r":1.45,"g":1.45,"b":1.45})"));
  ASSERT_EQ(m["angles_deg"], d["angles_deg"]);
  for (size_t i = 0; i < d["rs"].size(); ++i) {
    for (const char* ch : {"r", "g", "b"}) {
      EXPECT_NEAR(m[ch][i].get<double>(), d["unpolarized"][i].get<double>(), 1e-12) << i;
      EXPECT_NEAR(m["rs"][ch][i].get<double>(), d["rs"][i].get<double>(), 1e-12) << i;
      EXPECT_NEAR(m["rp"][ch][i].get<double>(), d["rp"][i].get<double>(), 1e-12) << i;
    }
  }
  // Seen from glass (eta_i = 1.45, eta = 1, k = 0) past the critical angle: total reflection.
  const json tir = get_json("?eta_i=1.45&eta=1&k=0&step=1");
  for (int i = 44; i <= 90; ++i) EXPECT_NEAR(tir["g"][i].get<double>(), 1.0, 1e-12) << i;
}

TEST(FresnelApi, ConductorCsv) {
  const json j = get_json("?metal=copper&step=10");
  const Reply r = get("?metal=copper&step=10&format=csv");
  ASSERT_EQ(r.status, 200) << r.body;
  EXPECT_EQ(r.type().rfind("text/csv", 0), 0u) << r.type();
  const auto rows = parse_csv(r.body);
  ASSERT_EQ(rows.size(), 11u);
  EXPECT_EQ(rows[0], (std::vector<std::string>{"angle_deg", "r", "g", "b", "rs_r", "rs_g", "rs_b", "rp_r",
                                               "rp_g", "rp_b"}));
  for (size_t i = 1; i < rows.size(); ++i) {
    ASSERT_EQ(rows[i].size(), 10u);
    EXPECT_EQ(std::stod(rows[i][0]), j["angles_deg"][i - 1].get<double>());
    EXPECT_EQ(std::stod(rows[i][1]), j["r"][i - 1].get<double>());
    EXPECT_EQ(std::stod(rows[i][3]), j["b"][i - 1].get<double>());
    EXPECT_EQ(std::stod(rows[i][5]), j["rs"]["g"][i - 1].get<double>());
    EXPECT_EQ(std::stod(rows[i][9]), j["rp"]["b"][i - 1].get<double>());
  }
}

TEST(FresnelApi, BadInputIs400NamingTheField) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"", "eta_t"},                    // nothing at all: eta_t missing
      {"?eta_i=1.0", "eta_t"},          // missing
      {"?eta_i=1.0&eta_t=", "eta_t"},   // empty is missing
      {"?eta_i=1.0&eta_t=0", "eta_t"},  // <= 0
      {"?eta_i=1.0&eta_t=-1.45", "eta_t"},
      {"?eta_i=1.0&eta_t=nan", "eta_t"},  // NaN
      {"?eta_i=1.0&eta_t=NaN", "eta_t"},
      {"?eta_i=1.0&eta_t=inf", "eta_t"},
      {"?eta_i=1.0&eta_t=glass", "eta_t"},
      {"?eta_i=1.0&eta_t=1.45abc", "eta_t"},
      {"?eta_i=1.0&eta_t=1e9", "eta_t"},  // over 1000
      {"?eta_i=0&eta_t=1.45", "eta_i"},
      {"?eta_i=-1&eta_t=1.45", "eta_i"},
      {"?eta_i=nan&eta_t=1.45", "eta_i"},
      {"?eta_i=1&eta_t=1.45&step=0", "step"},  // step <= 0
      {"?eta_i=1&eta_t=1.45&step=-1", "step"},
      {"?eta_i=1&eta_t=1.45&step=90.5", "step"},  // step > 90
      {"?eta_i=1&eta_t=1.45&step=91", "step"},
      {"?eta_i=1&eta_t=1.45&step=nan", "step"},
      {"?eta_i=1&eta_t=1.45&step=0.001", "step"},  // under the 0.01 minimum
      {"?eta_i=1&eta_t=1.45&format=xml", "format"},
      {"?eta_i=1&eta_t=1.45&etat=1.5", "etat"},    // unknown parameter (a typo)
      {"?eta_i=1&eta_t=1.45&eta_t=1.5", "eta_t"},  // repeated
      {"?metal=unobtainium", "metal"},             // unknown metal
      {"?metal=Gold", "metal"},
      {"?metal=gold&eta=0.2", "eta"},  // both metal and eta
      {"?metal=gold&eta=0.2&k=3", "eta"},
      {"?metal=gold&k=3", "k"},
      {"?metal=gold&eta_t=1.5", "eta_t"},  // dielectric and conductor mixed
      {"?eta=0.2&k=3&eta_t=1.5", "eta_t"},
      {"?eta=0.2", "k"},  // k missing
      {"?k=3", "eta"},    // eta missing
      {"?eta=0&k=3", "eta"},
      {"?eta=-0.2&k=3", "eta"},
      {"?eta=nan&k=3", "eta"},
      {"?eta=0.2&k=-1", "k"},
      {"?eta=0.2&k=nan", "k"},
      {"?metal=gold&eta_i=0", "eta_i"},
      {"?metal=gold&step=0", "step"},
  };
  for (const auto& [query, field] : cases) {
    const Reply r = get(query);
    EXPECT_EQ(r.status, 400) << query << ": " << r.body;
    const json j = json::parse(r.body, nullptr, false);
    ASSERT_FALSE(j.is_discarded()) << query << ": " << r.body;
    EXPECT_EQ(j["error"]["code"], "invalid_field") << query;
    EXPECT_NE(j["error"]["message"].get<std::string>().find("field '" + field + "'"), std::string::npos)
        << query << ": " << j["error"]["message"];
  }
  EXPECT_TRUE(test::shared_server().alive());
}

}  // namespace
}  // namespace lp
