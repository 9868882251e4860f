#pragma once
// A mesh object's model in the world: the model of its file (loaded here unless the scene holds it
// already) with the object's transform applied to its positions, normals and tangents.
#include "engine/model/model.hpp"
#include "engine/render/scene_desc.hpp"

namespace lp::render {

// Throws lp::Error as lp::load_model does, and InvalidArgument for a bad transform.
Model place_model(const MeshObject& mesh, const MeshLimits& limits);

}  // namespace lp::render
