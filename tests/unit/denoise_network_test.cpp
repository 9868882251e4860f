// The oneDNN U-Net against a plain loop-nest forward pass of the same network (as OIDN's UNetFilter builds
// it) on the vendored rt_hdr_alb_nrm weights: 3x3 zero-padded convolutions + ReLU, 2x2 max-pooling, nearest
// 2x upsampling, concatenation with the upsampled tensor first.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <random>

#include "engine/denoise/denoiser.hpp"
#include "engine/denoise/tza.hpp"
#include "engine/denoise/unet.hpp"

namespace lp::denoise {
namespace {

// Planes of height x width, in double.
struct Planes {
  int channels = 0, height = 0, width = 0;
  std::vector<double> v;
  Planes(int c, int h, int w) : channels(c), height(h), width(w), v(size_t(c) * size_t(h) * size_t(w)) {}
  double& at(int c, int y, int x) {
    return v[(size_t(c) * size_t(height) + size_t(y)) * size_t(width) + size_t(x)];
  }
  double at(int c, int y, int x) const {
    return v[(size_t(c) * size_t(height) + size_t(y)) * size_t(width) + size_t(x)];
  }
};

Planes conv(const TensorMap& t, const std::string& name, const Planes& in) {
  const Tensor& w = t.at(name + ".weight");
  const Tensor& b = t.at(name + ".bias");
  const int out_c = w.dims[0], in_c = w.dims[1];
  Planes out(out_c, in.height, in.width);
  for (int o = 0; o < out_c; ++o)
    for (int y = 0; y < in.height; ++y)
      for (int x = 0; x < in.width; ++x) {
        double sum = b.values[size_t(o)];
        for (int i = 0; i < in_c; ++i)
          for (int ky = 0; ky < 3; ++ky)
            for (int kx = 0; kx < 3; ++kx) {
              const int sy = y + ky - 1, sx = x + kx - 1;
              if (sy < 0 || sx < 0 || sy >= in.height || sx >= in.width) continue;
              sum += w.values[((size_t(o) * size_t(in_c) + size_t(i)) * 3 + size_t(ky)) * 3 + size_t(kx)] *
                     in.at(i, sy, sx);
            }
        out.at(o, y, x) = std::max(sum, 0.0);
      }
  return out;
}

Planes pool(const Planes& in) {
  Planes out(in.channels, in.height / 2, in.width / 2);
  for (int c = 0; c < in.channels; ++c)
    for (int y = 0; y < out.height; ++y)
      for (int x = 0; x < out.width; ++x)
        out.at(c, y, x) = std::max({in.at(c, 2 * y, 2 * x), in.at(c, 2 * y, 2 * x + 1),
                                    in.at(c, 2 * y + 1, 2 * x), in.at(c, 2 * y + 1, 2 * x + 1)});
  return out;
}

Planes upsample(const Planes& in) {
  Planes out(in.channels, in.height * 2, in.width * 2);
  for (int c = 0; c < out.channels; ++c)
    for (int y = 0; y < out.height; ++y)
      for (int x = 0; x < out.width; ++x) out.at(c, y, x) = in.at(c, y / 2, x / 2);
  return out;
}

Planes concat(const Planes& a, const Planes& b) {
  Planes out(a.channels + b.channels, a.height, a.width);
  std::copy(a.v.begin(), a.v.end(), out.v.begin());
  std::copy(b.v.begin(), b.v.end(), out.v.begin() + ptrdiff_t(a.v.size()));
  return out;
}

Planes reference_unet(const TensorMap& t, const Planes& in) {
  Planes x = conv(t, "enc_conv0", in);
  const Planes pool1 = pool(conv(t, "enc_conv1", x));
  const Planes pool2 = pool(conv(t, "enc_conv2", pool1));
  const Planes pool3 = pool(conv(t, "enc_conv3", pool2));
  x = pool(conv(t, "enc_conv4", pool3));
  x = upsample(conv(t, "enc_conv5b", conv(t, "enc_conv5a", x)));
  x = upsample(conv(t, "dec_conv4b", conv(t, "dec_conv4a", concat(x, pool3))));
  x = upsample(conv(t, "dec_conv3b", conv(t, "dec_conv3a", concat(x, pool2))));
  x = upsample(conv(t, "dec_conv2b", conv(t, "dec_conv2a", concat(x, pool1))));
  x = conv(t, "dec_conv1b", conv(t, "dec_conv1a", concat(x, in)));
  return conv(t, "dec_conv0", x);
}

TEST(DenoiseNetwork, MatchesAPlainForwardPass) {
  std::ifstream file(default_weights_dir() / "rt_hdr_alb_nrm.tza", std::ios::binary);
  const std::vector<uint8_t> bytes{std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
  const TensorMap tensors = parse_tza(bytes);
  const int channels = 9, height = 48, width = 32;
  Planes in(channels, height, width);
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> unit(0.f, 1.f);
  for (int c = 0; c < channels; ++c)  // ramps plus noise, in [0, 1] as the input transforms give
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x)
        in.at(c, y, x) = 0.25 * double(x + c) / double(width + c) + 0.25 * double(y) / double(height) +
                         0.5 * double(unit(rng));
  const Planes expected = reference_unet(tensors, in);

  const UNet net(tensors, channels);
  const std::vector<float> input(in.v.begin(), in.v.end());
  std::vector<float> output(size_t(3 * height * width));
  net.run(input.data(), height, width, output.data());
  double largest = 0, worst = 0;
  for (double v : expected.v) largest = std::max(largest, std::abs(v));
  for (size_t i = 0; i < output.size(); ++i) worst = std::max(worst, std::abs(output[i] - expected.v[i]));
  EXPECT_GT(largest, 0.1);
  EXPECT_LT(worst, 1e-5 * largest) << "largest " << largest;
}

}  // namespace
}  // namespace lp::denoise
