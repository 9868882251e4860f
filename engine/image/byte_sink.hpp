#pragma once
// The write callback stb_image_write calls: appends the encoded bytes to a std::vector<uint8_t>.
#include <cstdint>
#include <vector>

namespace lp {

inline void append_to_byte_vector(void* context, void* data, int size) {
  auto* out = static_cast<std::vector<uint8_t>*>(context);
  const auto* p = static_cast<const uint8_t*>(data);
  out->insert(out->end(), p, p + size);
}

}  // namespace lp
