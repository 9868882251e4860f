#pragma once
// Directional lights (median-cut lights, a map's sun) written for other tools: a Mitsuba 3 scene
// fragment, a Blender Python script, a USD layer (.usda) and a glTF 2.0 file with KHR_lights_punctual.
// Each light keeps its irradiance on a surface facing it (the integral of its radiance over its solid
// angle, in the map's units times steradians: lux for a map in cd/m^2), so the lights of a map sum to
// its power; each file also states the map's upper-hemisphere illuminance (engine/envmap/illuminance.hpp).
//
// Frames. World space is z up. Blender's world is the same. glTF and USD (upAxis "Y") are y up with
// world (x, y, z) = (x, z, -y) there (the inverse of the model import's glTF (x, y, z) -> world
// (x, -z, y)). Mitsuba 3 reads a lat-long map through its envmap emitter as direction (sin phi sin theta,
// cos theta, -cos phi sin theta) for pixel (u, v) = (phi / 2 pi, theta / pi), so our map loaded as a
// Mitsuba envmap shows world direction L at Mitsuba direction (L.y, L.z, -L.x) (a reflection of ours,
// determinant -1); MitsubaFrame picks that frame or ours (then the envmap takes a to_world).
#include <string>
#include <vector>

#include "api/params.hpp"
#include "engine/core/enum_table.hpp"
#include "engine/mediancut/median_cut.hpp"
#include "engine/sun/cone_pixels.hpp"
#include "engine/sun/sun.hpp"

namespace lp::api {

// The formats light endpoints answer in (the `format` query of POST .../median-cut and .../sun): the
// endpoint's own JSON answer, or a file for another tool.
enum class LightFormat { Answer, Mitsuba, Blender, Usd, Gltf };
constexpr auto enum_entries(LightFormat) {
  return std::to_array<EnumEntry<LightFormat>>({{LightFormat::Answer, "json"},
                                                {LightFormat::Mitsuba, "mitsuba"},
                                                {LightFormat::Blender, "blender"},
                                                {LightFormat::Usd, "usd"},
                                                {LightFormat::Gltf, "gltf"}});
}

// The frame of a Mitsuba export: Mitsuba's own, in which our lat-long map loaded as an envmap agrees
// with the lights, or ours (z up), with the envmap's to_world that makes it agree.
enum class MitsubaFrame { Mitsuba, World };
constexpr auto enum_entries(MitsubaFrame) {
  return std::to_array<EnumEntry<MitsubaFrame>>(
      {{MitsubaFrame::Mitsuba, "mitsuba"}, {MitsubaFrame::World, "world"}});
}

struct ExportLight {
  std::string name;
  Direction direction{};      // unit, towards the light, world frame
  Power irradiance{};         // RGB on a surface facing the light
  double angular_radius = 0;  // radians: 0 for a light without a size
};

struct LightSet {
  std::string description;  // one line: what the lights are
  std::vector<ExportLight> lights;
  double illuminance = 0;  // the map's upper-hemisphere illuminance
};

LightSet median_cut_light_set(const MedianCutResult& result, double illuminance);
LightSet sun_light_set(const Sun& sun, double illuminance);
// No light: `reason` says why the map has no sun.
LightSet no_sun_light_set(const std::string& reason, double illuminance);

// The `format` and `frame` query parameters of the light endpoints (400 naming a bad one; `frame` only
// with format mitsuba).
struct LightExportQuery {
  LightFormat format = LightFormat::Answer;
  MitsubaFrame frame = MitsubaFrame::Mitsuba;
};
LightExportQuery parse_light_export_query(const Query& query);

// The file of `set` in `format` (not Json); `frame` applies to Mitsuba only.
std::string export_lights(const LightSet& set, LightFormat format, MitsubaFrame frame);
// Its MIME type.
std::string light_format_content_type(LightFormat format);

// Directions between frames (see above).
Direction gltf_direction(const Direction& world);     // also USD's (upAxis Y)
Direction mitsuba_direction(const Direction& world);  // Mitsuba's envmap frame

// The unit quaternion (w, x, y, z) of the shortest rotation taking +Z to the unit vector `to`: a light
// that shines down its local -Z (a Blender sun, a USD DistantLight, a glTF directional light) so
// rotated shines away from `to`.
std::array<double, 4> rotation_from_z(const Direction& to);

}  // namespace lp::api
