#pragma once
// The display encoding of 8-bit output: display-linear [0, 1] to the nearest 8-bit code of the sRGB
// curve or of a gamma, from the 255 linear values where the codes change (no pow per value). A table
// indexed by a value's exponent and first mantissa bits gives the code where its bin starts; a step or
// two up the change points finds its own.
#include <array>
#include <bit>
#include <cstdint>
#include <optional>

namespace lp::tone {

class DisplayEncoding {
 public:
  explicit DisplayEncoding(std::optional<float> gamma);  // nullopt: the sRGB curve

  // The code whose interval holds `linear` (round to nearest of the encoded value); NaN gives 0.
  uint8_t operator()(float linear) const {
    if (!(linear >= kTableStart)) return search(linear);  // also NaN
    if (linear >= 1.0f) return 255;
    int code = first_code_[(std::bit_cast<uint32_t>(linear) >> kMantissaShift) - kFirstBin];
    while (code < 255 && linear >= starts_[size_t(code + 1)]) ++code;
    return uint8_t(code);
  }

 private:
  static constexpr float kTableStart = 1.0f / 65536.0f;  // 2^-16: the table covers [2^-16, 1)
  static constexpr int kMantissaShift = 23 - 7;          // 128 bins per octave
  static constexpr uint32_t kFirstBin = std::bit_cast<uint32_t>(kTableStart) >> kMantissaShift;
  static constexpr size_t kBins = 16 * 128;

  uint8_t search(float linear) const;  // by bisection of the change points (below the table)

  std::array<float, 256> starts_{};  // starts_[k]: the least linear value encoded as k (k >= 1)
  std::array<uint8_t, kBins> first_code_{};
};

}  // namespace lp::tone
