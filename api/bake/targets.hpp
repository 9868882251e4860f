#pragma once
// One declaration per bake target, each defined in api/bake/target_NAME.cpp and listed in the registry
// (bake_target.cpp).
#include "api/bake/bake_target.hpp"

namespace lp::api {

TargetSpec gltf_target();
TargetSpec filament_target();
TargetSpec babylon_target();
TargetSpec three_target();
TargetSpec unity_target();
TargetSpec unreal_target();
TargetSpec godot_target();

}  // namespace lp::api
