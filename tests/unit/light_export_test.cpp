// Lights written for other tools (api/light_export.hpp), read back by a parser of each format: a sun at
// a known azimuth and elevation points the right way in each tool's frame (checked against the frames'
// definitions, and Mitsuba's against its envmap's lat-long mapping), irradiance is conserved, and each
// file states the map's upper-hemisphere illuminance.
#include "api/light_export.hpp"

#include <expat.h>
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <regex>
#include <string>
#include <vector>

#include "api/api_error.hpp"
#include "engine/envmap/latlong.hpp"

namespace lp::api {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kIlluminance = 1234.5;

// A sun at azimuth `az` (from +x toward +y) and elevation `el`, in degrees.
Sun sun_at(double az_deg, double el_deg) {
  const double az = az_deg * kPi / 180, el = el_deg * kPi / 180;
  Sun s;
  s.axis = {std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el)};
  s.irradiance = {3.0, 2.0, 0.5};
  s.angular_radius = 0.27 * kPi / 180;
  s.share = 0.02;
  return s;
}

std::vector<double> numbers_in(const std::string& text) {
  std::vector<double> out;
  const std::regex number(R"re([-+]?[0-9]*\.?[0-9]+(?:[eE][-+]?[0-9]+)?)re");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), number); it != std::sregex_iterator(); ++it)
    out.push_back(std::stod(it->str()));
  return out;
}

// v rotated by the unit quaternion (w, x, y, z).
Direction rotate(const std::array<double, 4>& q, const Direction& v) {
  const double w = q[0];
  const Direction u{q[1], q[2], q[3]};
  const auto cross = [](const Direction& a, const Direction& b) {
    return Direction{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  };
  const Direction t = cross(u, v);
  const Direction t2{2 * t[0], 2 * t[1], 2 * t[2]};
  const Direction c = cross(u, t2);
  return {v[0] + w * t2[0] + c[0], v[1] + w * t2[1] + c[1], v[2] + w * t2[2] + c[2]};
}

void expect_direction(const Direction& got, const Direction& want, const std::string& what) {
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(got[size_t(i)], want[size_t(i)], 1e-6) << what << " [" << i << "]";
}

// The elements of an XML document (expat), each with its attributes, in document order.
struct XmlElement {
  std::string name;
  std::map<std::string, std::string> attributes;
};
std::vector<XmlElement> parse_xml(const std::string& text) {
  std::vector<XmlElement> out;
  XML_Parser parser = XML_ParserCreate(nullptr);
  XML_SetUserData(parser, &out);
  XML_SetStartElementHandler(parser, [](void* data, const XML_Char* name, const XML_Char** attributes) {
    XmlElement e{name, {}};
    for (int i = 0; attributes[i]; i += 2) e.attributes[attributes[i]] = attributes[i + 1];
    static_cast<std::vector<XmlElement>*>(data)->push_back(e);
  });
  const bool ok = XML_Parse(parser, text.data(), int(text.size()), 1) == XML_STATUS_OK;
  XML_ParserFree(parser);
  EXPECT_TRUE(ok) << "not well-formed XML:\n" << text;
  return out;
}

// Mitsuba 3's envmap: a direction in its frame looks up lat-long (u, v) = (atan2(x, -z) / 2 pi, acos(y) /
// pi) (src/emitters/envmap.cpp, direction_to_uv), u wrapping into [0, 1).
latlong::Uv mitsuba_envmap_uv(const Direction& d) {
  double u = std::atan2(d[0], -d[2]) / (2 * kPi);
  if (u < 0) u += 1;
  return {float(u), float(std::acos(d[1]) / kPi)};
}

TEST(LightExport, MitsubaDirectionsAgreeWithItsEnvmapInItsFrameAndOurs) {
  for (const auto& [az, el] : {std::pair{30.0, 10.0}, {200.0, 2.0}, {-75.0, 60.0}}) {
    const Sun sun = sun_at(az, el);
    const std::string what = "az " + std::to_string(az) + " el " + std::to_string(el);
    for (const MitsubaFrame frame : {MitsubaFrame::Mitsuba, MitsubaFrame::World}) {
      const std::string xml = export_lights(sun_light_set(sun, kIlluminance), LightFormat::Mitsuba, frame);
      EXPECT_NE(xml.find("upper-hemisphere illuminance (z up): 1234.5"), std::string::npos);
      Direction travel{};
      std::vector<double> irradiance;
      int emitters = 0;
      for (const XmlElement& e : parse_xml(xml)) {
        if (e.name == "emitter") {
          EXPECT_EQ(e.attributes.at("type"), "directional");
          ++emitters;
        }
        if (e.name == "vector" && e.attributes.at("name") == "direction") {
          const auto v = numbers_in(e.attributes.at("value"));
          travel = {v.at(0), v.at(1), v.at(2)};
        }
        if (e.name == "rgb" && e.attributes.at("name") == "irradiance")
          irradiance = numbers_in(e.attributes.at("value"));
      }
      EXPECT_EQ(emitters, 1);
      EXPECT_EQ(irradiance, std::vector<double>({3.0, 2.0, 0.5})) << what;
      const Direction towards{-travel[0], -travel[1], -travel[2]};
      // The map's pixel of the sun, looked up as Mitsuba's envmap looks it up.
      const latlong::Uv ours = latlong::uv(Vec3{float(sun.axis[0]), float(sun.axis[1]), float(sun.axis[2])});
      if (frame == MitsubaFrame::Mitsuba) {
        expect_direction(towards, {sun.axis[1], sun.axis[2], -sun.axis[0]}, what);
        const latlong::Uv theirs = mitsuba_envmap_uv(towards);
        EXPECT_NEAR(theirs.u, ours.u, 1e-6) << what;
        EXPECT_NEAR(theirs.v, ours.v, 1e-6) << what;
      } else {
        expect_direction(towards, sun.axis, what);
        // The to_world the file states, inverted (it is a permutation with a sign: its transpose),
        // takes the world direction to the envmap's local one.
        const std::smatch m = [&] {
          std::smatch found;
          std::regex_search(xml, found, std::regex(R"re(<matrix value="([^"]*)"/>)re"));
          return found;
        }();
        const auto a = numbers_in(m[1]);
        ASSERT_EQ(a.size(), 16u);
        const Direction local{a[0] * towards[0] + a[4] * towards[1] + a[8] * towards[2],
                              a[1] * towards[0] + a[5] * towards[1] + a[9] * towards[2],
                              a[2] * towards[0] + a[6] * towards[1] + a[10] * towards[2]};
        const latlong::Uv theirs = mitsuba_envmap_uv(local);
        EXPECT_NEAR(theirs.u, ours.u, 1e-6) << what;
        EXPECT_NEAR(theirs.v, ours.v, 1e-6) << what;
      }
    }
  }
}

TEST(LightExport, BlenderSunLampsShineFromTheSunWithItsIrradianceAndAngle) {
  const Sun sun = sun_at(30, 10);
  const std::string script = export_lights(sun_light_set(sun, kIlluminance), LightFormat::Blender, {});
  EXPECT_NE(script.find("UPPER_HEMISPHERE_ILLUMINANCE = 1234.5"), std::string::npos);
  EXPECT_NE(script.find("bpy.data.lights.new(name, type='SUN')"), std::string::npos);
  std::smatch m;
  ASSERT_TRUE(std::regex_search(script, m,
                                std::regex(R"re(\("sun", (\([^)]*\)), ([^,]*), (\([^)]*\)), ([^)]*)\),)re")));
  const auto q = numbers_in(m[1]);
  ASSERT_EQ(q.size(), 4u);
  // A sun lamp shines down its local -Z: rotated, towards the scene, from the sun (z up as ours).
  expect_direction(rotate({q[0], q[1], q[2], q[3]}, {0, 0, -1}), {-sun.axis[0], -sun.axis[1], -sun.axis[2]},
                   "blender");
  const double strength = std::stod(m[2]);
  const auto colour = numbers_in(m[3]);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(strength * colour.at(size_t(c)), sun.irradiance[size_t(c)], 1e-12);
  EXPECT_NEAR(std::stod(m[4]), 2 * sun.angular_radius, 1e-15);
}

TEST(LightExport, UsdDistantLightsAreYUpWithNormalizedIntensity) {
  const Sun sun = sun_at(30, 10);
  const std::string usda = export_lights(sun_light_set(sun, kIlluminance), LightFormat::Usd, {});
  EXPECT_EQ(usda.rfind("#usda 1.0\n", 0), 0u);
  EXPECT_NE(usda.find("upAxis = \"Y\""), std::string::npos);
  EXPECT_NE(usda.find("lightprobe:upperHemisphereIlluminance = 1234.5"), std::string::npos);
  EXPECT_NE(usda.find("def DistantLight \"sun\""), std::string::npos);
  EXPECT_NE(usda.find("bool inputs:normalize = true"), std::string::npos);
  const auto value = [&](const std::string& name) {
    std::smatch m;
    EXPECT_TRUE(std::regex_search(usda, m, std::regex(name + R"re( = ([^\n]*))re"))) << name;
    return numbers_in(m[1]);
  };
  const auto q = value("quatf xformOp:orient");
  ASSERT_EQ(q.size(), 4u);
  // The light travels down its -Z; in USD's y-up frame, from a sun 10 degrees up, it goes down by
  // sin(10 degrees), and world (x, y, z) is (x, z, -y).
  const Direction travel = rotate({q[0], q[1], q[2], q[3]}, {0, 0, -1});
  expect_direction(travel, {-sun.axis[0], -sun.axis[2], sun.axis[1]}, "usd");
  EXPECT_NEAR(travel[1], -std::sin(10 * kPi / 180), 1e-6);
  const double intensity = value("float inputs:intensity").at(0);
  const auto colour = value("color3f inputs:color");
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(intensity * colour.at(size_t(c)), sun.irradiance[size_t(c)], 1e-6);
  EXPECT_NEAR(value("float inputs:angle").at(0), 0.54, 1e-6);
  EXPECT_NE(usda.find("uniform token[] xformOpOrder = [\"xformOp:orient\"]"), std::string::npos);
}

TEST(LightExport, GltfDirectionalLightsPointDownTheirNodesMinusZInGltfsFrame) {
  const Sun sun = sun_at(30, 10);
  const Json doc = Json::parse(export_lights(sun_light_set(sun, kIlluminance), LightFormat::Gltf, {}));
  EXPECT_EQ(doc["asset"]["version"], "2.0");
  EXPECT_EQ(doc["asset"]["extras"]["upper_hemisphere_illuminance"], kIlluminance);
  EXPECT_EQ(doc["extensionsUsed"], Json::array({"KHR_lights_punctual"}));
  const Json& light = doc["extensions"]["KHR_lights_punctual"]["lights"].at(0);
  EXPECT_EQ(light["type"], "directional");
  const Json& node = doc["nodes"].at(0);
  EXPECT_EQ(node["extensions"]["KHR_lights_punctual"]["light"], 0);
  const auto r = node["rotation"].get<std::vector<double>>();  // glTF's order: x, y, z, w
  const Direction travel = rotate({r.at(3), r.at(0), r.at(1), r.at(2)}, {0, 0, -1});
  expect_direction(travel, {-sun.axis[0], -sun.axis[2], sun.axis[1]}, "gltf");
  EXPECT_NEAR(travel[1], -std::sin(10 * kPi / 180), 1e-9);
  const auto colour = light["color"].get<std::vector<double>>();
  for (int c = 0; c < 3; ++c) {
    EXPECT_LE(colour.at(size_t(c)), 1.0);
    EXPECT_NEAR(light["intensity"].get<double>() * colour.at(size_t(c)), sun.irradiance[size_t(c)], 1e-12);
  }
}

TEST(LightExport, MedianCutLightsKeepTheirPowerInEveryFormat) {
  MedianCutResult r;
  r.lights = {{normalize(Vec3{1, 2, 3}), 0, 0, 0, 0, {}, {1, 2, 3}, 0},
              {normalize(Vec3{-1, 0, -0.2f}), 0, 0, 0, 0, {}, {0.5, 0.25, 0.125}, 0},
              {Vec3{0, 0, -1}, 0, 0, 0, 0, {}, {0, 0, 0}, 0}};
  const LightSet set = median_cut_light_set(r, kIlluminance);
  const Json doc = Json::parse(export_lights(set, LightFormat::Gltf, {}));
  const Json& lights = doc["extensions"]["KHR_lights_punctual"]["lights"];
  ASSERT_EQ(lights.size(), 3u);
  ASSERT_EQ(doc["scenes"][0]["nodes"].size(), 3u);
  for (size_t i = 0; i < 3; ++i)
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(lights[i]["intensity"].get<double>() * lights[i]["color"][size_t(c)].get<double>(),
                  r.lights[i].power[size_t(c)], 1e-12)
          << i;
  // The light straight below: half a turn, its -Z pointing the way its light travels, up (+Y in glTF).
  const auto q = doc["nodes"][2]["rotation"].get<std::vector<double>>();
  expect_direction(rotate({q.at(3), q.at(0), q.at(1), q.at(2)}, {0, 0, -1}), {0, 1, 0}, "below");
  const std::string usda = export_lights(set, LightFormat::Usd, {});
  size_t prims = 0;
  for (size_t at = usda.find("def DistantLight"); at != std::string::npos;
       at = usda.find("def DistantLight", at + 1))
    ++prims;
  EXPECT_EQ(prims, 3u);
  EXPECT_EQ(parse_xml(export_lights(set, LightFormat::Mitsuba, MitsubaFrame::Mitsuba)).size(), 1u + 3 * 3);
}

TEST(LightExport, FrameOnlyWithMitsubaAndNamesFromTheTable) {
  EXPECT_EQ(parse_light_export_query({{"format", "usd"}}).format, LightFormat::Usd);
  EXPECT_EQ(parse_light_export_query({}).format, LightFormat::Answer);
  EXPECT_EQ(parse_light_export_query({{"format", "mitsuba"}, {"frame", "world"}}).frame, MitsubaFrame::World);
  for (const Query& bad : {Query{{"format", "fbx"}}, Query{{"format", "gltf"}, {"frame", "world"}},
                           Query{{"format", "mitsuba"}, {"frame", "x"}}}) {
    try {
      parse_light_export_query(bad);
      ADD_FAILURE() << "accepted " << bad.rbegin()->second;
    } catch (const ApiError& e) {
      EXPECT_EQ(e.status(), 400);
    }
  }
}

}  // namespace
}  // namespace lp::api
