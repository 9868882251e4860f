#pragma once
// The pictures made from a turntable's frames: each tone mapped to 8 bits at a requested size, the
// frames as a zip of PNGs with their cameras, a contact sheet, an animated WebP. Frames of a transparent
// background keep their alpha (api/render_pictures.hpp says what each format gives).
#include <cstdint>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "engine/image/image.hpp"
#include "engine/image/image_io.hpp"
#include "engine/image/pixels8.hpp"
#include "server/renders/render_job_image.hpp"

namespace lp::server {

// Frames tone mapped to 8-bit RGB (RGBA, straight alpha, with an alpha pass), each downscaled (in linear
// light) to `size` pixels.
struct Frames8 {
  std::vector<std::vector<uint8_t>> bytes;
  int width = 0;
  int height = 0;
  int channels = 3;
  std::vector<Pixels8> pictures() const;
};
Frames8 frames8(const std::vector<RenderImage>& frames, std::optional<int> size, const ToneMap& tone);

// The bytes those hold at once beside the frames: the 8-bit frames and one frame's resampling.
int64_t frames8_bytes(int64_t frames, int64_t width, int64_t height);

// frame_0000.png, frame_0001.png, ... and cameras.json, stored (PNG is compressed already).
std::vector<uint8_t> frames_zip(const Frames8& frames, const nlohmann::json& cameras);

// The contact sheet (contact_sheet.hpp) of the frames, each frame scaled so that the sheet's longest
// side is at most `size`.
std::vector<uint8_t> frames_contact_sheet(const std::vector<RenderImage>& frames, std::optional<int> size,
                                          const ToneMap& tone, ImageFormat format);

}  // namespace lp::server
