#pragma once
// The BSDF of a scene description's material (engine/bsdf/).
#include <memory>

#include "engine/bsdf/bsdf.hpp"
#include "engine/render/scene_desc.hpp"

namespace lp::render {

// Throws lp::Error(InvalidArgument) for out-of-range parameters.
std::unique_ptr<Bsdf> make_bsdf(const Material& material);

}  // namespace lp::render
