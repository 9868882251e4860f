#include "engine/image/ultrahdr.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "engine/core/error.hpp"
#include "engine/image/jpeg_turbo.hpp"
#include "engine/image/tone/display_encoding.hpp"

namespace lp {
namespace {

constexpr float kMaxRadiance = 1048576.0f;  // 2^20: 20 stops over SDR white, within any half float
// The least span of the gain codes: a map that is all SDR still gets a valid [min, max].
constexpr double kMinGainSpan = 1.0 / 64.0;

std::array<float, 256> srgb_to_linear_table() {
  std::array<float, 256> t{};
  for (size_t i = 0; i < t.size(); ++i) {
    const double c = double(i) / 255.0;
    t[i] = float(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
  }
  return t;
}
const std::array<float, 256>& srgb_to_linear() {
  static const auto table = srgb_to_linear_table();
  return table;
}

float clean(float v) {
  return std::isfinite(v) ? std::clamp(v, 0.0f, kMaxRadiance) : 0.0f;
}

std::vector<uint8_t> sdr_base(const Image& radiance) {
  const tone::DisplayEncoding encode(std::nullopt);
  const auto values = radiance.data();
  std::vector<uint8_t> out(values.size());
  std::transform(values.begin(), values.end(), out.begin(), [&](float v) { return encode(clean(v)); });
  return out;
}

// log2 of HDR / SDR with the offsets, per value.
std::vector<double> log_ratios(const Image& radiance, const std::vector<uint8_t>& sdr,
                               const ultrahdr::GainMapParams& p) {
  const auto values = radiance.data();
  std::vector<double> out(values.size());
  for (size_t i = 0; i < out.size(); ++i)
    out[i] = std::log2((clean(values[i]) + p.offset_hdr) / (srgb_to_linear()[sdr[i]] + p.offset_sdr));
  return out;
}

std::vector<uint8_t> gain_codes(const std::vector<double>& ratios, const ultrahdr::GainMapParams& p) {
  std::vector<uint8_t> out(ratios.size());
  const double span = p.gain_map_max - p.gain_map_min;
  std::transform(ratios.begin(), ratios.end(), out.begin(), [&](double r) {
    const double t = std::pow(std::clamp((r - p.gain_map_min) / span, 0.0, 1.0), p.gamma);
    return uint8_t(std::lround(t * 255.0));
  });
  return out;
}

std::vector<uint8_t> concat(std::initializer_list<std::span<const uint8_t>> parts) {
  std::vector<uint8_t> out;
  for (const auto& part : parts) out.insert(out.end(), part.begin(), part.end());
  return out;
}

// SOI, `segments`, then the rest of `jpeg` after its own SOI.
std::vector<uint8_t> with_segments(std::span<const uint8_t> jpeg, std::span<const uint8_t> segments) {
  static constexpr std::array<uint8_t, 2> kSoi{0xFF, 0xD8};
  return concat({kSoi, segments, jpeg.subspan(2)});
}

}  // namespace

std::vector<uint8_t> encode_ultrahdr(const Image& radiance, const UltraHdrOptions& options) {
  if (radiance.empty()) throw Error(ErrorKind::InvalidArgument, "Ultra HDR: the image is empty");
  const int w = radiance.width(), h = radiance.height();
  const std::vector<uint8_t> sdr = sdr_base(radiance);
  const std::vector<uint8_t> base = encode_jpeg_444({sdr, w, h, 3}, options.base_quality);
  // The gain is measured against the base as a reader decodes it, so it corrects the base's own loss.
  const DecodedJpeg decoded = decode_jpeg_rgb(base, {});

  ultrahdr::GainMapParams params;
  const std::vector<double> ratios = log_ratios(radiance, decoded.rgb, params);
  const auto [low, high] = std::minmax_element(ratios.begin(), ratios.end());
  params.gain_map_min = std::min(*low, 0.0);
  params.gain_map_max = std::max(*high, params.gain_map_min + kMinGainSpan);
  params.hdr_capacity_min = 0.0;
  params.hdr_capacity_max = std::max(params.gain_map_max, kMinGainSpan);

  const std::vector<uint8_t> codes = gain_codes(ratios, params);
  const std::vector<uint8_t> gain_jpeg =
      encode_jpeg_444({codes, w, h, 3}, options.gain_map_quality, JpegColours::Untransformed);
  const std::vector<uint8_t> gain_map = with_segments(gain_jpeg, ultrahdr::gain_map_xmp_segment(params));

  const std::vector<uint8_t> xmp = ultrahdr::primary_xmp_segment(gain_map.size());
  const size_t primary_bytes = base.size() + xmp.size() + ultrahdr::kMpfSegmentBytes;
  const size_t tiff_at = 2 + xmp.size() + ultrahdr::kMpfOffsetBase;
  const std::vector<uint8_t> mpf = ultrahdr::mpf_segment(uint32_t(primary_bytes), uint32_t(gain_map.size()),
                                                         uint32_t(primary_bytes - tiff_at));
  const std::vector<uint8_t> primary = with_segments(base, concat({xmp, mpf}));
  return concat({primary, gain_map});
}

DecodedUltraHdr decode_ultrahdr(std::span<const uint8_t> file, const ImageLimits& limits) {
  const ultrahdr::Parts parts = ultrahdr::split(file);
  const DecodedJpeg sdr = decode_jpeg_rgb(parts.primary, limits);
  const DecodedJpeg gain = decode_jpeg_rgb(parts.gain_map, limits);
  const ultrahdr::GainMapParams& p = parts.params;
  std::array<float, 256> boost{};
  for (size_t i = 0; i < boost.size(); ++i) {
    const double t = std::pow(double(i) / 255.0, 1.0 / p.gamma);
    boost[i] = float(std::exp2(p.gain_map_min + (p.gain_map_max - p.gain_map_min) * t));
  }
  DecodedUltraHdr out{Image(sdr.width, sdr.height), p};
  for (int y = 0; y < sdr.height; ++y) {
    const size_t gy = size_t(int64_t(y) * gain.height / sdr.height);
    for (int x = 0; x < sdr.width; ++x) {
      const size_t gx = size_t(int64_t(x) * gain.width / sdr.width);
      const uint8_t* s = &sdr.rgb[(size_t(y) * size_t(sdr.width) + size_t(x)) * 3];
      const uint8_t* g = &gain.rgb[(gy * size_t(gain.width) + gx) * 3];
      float* o = out.radiance.row(y) + size_t(x) * 3;
      for (int c = 0; c < 3; ++c)
        o[c] = std::max(0.0f, float((srgb_to_linear()[s[c]] + p.offset_sdr) * boost[g[c]] - p.offset_hdr));
    }
  }
  return out;
}

}  // namespace lp
