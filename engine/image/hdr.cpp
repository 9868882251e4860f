// Radiance RGBE: our own bounded reader (flat and new-style run-length scanlines), stb_image_write for
// writing. Every read is checked against the input size, so no file can make the reader loop or allocate
// more than its bytes can describe.
#include <stb_image_write.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string_view>

#include "engine/image/byte_sink.hpp"
#include "engine/image/image_limits.hpp"

namespace lp {
namespace {

[[noreturn]] void corrupt(const std::string& why) {
  throw Error(ErrorKind::Corrupt, "corrupt Radiance HDR: " + why);
}

// Longest header line we accept; real headers hold short key=value lines and comments.
constexpr size_t kMaxHeaderLine = 4096;
// A new-style run-length scanline: 2, 2, width (16 bits), then per channel runs of at most 127 pixels
// in two bytes; scanlines outside this width range are always flat.
constexpr int kMinRleWidth = 8, kMaxRleWidth = 32767, kMaxRun = 127;

class Cursor {
 public:
  explicit Cursor(std::span<const uint8_t> b) : b_(b) {}
  size_t left() const { return b_.size() - pos_; }
  uint8_t byte() {
    if (pos_ >= b_.size()) corrupt("data ends before the last pixel");
    return b_[pos_++];
  }
  const uint8_t* take(size_t n) {
    if (left() < n) corrupt("data ends before the last pixel");
    pos_ += n;
    return b_.data() + pos_ - n;
  }
  bool peek_rle_start(int width) const {
    return left() >= 4 && b_[pos_] == 2 && b_[pos_ + 1] == 2 && !(b_[pos_ + 2] & 0x80) &&
           ((int(b_[pos_ + 2]) << 8) | b_[pos_ + 3]) == width;
  }
  // The next line without its '\n'; throws if there is none or it holds a NUL byte.
  std::string_view line() {
    const auto* start = reinterpret_cast<const char*>(b_.data() + pos_);
    const std::string_view rest(start, std::min(left(), kMaxHeaderLine + 1));
    const size_t end = rest.find('\n');
    if (end == std::string_view::npos)
      corrupt("header line missing or over " + std::to_string(kMaxHeaderLine) + " bytes");
    const std::string_view text = rest.substr(0, end);
    if (text.find('\0') != std::string_view::npos) corrupt("header holds a NUL byte");
    pos_ += end + 1;
    return text;
  }

 private:
  std::span<const uint8_t> b_;
  size_t pos_ = 0;
};

struct Size {
  int64_t width = 0, height = 0;
};

int64_t parse_dimension(std::string_view& s) {
  int64_t v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end == s.data()) return -1;
  s.remove_prefix(size_t(end - s.data()));
  return v;
}

// "-Y H +X W" (rows top to bottom, pixels left to right), the only layout in common use.
Size parse_resolution(std::string_view line) {
  const std::string quoted = fmt::format("'{}'", line.substr(0, 64));
  std::string_view s = line;
  Size size;
  if (!s.starts_with("-Y ")) corrupt("unsupported resolution line " + quoted + " (expected -Y H +X W)");
  s.remove_prefix(3);
  size.height = parse_dimension(s);
  if (!s.starts_with(" +X ")) corrupt("unsupported resolution line " + quoted + " (expected -Y H +X W)");
  s.remove_prefix(4);
  size.width = parse_dimension(s);
  if (!s.empty() || size.width < 0 || size.height < 0) corrupt("bad resolution line " + quoted);
  return size;
}

Size read_header(Cursor& in) {
  const std::string_view magic = in.line();
  if (magic != "#?RADIANCE" && magic != "#?RGBE") corrupt("no #?RADIANCE signature");
  for (std::string_view line = in.line(); !line.empty(); line = in.line()) {
    if (line.starts_with("FORMAT=") && line != "FORMAT=32-bit_rle_rgbe")
      throw Error(ErrorKind::Unsupported, "Radiance HDR pixel format " + std::string(line.substr(7, 64)) +
                                              " is not supported (expected 32-bit_rle_rgbe)");
  }
  return parse_resolution(in.line());
}

// The fewest bytes a scanline of this width can take: flat, or run-length with every run full.
size_t min_scanline_bytes(int64_t width) {
  if (width < kMinRleWidth || width > kMaxRleWidth) return size_t(width) * 4;
  return std::min(size_t(width) * 4, 4 + 4 * 2 * size_t((width + kMaxRun - 1) / kMaxRun));
}

void read_rle_scanline(Cursor& in, int width, uint8_t* rgbe) {
  in.take(4);  // 2, 2, width: checked by peek_rle_start
  for (int channel = 0; channel < 4; ++channel) {
    for (int x = 0; x < width;) {
      int count = in.byte();
      const bool run = count > 128;
      if (run) count -= 128;
      if (count == 0) corrupt("zero-length run");
      if (count > width - x) corrupt("run past the end of a scanline");
      if (run) {
        const uint8_t value = in.byte();
        for (int i = 0; i < count; ++i) rgbe[(x + i) * 4 + channel] = value;
      } else {
        const uint8_t* values = in.take(size_t(count));
        for (int i = 0; i < count; ++i) rgbe[(x + i) * 4 + channel] = values[i];
      }
      x += count;
    }
  }
}

// The same conversion as stb_image and Radiance's colr_color without the half-step: m * 2^(e - 136).
void rgbe_to_float(const uint8_t* rgbe, int width, float* out) {
  for (int x = 0; x < width; ++x, rgbe += 4, out += 3) {
    const float f = rgbe[3] ? std::ldexp(1.0f, int(rgbe[3]) - 136) : 0.0f;
    out[0] = rgbe[0] * f, out[1] = rgbe[1] * f, out[2] = rgbe[2] * f;
  }
}

}  // namespace

Image read_hdr(std::span<const uint8_t> bytes, const ImageLimits& limits) {
  Cursor in(bytes);
  const Size size = read_header(in);
  check_image_size(size.width, size.height, limits);
  if (in.left() / min_scanline_bytes(size.width) < size_t(size.height))
    corrupt(
        fmt::format("{} bytes of pixel data cannot hold {} x {} pixels", in.left(), size.width, size.height));
  const int width = int(size.width);
  const bool rle_width = width >= kMinRleWidth && width <= kMaxRleWidth;
  Image image(width, int(size.height));
  std::vector<uint8_t> rgbe(size_t(width) * 4);
  for (int y = 0; y < image.height(); ++y) {
    if (rle_width && in.peek_rle_start(width))
      read_rle_scanline(in, width, rgbe.data());
    else
      std::copy_n(in.take(rgbe.size()), rgbe.size(), rgbe.begin());
    rgbe_to_float(rgbe.data(), width, image.row(y));
  }
  return image;
}

std::vector<uint8_t> write_hdr(const Image& image) {
  std::vector<uint8_t> out;
  if (!stbi_write_hdr_to_func(append_to_byte_vector, &out, image.width(), image.height(), 3,
                              image.data().data()))
    throw Error(ErrorKind::Internal, "cannot encode Radiance HDR");
  return out;
}

}  // namespace lp
