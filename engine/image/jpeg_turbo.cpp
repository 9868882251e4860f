#include "engine/image/jpeg_turbo.hpp"

// jpeglib.h needs size_t and FILE declared first.
#include <jpeglib.h>

#include <csetjmp>
#include <cstdio>
#include <memory>
#include <string>

#include "engine/image/image_limits.hpp"

namespace lp {
namespace {

// libjpeg reports a fatal error through error_exit, which must not return: it jumps back to the
// setjmp of the call in progress with the library's message.
struct ErrorJump {
  jpeg_error_mgr manager{};
  std::jmp_buf jump{};
  char message[JMSG_LENGTH_MAX] = {};
};

void jump_on_error(j_common_ptr info) {
  auto* error = reinterpret_cast<ErrorJump*>(info->err);
  info->err->format_message(info, error->message);
  std::longjmp(error->jump, 1);
}

void keep_warnings_quiet(j_common_ptr, int) {}

void install(ErrorJump& error) {
  jpeg_std_error(&error.manager);
  error.manager.error_exit = jump_on_error;
  error.manager.emit_message = keep_warnings_quiet;
}

// The body of a libjpeg call sequence, kept free of objects with destructors: longjmp skips them.
bool compress(jpeg_compress_struct& info, const Pixels8& p, int quality, JpegColours colours,
              unsigned char** out, unsigned long* size) {
  auto* error = reinterpret_cast<ErrorJump*>(info.err);
  if (setjmp(error->jump)) return false;
  jpeg_create_compress(&info);
  jpeg_mem_dest(&info, out, size);
  info.image_width = JDIMENSION(p.width);
  info.image_height = JDIMENSION(p.height);
  info.input_components = 3;
  info.in_color_space = JCS_RGB;
  jpeg_set_defaults(&info);
  if (colours == JpegColours::Untransformed) jpeg_set_colorspace(&info, JCS_RGB);
  info.write_JFIF_header = FALSE;
  jpeg_set_quality(&info, quality, TRUE);
  for (int c = 0; c < 3; ++c) info.comp_info[c].h_samp_factor = info.comp_info[c].v_samp_factor = 1;
  jpeg_start_compress(&info, TRUE);
  const auto stride = size_t(p.width) * 3;
  while (info.next_scanline < info.image_height) {
    auto* row = const_cast<JSAMPLE*>(p.bytes.data() + size_t(info.next_scanline) * stride);
    jpeg_write_scanlines(&info, &row, 1);
  }
  jpeg_finish_compress(&info);
  return true;
}

bool read_header(jpeg_decompress_struct& info, std::span<const uint8_t> bytes) {
  auto* error = reinterpret_cast<ErrorJump*>(info.err);
  if (setjmp(error->jump)) return false;
  jpeg_create_decompress(&info);
  jpeg_mem_src(&info, bytes.data(), static_cast<unsigned long>(bytes.size()));
  jpeg_read_header(&info, TRUE);
  info.out_color_space = JCS_RGB;
  return true;
}

bool read_pixels(jpeg_decompress_struct& info, uint8_t* rgb) {
  auto* error = reinterpret_cast<ErrorJump*>(info.err);
  if (setjmp(error->jump)) return false;
  jpeg_start_decompress(&info);
  const auto stride = size_t(info.output_width) * 3;
  while (info.output_scanline < info.output_height) {
    JSAMPLE* row = rgb + size_t(info.output_scanline) * stride;
    jpeg_read_scanlines(&info, &row, 1);
  }
  jpeg_finish_decompress(&info);
  return true;
}

}  // namespace

std::vector<uint8_t> encode_jpeg_444(const Pixels8& p, int quality, JpegColours colours) {
  check_pixels8(p, "JPEG");
  if (p.channels != 3) throw Error(ErrorKind::InvalidArgument, "JPEG: expected RGB pixels");
  ErrorJump error;
  install(error);
  jpeg_compress_struct info{};
  info.err = &error.manager;
  unsigned char* out = nullptr;
  unsigned long size = 0;
  const bool done = compress(info, p, quality, colours, &out, &size);
  jpeg_destroy_compress(&info);
  const std::unique_ptr<unsigned char, decltype(&std::free)> owned(out, &std::free);
  if (!done) throw Error(ErrorKind::Internal, std::string("cannot encode JPEG: ") + error.message);
  return {out, out + size};
}

DecodedJpeg decode_jpeg_rgb(std::span<const uint8_t> bytes, const ImageLimits& limits) {
  ErrorJump error;
  install(error);
  jpeg_decompress_struct info{};
  info.err = &error.manager;
  // jpeg_destroy_decompress frees nothing of a struct that was never created (its mem is null).
  const std::unique_ptr<jpeg_decompress_struct, decltype(&jpeg_destroy_decompress)> guard(
      &info, &jpeg_destroy_decompress);
  if (bytes.empty() || !read_header(info, bytes))
    throw Error(ErrorKind::Corrupt, std::string("corrupt JPEG: ") + error.message);
  check_image_size(info.image_width, info.image_height, limits);
  DecodedJpeg out;
  out.width = int(info.image_width);
  out.height = int(info.image_height);
  out.rgb.resize(size_t(out.width) * size_t(out.height) * 3);
  if (!read_pixels(info, out.rgb.data()))
    throw Error(ErrorKind::Corrupt, std::string("corrupt JPEG: ") + error.message);
  return out;
}

}  // namespace lp
