#pragma once
// The model of the `textured` scene preset, generated rather than read from a file: a UV sphere of
// radius 1 at the origin with a brick colour texture and the bricks' tangent-space normal map (mortar
// grooves), standing on a 12 x 12 ground square at z = -1 with a checkerboard texture repeated six
// times by a texture transform (so that mipmaps matter at a grazing view). Built once and shared.
#include <memory>

#include "engine/model/model.hpp"

namespace lp::render {

inline constexpr int kBrickTextureWidth = 512, kBrickTextureHeight = 256;
inline constexpr int kCheckerTextureSize = 256;

std::shared_ptr<const Model> textured_preset_model();

}  // namespace lp::render
