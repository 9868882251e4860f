// Radiance RGBE through stb_image / stb_image_write.
#include <stb_image.h>
#include <stb_image_write.h>

#include <algorithm>
#include <memory>

#include "engine/image/byte_sink.hpp"
#include "engine/image/hdr_guard.hpp"
#include "engine/image/image_limits.hpp"

namespace lp {

Image read_hdr(std::span<const uint8_t> bytes, const ImageLimits& limits) {
  if (bytes.size() > size_t(std::numeric_limits<int>::max()))
    throw Error(ErrorKind::TooLarge, "Radiance HDR data over 2 GiB");
  const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
  const int len = int(bytes.size());
  int w = 0, h = 0, n = 0;
  if (!stbi_info_from_memory(data, len, &w, &h, &n))
    throw Error(ErrorKind::Corrupt, std::string("cannot read Radiance HDR header: ") + stbi_failure_reason());
  check_image_size(w, h, limits);
  check_hdr_structure(bytes);
  std::unique_ptr<float, void (*)(void*)> pixels(stbi_loadf_from_memory(data, len, &w, &h, &n, 3), stbi_image_free);
  if (!pixels) throw Error(ErrorKind::Corrupt, std::string("cannot decode Radiance HDR: ") + stbi_failure_reason());
  Image image(w, h);
  std::copy_n(pixels.get(), size_t(w) * size_t(h) * 3, image.data().begin());
  return image;
}

std::vector<uint8_t> write_hdr(const Image& image) {
  std::vector<uint8_t> out;
  if (!stbi_write_hdr_to_func(append_to_byte_vector, &out, image.width(), image.height(), 3, image.data().data()))
    throw Error(ErrorKind::InvalidArgument, "cannot encode Radiance HDR");
  return out;
}

}  // namespace lp
