// KTX 1.1 writer and reader of R11F_G11F_B10F cube maps and 2D textures. The reader checks every size
// against the bytes present and the limits before it allocates.
#include "engine/image/ktx1.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cstring>

#include "engine/core/error.hpp"
#include "engine/image/image_limits.hpp"
#include "engine/image/ktx_key_values.hpp"
#include "engine/image/packed_float.hpp"

namespace lp {
namespace {

static_assert(std::endian::native == std::endian::little, "KTX files are written little-endian");

constexpr std::array<uint8_t, 12> kIdentifier = {0xAB, 0x4B, 0x54, 0x58, 0x20, 0x31,
                                                 0x31, 0xBB, 0x0D, 0x0A, 0x1A, 0x0A};
constexpr size_t kHeaderBytes = 64;
constexpr uint32_t kTexelBytes = 4;

[[noreturn]] void corrupt(const std::string& what) {
  throw Error(ErrorKind::Corrupt, "KTX1: " + what);
}

void put(std::vector<uint8_t>& out, uint32_t word) {
  const size_t at = out.size();
  out.resize(at + 4);
  std::memcpy(out.data() + at, &word, 4);
}

void put_string(std::vector<uint8_t>& out, const std::string& s) {
  out.insert(out.end(), s.begin(), s.end());
  out.push_back(0);
}

void check_cube_chain(std::span<const Image> levels) {
  if (levels.empty() || levels[0].empty()) throw Error(ErrorKind::InvalidArgument, "KTX1: no base level");
  const int size = levels[0].height();
  const size_t most = size_t(std::bit_width(unsigned(size)));
  if (levels.size() > most)
    throw Error(ErrorKind::InvalidArgument,
                fmt::format("KTX1: {} levels, a cube of {} has at most {}", levels.size(), size, most));
  for (size_t p = 0; p < levels.size(); ++p) {
    const int n = std::max(1, size >> p);
    if (levels[p].width() != ktx1::kCubeFaces * n || levels[p].height() != n)
      throw Error(ErrorKind::InvalidArgument,
                  fmt::format("KTX1: level {} is {}x{}, not a strip of six faces of {}", p, levels[p].width(),
                              levels[p].height(), n));
  }
}

std::vector<uint8_t> key_values(const std::map<std::string, std::string>& metadata) {
  std::vector<uint8_t> out;
  for (const auto& [key, value] : metadata) {
    if (key.empty() || key.find('\0') != std::string::npos || value.find('\0') != std::string::npos)
      throw Error(ErrorKind::InvalidArgument, "KTX1: metadata key '" + key + "' is empty or holds a NUL");
    put(out, uint32_t(key.size() + 1 + value.size() + 1));
    put_string(out, key);
    put_string(out, value);
    out.resize((out.size() + 3) / 4 * 4, 0);  // valuePadding
  }
  return out;
}

}  // namespace

std::vector<uint8_t> write_ktx1_cube(std::span<const Image> levels,
                                     const std::map<std::string, std::string>& metadata) {
  check_cube_chain(levels);
  const std::vector<uint8_t> kv = key_values(metadata);
  std::vector<uint8_t> out(kIdentifier.begin(), kIdentifier.end());
  const uint32_t size = uint32_t(levels[0].height());
  for (const uint32_t field :
       {ktx1::kEndianness, ktx1::kGlR11fG11fB10f, 1u, ktx1::kGlRgb, ktx1::kGlR11fG11fB10f,
        ktx1::kGlR11fG11fB10f, size, size, 0u /* depth */, 0u /* array elements */,
        uint32_t(ktx1::kCubeFaces), uint32_t(levels.size()), uint32_t(kv.size())})
    put(out, field);
  out.insert(out.end(), kv.begin(), kv.end());
  for (const Image& level : levels) {
    const int n = level.height();
    put(out, uint32_t(n) * uint32_t(n) * kTexelBytes);  // imageSize: one face
    for (int face = 0; face < ktx1::kCubeFaces; ++face)
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) put(out, pack_r11g11b10f(level.at(face * n + i, j)));
  }
  return out;
}

namespace {

class Reader {
 public:
  explicit Reader(std::span<const uint8_t> bytes) : bytes_(bytes) {}
  std::span<const uint8_t> take(uint64_t length, const char* what) {
    if (length > bytes_.size() - at_)
      corrupt(
          fmt::format("{} ({} bytes at {}) leaves the file of {} bytes", what, length, at_, bytes_.size()));
    const auto out = bytes_.subspan(at_, size_t(length));
    at_ += size_t(length);
    return out;
  }
  uint32_t word(const char* what) {
    uint32_t w;
    std::memcpy(&w, take(4, what).data(), 4);
    return w;
  }
  bool done() const { return at_ == bytes_.size(); }

 private:
  std::span<const uint8_t> bytes_;
  size_t at_ = 0;
};

Ktx1Header read_header(Reader& in) {
  const auto id = in.take(kIdentifier.size(), "the identifier");
  if (!std::equal(id.begin(), id.end(), kIdentifier.begin()))
    throw Error(ErrorKind::Unsupported, "not a KTX 1.1 file");
  if (in.word("the header") != ktx1::kEndianness)
    throw Error(ErrorKind::Unsupported, "KTX1: not little-endian");
  Ktx1Header h;
  for (uint32_t* field :
       {&h.gl_type, &h.gl_type_size, &h.gl_format, &h.gl_internal_format, &h.gl_base_internal_format,
        &h.width, &h.height, &h.depth, &h.array_elements, &h.faces, &h.levels})
    *field = in.word("the header");
  return h;
}

void check_header(const Ktx1Header& h) {
  if (h.gl_internal_format != ktx1::kGlR11fG11fB10f ||
      (h.gl_type != ktx1::kGlR11fG11fB10f && h.gl_type != ktx1::kGlUnsignedInt10f11f11fRev))
    throw Error(ErrorKind::Unsupported, fmt::format("KTX1: glInternalFormat {:#x} glType {:#x} is not "
                                                    "R11F_G11F_B10F",
                                                    h.gl_internal_format, h.gl_type));
  if (h.depth != 0 || h.array_elements != 0 || (h.faces != 1 && h.faces != ktx1::kCubeFaces))
    throw Error(ErrorKind::Unsupported, "KTX1: not a 2D texture or a cube map (a volume or an array)");
  if (h.faces == ktx1::kCubeFaces && h.width != h.height)
    corrupt(fmt::format("a cube map of {}x{} faces, not square", h.width, h.height));
  if (h.width == 0 || h.height == 0) corrupt("a texture of no texels");
  if (h.levels < 1 || h.levels > uint32_t(std::bit_width(std::max(h.width, h.height))))
    corrupt(fmt::format("{} levels for a {}x{} base", h.levels, h.width, h.height));
}

// A level: its faces side by side, each face's texels unpacked.
Image read_level(Reader& in, uint32_t p, uint32_t width, uint32_t height, uint32_t faces) {
  const uint64_t face_bytes = uint64_t(width) * height * kTexelBytes;
  if (in.word("a level's imageSize") != face_bytes)
    corrupt(fmt::format("level {} does not hold {}x{} faces", p, width, height));
  const auto data = in.take(face_bytes * faces, "a level");
  Image image(int(width * faces), int(height));
  size_t at = 0;
  for (uint32_t face = 0; face < faces; ++face)
    for (uint32_t j = 0; j < height; ++j)
      for (uint32_t i = 0; i < width; ++i, at += kTexelBytes) {
        uint32_t texel;
        std::memcpy(&texel, data.data() + at, 4);
        image.set(int(face * width + i), int(j), unpack_r11g11b10f(texel));
      }
  return image;
}

}  // namespace

Ktx1Texture read_ktx1(std::span<const uint8_t> bytes, const ImageLimits& limits) {
  Reader in(bytes);
  Ktx1Texture t;
  t.header = read_header(in);
  const Ktx1Header& h = t.header;
  const uint32_t kv_bytes = in.word("the header");
  check_header(h);
  t.metadata = read_ktx_key_values(in.take(kv_bytes, "the key/value data"), "KTX1");
  check_image_size(int64_t(h.width) * h.faces, h.height, limits);  // the levels after it take a third more
  for (uint32_t p = 0; p < h.levels; ++p)
    t.levels.push_back(read_level(in, p, std::max(1u, h.width >> p), std::max(1u, h.height >> p), h.faces));
  if (!in.done()) corrupt("bytes after the last level");
  return t;
}

}  // namespace lp
