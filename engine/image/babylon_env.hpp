#pragma once
// Babylon.js's .env container, version 2 (its EnvironmentTextureTools): 8 magic bytes, a JSON manifest
// ended by a NUL byte, then the encoded images. The manifest holds `version` 2, `width` (the face size
// of level 0, a power of two), `imageType` (the images' MIME type), `irradiance` (the spherical
// polynomial, babylon_polynomial.hpp) and `specular`: `mipmaps`, the {position, length} of each image
// from the end of the manifest, for every level of the full chain (log2(width) + 1 of them, down to 1x1)
// and, within a level, the faces +X, -X, +Y, -Y, +Z, -Z; and `lodGenerationScale`. Babylon reads the
// faces as RGBD (rgbd.hpp) and uploads each image bottom row first: image row 0 is the face's last row
// (t = 1 of OpenGL's cube map table).
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "engine/sh/babylon_polynomial.hpp"

namespace lp {

inline constexpr int kBabylonEnvVersion = 2;
inline constexpr double kBabylonLodGenerationScale = 0.8;  // HDRFiltering's, and the reader's default
inline constexpr int kBabylonEnvMaxWidth = 1 << 14;        // the reader's limit

struct BabylonEnv {
  int width = 0;
  std::string image_type = "image/png";
  double lod_generation_scale = kBabylonLodGenerationScale;
  std::optional<BabylonSphericalPolynomial> irradiance;
  std::vector<std::vector<uint8_t>> specular;  // babylon_env_images(width) encoded images, level-major
};

// The levels of a face size (log2(width) + 1) and the images of the file (6 per level).
int babylon_env_levels(int width);
size_t babylon_env_images(int width);

// Throws lp::Error(InvalidArgument) unless width is a power of two and every image is present.
std::vector<uint8_t> write_babylon_env(const BabylonEnv& env);
// Throws lp::Error: Unsupported (no magic), Corrupt (manifest or image positions broken), TooLarge
// (width over kBabylonEnvMaxWidth).
BabylonEnv read_babylon_env(std::span<const uint8_t> bytes);

}  // namespace lp
