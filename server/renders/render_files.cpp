#include "server/renders/render_files.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <stdexcept>

#include "engine/image/image_io.hpp"
#include "server/storage/storage_error.hpp"

namespace lp::server {

RenderFiles::RenderFiles(StateStore* store, std::string id, std::string image_file, render::PassSet passes,
                         std::optional<double> denoise_s)
    : store_(store),
      id_(std::move(id)),
      image_file_(std::move(image_file)),
      image_passes_(passes),
      denoise_s_(denoise_s) {}

std::string RenderFiles::image_file() const {
  std::lock_guard lock(mutex_);
  return image_file_;
}

std::optional<double> RenderFiles::denoise_s() const {
  std::lock_guard lock(mutex_);
  return denoise_s_;
}

void RenderFiles::write_record(const RenderRecord& record) const {
  try {
    store_->write_record(store_->renders_dir() / (id_ + ".json"), record_json(record));
  } catch (const std::exception& e) {
    const auto* s = dynamic_cast<const StorageError*>(&e);
    spdlog::error("render {}: cannot save its record: {}{}", id_, e.what(),
                  s ? " (" + s->path().string() + ")" : "");
  }
}

void RenderFiles::save_record(const RenderRecord& record) const {
  if (!store_) return;
  std::lock_guard lock(mutex_);
  if (!removed_) write_record(record);
}

void RenderFiles::keep_record(const RenderRecord& record) const {
  if (!store_) return;
  std::lock_guard lock(mutex_);
  try {
    store_->write_record(store_->renders_dir() / (id_ + ".json"), record_json(record));
  } catch (const StorageError& e) {
    throw storage_refusal(e, "render " + id_);
  }
}

std::string RenderFiles::pass_file(const std::string& image_file, render::AuxPass pass) {
  const std::string stem = image_file.substr(0, image_file.rfind('.'));
  return fmt::format("{}.{}.exr", stem, enum_name(pass));
}

std::string RenderFiles::denoised_file(const std::string& image_file) {
  const std::string stem = image_file.substr(0, image_file.rfind('.'));
  return stem + ".denoised.exr";
}

std::string RenderFiles::image_file_of(const std::string& file) {
  std::vector<std::string> kinds{"denoised"};
  for (const auto& e : enum_entries(render::AuxPass{})) kinds.emplace_back(e.name);
  for (const std::string& kind : kinds) {
    const std::string suffix = fmt::format(".{}.exr", kind);
    if (file.size() > suffix.size() && file.ends_with(suffix))
      return file.substr(0, file.size() - suffix.size()) + ".exr";
  }
  return file;
}

void RenderFiles::remove_image(const std::string& image_file, const render::PassSet& passes,
                               bool denoised) const {
  store_->remove(store_->renders_dir() / image_file);
  for (const auto p : passes.list()) store_->remove(store_->renders_dir() / pass_file(image_file, p));
  if (denoised) store_->remove(store_->renders_dir() / denoised_file(image_file));
}

bool RenderFiles::save_image(const RenderImage& image, RenderRecord record) {
  if (!store_) return false;
  const std::string file = fmt::format("{}.{}.exr", id_, image.spp_done);
  // Encoded without the lock: the colour, then each pass.
  std::vector<std::pair<std::string, std::vector<uint8_t>>> files;
  files.emplace_back(file, write_exr(*image.image, ExrCompression::None));
  render::PassSet passes;
  for (const auto& e : enum_entries(render::AuxPass{}))
    if (const Image* pass = image.pass(e.value)) {
      files.emplace_back(pass_file(file, e.value), write_exr(*pass, ExrCompression::None));
      passes.add(e.value);
    }
  if (image.denoised)
    files.emplace_back(denoised_file(file), write_exr(*image.denoised, ExrCompression::None));
  std::lock_guard lock(mutex_);
  if (removed_) return false;
  try {
    // The passes first: the colour image's file, once written, says the set is whole.
    for (size_t i = files.size(); i-- > 0;)
      store_->write_bytes(store_->renders_dir() / files[i].first, files[i].second);
  } catch (const StorageError& e) {
    throw storage_refusal(e, "the image of render " + id_);
  }
  const std::string previous = std::exchange(image_file_, file);
  const render::PassSet previous_passes = std::exchange(image_passes_, passes);
  const bool previous_denoised =
      std::exchange(denoise_s_, image.denoised ? image.denoise_s : std::nullopt).has_value();
  record.image_file = file;
  record.denoise_s = denoise_s_;
  write_record(record);
  if (!previous.empty() && previous != file) remove_image(previous, previous_passes, previous_denoised);
  return true;
}

void RenderFiles::remove() {
  if (!store_) return;
  std::lock_guard lock(mutex_);
  removed_ = true;
  store_->remove(store_->renders_dir() / (id_ + ".json"));
  if (!image_file_.empty()) remove_image(image_file_, image_passes_, denoise_s_.has_value());
}

RenderImage RenderFiles::read_image(const StateStore& store, const RenderRecord& record,
                                    const api::RenderRequest& request) {
  if (record.image_file.empty()) return {};
  const auto& s = request.settings;
  const auto read = [&](const std::string& file) {
    ImageLimits limits;
    limits.max_pixels = int64_t{s.width} * s.height;
    auto decoded = read_image_file(store.renders_dir() / file, limits);
    if (decoded.image.width() != s.width || decoded.image.height() != s.height)
      throw std::runtime_error(file + ": its size is not the render's");
    return std::make_shared<const Image>(std::move(decoded.image));
  };
  RenderImage out;
  try {
    out = {read(record.image_file), record.spp_done, {}, nullptr, std::nullopt};
    for (const auto p : s.passes.list()) out.passes[size_t(p)] = read(pass_file(record.image_file, p));
  } catch (const std::exception& e) {
    spdlog::warn("state: render {}: cannot use {}: {}", record.id, record.image_file, e.what());
    return {};
  }
  if (!record.denoise_s) return out;
  try {
    out.denoised = read(denoised_file(record.image_file));
    out.denoise_s = record.denoise_s;
  } catch (const std::exception& e) {
    spdlog::warn("state: render {}: cannot use its denoised image: {}", record.id, e.what());
  }
  return out;
}

}  // namespace lp::server
