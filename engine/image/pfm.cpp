// Portable Float Map: "PF" (RGB) or "Pf" (grey), width height, scale (negative = little-endian),
// then float rows stored bottom to top.
#include <bit>
#include <cstring>
#include <string>

#include "engine/image/image_limits.hpp"

namespace lp {
namespace {

class HeaderReader {
 public:
  explicit HeaderReader(std::span<const uint8_t> b) : b_(b) {}

  std::string token() {
    while (pos_ < b_.size() && std::isspace(b_[pos_])) ++pos_;
    std::string t;
    while (pos_ < b_.size() && !std::isspace(b_[pos_]) && t.size() < 64) t.push_back(char(b_[pos_++]));
    if (t.empty()) throw Error(ErrorKind::Corrupt, "PFM header is truncated");
    return t;
  }
  // The header ends with exactly one whitespace character after the scale.
  size_t data_offset() {
    if (pos_ >= b_.size()) throw Error(ErrorKind::Corrupt, "PFM header is truncated");
    return pos_ + 1;
  }

 private:
  std::span<const uint8_t> b_;
  size_t pos_ = 0;
};

template <class T>
T parse_number(const std::string& s, const char* what) {
  try {
    size_t used = 0;
    T v;
    if constexpr (std::is_same_v<T, double>) v = std::stod(s, &used);
    else v = T(std::stoll(s, &used));
    if (used != s.size()) throw std::invalid_argument(s);
    return v;
  } catch (const std::exception&) {
    throw Error(ErrorKind::Corrupt, std::string("PFM header has a bad ") + what + ": '" + s + "'");
  }
}

float load_float(const uint8_t* p, bool little_endian) {
  uint32_t bits;
  std::memcpy(&bits, p, 4);
  if (little_endian != (std::endian::native == std::endian::little)) bits = __builtin_bswap32(bits);
  return std::bit_cast<float>(bits);
}

}  // namespace

Image read_pfm(std::span<const uint8_t> bytes, const ImageLimits& limits) {
  HeaderReader header(bytes);
  const std::string magic = header.token();
  if (magic != "PF" && magic != "Pf") throw Error(ErrorKind::Unsupported, "not a PFM file");
  const int channels = magic == "PF" ? 3 : 1;
  const auto width = parse_number<int64_t>(header.token(), "width");
  const auto height = parse_number<int64_t>(header.token(), "height");
  const auto scale = parse_number<double>(header.token(), "scale");
  if (scale == 0.0 || !std::isfinite(scale)) throw Error(ErrorKind::Corrupt, "PFM scale must be non-zero");
  check_image_size(width, height, limits);
  const size_t offset = header.data_offset();
  const size_t needed = size_t(width) * size_t(height) * size_t(channels) * 4;
  if (bytes.size() - offset < needed)
    throw Error(ErrorKind::Corrupt, fmt::format("PFM data is truncated: {} bytes for {} x {} x {} floats",
                                                bytes.size() - offset, width, height, channels));
  const bool little = scale < 0;
  Image image(static_cast<int>(width), static_cast<int>(height));
  for (int y = 0; y < height; ++y) {
    const uint8_t* src = bytes.data() + offset + size_t(height - 1 - y) * size_t(width) * channels * 4;
    float* dst = image.row(y);
    for (int64_t x = 0; x < width; ++x) {
      for (int c = 0; c < 3; ++c) dst[x * 3 + c] = load_float(src + (x * channels + (channels == 3 ? c : 0)) * 4, little);
    }
  }
  return image;
}

std::vector<uint8_t> write_pfm(const Image& image) {
  const std::string header = fmt::format("PF\n{} {}\n-1.0\n", image.width(), image.height());
  std::vector<uint8_t> out(header.begin(), header.end());
  const size_t row_bytes = size_t(image.width()) * 3 * 4;
  out.resize(header.size() + row_bytes * size_t(image.height()));
  for (int y = 0; y < image.height(); ++y) {
    uint8_t* dst = out.data() + header.size() + size_t(image.height() - 1 - y) * row_bytes;
    const float* src = image.row(y);
    for (size_t i = 0; i < size_t(image.width()) * 3; ++i) {
      uint32_t bits = std::bit_cast<uint32_t>(src[i]);
      if constexpr (std::endian::native == std::endian::big) bits = __builtin_bswap32(bits);
      std::memcpy(dst + i * 4, &bits, 4);
    }
  }
  return out;
}

}  // namespace lp
