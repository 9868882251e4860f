#include "api/bake/bake_manifest.hpp"

#include "api/sh_request.hpp"
#include "api/sh_schema.hpp"
#include "engine/envmap/envmap.hpp"
#include "engine/envmap/illuminance.hpp"
#include "engine/projection/cube_face.hpp"
#include "engine/sh/sh_projection.hpp"

namespace lp::api {

Matrix3 world_to_engine() {
  Matrix3 m{};
  for (int axis = 0; axis < 3; ++axis) {
    const Vec3d look = cube_face_frame(2 * axis).look;
    m[size_t(axis)] = {look.x, look.y, look.z};
  }
  return m;
}

namespace {

Json frame_json() {
  return {{"text",
           "the world is z up (the map's lat-long frame); the engine is y up, glTF's: world direction (x, y, "
           "z) is engine (x, z, -y), so the engine's +Y is the world's zenith and its -Z the world's +y"},
          {"world_to_engine", world_to_engine()}};
}

Json sh_of(const ShCoefficients& sh) {
  ShRequest request;
  request.irradiance = false;
  Json text = Json::parse(sh_json(sh, request, 0, false));
  return {{"bands", text["bands"]}, {"convention", text["convention"]}, {"radiance", text["radiance"]}};
}

}  // namespace

Json manifest_common(const BakeInput& input, BakeTarget target) {
  return {{"map", {{"name", input.name}, {"width", input.map.width()}, {"height", input.map.height()}}},
          {"target", enum_name(target)},
          {"frame", frame_json()},
          {"units",
           {{"radiance", "linear Rec.709 (sRGB primaries, D65 white) radiance, as in the map"},
            {"illuminance", upper_hemisphere_illuminance(input.map)},
            {"illuminance_text",
             "the upper hemisphere's illuminance (luminance x cos theta over theta < 90 degrees from the "
             "zenith) in the map's units: lux for a map in cd/m^2; pbrt-v4's `illuminance` of the map"}}},
          {"sh", sh_of(input.sh)}};
}

BakeFile manifest_file(const Json& manifest) {
  const std::string text = manifest.dump(2) + "\n";
  return {kManifestFile, "application/json", {text.begin(), text.end()}};
}

}  // namespace lp::api
