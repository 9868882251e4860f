#include "engine/image/exr_attributes.hpp"

#include <fmt/format.h>

#include <map>
#include <set>
#include <string>
#include <string_view>

#include "engine/core/error.hpp"

namespace lp {
namespace {

constexpr uint32_t kMultiPartFlag = 0x1000;
constexpr size_t kMaxNameLength = 255;

// The bytes the C++ reader consumes for a value of a fixed-layout type.
const std::map<std::string_view, uint64_t>& fixed_sizes() {
  static const std::map<std::string_view, uint64_t> sizes = {
      {"box2i", 16},    {"box2f", 16},   {"compression", 1},
      {"lineOrder", 1}, {"float", 4},    {"double", 8},
      {"int", 4},       {"v2i", 8},      {"v2f", 8},
      {"v2d", 16},      {"v3i", 12},     {"v3f", 12},
      {"v3d", 24},      {"m33f", 36},    {"m33d", 72},
      {"m44f", 64},     {"m44d", 128},   {"chromaticities", 32},
      {"envmap", 1},    {"keycode", 28}, {"rational", 8},
      {"timecode", 8},  {"tiledesc", 9}, {"deepImageState", 1}};
  return sizes;
}

class Walk {
 public:
  explicit Walk(std::span<const uint8_t> b) : b_(b) {}

  void headers() {
    const bool multi_part = u32(4) & kMultiPartFlag;
    pos_ = 8;
    do header();
    while (multi_part && at(pos_) != 0);
  }

 private:
  [[noreturn]] void bad(const std::string& why) const {
    throw Error(ErrorKind::Corrupt, "cannot read OpenEXR header: " + why);
  }
  uint8_t at(size_t i) const {
    if (i >= b_.size()) bad("the header ends early");
    return b_[i];
  }
  uint32_t u32(size_t i) const {
    return uint32_t(at(i)) | uint32_t(at(i + 1)) << 8 | uint32_t(at(i + 2)) << 16 | uint32_t(at(i + 3)) << 24;
  }
  std::string_view name() {
    const size_t start = pos_;
    while (at(pos_) != 0)
      if (++pos_ - start > kMaxNameLength) bad("a name of over 255 characters");
    ++pos_;
    return {reinterpret_cast<const char*>(b_.data() + start), pos_ - 1 - start};
  }

  void header() {
    std::set<std::string_view> seen;
    for (std::string_view attribute = name(); !attribute.empty(); attribute = name()) {
      if (!seen.insert(attribute).second) bad(fmt::format("attribute '{}' appears twice", attribute));
      const std::string_view type = name();
      const auto declared = int32_t(u32(pos_));
      pos_ += 4;
      if (declared < 0 || uint64_t(declared) > b_.size() - pos_)
        bad(fmt::format("an attribute of {} bytes with {} bytes left", declared, b_.size() - pos_));
      const uint64_t consumed = value_bytes(type, uint64_t(declared));
      if (consumed != uint64_t(declared))
        bad(fmt::format("attribute '{}' of type {} declares {} bytes but holds {}", attribute, type, declared,
                        consumed));
      pos_ += consumed;
    }
  }

  // What the C++ reader consumes for a value starting at pos_.
  uint64_t value_bytes(std::string_view type, uint64_t declared) const {
    if (const auto it = fixed_sizes().find(type); it != fixed_sizes().end()) return it->second;
    if (type == "chlist") return channel_list_bytes();
    if (type == "preview") return 8 + uint64_t{u32(pos_)} * u32(pos_ + 4) * 4;
    if (type == "floatvector") return declared - declared % 4;
    if (type == "stringvector") return string_vector_bytes(declared);
    if (type == "idmanifest") throw Error(ErrorKind::Unsupported, "OpenEXR ID manifests are not supported");
    return declared;  // string and unknown types: exactly the declared bytes
  }
  // Entries of a name, a NUL and 16 bytes, up to an empty name.
  uint64_t channel_list_bytes() const {
    size_t p = pos_;
    for (;;) {
      const size_t start = p;
      while (at(p) != 0)
        if (++p - start > kMaxNameLength) bad("a channel name of over 255 characters");
      if (p++ == start) return p - pos_;
      p += 16;
    }
  }
  // Strings of a 32-bit length and that many bytes, while under the declared size.
  uint64_t string_vector_bytes(uint64_t declared) const {
    uint64_t used = 0;
    while (used < declared) {
      used += 4 + uint64_t{u32(pos_ + used)};
      if (used > declared) bad("a string vector longer than its attribute");
    }
    return used;
  }

  std::span<const uint8_t> b_;
  size_t pos_ = 0;
};

}  // namespace

void check_exr_attributes(std::span<const uint8_t> bytes) {
  if (bytes.size() < 8) throw Error(ErrorKind::Corrupt, "cannot read OpenEXR header: no version field");
  Walk(bytes).headers();
}

}  // namespace lp
