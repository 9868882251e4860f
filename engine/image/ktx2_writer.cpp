// KTX 2.0 writer: header, index, level index, Data Format Descriptor, key/value data, then the levels
// from the smallest to the largest, each on its alignment, little-endian throughout; RGBA floats or ASTC
// HDR blocks.
#include <Imath/half.h>
#include <fmt/format.h>

#include <array>
#include <bit>
#include <cstring>
#include <functional>

#include "engine/core/error.hpp"
#include "engine/image/astc.hpp"
#include "engine/image/ktx2.hpp"
#include "engine/image/ktx2_layout.hpp"

namespace lp {
namespace {

static_assert(std::endian::native == std::endian::little, "KTX 2.0 files are little-endian");

class Writer {
 public:
  template <class T>
  void put(T value) {
    const size_t at = bytes_.size();
    bytes_.resize(at + sizeof(T));
    std::memcpy(bytes_.data() + at, &value, sizeof(T));
  }
  template <class T>
  void put_at(size_t at, T value) {
    std::memcpy(bytes_.data() + at, &value, sizeof(T));
  }
  void put_bytes(const void* data, size_t size) {
    const auto* p = static_cast<const uint8_t*>(data);
    bytes_.insert(bytes_.end(), p, p + size);
  }
  void align(size_t alignment) { bytes_.resize((bytes_.size() + alignment - 1) / alignment * alignment, 0); }
  size_t size() const { return bytes_.size(); }
  void reserve(size_t size) { bytes_.reserve(size); }
  std::vector<uint8_t> take() { return std::move(bytes_); }

 private:
  std::vector<uint8_t> bytes_;
};

// A level's image: one face (2D) or six stacked (a cube map). The face of level 0 is w0 x h0.
void check_chain(std::span<const Image> levels, int faces) {
  if (levels.empty() || levels[0].empty()) throw Error(ErrorKind::InvalidArgument, "KTX2: no base level");
  const int w0 = levels[0].width(), h0 = levels[0].height() / faces;
  if (faces > 1 && (levels[0].height() != faces * w0))
    throw Error(ErrorKind::InvalidArgument, fmt::format("KTX2: a cube map level of {}x{} is not six square "
                                                        "faces stacked",
                                                        levels[0].width(), levels[0].height()));
  const size_t most = size_t(std::bit_width(unsigned(std::max(w0, h0))));
  if (levels.size() > most)
    throw Error(ErrorKind::InvalidArgument,
                fmt::format("KTX2: {} levels, a {}x{} base has at most {}", levels.size(), w0, h0, most));
  for (size_t p = 1; p < levels.size(); ++p)
    if (levels[p].width() != std::max(1, w0 >> p) || levels[p].height() != faces * std::max(1, h0 >> p))
      throw Error(ErrorKind::InvalidArgument,
                  fmt::format("KTX2: level {} is {}x{}, not a mip level of {}x{}", p, levels[p].width(),
                              levels[p].height(), w0, faces * h0));
}

std::map<std::string, std::string> all_metadata(const std::map<std::string, std::string>& metadata) {
  std::map<std::string, std::string> all = {{"KTXorientation", "rd"},
                                            {"KTXwriter", std::string("Lightprobe ") + LIGHTPROBE_VERSION}};
  for (const auto& [key, value] : metadata) {
    if (key.empty() || key.starts_with("KTX") || key.starts_with("ktx") ||
        key.find('\0') != std::string::npos)
      throw Error(ErrorKind::InvalidArgument, "KTX2: metadata key '" + key + "' is empty or reserved");
    all[key] = value;
  }
  return all;  // sorted by key, bytewise: the order of UTF-8 code points the format asks for
}

void put_key_values(Writer& out, const std::map<std::string, std::string>& metadata) {
  for (const auto& [key, value] : metadata) {
    out.put(uint32_t(key.size() + 1 + value.size() + 1));
    out.put_bytes(key.c_str(), key.size() + 1);
    out.put_bytes(value.c_str(), value.size() + 1);
    out.align(4);
  }
}

void put_pixels(Writer& out, const Image& image, PixelPrecision precision) {
  const auto put = [&](float v) {
    if (precision == PixelPrecision::Half)
      out.put(imath_float_to_half(v));
    else
      out.put(v);
  };
  const auto data = image.data();
  for (size_t i = 0; i < data.size(); i += 3) {
    put(data[i]), put(data[i + 1]), put(data[i + 2]);
    put(1.0f);  // alpha
  }
}

// What the file's format fixes: the header's vkFormat and typeSize, the levels' alignment, the Data Format
// Descriptor, and how a level's bytes are made from its image.
struct Format {
  uint32_t vk_format;
  uint32_t type_size;
  uint32_t alignment;
  std::vector<uint32_t> descriptor;
  std::function<size_t(const Image&)> level_bytes;
  std::function<void(Writer&, const Image&)> put_level;
};

Format uncompressed(PixelPrecision precision) {
  return {
      ktx2::vk_format(precision),
      ktx2::component_bytes(precision),
      ktx2::level_alignment(precision),
      ktx2::data_format_descriptor(precision),
      [precision](const Image& level) { return size_t(level.pixel_count()) * ktx2::texel_bytes(precision); },
      [precision](Writer& out, const Image& level) { put_pixels(out, level, precision); }};
}

// typeSize 1 and levels on 16 bytes (lcm of the block size and 4), as the specification asks of a block-
// compressed format; a cube level's faces one after the other, each its own blocks.
Format astc_cube(AstcHdrEncoder& encoder) {
  const auto face_size = [](const Image& level) { return level.width(); };
  return {ktx2::kVkFormatAstc4x4Sfloat,
          1,
          uint32_t(kAstcBlockBytes),
          ktx2::astc_4x4_sfloat_descriptor(),
          [face_size](const Image& level) {
            return ktx2::kCubeFaces * astc_bytes(face_size(level), face_size(level));
          },
          [&encoder](Writer& out, const Image& level) {
            for (int f = 0; f < ktx2::kCubeFaces; ++f) {
              const std::vector<uint8_t> blocks = encoder.compress(ktx2_cube_face(level, f));
              out.put_bytes(blocks.data(), blocks.size());
            }
          }};
}

std::vector<uint8_t> write(std::span<const Image> levels, int faces, const Format& format,
                           const std::map<std::string, std::string>& metadata) {
  check_chain(levels, faces);
  const uint32_t level_count = uint32_t(levels.size());
  Writer out;
  size_t pixel_bytes = 0;
  for (const Image& level : levels) pixel_bytes += format.level_bytes(level);
  out.reserve(pixel_bytes + levels.size() * format.alignment + 4096);
  out.put_bytes(ktx2::kIdentifier.data(), ktx2::kIdentifier.size());
  for (const uint32_t field :
       {format.vk_format, format.type_size, uint32_t(levels[0].width()), uint32_t(levels[0].height() / faces),
        0u /* depth */, 0u /* layers */, uint32_t(faces), level_count, 0u /* supercompression */})
    out.put(field);
  const size_t index_at = out.size();
  out.put_bytes(std::array<uint8_t, ktx2::kIndexEnd - ktx2::kHeaderEnd>{}.data(),
                ktx2::kIndexEnd - ktx2::kHeaderEnd);
  const size_t level_index_at = out.size();
  out.put_bytes(std::vector<uint8_t>(level_count * ktx2::kLevelIndexEntryBytes).data(),
                level_count * ktx2::kLevelIndexEntryBytes);

  const uint32_t dfd_at = uint32_t(out.size());
  for (const uint32_t word : format.descriptor) out.put(word);
  const uint32_t kvd_at = uint32_t(out.size());
  put_key_values(out, all_metadata(metadata));
  const uint32_t kvd_bytes = uint32_t(out.size()) - kvd_at;
  out.put_at(index_at, dfd_at);
  out.put_at(index_at + 4, kvd_at - dfd_at);
  out.put_at(index_at + 8, kvd_at);
  out.put_at(index_at + 12, kvd_bytes);  // sgdByteOffset and sgdByteLength stay 0

  for (size_t p = levels.size(); p-- > 0;) {
    out.align(format.alignment);
    const uint64_t at = out.size();
    format.put_level(out, levels[p]);
    const uint64_t length = out.size() - at;
    const size_t entry = level_index_at + p * ktx2::kLevelIndexEntryBytes;
    out.put_at(entry, at);
    out.put_at(entry + 8, length);
    out.put_at(entry + 16, length);
  }
  return out.take();
}

}  // namespace

std::vector<uint8_t> write_ktx2(std::span<const Image> levels, PixelPrecision precision,
                                const std::map<std::string, std::string>& metadata) {
  return write(levels, 1, uncompressed(precision), metadata);
}

std::vector<uint8_t> write_ktx2_cube(std::span<const Image> levels, PixelPrecision precision,
                                     const std::map<std::string, std::string>& metadata) {
  return write(levels, ktx2::kCubeFaces, uncompressed(precision), metadata);
}

std::vector<uint8_t> write_ktx2_astc_cube(std::span<const Image> levels, const AstcOptions& options,
                                          const std::map<std::string, std::string>& metadata) {
  check_chain(levels, ktx2::kCubeFaces);  // before the compressor's setup
  AstcHdrEncoder encoder(options);
  return write(levels, ktx2::kCubeFaces, astc_cube(encoder), metadata);
}

}  // namespace lp
