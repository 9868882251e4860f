#pragma once
// The part of manifest.json every bake target shares: the map, the target, the frame from the z-up world
// to the engine's y-up one, the units and the SH. A target adds its face_order, roughness_to_lod, files
// and import settings, and writes it as kManifestFile.
#include <array>

#include "api/bake/bake_target.hpp"
#include "api/params.hpp"

namespace lp::api {

inline constexpr const char* kManifestFile = "manifest.json";

// The engine frame (glTF's, y up) of a world direction: engine = M world, row i the world axis engine
// axis i points along (the look directions of the cube's +X, +Y and +Z faces, cube_face.hpp).
using Matrix3 = std::array<std::array<double, 3>, 3>;
Matrix3 world_to_engine();

Json manifest_common(const BakeInput& input, BakeTarget target);

// "manifest.json" as a file of the target.
BakeFile manifest_file(const Json& manifest);

}  // namespace lp::api
