#pragma once
// Inputs of the benchmarks: the full-size (1024x512) CC0 maps and the bunny of ../shared/data when that
// folder is beside the repository, else the reduced copies in tests/data (figures then differ).
#include <filesystem>
#include <string>

#include "engine/image/image.hpp"
#include "engine/render/scene_desc.hpp"

namespace lp::bench {

std::filesystem::path envmap_path(const std::string& file);
std::filesystem::path mesh_path(const std::string& file);

// forest.exr at its own width, or enlarged (box filter) to 8192 x 4096 for any other `width`; each
// read or built once.
const Image& forest(int width);

// A diffuse sphere, a glossy plastic one (roughness 0.15) and rough gold (0.3) on a diffuse plane: glossy
// surfaces with no mirror or glass, whose caustics a path tracer finds only by chance.
render::SceneDesc diffuse_and_glossy();

// A glass sphere (ior 1.5) on a diffuse plane, seen from above the plane: a sun focused through the
// glass makes a caustic on the plane that only BSDF samples of the plane find.
render::SceneDesc glass_on_plane();

}  // namespace lp::bench
