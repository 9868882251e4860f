#include "engine/model/model_textures.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "engine/core/error.hpp"

namespace lp {

ModelTextures::ModelTextures(ModelFiles& files, TextureCache& cache, const ModelLimits& limits,
                             std::string model_key)
    : files_(files), cache_(cache), limits_(limits), model_key_(std::move(model_key)) {}

ImageLimits ModelTextures::image_limits() const {
  ImageLimits l;
  l.max_pixels = std::min(limits_.max_texture_pixels, limits_.max_total_texture_pixels - pixels_);
  return l;
}

std::shared_ptr<const Texture> ModelTextures::counted(std::shared_ptr<const Texture> texture,
                                                      const std::string& what) {
  if (seen_.insert(texture.get()).second) {
    pixels_ += int64_t(texture->width()) * texture->height();
    if (pixels_ > limits_.max_total_texture_pixels)
      throw Error(ErrorKind::TooLarge, fmt::format("the model's textures are over {} pixels together (at {})",
                                                   limits_.max_total_texture_pixels, what));
  }
  return texture;
}

std::shared_ptr<const Texture> ModelTextures::embedded(int image, std::span<const uint8_t> bytes,
                                                       ColorSpace space, const std::string& what) {
  return counted(cache_.get(fmt::format("{}#image{}", model_key_, image), space,
                            [&] { return decode_texture(bytes, space, image_limits(), what); }),
                 what);
}

std::shared_ptr<const Texture> ModelTextures::file(const std::string& relative, ColorSpace space,
                                                   const std::string& what) {
  return counted(
      cache_.get(files_.cache_key(relative), space,
                 [&] { return decode_texture(files_.read(relative, what), space, image_limits(), what); }),
      what);
}

}  // namespace lp
