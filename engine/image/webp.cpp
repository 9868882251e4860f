#include "engine/image/webp.hpp"

#include <webp/encode.h>
#include <webp/mux.h>

#include <cmath>
#include <memory>

namespace lp {
namespace {

// A WebPPicture holding `p`'s pixels (ARGB, as the encoders want them).
struct Picture {
  WebPPicture picture;
  explicit Picture(const Pixels8& p) {
    if (!WebPPictureInit(&picture)) throw Error(ErrorKind::Internal, "libwebp: version mismatch");
    picture.use_argb = 1;
    picture.width = p.width;
    picture.height = p.height;
    const int stride = p.width * p.channels;
    const int ok = p.channels == 4 ? WebPPictureImportRGBA(&picture, p.bytes.data(), stride)
                                   : WebPPictureImportRGB(&picture, p.bytes.data(), stride);
    if (!ok) throw Error(ErrorKind::Internal, "libwebp: cannot hold the picture");
  }
  ~Picture() { WebPPictureFree(&picture); }
  Picture(const Picture&) = delete;
  Picture& operator=(const Picture&) = delete;
};

WebPConfig lossy_config(float quality) {
  WebPConfig config;
  if (!WebPConfigPreset(&config, WEBP_PRESET_DEFAULT, quality) || !WebPValidateConfig(&config))
    throw Error(ErrorKind::InvalidArgument, "WebP quality must be in [0, 100]");
  return config;
}

void check_size(const Pixels8& p) {
  check_pixels8(p, "WebP");
  if (p.width > WEBP_MAX_DIMENSION || p.height > WEBP_MAX_DIMENSION)
    throw Error(ErrorKind::TooLarge,
                "WebP pictures are at most " + std::to_string(WEBP_MAX_DIMENSION) + " pixels on a side");
}

}  // namespace

std::vector<uint8_t> encode_webp(const Pixels8& p, float quality) {
  check_size(p);
  const WebPConfig config = lossy_config(quality);
  Picture picture(p);
  WebPMemoryWriter writer;
  WebPMemoryWriterInit(&writer);
  picture.picture.writer = WebPMemoryWrite;
  picture.picture.custom_ptr = &writer;
  const bool ok = WebPEncode(&config, &picture.picture);
  std::vector<uint8_t> out(writer.mem, writer.mem + writer.size);
  WebPMemoryWriterClear(&writer);
  if (!ok)
    throw Error(ErrorKind::Internal,
                "cannot encode WebP (error " + std::to_string(int(picture.picture.error_code)) + ")");
  return out;
}

std::vector<uint8_t> encode_webp_animation(std::span<const Pixels8> frames, int fps, float quality) {
  if (frames.empty()) throw Error(ErrorKind::InvalidArgument, "an animation needs at least one frame");
  if (fps < 1 || fps > 1000) throw Error(ErrorKind::InvalidArgument, "fps must be in [1, 1000]");
  const Pixels8& first = frames.front();
  WebPAnimEncoderOptions options;
  if (!WebPAnimEncoderOptionsInit(&options)) throw Error(ErrorKind::Internal, "libwebp: version mismatch");
  options.anim_params.loop_count = 0;  // forever
  const auto deleter = [](WebPAnimEncoder* e) { WebPAnimEncoderDelete(e); };
  std::unique_ptr<WebPAnimEncoder, decltype(deleter)> encoder(
      WebPAnimEncoderNew(first.width, first.height, &options), deleter);
  if (!encoder) throw Error(ErrorKind::Internal, "libwebp: cannot start an animation");
  const WebPConfig config = lossy_config(quality);
  const int frame_ms = int(std::lround(1000.0 / fps));
  int timestamp_ms = 0;
  for (const Pixels8& frame : frames) {
    check_size(frame);
    if (frame.width != first.width || frame.height != first.height || frame.channels != first.channels)
      throw Error(ErrorKind::InvalidArgument, "the frames of an animation must share their size");
    Picture picture(frame);
    if (!WebPAnimEncoderAdd(encoder.get(), &picture.picture, timestamp_ms, &config))
      throw Error(ErrorKind::Internal,
                  std::string("cannot encode a WebP frame: ") + WebPAnimEncoderGetError(encoder.get()));
    timestamp_ms += frame_ms;
  }
  WebPData data;
  WebPDataInit(&data);
  if (!WebPAnimEncoderAdd(encoder.get(), nullptr, timestamp_ms, nullptr) ||
      !WebPAnimEncoderAssemble(encoder.get(), &data))
    throw Error(ErrorKind::Internal,
                std::string("cannot assemble a WebP animation: ") + WebPAnimEncoderGetError(encoder.get()));
  std::vector<uint8_t> out(data.bytes, data.bytes + data.size);
  WebPDataClear(&data);
  return out;
}

}  // namespace lp
