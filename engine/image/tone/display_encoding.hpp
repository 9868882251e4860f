#pragma once
// The display encoding of 8-bit output: display-linear [0, 1] to the nearest 8-bit code of the sRGB
// curve or of a gamma, by a search of the 255 linear values where the codes change (no pow per value).
#include <array>
#include <cstdint>
#include <optional>

namespace lp::tone {

class DisplayEncoding {
 public:
  explicit DisplayEncoding(std::optional<float> gamma);  // nullopt: the sRGB curve

  // The code whose interval holds `linear` (round to nearest of the encoded value); NaN gives 0.
  uint8_t operator()(float linear) const {
    int code = 0;
    for (int step = 128; step > 0; step >>= 1)
      if (linear >= starts_[size_t(code + step)]) code += step;
    return uint8_t(code);
  }

 private:
  std::array<float, 256> starts_{};  // starts_[k]: the least linear value encoded as k (k >= 1)
};

}  // namespace lp::tone
