#pragma once
// Linear radiance to 8-bit display values for previews.
#include <cstdint>

#include "engine/image/image_io.hpp"

namespace lp {

// Precomputed per-call state so the per-pixel cost is a multiply, a curve and a round.
class ToneMapper {
 public:
  explicit ToneMapper(const ToneMap& tone);
  uint8_t operator()(float linear) const;

 private:
  float scale_;
  float inv_gamma_;
  bool srgb_;
};

}  // namespace lp
