#pragma once
// The textures one model loads: from the shared cache, or decoded under the model's pixel limits (each
// texture's, and all of the model's textures together, checked before decoding).
#include <cstdint>
#include <memory>
#include <set>
#include <span>
#include <string>

#include "engine/model/model.hpp"
#include "engine/model/model_files.hpp"
#include "engine/texture/texture_cache.hpp"

namespace lp {

class ModelTextures {
 public:
  // `model_key` names the model file's content (ModelFiles::cache_key) for images embedded in it.
  ModelTextures(ModelFiles& files, TextureCache& cache, const ModelLimits& limits, std::string model_key);

  // An image stored inside the model file (glTF buffer view or data URI), `image` its index there.
  std::shared_ptr<const Texture> embedded(int image, std::span<const uint8_t> bytes, ColorSpace space,
                                          const std::string& what);
  // An image file next to the model.
  std::shared_ptr<const Texture> file(const std::string& relative, ColorSpace space, const std::string& what);

 private:
  std::shared_ptr<const Texture> counted(std::shared_ptr<const Texture> texture, const std::string& what);
  ImageLimits image_limits(std::span<const uint8_t> bytes, const std::string& what) const;
  Texture decode(std::span<const uint8_t> bytes, ColorSpace space, const std::string& what) const;
  void check_total(int64_t pixels, const std::string& what) const;

  ModelFiles& files_;
  TextureCache& cache_;
  const ModelLimits& limits_;
  std::string model_key_;
  std::set<const Texture*> seen_;
  int64_t pixels_ = 0;
};

}  // namespace lp
