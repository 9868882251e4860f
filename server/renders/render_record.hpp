#pragma once
// A render's record in the state directory: enough to list it after a restart, serve its image, and
// continue it exactly where it stopped (the request as accepted, the samples per pixel done, the file of
// their mean image, and the content hashes of the map and the models it was rendered with).
#include <chrono>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "engine/render/partial_film.hpp"
#include "engine/render/renderer.hpp"
#include "server/jobs/job.hpp"
#include "server/renders/model_hashes.hpp"

namespace lp::server {

struct RenderRecord {
  std::string id;
  std::chrono::system_clock::time_point created = std::chrono::system_clock::now();
  nlohmann::json request;  // the body of POST /api/v1/renders
  JobStatus status = JobStatus::Queued;
  std::optional<JobError> error;
  int spp_done = 0;
  // The sample ranges in the image when they are not [0, spp_done): a render split over Redis merges
  // ranges as they arrive. Empty for a render that ran here.
  std::vector<render::SampleRange> ranges_done;
  std::string image_file;  // in the renders folder; empty before the first pass
  // Set when the denoised colour is kept beside image_file (RenderFiles::denoised_file): the seconds the
  // denoise took.
  std::optional<double> denoise_s;
  std::string envmap_fingerprint;  // envmap_content_hash() of the map; empty before the first pass
  ModelHashes model_hashes;        // of the mesh objects' models; empty before the first pass
  double elapsed_s = 0;
  render::RenderStats stats;
  double render_s = 0;  // time spent in passes
};

nlohmann::json record_json(const RenderRecord& record);
// Throws std::exception (nlohmann's or std::invalid_argument) for a record that is not one.
RenderRecord parse_render_record(const nlohmann::json& json);

}  // namespace lp::server
