#pragma once
// EXT_lights_image_based (KhronosGroup/glTF extensions/2.0/Vendor): a prefiltered cube chain as RGBD PNG
// faces and the irradiance SH, as Babylon.js's glTF loader, the extension's reference reader, reads them.
//
// The extension's faces are the standard (OpenGL, left-handed) cube map table's, each image flipped for
// glTF's texture space; Babylon's loader uploads them exactly as it uploads the faces of a .env, in its
// scene frame (glTF with x mirrored, babylon_env_chain.hpp). So a face image here is babylon_face's.
// irradianceCoefficients are read by Babylon as SphericalHarmonics.FromArray: the irradiance E_lm = A_l L_lm
// (it divides by pi itself) in its basis, ours with the Condon-Shortley sign on m = -1 and m = 1, in its
// frame (kWorldToBabylon), order l (l + 1) + m, each [r, g, b].
#include <cstdint>
#include <string>
#include <vector>

#include "api/bake/bake_target.hpp"
#include "api/params.hpp"
#include "engine/sh/sh_projection.hpp"

namespace lp::api {

inline constexpr const char* kImageBasedExtension = "EXT_lights_image_based";

// The 9 x 3 irradianceCoefficients of the radiance `radiance` (3 bands at least).
Json image_based_irradiance(const ShCoefficients& radiance);

// The extension's light and its images: the face files (appended to `files`, named STEM_specular_L_F.png
// for level L and face F) and the glTF images naming them, appended to `images` from its current size on.
Json image_based_light(const BakeInput& in, const std::string& stem, Json& images,
                       std::vector<BakeFile>& files);

}  // namespace lp::api
