#include "engine/image/exr_standard_attributes.hpp"

namespace lp {

std::vector<uint8_t> write_image_envmap(const Image& image, ImageFormat format, const ToneMap& tone,
                                        ExrEnvmap envmap) {
  return format == ImageFormat::Exr ? write_exr_envmap(image, envmap) : write_image(image, format, tone);
}

}  // namespace lp
