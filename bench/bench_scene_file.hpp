#pragma once
// Scenes of the benchmarks kept as render request files in bench/scenes (the JSON body of POST
// /api/v1/renders), so that the command line and Blender (bench/cycles_compare.py --scene) render the
// same one: "bunny.json" is the Stanford bunny (3.7k triangles) on a plane, a scene whose rays walk the
// BVH of a mesh.
#include <string>

#include "engine/render/scene_desc.hpp"

namespace lp::bench {

// The scene of bench/scenes/`file`, its mesh paths taken from the file's folder as the command line
// takes them.
render::SceneDesc bench_scene_file(const std::string& file);

}  // namespace lp::bench
