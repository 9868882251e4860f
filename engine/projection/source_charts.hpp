#pragma once
// The sources of each projection (projection_source.hpp), one per file.
#include <memory>

#include "engine/projection/projection_source.hpp"

namespace lp {

std::unique_ptr<const ProjectionSource> make_latlong_source(const Image& image);
// A cube strip or cross.
std::unique_ptr<const ProjectionSource> make_cube_source(const Image& image, Projection layout);
// An octahedral or equal-area square.
std::unique_ptr<const ProjectionSource> make_square_source(const Image& image, Projection projection);

}  // namespace lp
