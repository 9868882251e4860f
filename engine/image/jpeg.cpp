#include "engine/image/jpeg.hpp"

#include <stb_image_write.h>

#include "engine/image/byte_sink.hpp"

namespace lp {

std::vector<uint8_t> encode_jpeg(const Pixels8& p, int quality) {
  check_pixels8(p, "JPEG");
  std::vector<uint8_t> out;
  if (!stbi_write_jpg_to_func(append_to_byte_vector, &out, p.width, p.height, p.channels, p.bytes.data(),
                              quality))
    throw Error(ErrorKind::Internal, "cannot encode JPEG");
  return out;
}

}  // namespace lp
