#pragma once
// OIDN's tensor archive (.tza): named float16 or float32 tensors (convolution weights "oihw", biases "x").
#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <vector>

namespace lp::denoise {

struct Tensor {
  std::vector<int> dims;      // e.g. {out, in, 3, 3} for weights, {out} for biases
  std::string layout;         // "oihw" or "x"
  std::vector<float> values;  // row-major in `dims`, converted to float32
};

using TensorMap = std::map<std::string, Tensor>;

// Throws DenoiseError naming what is wrong with a malformed or truncated archive.
TensorMap parse_tza(std::span<const uint8_t> bytes);

float half_to_float(uint16_t bits);

}  // namespace lp::denoise
