#include "server/turntables/turntable_outputs.hpp"

#include <archive.h>
#include <archive_entry.h>
#include <fmt/format.h>

#include <algorithm>
#include <memory>
#include <stdexcept>

#include "engine/image/contact_sheet.hpp"
#include "engine/image/encode_pixels8.hpp"
#include "engine/image/resize.hpp"

namespace lp::server {
namespace {

struct WriterCloser {
  void operator()(archive* a) const { archive_write_free(a); }
};
struct EntryCloser {
  void operator()(archive_entry* e) const { archive_entry_free(e); }
};

la_ssize_t append_bytes(archive*, void* out, const void* data, size_t n) {
  auto& bytes = *static_cast<std::vector<uint8_t>*>(out);
  bytes.insert(bytes.end(), static_cast<const uint8_t*>(data), static_cast<const uint8_t*>(data) + n);
  return la_ssize_t(n);
}

void zip_check(archive* a, int r, const char* what) {
  if (r < ARCHIVE_WARN)
    throw std::runtime_error(
        fmt::format("cannot write the frames' zip ({}): {}", what,
                    archive_error_string(a) ? archive_error_string(a) : "unknown error"));
}

void zip_member(archive* a, const std::string& name, std::span<const uint8_t> bytes) {
  const std::unique_ptr<archive_entry, EntryCloser> entry(archive_entry_new());
  archive_entry_set_pathname(entry.get(), name.c_str());
  archive_entry_set_filetype(entry.get(), AE_IFREG);
  archive_entry_set_perm(entry.get(), 0644);
  archive_entry_set_size(entry.get(), int64_t(bytes.size()));
  zip_check(a, archive_write_header(a, entry.get()), "header");
  if (!bytes.empty() && archive_write_data(a, bytes.data(), bytes.size()) < 0)
    zip_check(a, ARCHIVE_FATAL, "data");
}

// Each frame's scale so that a sheet of `layout` is at most `size` on its longest side.
std::optional<int> cell_longest_side(int width, int height, SheetLayout layout, std::optional<int> size) {
  if (!size) return std::nullopt;
  const int64_t sheet_w = int64_t(width) * layout.columns, sheet_h = int64_t(height) * layout.rows;
  const double scale = double(*size) / double(std::max(sheet_w, sheet_h));
  return std::max(1, int(double(std::max(width, height)) * scale));
}

}  // namespace

std::vector<Pixels8> Frames8::pictures() const {
  std::vector<Pixels8> out;
  for (const auto& b : bytes) out.push_back({b, width, height, channels});
  return out;
}

Frames8 frames8(const std::vector<RenderImage>& frames, std::optional<int> size, const ToneMap& tone) {
  Frames8 out;
  for (const RenderImage& frame : frames) {
    const Image small = fit_longest_side(*frame.image, size);
    out.width = small.width();
    out.height = small.height();
    const Image* alpha = frame.pass(render::AuxPass::Alpha);
    out.channels = alpha ? 4 : 3;
    out.bytes.push_back(alpha ? tone_map_rgba8(small, fit_longest_side(*alpha, size), tone)
                              : tone_map_rgb8(small, tone));
  }
  return out;
}

int64_t frames8_bytes(int64_t frames, int64_t width, int64_t height) {
  return frames * 4 * width * height + 24 * width * height;
}

std::vector<uint8_t> frames_zip(const Frames8& frames, const nlohmann::json& cameras) {
  std::vector<uint8_t> out;
  const std::unique_ptr<archive, WriterCloser> a(archive_write_new());
  if (!a) throw std::bad_alloc();
  zip_check(a.get(), archive_write_set_format_zip(a.get()), "format");
  zip_check(a.get(), archive_write_set_options(a.get(), "zip:compression=store"), "options");
  zip_check(a.get(), archive_write_open(a.get(), &out, nullptr, append_bytes, nullptr), "open");
  const std::vector<Pixels8> pictures = frames.pictures();
  for (size_t i = 0; i < pictures.size(); ++i)
    zip_member(a.get(), fmt::format("frame_{:04}.png", i), encode_pixels8(pictures[i], ImageFormat::Png));
  const std::string json = cameras.dump(2) + "\n";
  zip_member(a.get(), "cameras.json", {reinterpret_cast<const uint8_t*>(json.data()), json.size()});
  zip_check(a.get(), archive_write_close(a.get()), "close");
  return out;
}

std::vector<uint8_t> frames_contact_sheet(const std::vector<RenderImage>& frames, std::optional<int> size,
                                          const ToneMap& tone, ImageFormat format) {
  const SheetLayout layout = contact_sheet_layout(int(frames.size()));
  const Image& first = *frames.front().image;
  const Frames8 cells = frames8(frames, cell_longest_side(first.width(), first.height(), layout, size), tone);
  const auto pictures = cells.pictures();
  const std::vector<uint8_t> sheet = contact_sheet(pictures, layout);
  const Pixels8 picture{sheet, cells.width * layout.columns, cells.height * layout.rows, cells.channels};
  return encode_pixels8(picture, format);
}

}  // namespace lp::server
