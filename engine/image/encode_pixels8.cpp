#include "engine/image/encode_pixels8.hpp"

#include "engine/image/jpeg.hpp"
#include "engine/image/webp.hpp"

namespace lp {

std::vector<uint8_t> encode_pixels8(const Pixels8& picture, ImageFormat format) {
  switch (format) {
    case ImageFormat::Png:
      if (picture.channels != 3) throw Error(ErrorKind::InvalidArgument, "PNG previews are RGB");
      return encode_png_rgb8(picture.bytes, picture.width, picture.height);
    case ImageFormat::Jpeg:
      return encode_jpeg(picture);
    case ImageFormat::Webp:
      return encode_webp(picture);
    default:
      throw Error(ErrorKind::InvalidArgument,
                  std::string("not an 8-bit format: ") + std::string(enum_name(format)));
  }
}

}  // namespace lp
