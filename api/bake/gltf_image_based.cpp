#include "api/bake/gltf_image_based.hpp"

#include <fmt/format.h>

#include "api/bake/babylon_env_chain.hpp"
#include "engine/image/image_io.hpp"
#include "engine/image/rgbd.hpp"
#include "engine/prefilter/prefilter_chain.hpp"
#include "engine/projection/cube_face.hpp"
#include "engine/sh/sh_rotation.hpp"

namespace lp::api {

Json image_based_irradiance(const ShCoefficients& radiance) {
  const ShCoefficients e = rotate_sh(sh_irradiance(radiance), kWorldToBabylon);
  Json out = Json::array();
  for (int l = 0; l < 3; ++l)
    for (int m = -l; m <= l; ++m) {
      const double sign = (m == 1 || m == -1) ? -1 : 1;  // Condon-Shortley
      const ShRgb& c = e.rgb[size_t(sh_index(l, m))];
      out.push_back({sign * c[0], sign * c[1], sign * c[2]});
    }
  return out;
}

Json image_based_light(const BakeInput& in, const std::string& stem, Json& images,
                       std::vector<BakeFile>& files) {
  const PrefilteredChain& chain = *in.chain;
  Json levels = Json::array();
  for (size_t level = 0; level < chain.levels.size(); ++level) {
    Json faces = Json::array();
    for (int f = 0; f < kCubeFaces; ++f) {
      const Image face = babylon_face(chain.levels[level], f);
      const std::string name = fmt::format("{}_specular_{}_{}.png", stem, level, f);
      files.push_back(
          {name, "image/png", encode_png_rgba8(encode_rgbd_pixels(face), face.width(), face.height())});
      faces.push_back(images.size());
      images.push_back({{"name", fmt::format("{} specular level {} face {}", in.name, level, f)},
                        {"uri", name},
                        {"mimeType", "image/png"}});
    }
    levels.push_back(faces);
  }
  return {{"name", in.name},
          {"intensity", 1.0},
          {"rotation", {0.0, 0.0, 0.0, 1.0}},
          {"irradianceCoefficients", image_based_irradiance(in.sh)},
          {"specularImageSize", chain.params.base_size},
          {"specularImages", levels}};
}

}  // namespace lp::api
