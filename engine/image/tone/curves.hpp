#pragma once
// The tone curves: scaled linear Rec. 709 RGB (non-negative, finite) in, display-linear Rec. 709 RGB in
// [0, 1] out, before the display encoding (sRGB or a gamma). Each names the formulation it follows.
#include "engine/core/vec3.hpp"

namespace lp::tone {

// Khronos PBR Neutral, exactly as its specification and reference code (KhronosGroup/ToneMapping,
// PBR_Neutral): a toe below 0.08, the identity less 0.04 up to a peak of 0.76, then highlight compression
// towards white with desaturation, without hue shift.
Vec3 pbr_neutral(Vec3 rgb);
// Its published analytic inverse (lut-writer.mjs there): pbr_neutral_inverse(pbr_neutral(c)) == c.
Vec3 pbr_neutral_inverse(Vec3 rgb);

// AgX as Blender 4.x ships it ("AgX", look "None" = the base contrast), in the formulation of three.js's
// AgXToneMapping (r162 on), which follows Filament's: Rec. 2020 working space, Blender's inset and outset
// matrices, a log2 encoding from -12.47393 to +4.026069 stops around 0.18, and the sixth-order polynomial
// fit of the default contrast sigmoid by Benjamin Wrensch (iolite-engine.com, "minimal AgX").
Vec3 agx(Vec3 rgb);

// ACES filmic: Stephen Hill's fit of the ACES RRT + sRGB ODT (BakingLab ACES.hlsl) with its input and
// output matrices, after three.js's 1/0.6 scale of the input (three.js ACESFilmicToneMapping).
Vec3 aces_hill(Vec3 rgb);

// Reinhard's simple operator x / (1 + x) on each channel (as three.js's ReinhardToneMapping).
Vec3 reinhard(Vec3 rgb);

}  // namespace lp::tone
