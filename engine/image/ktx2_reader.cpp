// KTX 2.0 reader for the textures write_ktx2 makes. Every offset and length is checked against the
// file before it is followed, and the image sizes against the limits before anything is allocated.
#include <Imath/half.h>
#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cstring>
#include <optional>

#include "engine/core/error.hpp"
#include "engine/image/image_limits.hpp"
#include "engine/image/ktx2.hpp"
#include "engine/image/ktx2_layout.hpp"
#include "engine/image/ktx_key_values.hpp"

namespace lp {
namespace {

[[noreturn]] void corrupt(const std::string& what) {
  throw Error(ErrorKind::Corrupt, "KTX2: " + what);
}

class Reader {
 public:
  explicit Reader(std::span<const uint8_t> bytes) : bytes_(bytes) {}

  // `length` bytes at `offset`, or Corrupt naming `what` if they are not all in the file.
  std::span<const uint8_t> range(uint64_t offset, uint64_t length, const char* what) const {
    if (offset > bytes_.size() || length > bytes_.size() - offset)
      corrupt(fmt::format("{} ({} bytes at {}) leaves the file of {} bytes", what, length, offset,
                          bytes_.size()));
    return bytes_.subspan(size_t(offset), size_t(length));
  }
  template <class T>
  T get(uint64_t offset, const char* what) const {
    T value;
    std::memcpy(&value, range(offset, sizeof(T), what).data(), sizeof(T));
    return value;
  }

 private:
  std::span<const uint8_t> bytes_;
};

struct Header {
  uint32_t vk_format, type_size, width, height, depth, layers, faces, levels, supercompression;
  uint32_t dfd_offset, dfd_length, kvd_offset, kvd_length;
  uint64_t sgd_offset, sgd_length;
};

Header read_header(const Reader& in) {
  const auto id = in.range(0, ktx2::kIdentifier.size(), "the identifier");
  if (!std::equal(id.begin(), id.end(), ktx2::kIdentifier.begin()))
    throw Error(ErrorKind::Unsupported, "not a KTX 2.0 file");
  uint32_t f[13];
  for (size_t i = 0; i < 13; ++i) f[i] = in.get<uint32_t>(12 + 4 * i, "the header");
  return {f[0],
          f[1],
          f[2],
          f[3],
          f[4],
          f[5],
          f[6],
          f[7],
          f[8],
          f[9],
          f[10],
          f[11],
          f[12],
          in.get<uint64_t>(ktx2::kIndexEnd - 16, "the index"),
          in.get<uint64_t>(ktx2::kIndexEnd - 8, "the index")};
}

PixelPrecision check_texture_kind(const Header& h) {
  std::optional<PixelPrecision> precision;
  for (const auto p : {PixelPrecision::Half, PixelPrecision::Float})
    if (h.vk_format == ktx2::vk_format(p)) precision = p;
  if (!precision)
    throw Error(ErrorKind::Unsupported,
                fmt::format("KTX2: vkFormat {} is not RGBA16F or RGBA32F", h.vk_format));
  if (h.type_size != ktx2::component_bytes(*precision)) corrupt(fmt::format("typeSize {}", h.type_size));
  if (h.depth != 0 || h.layers != 0 || (h.faces != 1 && h.faces != ktx2::kCubeFaces))
    throw Error(ErrorKind::Unsupported, "KTX2: not a 2D texture or a cube map (a volume or an array)");
  if (h.faces == ktx2::kCubeFaces && h.width != h.height)
    corrupt(fmt::format("a cube map of {}x{} faces, not square", h.width, h.height));
  if (h.supercompression != 0) throw Error(ErrorKind::Unsupported, "KTX2: supercompressed");
  if (h.sgd_length != 0 || h.sgd_offset != 0) corrupt("global data without supercompression");
  if (h.levels < 1 || h.levels > uint32_t(std::bit_width(std::max(h.width, h.height))))
    corrupt(fmt::format("{} levels for a {}x{} base", h.levels, h.width, h.height));
  return *precision;
}

void check_dfd(const Reader& in, const Header& h, PixelPrecision precision) {
  const auto want = ktx2::data_format_descriptor(precision);
  if (h.dfd_offset != ktx2::kIndexEnd + uint64_t(h.levels) * ktx2::kLevelIndexEntryBytes)
    corrupt("the data format descriptor does not follow the level index");
  if (h.dfd_length != want.size() * 4 || h.kvd_offset != (h.kvd_length ? h.dfd_offset + h.dfd_length : 0))
    corrupt("the data format descriptor's length");
  const auto dfd = in.range(h.dfd_offset, h.dfd_length, "the data format descriptor");
  if (std::memcmp(dfd.data(), want.data(), dfd.size()) != 0)
    throw Error(ErrorKind::Unsupported, "KTX2: a data format descriptor other than linear RGBA floats");
}

std::map<std::string, std::string> read_key_values(const Reader& in, const Header& h) {
  return read_ktx_key_values(in.range(h.kvd_offset, h.kvd_length, "the key/value data"), "KTX2");
}

// A level of `height` rows: one face, or a cube map's faces one after the other.
Image read_level(const Reader& in, uint64_t level_index_at, uint32_t p, int width, int height,
                 PixelPrecision precision) {
  const uint64_t entry = level_index_at + uint64_t(p) * ktx2::kLevelIndexEntryBytes;
  const auto offset = in.get<uint64_t>(entry, "the level index");
  const auto length = in.get<uint64_t>(entry + 8, "the level index");
  const auto uncompressed = in.get<uint64_t>(entry + 16, "the level index");
  const uint64_t expected = uint64_t(width) * uint64_t(height) * ktx2::texel_bytes(precision);
  if (length != expected || uncompressed != expected || offset % ktx2::level_alignment(precision) != 0)
    corrupt(fmt::format("level {} has {} bytes at {}, a {}x{} level takes {}", p, length, offset, width,
                        height, expected));
  const auto data = in.range(offset, length, "a level");
  Image image(width, height);
  auto out = image.data();
  const size_t component = ktx2::component_bytes(precision);
  for (size_t i = 0, texel = 0; i < out.size(); i += 3, texel += ktx2::kChannels)
    for (size_t c = 0; c < 3; ++c) {
      const uint8_t* at = data.data() + (texel + c) * component;
      if (precision == PixelPrecision::Half) {
        imath_half_bits_t bits;
        std::memcpy(&bits, at, 2);
        out[i + c] = imath_half_to_float(bits);
      } else {
        std::memcpy(&out[i + c], at, 4);
      }
    }
  return image;
}

}  // namespace

Ktx2Texture read_ktx2(std::span<const uint8_t> bytes, const ImageLimits& limits) {
  const Reader in(bytes);
  const Header h = read_header(in);
  Ktx2Texture t;
  t.precision = check_texture_kind(h);
  t.vk_format = h.vk_format;
  t.type_size = h.type_size;
  check_dfd(in, h, t.precision);
  t.metadata = read_key_values(in, h);
  const uint64_t level_index_at = ktx2::kIndexEnd;
  t.faces = h.faces;
  // The levels after it take a third more at most.
  check_image_size(h.width, int64_t(h.height) * h.faces, limits);
  for (uint32_t p = 0; p < h.levels; ++p)
    t.levels.push_back(read_level(in, level_index_at, p, int(std::max(1u, h.width >> p)),
                                  int(std::max(1u, h.height >> p) * h.faces), t.precision));
  return t;
}

Image ktx2_cube_face(const Image& level, int face) {
  const int size = level.width();
  if (level.height() != ktx2::kCubeFaces * size || face < 0 || face >= ktx2::kCubeFaces)
    throw Error(ErrorKind::InvalidArgument, fmt::format("KTX2: no face {} in a cube map level of {}x{}", face,
                                                        level.width(), level.height()));
  Image out(size, size);
  for (int j = 0; j < size; ++j) std::copy_n(level.row(face * size + j), 3 * size, out.row(j));
  return out;
}

}  // namespace lp
