#pragma once
// OIDN's U-Net for its rt filters, as its UNetFilter builds it: 3x3 convolutions each followed by ReLU,
// five encoder levels joined by 2x2 max-pooling, a decoder that upsamples (nearest, 2x) and concatenates the
// encoder's output of the same level (upsampled channels first), and a last 3x3 convolution to RGB.
#include <memory>
#include <string>
#include <vector>

#include "engine/denoise/tza.hpp"

namespace lp::denoise {

struct ConvWeights {
  int out_channels = 0, in_channels = 0;
  std::vector<float> weights;  // oihw, 3x3
  std::vector<float> bias;     // empty: none
};

// A convolution layer; one fed with a concatenation is split into the part reading the upsampled tensor
// and the part reading the skip connection, their sum computed by oneDNN's sum post-op.
struct ConvLayer {
  std::string name;
  ConvWeights main;
  ConvWeights skip;  // empty unless the layer reads a concatenation
};

class UNet {
 public:
  // Checks that the archive holds every layer with consistent channel counts; throws DenoiseError.
  UNet(const TensorMap& tensors, int input_channels);
  ~UNet();

  int input_channels() const { return input_channels_; }

  // Input: input_channels planes of height x width (multiples of 16); output: 3 planes, in the transfer
  // function's space. Runs on the calling thread's oneDNN (OpenMP) threads.
  void run(const float* input, int height, int width, float* output) const;

  struct Engine;  // oneDNN's engine and the weights reordered for it

 private:
  int input_channels_;
  std::vector<ConvLayer> layers_;
  std::unique_ptr<Engine> engine_;
};

}  // namespace lp::denoise
