#include "engine/model/model_textures.hpp"

#include <fmt/format.h>

#include <limits>

#include "engine/core/error.hpp"

namespace lp {

ModelTextures::ModelTextures(ModelFiles& files, TextureCache& cache, const ModelLimits& limits,
                             std::string model_key)
    : files_(files), cache_(cache), limits_(limits), model_key_(std::move(model_key)) {}

// Both limits are checked once the decoder knows the size and before it allocates, in messages naming
// the texture (the decoder's own pixel limit is lifted for that); then the memory it will take is
// reserved.
ImageLimits ModelTextures::image_limits(std::span<const uint8_t> bytes, const std::string& what) const {
  ImageLimits l;
  l.max_pixels = std::numeric_limits<int64_t>::max();
  l.before_allocation = [this, bytes, what](int64_t width, int64_t height) {
    if (width * height > limits_.max_texture_pixels)
      throw Error(ErrorKind::TooLarge,
                  fmt::format("{} is {} x {} pixels, over the limit of {} pixels per texture", what, width,
                              height, limits_.max_texture_pixels));
    check_total(pixels_ + width * height, what);
    if (limits_.reserve) limits_.reserve(texture_decode_bytes(bytes, width, height), what);
  };
  return l;
}

Texture ModelTextures::decode(std::span<const uint8_t> bytes, ColorSpace space,
                              const std::string& what) const {
  return decode_texture(bytes, space, image_limits(bytes, what), what);
}

void ModelTextures::check_total(int64_t pixels, const std::string& what) const {
  if (pixels > limits_.max_total_texture_pixels)
    throw Error(ErrorKind::TooLarge, fmt::format("the model's textures are over {} pixels together (at {})",
                                                 limits_.max_total_texture_pixels, what));
}

std::shared_ptr<const Texture> ModelTextures::counted(std::shared_ptr<const Texture> texture,
                                                      const std::string& what) {
  if (seen_.insert(texture.get()).second) {
    pixels_ += int64_t(texture->width()) * texture->height();
    check_total(pixels_, what);
  }
  return texture;
}

std::shared_ptr<const Texture> ModelTextures::embedded(int image, std::span<const uint8_t> bytes,
                                                       ColorSpace space, const std::string& what) {
  return counted(cache_.get(fmt::format("{}#image{}", model_key_, image), space,
                            [&] { return decode(bytes, space, what); }),
                 what);
}

std::shared_ptr<const Texture> ModelTextures::file(const std::string& relative, ColorSpace space,
                                                   const std::string& what) {
  return counted(cache_.get(files_.cache_key(relative), space,
                            [&] { return decode(files_.read(relative, what), space, what); }),
                 what);
}

}  // namespace lp
