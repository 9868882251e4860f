#include "api/light_export_writers.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <iterator>
#include <numbers>

#include "api/params.hpp"

namespace lp::api {
namespace {

constexpr double kDegrees = 180 / std::numbers::pi;

std::string illuminance_line(const LightSet& set) {
  return fmt::format("The map's upper-hemisphere illuminance (z up): {}", set.illuminance);
}

Direction negated(const Direction& d) {
  return {-d[0], -d[1], -d[2]};
}

}  // namespace

ColorStrength color_strength(const Power& irradiance) {
  const double top = std::max({irradiance[0], irradiance[1], irradiance[2]});
  if (!(top > 0)) return {{1, 1, 1}, 0};
  return {{irradiance[0] / top, irradiance[1] / top, irradiance[2] / top}, top};
}

// <directional> emitters: "direction" is the way the light travels, "irradiance" its RGB irradiance.
std::string mitsuba_lights(const LightSet& set, MitsubaFrame frame) {
  const bool own = frame == MitsubaFrame::Mitsuba;
  std::string out = fmt::format(
      "<scene version=\"3.0.0\">\n    <!-- {}.\n         {}.\n         {} -->\n", set.description,
      illuminance_line(set),
      own ? "Mitsuba's frame (y up): the map loaded as an envmap emitter without to_world agrees "
            "with these lights; a world direction (x, y, z) is (y, z, -x) here"
          : "Lightprobe's frame (z up): load the map as an envmap emitter with <transform "
            "name=\"to_world\"><matrix value=\"0 0 -1 0 1 0 0 0 0 1 0 0 0 0 0 1\"/></transform> to agree");
  for (const ExportLight& l : set.lights) {
    const Direction travel = negated(own ? mitsuba_direction(l.direction) : l.direction);
    fmt::format_to(std::back_inserter(out),
                   "    <emitter type=\"directional\" id=\"{}\">\n"
                   "        <vector name=\"direction\" value=\"{}, {}, {}\"/>\n"
                   "        <rgb name=\"irradiance\" value=\"{}, {}, {}\"/>\n"
                   "    </emitter>\n",
                   l.name, travel[0], travel[1], travel[2], l.irradiance[0], l.irradiance[1],
                   l.irradiance[2]);
  }
  return out + "</scene>\n";
}

// Sun lamps: strength the irradiance (W/m^2 in Blender's terms), angle the angular diameter, each
// rotated so that its -Z (the way a sun lamp shines) runs from the light towards the scene.
std::string blender_lights(const LightSet& set) {
  std::string out = fmt::format(
      "# {}.\n# {}.\n# Blender's world is Lightprobe's (z up). Run in Blender: Scripting > Run Script.\n"
      "import bpy\nfrom mathutils import Quaternion\n\n"
      "UPPER_HEMISPHERE_ILLUMINANCE = {}\n\n"
      "# (name, rotation quaternion (w, x, y, z), strength, colour, angle in radians)\nLIGHTS = [\n",
      set.description, illuminance_line(set), set.illuminance);
  for (const ExportLight& l : set.lights) {
    const auto q = rotation_from_z(l.direction);
    const ColorStrength cs = color_strength(l.irradiance);
    fmt::format_to(std::back_inserter(out), "    (\"{}\", ({}, {}, {}, {}), {}, ({}, {}, {}), {}),\n", l.name,
                   q[0], q[1], q[2], q[3], cs.strength, cs.color[0], cs.color[1], cs.color[2],
                   2 * l.angular_radius);
  }
  out +=
      "]\n\n"
      "for name, rotation, strength, colour, angle in LIGHTS:\n"
      "    light = bpy.data.lights.new(name, type='SUN')\n"
      "    light.energy = strength\n"
      "    light.color = colour\n"
      "    light.angle = angle\n"
      "    lamp = bpy.data.objects.new(name, light)\n"
      "    lamp.rotation_mode = 'QUATERNION'\n"
      "    lamp.rotation_quaternion = Quaternion(rotation)\n"
      "    bpy.context.collection.objects.link(lamp)\n";
  return out;
}

// DistantLight prims under /Lights, y up: inputs:normalize makes inputs:intensity the illuminance on a
// surface facing the light whatever inputs:angle (its angular diameter in degrees); xformOp:orient
// turns its -Z to the way the light travels.
std::string usd_lights(const LightSet& set) {
  std::string out = fmt::format(
      "#usda 1.0\n(\n    doc = \"{}. {}. World (x, y, z) of Lightprobe (z up) is (x, z, -y) here.\"\n"
      "    upAxis = \"Y\"\n    metersPerUnit = 1\n    defaultPrim = \"Lights\"\n    customLayerData = {{\n"
      "        double lightprobe:upperHemisphereIlluminance = {}\n    }}\n)\n\ndef Xform \"Lights\"\n{{\n",
      set.description, illuminance_line(set), set.illuminance);
  for (const ExportLight& l : set.lights) {
    const auto q = rotation_from_z(gltf_direction(l.direction));
    const ColorStrength cs = color_strength(l.irradiance);
    fmt::format_to(std::back_inserter(out),
                   "    def DistantLight \"{}\"\n    {{\n"
                   "        float inputs:angle = {}\n"
                   "        color3f inputs:color = ({}, {}, {})\n"
                   "        float inputs:intensity = {}\n"
                   "        bool inputs:normalize = true\n"
                   "        quatf xformOp:orient = ({}, {}, {}, {})\n"
                   "        uniform token[] xformOpOrder = [\"xformOp:orient\"]\n    }}\n",
                   l.name, 2 * l.angular_radius * kDegrees, cs.color[0], cs.color[1], cs.color[2],
                   cs.strength, q[0], q[1], q[2], q[3]);
  }
  return out + "}\n";
}

// KHR_lights_punctual directional lights (intensity in lux for a map in cd/m^2), one node each whose
// rotation turns its -Z to the way the light travels, in glTF's frame (y up).
std::string gltf_lights(const LightSet& set) {
  Json lights = Json::array(), nodes = Json::array(), roots = Json::array();
  for (const ExportLight& l : set.lights) {
    const auto q = rotation_from_z(gltf_direction(l.direction));
    const ColorStrength cs = color_strength(l.irradiance);
    roots.push_back(nodes.size());
    nodes.push_back({{"name", l.name},
                     {"rotation", {q[1], q[2], q[3], q[0]}},
                     {"extensions", {{"KHR_lights_punctual", {{"light", lights.size()}}}}}});
    lights.push_back(
        {{"type", "directional"}, {"name", l.name}, {"color", cs.color}, {"intensity", cs.strength}});
  }
  const Json doc = {
      {"asset",
       {{"version", "2.0"},
        {"generator", "Lightprobe"},
        {"extras", {{"description", set.description}, {"upper_hemisphere_illuminance", set.illuminance}}}}},
      {"extensionsUsed", {"KHR_lights_punctual"}},
      {"extensions", {{"KHR_lights_punctual", {{"lights", lights}}}}},
      {"scene", 0},
      {"scenes", {{{"name", "Lights"}, {"nodes", roots}}}},
      {"nodes", nodes}};
  return doc.dump(2) + "\n";
}

}  // namespace lp::api
