#pragma once
// The container of an Ultra HDR JPEG (Google's Ultra HDR Image Format 1.0): the primary (SDR) JPEG
// carries an APP1 XMP packet naming the gain map (Container:Directory) and an APP2 MPF index (CIPA
// DC-007 Multi-Picture Format) whose second entry locates the gain map JPEG, appended after the
// primary; the gain map carries an APP1 XMP packet with the `hdrgm` (Adobe gain map) parameters.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace lp::ultrahdr {

// The gain map's parameters as the hdrgm XMP states them (log2 values, offsets in linear light).
struct GainMapParams {
  double gain_map_min = 0.0;  // log2 of the least content boost (gain code 0)
  double gain_map_max = 1.0;  // log2 of the greatest content boost (gain code 255)
  double gamma = 1.0;         // the gain codes hold ((log2 boost - min) / (max - min))^(1/gamma)
  double offset_sdr = 1.0 / 64.0;
  double offset_hdr = 1.0 / 64.0;
  double hdr_capacity_min = 0.0;  // log2 of the display headroom where the gain starts to apply
  double hdr_capacity_max = 1.0;  // ... and where it applies in full
};

// An APPn segment (marker 0xE0 + n) holding `payload`.
std::vector<uint8_t> app_segment(int n, std::span<const uint8_t> payload);
// The APP1 XMP segments of the primary image and of the gain map.
std::vector<uint8_t> primary_xmp_segment(size_t gain_map_bytes);
std::vector<uint8_t> gain_map_xmp_segment(const GainMapParams& params);

// The MPF segment's size (marker included) and where its offsets count from (the TIFF header, after
// the marker, length and "MPF\0").
inline constexpr size_t kMpfSegmentBytes = 90;
inline constexpr size_t kMpfOffsetBase = 8;
// The MPF segment: two entries, the primary (offset 0) and the gain map at `gain_map_offset` bytes
// from the TIFF header of this segment.
std::vector<uint8_t> mpf_segment(uint32_t primary_bytes, uint32_t gain_map_bytes, uint32_t gain_map_offset);

struct Parts {
  std::span<const uint8_t> primary, gain_map;
  GainMapParams params;
};
// The two JPEGs and the gain map's parameters of an Ultra HDR file. Throws lp::Error(Corrupt) naming
// what is missing or out of bounds.
Parts split(std::span<const uint8_t> file);

}  // namespace lp::ultrahdr
