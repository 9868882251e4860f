// OpenEXR through the OpenEXR library, from and to memory: any compression it supports,
// scanline or tiled, RGB(A) or Y channels.
#include <Imath/half.h>
#include <ImfChannelList.h>
#include <ImfChromaticities.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfStandardAttributes.h>
#include <ImfThreading.h>

#include <algorithm>
#include <cstring>
#include <mutex>
#include <thread>

#include "engine/image/exr_capacity.hpp"
#include "engine/image/exr_standard_attributes.hpp"
#include "engine/image/image_limits.hpp"

namespace lp {
namespace {

class MemoryIStream : public Imf::IStream {
 public:
  explicit MemoryIStream(std::span<const uint8_t> b) : Imf::IStream("memory"), b_(b) {}
  bool read(char c[], int n) override {
    if (n < 0 || pos_ + uint64_t(n) > b_.size()) throw Iex::InputExc("unexpected end of file");
    std::memcpy(c, b_.data() + pos_, size_t(n));
    pos_ += uint64_t(n);
    return pos_ < b_.size();
  }
  uint64_t tellg() override { return pos_; }
  void seekg(uint64_t pos) override { pos_ = std::min<uint64_t>(pos, b_.size()); }
  void clear() override {}

 private:
  std::span<const uint8_t> b_;
  uint64_t pos_ = 0;
};

class MemoryOStream : public Imf::OStream {
 public:
  MemoryOStream() : Imf::OStream("memory") {}
  void write(const char c[], int n) override {
    if (pos_ + size_t(n) > out_.size()) out_.resize(pos_ + size_t(n));
    std::memcpy(out_.data() + pos_, c, size_t(n));
    pos_ += size_t(n);
  }
  uint64_t tellp() override { return pos_; }
  void seekp(uint64_t pos) override { pos_ = pos; }
  std::vector<uint8_t> take() { return std::move(out_); }

 private:
  std::vector<uint8_t> out_;
  size_t pos_ = 0;
};

void enable_exr_threads() {
  static std::once_flag once;
  std::call_once(once,
                 [] { Imf::setGlobalThreadCount(int(std::max(1u, std::thread::hardware_concurrency()))); });
}

// The channel names to read into R, G, B: "R","G","B", or "Y" for all three.
std::array<const char*, 3> pick_channels(const Imf::ChannelList& channels) {
  if (channels.findChannel("R") && channels.findChannel("G") && channels.findChannel("B"))
    return {"R", "G", "B"};
  if (channels.findChannel("Y")) return {"Y", "Y", "Y"};
  throw Error(ErrorKind::Unsupported, "OpenEXR file has neither R, G, B nor Y channels");
}

}  // namespace

Image read_exr(std::span<const uint8_t> bytes, const ImageLimits& limits) {
  enable_exr_threads();
  try {
    const ExrHeaderSummary checked = check_exr_capacity(bytes, limits);
    MemoryIStream stream(bytes);
    Imf::InputFile file(stream);
    const Imath::Box2i window = file.header().dataWindow();
    if (window.min.x != checked.min_x || window.min.y != checked.min_y || window.max.x != checked.max_x ||
        window.max.y != checked.max_y || int(file.header().compression()) != checked.compression)
      throw Error(ErrorKind::Corrupt,
                  "cannot read OpenEXR data: the header reads differently on a second pass");
    const int64_t width = int64_t{window.max.x} - window.min.x + 1;
    const int64_t height = int64_t{window.max.y} - window.min.y + 1;
    check_image_size(width, height, limits);
    const auto names = pick_channels(file.header().channels());

    Image image(static_cast<int>(width), static_cast<int>(height));
    const bool grey = names[0] == names[1];
    Imf::FrameBuffer fb;
    // Slice::Make places the data window's first pixel at the buffer start without forming a pointer
    // outside the buffer here (the window may sit anywhere in int32 space).
    for (int c = 0; c < (grey ? 1 : 3); ++c)
      fb.insert(names[c], Imf::Slice::Make(Imf::FLOAT, image.data().data() + c, window, sizeof(float) * 3,
                                           sizeof(float) * 3 * size_t(width)));
    file.setFrameBuffer(fb);
    file.readPixels(window.min.y, window.max.y);
    if (grey) {
      auto d = image.data();
      for (size_t i = 0; i < d.size(); i += 3) d[i + 1] = d[i + 2] = d[i];
    }
    return image;
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    throw Error(ErrorKind::Corrupt, std::string("cannot read OpenEXR data: ") + e.what());
  }
}

namespace {

// OpenEXR's standard attributes (exr_standard_attributes.hpp). Imf::Chromaticities() is Rec. ITU-R
// BT.709-3: the sRGB primaries and D65.
void add_standard_attributes(Imf::Header& header, ExrEnvmap envmap) {
  Imf::addChromaticities(header, Imf::Chromaticities());
  if (envmap == ExrEnvmap::LatLong) Imf::addEnvmap(header, Imf::ENVMAP_LATLONG);
  if (envmap == ExrEnvmap::Cube) Imf::addEnvmap(header, Imf::ENVMAP_CUBE);
}

}  // namespace

std::vector<uint8_t> write_exr(const Image& image, ExrCompression compression, PixelPrecision precision) {
  return write_exr_envmap(image, ExrEnvmap::None, compression, precision);
}

std::vector<uint8_t> write_exr_envmap(const Image& image, ExrEnvmap envmap, ExrCompression compression,
                                      PixelPrecision precision) {
  enable_exr_threads();
  Imf::Header header(image.width(), image.height());
  header.compression() = compression == ExrCompression::Zip ? Imf::ZIP_COMPRESSION : Imf::NO_COMPRESSION;
  add_standard_attributes(header, envmap);
  // An output file takes pixels of its channels' own type (it converts only when reading): half
  // channels are written from a copy of the pixels in half.
  const bool half = precision == PixelPrecision::Half;
  const Imf::PixelType type = half ? Imf::HALF : Imf::FLOAT;
  for (const char* name : {"R", "G", "B"}) header.channels().insert(name, Imf::Channel(type));
  std::vector<Imath::half> halves;
  if (half) halves.assign(image.data().begin(), image.data().end());
  MemoryOStream stream;
  {
    Imf::OutputFile file(stream, header);
    Imf::FrameBuffer fb;
    const char* names[] = {"R", "G", "B"};
    auto* base = half ? reinterpret_cast<char*>(halves.data())
                      : reinterpret_cast<char*>(const_cast<float*>(image.data().data()));
    const size_t texel = half ? sizeof(Imath::half) : sizeof(float);
    for (int c = 0; c < 3; ++c)
      fb.insert(names[c], Imf::Slice(type, base + c * texel, texel * 3, texel * 3 * size_t(image.width())));
    file.setFrameBuffer(fb);
    file.writePixels(image.height());
  }
  return stream.take();
}

std::vector<uint8_t> write_exr_channels(int width, int height, std::span<const ExrChannel> channels,
                                        ExrCompression compression) {
  enable_exr_threads();
  Imf::Header header(width, height);
  header.compression() = compression == ExrCompression::Zip ? Imf::ZIP_COMPRESSION : Imf::NO_COMPRESSION;
  add_standard_attributes(header, ExrEnvmap::None);
  for (const ExrChannel& c : channels) header.channels().insert(c.name, Imf::Channel(Imf::FLOAT));
  MemoryOStream stream;
  {
    Imf::OutputFile file(stream, header);
    Imf::FrameBuffer fb;
    for (const ExrChannel& c : channels)
      fb.insert(c.name, Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(const_cast<float*>(c.data)),
                                   sizeof(float) * c.stride, sizeof(float) * c.stride * size_t(width)));
    file.setFrameBuffer(fb);
    file.writePixels(height);
  }
  return stream.take();
}

std::vector<uint8_t> write_exr_rgba(const Image& color, const Image& alpha, ExrCompression compression) {
  if (alpha.width() != color.width() || alpha.height() != color.height())
    throw Error(ErrorKind::Internal, "RGBA: the alpha does not match the colour's size");
  const float* c = color.data().data();
  const ExrChannel channels[] = {
      {"R", c, 3}, {"G", c + 1, 3}, {"B", c + 2, 3}, {"A", alpha.data().data(), 3}};
  return write_exr_channels(color.width(), color.height(), channels, compression);
}

}  // namespace lp
