#pragma once
// What a turntable answers about its frames: each frame's camera, as the status and cameras.json give it.
#include <nlohmann/json.hpp>
#include <span>

#include "engine/render/scene_desc.hpp"

namespace lp::api {

// [{index, position, look_at, up, fov_deg, matrix}], matrix the row-major camera-to-world of
// render::camera_to_world (Blender's camera convention).
nlohmann::json describe_turntable_cameras(std::span<const render::Camera> cameras);

}  // namespace lp::api
