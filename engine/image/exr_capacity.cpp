#include "engine/image/exr_capacity.hpp"

#include <fmt/format.h>
#include <openexr.h>

#include <algorithm>
#include <memory>
#include <string>

#include "engine/core/error.hpp"
#include "engine/image/exr_attributes.hpp"
#include "engine/image/image_limits.hpp"

namespace lp {
namespace {

[[noreturn]] void cannot_hold(const std::string& why) {
  throw Error(ErrorKind::Corrupt,
              "cannot read OpenEXR data: the file cannot hold the pixels it claims (" + why + ")");
}

int64_t read_from_span(exr_const_context_t, void* user, void* buffer, uint64_t size, uint64_t offset,
                       exr_stream_error_func_ptr_t) {
  const auto& bytes = *static_cast<const std::span<const uint8_t>*>(user);
  if (offset >= bytes.size()) return 0;
  const uint64_t n = std::min<uint64_t>(size, bytes.size() - offset);
  std::copy_n(bytes.data() + offset, n, static_cast<uint8_t*>(buffer));
  return int64_t(n);
}

int64_t span_size(exr_const_context_t, void* user) {
  return int64_t(static_cast<const std::span<const uint8_t>*>(user)->size());
}

void ignore_errors(exr_const_context_t, exr_result_t, const char*) {}

// Tiles may extend past a small image, up to this size.
constexpr int64_t kMaxTileOverhang = 256;

// The most uncompressed bytes one compressed byte can stand for; 0 where no simple bound exists
// (PIZ and DWA combine wavelets or DCT with Huffman and zlib).
uint64_t max_expansion(exr_compression_t c) {
  switch (c) {
    case EXR_COMPRESSION_NONE:
      return 1;
    case EXR_COMPRESSION_RLE:
      return 64;  // a 2-byte run stands for at most 128 bytes
    case EXR_COMPRESSION_ZIPS:
    case EXR_COMPRESSION_ZIP:
      return 1040;  // deflate's limit is about 1032:1
    case EXR_COMPRESSION_PXR24:
      return 1400;  // 32-bit floats stored as 24 bits, then deflate
    case EXR_COMPRESSION_B44:
      return 3;  // 32 bytes of halfs in 14; floats are stored as is
    case EXR_COMPRESSION_B44A:
      return 11;  // a flat 4x4 block in 3 bytes
    default:
      return 0;
  }
}

struct ContextDeleter {
  void operator()(exr_context_t c) const { exr_finish(&c); }
};
using Context = std::unique_ptr<std::remove_pointer_t<exr_context_t>, ContextDeleter>;

Context open(const std::span<const uint8_t>& bytes) {
  exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
  init.user_data = const_cast<std::span<const uint8_t>*>(&bytes);
  init.read_fn = read_from_span;
  init.size_fn = span_size;
  init.error_handler_fn = ignore_errors;
  init.flags = EXR_CONTEXT_FLAG_SILENT_HEADER_PARSE;
  exr_context_t raw = nullptr;
  if (const exr_result_t r = exr_start_read(&raw, "memory", &init); r != EXR_ERR_SUCCESS) {
    if (raw) exr_finish(&raw);
    throw Error(ErrorKind::Corrupt,
                std::string("cannot read OpenEXR header: ") + exr_get_default_error_message(r));
  }
  return Context(raw);
}

struct Totals {
  uint64_t packed = 0, unpacked = 0;
  void add(const exr_chunk_info_t& c, uint64_t file_size) {
    if (c.data_offset > file_size || c.packed_size > file_size - c.data_offset)
      cannot_hold(fmt::format("a chunk at offset {} of {} bytes ends past the end of the file", c.data_offset,
                              c.packed_size));
    packed += c.packed_size;
    unpacked += c.unpacked_size;
  }
};

void check_result(exr_result_t r, const char* what) {
  if (r != EXR_ERR_SUCCESS) cannot_hold(fmt::format("{}: {}", what, exr_get_default_error_message(r)));
}

Totals scanline_totals(exr_const_context_t ctx, const exr_attr_box2i_t& window, uint64_t file_size) {
  int32_t lines = 0;
  check_result(exr_get_scanlines_per_chunk(ctx, 0, &lines), "scanlines per chunk");
  if (lines <= 0) cannot_hold("no scanlines per chunk");
  Totals t;
  for (int64_t y = window.min.y; y <= window.max.y; y += lines) {
    exr_chunk_info_t chunk;
    check_result(exr_read_scanline_chunk_info(ctx, 0, int(y), &chunk), "scanline chunk");
    t.add(chunk, file_size);
  }
  return t;
}

Totals tile_totals(exr_const_context_t ctx, const exr_attr_box2i_t& window, uint64_t file_size) {
  int32_t tile_w = 0, tile_h = 0;
  check_result(exr_get_tile_sizes(ctx, 0, 0, 0, &tile_w, &tile_h), "tile size");
  if (tile_w <= 0 || tile_h <= 0) cannot_hold("empty tiles");
  const int64_t width = int64_t{window.max.x} - window.min.x + 1,
                height = int64_t{window.max.y} - window.min.y + 1;
  // The library reads tiles through a buffer of one row of tiles across the image: a tile far taller
  // or wider than the image would make that buffer larger than the image.
  // (exr_get_tile_sizes above gives the size clipped to the level; the buffer uses the declared one.)
  uint32_t declared_w = 0, declared_h = 0;
  exr_tile_level_mode_t levels;
  exr_tile_round_mode_t rounding;
  check_result(exr_get_tile_descriptor(ctx, 0, &declared_w, &declared_h, &levels, &rounding),
               "tile description");
  if (declared_w > std::max<int64_t>(width, kMaxTileOverhang) ||
      declared_h > std::max<int64_t>(height, kMaxTileOverhang))
    cannot_hold(fmt::format("tiles of {} x {} for {} x {} pixels", declared_w, declared_h, width, height));
  const int64_t columns = (width + tile_w - 1) / tile_w, rows = (height + tile_h - 1) / tile_h;
  Totals t;
  for (int64_t ty = 0; ty < rows; ++ty) {
    for (int64_t tx = 0; tx < columns; ++tx) {
      exr_chunk_info_t chunk;
      check_result(exr_read_tile_chunk_info(ctx, 0, int(tx), int(ty), 0, 0, &chunk), "tile chunk");
      t.add(chunk, file_size);
    }
  }
  return t;
}

}  // namespace

ExrHeaderSummary check_exr_capacity(std::span<const uint8_t> bytes, const ImageLimits& limits) {
  check_exr_attributes(bytes);
  const Context ctx = open(bytes);
  exr_storage_t storage;
  exr_compression_t compression;
  exr_attr_box2i_t window;
  check_result(exr_get_storage(ctx.get(), 0, &storage), "storage");
  check_result(exr_get_compression(ctx.get(), 0, &compression), "compression");
  check_result(exr_get_data_window(ctx.get(), 0, &window), "data window");
  if (storage != EXR_STORAGE_SCANLINE && storage != EXR_STORAGE_TILED)
    throw Error(ErrorKind::Unsupported, "deep OpenEXR images are not supported");
  check_image_size(int64_t{window.max.x} - window.min.x + 1, int64_t{window.max.y} - window.min.y + 1,
                   limits);
  int32_t chunks = 0;
  check_result(exr_get_chunk_count(ctx.get(), 0, &chunks), "chunk count");
  if (chunks <= 0 || uint64_t(chunks) > bytes.size() / sizeof(uint64_t))
    cannot_hold(fmt::format("an offset table of {} chunks", chunks));
  const Totals t = storage == EXR_STORAGE_SCANLINE ? scanline_totals(ctx.get(), window, bytes.size())
                                                   : tile_totals(ctx.get(), window, bytes.size());
  const uint64_t ratio = max_expansion(compression);
  if (t.packed == 0 || (ratio && t.unpacked / ratio > t.packed))
    cannot_hold(fmt::format("{} bytes of compressed pixels for {} bytes of pixels", t.packed, t.unpacked));
  return {window.min.x, window.min.y, window.max.x, window.max.y, int(compression)};
}

}  // namespace lp
