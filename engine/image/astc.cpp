// astcenc's context carries the compressor's tables; one context compresses one image at a time with all
// its threads (each calls astcenc_compress_image with its index), then is reset for the next image.
#include "engine/image/astc.hpp"

#include <astcenc.h>
#include <fmt/format.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "engine/core/error.hpp"

namespace lp {
namespace {

constexpr astcenc_swizzle kRgba = {ASTCENC_SWZ_R, ASTCENC_SWZ_G, ASTCENC_SWZ_B, ASTCENC_SWZ_A};

void check(astcenc_error status, const char* what) {
  if (status != ASTCENC_SUCCESS)
    throw Error(ErrorKind::Internal,
                fmt::format("ASTC: {} failed: {}", what, astcenc_get_error_string(status)));
}

astcenc_context* make_context(float quality, unsigned flags, unsigned threads) {
  astcenc_config config{};
  check(astcenc_config_init(ASTCENC_PRF_HDR_RGB_LDR_A, kAstcBlockSize, kAstcBlockSize, 1, quality, flags,
                            &config),
        "configuration");
  astcenc_context* context = nullptr;
  check(astcenc_context_alloc(&config, threads, &context), "context");
  return context;
}

// RGBA floats, alpha 1, as astcenc reads an image.
std::vector<float> rgba(const Image& image) {
  std::vector<float> out(size_t(image.pixel_count()) * 4);
  const auto rgb = image.data();
  for (size_t i = 0, o = 0; i < rgb.size(); i += 3, o += 4) {
    out[o] = rgb[i], out[o + 1] = rgb[i + 1], out[o + 2] = rgb[i + 2];
    out[o + 3] = 1.0f;
  }
  return out;
}

astcenc_image view(std::vector<float>& pixels, int width, int height, void*& slice) {
  slice = pixels.data();
  return astcenc_image{unsigned(width), unsigned(height), 1, ASTCENC_TYPE_F32, &slice};
}

struct OwnedContext {
  explicit OwnedContext(astcenc_context* c) : context(c) {}
  ~OwnedContext() { astcenc_context_free(context); }
  OwnedContext(const OwnedContext&) = delete;
  OwnedContext& operator=(const OwnedContext&) = delete;
  astcenc_context* context;
};

}  // namespace

struct AstcHdrEncoder::Context : OwnedContext {
  using OwnedContext::OwnedContext;
};

size_t astc_bytes(int width, int height) {
  const auto blocks = [](int n) { return size_t((n + kAstcBlockSize - 1) / kAstcBlockSize); };
  return blocks(width) * blocks(height) * kAstcBlockBytes;
}

AstcHdrEncoder::AstcHdrEncoder(const AstcOptions& options)
    : threads_(options.threads > 0 ? options.threads : tbb::this_task_arena::max_concurrency()) {
  context_ = std::make_unique<Context>(make_context(options.quality, 0, unsigned(threads_)));
}

AstcHdrEncoder::~AstcHdrEncoder() = default;

std::vector<uint8_t> AstcHdrEncoder::compress(const Image& image) {
  if (image.empty()) throw Error(ErrorKind::InvalidArgument, "ASTC: an empty image");
  const int threads = threads_;
  astcenc_context* context = context_->context;
  std::vector<float> pixels = rgba(image);
  void* slice = nullptr;
  astcenc_image input = view(pixels, image.width(), image.height(), slice);
  std::vector<uint8_t> blocks(astc_bytes(image.width(), image.height()));
  // A thread that starts late finds the work taken and returns: none waits on another's start.
  std::vector<astcenc_error> status(size_t(threads), ASTCENC_SUCCESS);
  tbb::parallel_for(0, threads, [&](int t) {
    status[size_t(t)] =
        astcenc_compress_image(context, &input, &kRgba, blocks.data(), blocks.size(), unsigned(t));
  });
  check(astcenc_compress_reset(context), "reset");
  for (const astcenc_error s : status) check(s, "compression");
  return blocks;
}

Image decompress_astc_hdr(std::span<const uint8_t> blocks, int width, int height) {
  if (width <= 0 || height <= 0 || blocks.size() != astc_bytes(width, height))
    throw Error(ErrorKind::Corrupt, fmt::format("ASTC: {} bytes are not the blocks of a {}x{} image",
                                                blocks.size(), width, height));
  const OwnedContext context(make_context(ASTCENC_PRE_FASTEST, ASTCENC_FLG_DECOMPRESS_ONLY, 1));
  std::vector<float> pixels(size_t(width) * size_t(height) * 4);
  void* slice = nullptr;
  astcenc_image output = view(pixels, width, height, slice);
  check(astcenc_decompress_image(context.context, blocks.data(), blocks.size(), &output, &kRgba, 0),
        "decompression");
  Image image(width, height);
  auto rgb = image.data();
  for (size_t i = 0, o = 0; o < rgb.size(); i += 4, o += 3)
    rgb[o] = pixels[i], rgb[o + 1] = pixels[i + 1], rgb[o + 2] = pixels[i + 2];
  return image;
}

}  // namespace lp
