#pragma once
// A render's files in the state directory (storage/state_store.hpp): its record, renders/ID.json, and the
// mean image of its finished passes, renders/ID.SPP.exr. One write at a time, and none once the files are
// deleted. An image that cannot be written fails the render (its result could not be kept); a record
// that cannot be written is logged.
#include <memory>
#include <mutex>
#include <string>

#include "api/render_request.hpp"
#include "engine/image/image.hpp"
#include "server/renders/render_record.hpp"
#include "server/storage/state_store.hpp"

namespace lp::server {

class RenderFiles {
 public:
  // `store` null keeps nothing; `image_file` is the image an earlier run kept (empty: none).
  RenderFiles(StateStore* store, std::string id, std::string image_file);

  bool keeps() const { return store_ != nullptr; }
  std::string image_file() const;

  void save_record(const RenderRecord& record) const;  // a failure is logged
  // The same for a render being accepted: throws api::ApiError 507 insufficient_storage (disk full) or 500
  // write_failed when the record cannot be written.
  void keep_record(const RenderRecord& record) const;
  // Writes `image` (the mean of `spp_done` samples per pixel), then `record` naming it, then removes the
  // image kept before. False if nothing is kept (no store, or the files were removed). Throws
  // api::ApiError 507 insufficient_storage (disk full) or 500 write_failed when the image cannot be
  // written (then nothing changes).
  bool save_image(const Image& image, int spp_done, RenderRecord record);
  // Removes the record and the image, for good.
  void remove();

  // The mean image a record names, or null if it names none or the file is unusable (logged).
  static std::shared_ptr<const Image> read_image(const StateStore& store, const RenderRecord& record,
                                                 const api::RenderRequest& request);

 private:
  void write_record(const RenderRecord& record) const;  // with the lock held

  StateStore* const store_;
  const std::string id_;
  mutable std::mutex mutex_;
  std::string image_file_;
  bool removed_ = false;
};

}  // namespace lp::server
