#include "engine/denoise/denoiser.hpp"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <fstream>
#include <map>
#include <mutex>

#include "engine/denoise/tiles.hpp"
#include "engine/denoise/transfer.hpp"
#include "engine/denoise/unet.hpp"

// The OpenMP runtime oneDNN threads with (libgomp), declared here so that no source needs -fopenmp.
extern "C" {
int omp_get_max_threads();
void omp_set_num_threads(int threads);
}

namespace lp::denoise {
namespace {

const char* const kFilterFiles[] = {"rt_hdr.tza", "rt_hdr_alb.tza", "rt_hdr_alb_nrm.tza",
                                    "rt_ldr.tza", "rt_ldr_alb.tza", "rt_ldr_alb_nrm.tza"};

// Floats per tile pixel the network holds at its peak (the decoder's last level: the input, the upsampled
// tensor, the concatenation's result and the pooled skips): bench/denoise_bench measures about 140 (560 MB
// at 1024x1024, 572 MB for tiles of 1056x1088).
constexpr int64_t kPeakFloatsPerPixel = 160;
constexpr int64_t kFixedWorkingBytes = int64_t{64} << 20;  // weights, their reordered copies, primitives

std::string filter_file(Range range, const DenoiseInputs& in) {
  std::string name = range == Range::Hdr ? "rt_hdr" : "rt_ldr";
  if (in.albedo) name += "_alb";
  if (in.normal) name += "_nrm";
  return name + ".tza";
}

std::vector<uint8_t> read_file(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw DenoiseError("denoiser weights not found: " + path.string());
  return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

void check_inputs(const DenoiseInputs& in, const DenoiseOptions& options) {
  if (!in.color || in.color->empty()) throw DenoiseError("denoise needs a colour image");
  const auto same_size = [&](const Image* aux, const char* what) {
    if (aux && (aux->width() != in.color->width() || aux->height() != in.color->height()))
      throw DenoiseError(std::string(what) + " is " + std::to_string(aux->width()) + "x" +
                         std::to_string(aux->height()) + ", the colour " + std::to_string(in.color->width()) +
                         "x" + std::to_string(in.color->height()));
  };
  same_size(in.albedo, "the albedo");
  same_size(in.normal, "the normal");
  if (in.normal && !in.albedo) throw DenoiseError("a normal image needs an albedo image too");
  if (options.threads < 0) throw DenoiseError("threads must be 0 (all) or positive");
  if (!(options.input_scale >= 0) || !std::isfinite(options.input_scale))
    throw DenoiseError("input_scale must be 0 (automatic) or positive");
  if (options.tile_size != 0 && options.tile_size < kMinTileSize)
    throw DenoiseError("tile_size must be at least " + std::to_string(kMinTileSize));
}

// The tile's input planes: colour (scaled, sanitised, through the transfer function), albedo, normal mapped
// to [0, 1], zero outside the image.
void fill_tile(const DenoiseInputs& in, const Tile& t, Transfer transfer, bool hdr, float scale,
               float* planes) {
  const size_t plane = size_t(t.in_width) * size_t(t.in_height);
  const int channels = 3 * (1 + (in.albedo ? 1 : 0) + (in.normal ? 1 : 0));
  tbb::parallel_for(0, t.in_height, [&](int ty) {
    const int y = t.in_y + ty;
    for (int tx = 0; tx < t.in_width; ++tx) {
      const int x = t.in_x + tx;
      const size_t at = size_t(ty) * size_t(t.in_width) + size_t(tx);
      if (y >= in.color->height() || x >= in.color->width()) {
        for (int c = 0; c < channels; ++c) planes[size_t(c) * plane + at] = 0;
        continue;
      }
      const Rgb color = in.color->at(x, y);
      const float rgb[3] = {color.x, color.y, color.z};
      for (int c = 0; c < 3; ++c)
        planes[size_t(c) * plane + at] =
            transfer_forward(transfer, sanitize(rgb[c] * scale, 0, hdr ? kFloatMax : 1));
      if (in.albedo) {
        const Rgb a = in.albedo->at(x, y);
        planes[3 * plane + at] = sanitize(a.x, 0, 1);
        planes[4 * plane + at] = sanitize(a.y, 0, 1);
        planes[5 * plane + at] = sanitize(a.z, 0, 1);
      }
      if (in.normal) {
        const Rgb n = in.normal->at(x, y);
        planes[6 * plane + at] = sanitize(n.x, -1, 1) * 0.5f + 0.5f;
        planes[7 * plane + at] = sanitize(n.y, -1, 1) * 0.5f + 0.5f;
        planes[8 * plane + at] = sanitize(n.z, -1, 1) * 0.5f + 0.5f;
      }
    }
  });
}

// The network's output for the tile's written part, back through the inverse transfer function.
void store_tile(const float* planes, const Tile& t, Transfer transfer, bool hdr, float scale, Image& out) {
  const size_t plane = size_t(t.in_width) * size_t(t.in_height);
  const float out_scale = scale != 0 ? 1 / scale : 0;
  tbb::parallel_for(0, t.out_height, [&](int oy) {
    const int y = t.out_y + oy;
    for (int ox = 0; ox < t.out_width; ++ox) {
      const int x = t.out_x + ox;
      const size_t at = size_t(y - t.in_y) * size_t(t.in_width) + size_t(x - t.in_x);
      float rgb[3];
      for (int c = 0; c < 3; ++c) {
        float v = transfer_inverse(transfer, sanitize(planes[size_t(c) * plane + at], 0, kFloatMax));
        if (!hdr) v = std::min(v, 1.f);
        rgb[c] = v * out_scale;
      }
      out.set(x, y, {rgb[0], rgb[1], rgb[2]});
    }
  });
}

// Sets the calling thread's OpenMP team size (oneDNN's threads) for a scope.
class OmpThreads {
 public:
  explicit OmpThreads(int threads) : previous_(omp_get_max_threads()) {
    if (threads > 0) omp_set_num_threads(threads);
  }
  ~OmpThreads() { omp_set_num_threads(previous_); }
  OmpThreads(const OmpThreads&) = delete;
  OmpThreads& operator=(const OmpThreads&) = delete;

 private:
  int previous_;
};

}  // namespace

struct Denoiser::Filters {
  std::mutex mutex;
  std::map<std::string, std::shared_ptr<const UNet>> loaded;
};

Denoiser::Denoiser(std::filesystem::path weights_dir)
    : weights_dir_(std::move(weights_dir)), filters_(std::make_unique<Filters>()) {}

Denoiser::~Denoiser() = default;

bool Denoiser::available() const {
  std::error_code error;
  for (const char* file : kFilterFiles)
    if (!std::filesystem::is_regular_file(weights_dir_ / file, error)) return false;
  return true;
}

int64_t Denoiser::working_bytes(int width, int height, int tile_size) {
  const int64_t tile_w = std::min(round_up(width, kTileAlignment), tile_size);
  const int64_t tile_h = std::min(round_up(height, kTileAlignment), tile_size);
  return tile_w * tile_h * kPeakFloatsPerPixel * int64_t{sizeof(float)} + kFixedWorkingBytes;
}

Image Denoiser::run(const DenoiseInputs& in, const DenoiseOptions& options) const {
  check_inputs(in, options);
  const std::string file = filter_file(options.range, in);
  std::shared_ptr<const UNet> net;
  {
    std::lock_guard lock(filters_->mutex);
    auto& slot = filters_->loaded[file];
    if (!slot) {
      const std::vector<uint8_t> bytes = read_file(weights_dir_ / file);
      slot =
          std::make_shared<const UNet>(parse_tza(bytes), 3 * (1 + (in.albedo ? 1 : 0) + (in.normal ? 1 : 0)));
    }
    net = slot;
  }
  const bool hdr = options.range == Range::Hdr;
  const Transfer transfer = hdr ? Transfer::Pu : Transfer::Srgb;
  const int threads = options.threads > 0 ? options.threads : tbb::this_task_arena::max_concurrency();
  tbb::task_arena arena(threads);
  OmpThreads omp_threads(threads);

  const float scale = options.input_scale > 0 ? options.input_scale : (hdr ? autoexposure(*in.color) : 1.f);
  const auto tiles = plan_tiles(
      in.color->width(), in.color->height(),
      options.tile_size > 0 ? options.tile_size / kTileAlignment * kTileAlignment : kDefaultTileSize);
  Image out(in.color->width(), in.color->height());
  std::vector<float> input, output;
  for (size_t i = 0; i < tiles.size(); ++i) {
    if (options.progress && !options.progress(double(i) / double(tiles.size())))
      throw DenoiseCancelled("denoising cancelled");
    const Tile& t = tiles[i];
    const size_t plane = size_t(t.in_width) * size_t(t.in_height);
    input.resize(plane * size_t(net->input_channels()));
    output.resize(plane * 3);
    arena.execute([&] { fill_tile(in, t, transfer, hdr, scale, input.data()); });
    net->run(input.data(), t.in_height, t.in_width, output.data());
    arena.execute([&] { store_tile(output.data(), t, transfer, hdr, scale, out); });
  }
  if (options.progress) options.progress(1.0);
  return out;
}

}  // namespace lp::denoise
