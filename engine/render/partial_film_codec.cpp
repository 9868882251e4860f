#include "engine/render/partial_film_codec.hpp"

#include <bit>
#include <cmath>
#include <cstring>
#include <optional>
#include <string>

#include "engine/core/error.hpp"
#include "engine/render/aux_passes.hpp"

namespace lp::render {
namespace {

constexpr char kMagic[4] = {'L', 'P', 'P', 'F'};
constexpr uint32_t kVersion = 2;
constexpr size_t kHeaderBytes = 4 + 4 * 6 + 8;  // magic, version, size, range, passes, rays

size_t pixel_bytes(const PassSet& passes) {
  return size_t(3 + passes.channels()) * sizeof(float) + sizeof(uint32_t);
}

static_assert(std::endian::native == std::endian::little, "the partial film format is little endian");

template <class T>
void put(std::vector<uint8_t>& out, T value) {
  const auto* p = reinterpret_cast<const uint8_t*>(&value);
  out.insert(out.end(), p, p + sizeof(T));
}

class Reader {
 public:
  explicit Reader(std::span<const uint8_t> bytes) : bytes_(bytes) {}
  template <class T>
  T get() {
    T value;
    std::memcpy(&value, bytes_.data() + at_, sizeof(T));
    at_ += sizeof(T);
    return value;
  }

 private:
  std::span<const uint8_t> bytes_;
  size_t at_ = 0;
};

Error corrupt(const std::string& what) {
  return Error(ErrorKind::Corrupt, "partial film: " + what);
}

}  // namespace

std::vector<uint8_t> encode_partial(const RangePartial& partial) {
  const PartialFilm& film = partial.film;
  std::vector<uint8_t> out;
  out.reserve(kHeaderBytes + film.pixel_count() * pixel_bytes(film.passes()));
  for (const char c : kMagic) out.push_back(uint8_t(c));
  for (const uint32_t v : {kVersion, uint32_t(film.width()), uint32_t(film.height()), partial.range.first,
                           partial.range.end, film.passes().bits()})
    put(out, v);
  put(out, partial.rays);
  for (size_t p = 0; p < film.pixel_count(); ++p) {
    const Rgb s = film.sum(p);
    put(out, s.x), put(out, s.y), put(out, s.z);
    for (size_t c = 0; c < film.aux_channels(); ++c) put(out, float(film.aux(p)[c]));
    put(out, film.count(p));
  }
  return out;
}

RangePartial decode_partial(std::span<const uint8_t> bytes, int64_t max_pixels) {
  if (bytes.size() < kHeaderBytes || std::memcmp(bytes.data(), kMagic, 4) != 0)
    throw corrupt("not a partial film");
  Reader in(bytes.subspan(4));
  if (in.get<uint32_t>() != kVersion) throw corrupt("unknown version");
  const uint32_t width = in.get<uint32_t>(), height = in.get<uint32_t>();
  RangePartial out;
  out.range.first = in.get<uint32_t>();
  out.range.end = in.get<uint32_t>();
  const std::optional<PassSet> passes = PassSet::from_bits(in.get<uint32_t>());
  out.rays = in.get<uint64_t>();
  if (!passes) throw corrupt("unknown passes");
  if (width == 0 || height == 0 || width > (1u << 16) || height > (1u << 16)) throw corrupt("bad size");
  if (out.range.end <= out.range.first || out.range.count() <= 0) throw corrupt("empty sample range");
  const int64_t pixels = int64_t(width) * int64_t(height);
  if (pixels > max_pixels)
    throw Error(ErrorKind::TooLarge, "partial film: " + std::to_string(pixels) + " pixels, over the limit");
  if (bytes.size() != kHeaderBytes + size_t(pixels) * pixel_bytes(*passes)) throw corrupt("wrong length");
  out.film = PartialFilm(int(width), int(height), *passes);
  Reader px(bytes.subspan(kHeaderBytes));
  float aux[kMaxAuxChannels];
  for (size_t p = 0; p < size_t(pixels); ++p) {
    const float r = px.get<float>(), g = px.get<float>(), b = px.get<float>();
    bool finite = std::isfinite(r) && std::isfinite(g) && std::isfinite(b);
    for (size_t c = 0; c < out.film.aux_channels(); ++c)
      finite = std::isfinite(aux[c] = px.get<float>()) && finite;
    const uint32_t count = px.get<uint32_t>();
    if (!finite) throw corrupt("a sum is not finite");
    if (count != uint32_t(out.range.count())) throw corrupt("a pixel's count is not the range's");
    out.film.add(p, {r, g, b}, count, aux);
  }
  return out;
}

}  // namespace lp::render
