#pragma once
// The glTF samples of Debian's assimp-testmodels (models/glTF2, and the glTF 1.0 ones in models/glTF)
// and what the loader makes of each: the valid ones load with the triangles their default scene holds,
// every other one is refused with the kind of error given. Paths relative to /usr/share/assimp/models
// (test::assimp_model_path).
#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "engine/core/error.hpp"

namespace lp::test {

const std::map<std::string, size_t>& valid_gltf_samples();
const std::map<std::string, ErrorKind>& refused_gltf_samples();
// Every .gltf and .glb file of the package, sorted.
std::vector<std::string> gltf_sample_files();

}  // namespace lp::test
