#pragma once
// A render's files in the state directory (storage/state_store.hpp): its record, renders/ID.json, the
// mean image of its finished passes, renders/ID.SPP.exr, and that of each auxiliary pass it asks for,
// renders/ID.SPP.PASS.exr (PASS: albedo, normal, depth, alpha; greys for depth and alpha), and the colour
// denoised once a render that asked for it has finished, renders/ID.SPP.denoised.exr. One write at a
// time, and none once the files are deleted. An image that cannot be written fails the render (its result
// could not be kept); a record that cannot be written is logged.
#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include "api/render_request.hpp"
#include "engine/image/image.hpp"
#include "server/renders/render_job_image.hpp"
#include "server/renders/render_record.hpp"
#include "server/storage/state_store.hpp"

namespace lp::server {

class RenderFiles {
 public:
  // `store` null keeps nothing; `image_file` is the image an earlier run kept (empty: none), with
  // `passes` beside it, and its denoised colour when `denoise_s` is set.
  RenderFiles(StateStore* store, std::string id, std::string image_file, render::PassSet passes,
              std::optional<double> denoise_s = std::nullopt);

  bool keeps() const { return store_ != nullptr; }
  std::string image_file() const;
  std::optional<double> denoise_s() const;  // of the denoised colour kept beside image_file()

  void save_record(const RenderRecord& record) const;  // a failure is logged
  // The same for a render being accepted: throws api::ApiError 507 insufficient_storage (disk full) or 500
  // write_failed when the record cannot be written.
  void keep_record(const RenderRecord& record) const;
  // Writes `image` (the mean of its spp_done samples per pixel, its passes and its denoised colour if it
  // has one), then `record` naming it,
  // then removes the images kept before. False if nothing is kept (no store, or the files were removed).
  // Throws api::ApiError 507 insufficient_storage (disk full) or 500 write_failed when the image cannot be
  // written (then nothing changes).
  bool save_image(const RenderImage& image, RenderRecord record);
  // Removes the record and the image, for good.
  void remove();

  // The mean image a record names, with the passes its request asks for, or no image if it names none
  // or a file is unusable (logged); an unusable denoised colour is left out alone (logged).
  static RenderImage read_image(const StateStore& store, const RenderRecord& record,
                                const api::RenderRequest& request);
  // The file of pass `pass` beside the colour image `image_file`.
  static std::string pass_file(const std::string& image_file, render::AuxPass pass);
  // The file of the denoised colour beside the colour image `image_file`.
  static std::string denoised_file(const std::string& image_file);
  // The colour image a file of the renders folder goes with: itself, or the image of a pass's file or of
  // its denoised colour's.
  static std::string image_file_of(const std::string& file);

 private:
  void write_record(const RenderRecord& record) const;  // with the lock held
  void remove_image(const std::string& image_file, const render::PassSet& passes, bool denoised) const;

  StateStore* const store_;
  const std::string id_;
  mutable std::mutex mutex_;
  std::string image_file_;
  render::PassSet image_passes_;     // the passes kept beside image_file_
  std::optional<double> denoise_s_;  // set when its denoised colour is kept beside it
  bool removed_ = false;
};

}  // namespace lp::server
