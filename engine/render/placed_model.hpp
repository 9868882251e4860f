#pragma once
// A mesh object's model in the world: the model of its file (loaded here unless the scene holds it
// already) with the object's transform applied to its positions, normals and tangents.
#include "engine/model/model.hpp"
#include "engine/render/scene_desc.hpp"

namespace lp::render {

// The rotation from the model's coordinates to the world's before the object's transform: the up axis
// of an OBJ (mesh.up_axis, y by default); none for a glTF, already in the world frame. Throws
// InvalidArgument for up_axis z on a glTF.
Mat4 file_to_world(const MeshObject& mesh, const Model& model);

// Throws lp::Error as lp::load_model does, and InvalidArgument for a bad transform.
Model place_model(const MeshObject& mesh, const MeshLimits& limits);

}  // namespace lp::render
