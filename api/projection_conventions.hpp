#pragma once
// The conventions of each projection in words, for the answers and files that carry a map in one
// (prefiltered chains, bundles): written from the declarations of engine/projection, so the words and
// the code agree.
#include <string>

#include "engine/projection/projection.hpp"

namespace lp::api {

// How the texels of an image in `projection` map to directions (pixel centres, rows, folds).
std::string projection_convention(Projection projection);
// The cube's faces: their order, and the world axes each looks at and runs along (cube_face.hpp).
std::string cube_faces_convention();

}  // namespace lp::api
