#include "server/renders/render_files.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <stdexcept>

#include "engine/image/image_io.hpp"
#include "server/storage/storage_error.hpp"

namespace lp::server {

RenderFiles::RenderFiles(StateStore* store, std::string id, std::string image_file)
    : store_(store), id_(std::move(id)), image_file_(std::move(image_file)) {}

std::string RenderFiles::image_file() const {
  std::lock_guard lock(mutex_);
  return image_file_;
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

bool RenderFiles::save_image(const Image& image, int spp_done, RenderRecord record) {
  if (!store_) return false;
  const std::string file = fmt::format("{}.{}.exr", id_, spp_done);
  const std::vector<uint8_t> bytes = write_exr(image, ExrCompression::None);  // encoded without the lock
  std::lock_guard lock(mutex_);
  if (removed_) return false;
  try {
    store_->write_bytes(store_->renders_dir() / file, bytes);
  } catch (const StorageError& e) {
    throw storage_refusal(e, "the image of render " + id_);
  }
  const std::string previous = std::exchange(image_file_, file);
  record.image_file = file;
  write_record(record);
  if (!previous.empty() && previous != file) store_->remove(store_->renders_dir() / previous);
  return true;
}

void RenderFiles::remove() {
  if (!store_) return;
  std::lock_guard lock(mutex_);
  removed_ = true;
  store_->remove(store_->renders_dir() / (id_ + ".json"));
  if (!image_file_.empty()) store_->remove(store_->renders_dir() / image_file_);
}

std::shared_ptr<const Image> RenderFiles::read_image(const StateStore& store, const RenderRecord& record,
                                                     const api::RenderRequest& request) {
  if (record.image_file.empty()) return nullptr;
  const auto& s = request.settings;
  try {
    ImageLimits limits;
    limits.max_pixels = int64_t{s.width} * s.height;
    auto decoded = read_image_file(store.renders_dir() / record.image_file, limits);
    if (decoded.image.width() != s.width || decoded.image.height() != s.height)
      throw std::runtime_error("its size is not the render's");
    return std::make_shared<const Image>(std::move(decoded.image));
  } catch (const std::exception& e) {
    spdlog::warn("state: render {}: cannot use {}: {}", record.id, record.image_file, e.what());
    return nullptr;
  }
}

}  // namespace lp::server
