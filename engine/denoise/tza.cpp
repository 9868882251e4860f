#include "engine/denoise/tza.hpp"

#include <bit>
#include <cstring>

#include "engine/denoise/denoiser.hpp"

namespace lp::denoise {
namespace {

constexpr uint16_t kMagic = 0x41D7;
constexpr int kMajorVersion = 2;
constexpr int kMaxDims = 4;
constexpr int64_t kMaxTensorValues = int64_t{1} << 28;

// Little-endian reads bounded by the archive's end.
class Reader {
 public:
  explicit Reader(std::span<const uint8_t> bytes) : bytes_(bytes) {}

  void seek(uint64_t offset) {
    if (offset > bytes_.size()) fail("an offset points past the end");
    pos_ = size_t(offset);
  }
  template <typename T>
  T read() {
    need(sizeof(T));
    T value{};
    for (size_t i = 0; i < sizeof(T); ++i) value = T(value | T(uint64_t{bytes_[pos_ + i]} << (8 * i)));
    pos_ += sizeof(T);
    return value;
  }
  std::string read_string(size_t length) {
    need(length);
    std::string s(reinterpret_cast<const char*>(bytes_.data() + pos_), length);
    pos_ += length;
    return s;
  }
  std::span<const uint8_t> bytes_at(uint64_t offset, uint64_t length) const {
    if (offset > bytes_.size() || length > bytes_.size() - offset) fail("a tensor's data runs past the end");
    return bytes_.subspan(size_t(offset), size_t(length));
  }
  [[noreturn]] static void fail(const std::string& what) {
    throw DenoiseError("invalid weights archive: " + what);
  }

 private:
  void need(size_t n) const {
    if (n > bytes_.size() - pos_) fail("truncated");
  }
  std::span<const uint8_t> bytes_;
  size_t pos_ = 0;
};

Tensor read_tensor_header(Reader& in, uint64_t& data_offset, char& type) {
  Tensor t;
  const int ndims = in.read<uint8_t>();
  if (ndims < 1 || ndims > kMaxDims) Reader::fail("a tensor has " + std::to_string(ndims) + " dimensions");
  int64_t count = 1;
  for (int i = 0; i < ndims; ++i) {
    const uint32_t d = in.read<uint32_t>();
    if (d == 0 || d > kMaxTensorValues) Reader::fail("a tensor dimension is out of range");
    count *= d;
    if (count > kMaxTensorValues) Reader::fail("a tensor is too large");
    t.dims.push_back(int(d));
  }
  t.layout = in.read_string(size_t(ndims));
  if (t.layout != "x" && t.layout != "oihw") Reader::fail("unknown tensor layout '" + t.layout + "'");
  type = char(in.read<uint8_t>());
  if (type != 'h' && type != 'f') Reader::fail(std::string("unknown tensor data type '") + type + "'");
  data_offset = in.read<uint64_t>();
  return t;
}

void read_values(const Reader& in, Tensor& t, uint64_t offset, char type) {
  size_t count = 1;
  for (int d : t.dims) count *= size_t(d);
  const size_t element = type == 'h' ? 2 : 4;
  const auto data = in.bytes_at(offset, uint64_t(count * element));
  t.values.resize(count);
  for (size_t i = 0; i < count; ++i) {
    const uint8_t* p = data.data() + i * element;
    if (type == 'h') {
      t.values[i] = half_to_float(uint16_t(p[0] | (p[1] << 8)));
    } else {
      const uint32_t bits =
          uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
      t.values[i] = std::bit_cast<float>(bits);
    }
  }
}

}  // namespace

float half_to_float(uint16_t bits) {
  const uint32_t sign = uint32_t(bits & 0x8000u) << 16;
  const uint32_t exponent = (bits >> 10) & 0x1Fu;
  uint32_t mantissa = bits & 0x3FFu;
  if (exponent == 0x1F) return std::bit_cast<float>(sign | 0x7F800000u | (mantissa << 13));  // inf, NaN
  if (exponent != 0) return std::bit_cast<float>(sign | ((exponent + 112) << 23) | (mantissa << 13));
  if (mantissa == 0) return std::bit_cast<float>(sign);
  int shift = 0;  // subnormal: normalise the mantissa
  while ((mantissa & 0x400u) == 0) mantissa <<= 1, ++shift;
  mantissa &= 0x3FFu;
  return std::bit_cast<float>(sign | uint32_t(113 - shift) << 23 | (mantissa << 13));
}

TensorMap parse_tza(std::span<const uint8_t> bytes) {
  Reader in(bytes);
  if (in.read<uint16_t>() != kMagic) Reader::fail("not a tensor archive (bad magic)");
  const int major = in.read<uint8_t>();
  in.read<uint8_t>();  // minor version
  if (major != kMajorVersion) Reader::fail("unsupported version " + std::to_string(major));
  in.seek(in.read<uint64_t>());
  const uint32_t count = in.read<uint32_t>();
  TensorMap tensors;
  for (uint32_t i = 0; i < count; ++i) {
    const std::string name = in.read_string(in.read<uint16_t>());
    uint64_t offset = 0;
    char type = 0;
    Tensor t = read_tensor_header(in, offset, type);
    read_values(in, t, offset, type);
    if (!tensors.emplace(name, std::move(t)).second) Reader::fail("tensor '" + name + "' appears twice");
  }
  return tensors;
}

}  // namespace lp::denoise
