#pragma once
// A prefiltered cube chain and the SH of its map as Babylon.js's .env (babylon_env.hpp), in Babylon's
// frame.
//
// Babylon's scenes are left-handed, y up. A glTF asset enters one through Babylon's glTF loader, whose
// root node turns it 180 degrees about y and scales z by -1: glTF (x, y, z) becomes Babylon (-x, y, z).
// With our model import (glTF (x, y, z) is world (x, -z, y)), a world direction (x, y, z) is Babylon
// (-x, z, -y), so a model and the map keep in Babylon the places they have in our renders. Babylon
// samples a cube as OpenGL does with the direction in its world frame, so its face texel in direction d
// holds our cube (glTF frame) in direction (-d.x, d.y, d.z): its +X and -X faces are our -X and +X, and
// every face is ours mirrored left to right. Babylon uploads a face's image bottom row first
// (babylon_env.hpp), so each image is also upside down: a face image is ours turned by 180 degrees.
#include <cstdint>
#include <vector>

#include "engine/prefilter/prefilter_chain.hpp"
#include "engine/sh/babylon_polynomial.hpp"

namespace lp {

// World z-up directions to Babylon's frame (row i gives component i).
inline constexpr Matrix3 kWorldToBabylon = {{{-1, 0, 0}, {0, 0, 1}, {0, -1, 0}}};

// The image of one face of a Babylon cube (its order +X, -X, +Y, -Y, +Z, -Z) from one level of our
// cube strip.
Image babylon_face(const Image& strip, int face);

// The .env of a cube chain whose base size is a power of two: RGBD PNG faces, the chain's levels and,
// down to 1x1, each further level the 2x2 box average of the one before (levels Babylon's materials
// reach only above roughness 1 for faces of 64 texels and more); the polynomial of `radiance` (3 bands
// at least). Throws lp::Error(InvalidArgument) for another projection or size.
std::vector<uint8_t> babylon_env_file(const PrefilteredChain& chain, const ShCoefficients& radiance);

}  // namespace lp
