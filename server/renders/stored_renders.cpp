#include "server/renders/stored_renders.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <map>
#include <set>
#include <stdexcept>
#include <variant>

#include "api/api_error.hpp"
#include "server/maps/envmap_content_hash.hpp"
#include "server/renders/model_hashes.hpp"
#include "server/renders/render_memory.hpp"
#include "server/renders/scene_meshes.hpp"

namespace lp::server {
namespace {

namespace fs = std::filesystem;

struct MissingImage {};  // a finished render's record whose image is gone

std::shared_ptr<RenderJob> restore_render(App& app, RenderRecord record) {
  const auto request = api::parse_render_request(record.request, app.options.limits);
  const JobStatus status = is_finished(record.status) ? record.status : JobStatus::Interrupted;
  // The image stays with the job, so it is held from the budget like a finished render's.
  MemoryReservation memory;
  if (!record.image_file.empty())
    memory = app.memory.reserve(rendered_image_bytes(request.settings, request.denoise), MemoryUse::Held,
                                fmt::format("the image of render {}", record.id));
  auto image = RenderFiles::read_image(*app.state, record, request);
  if (!image.image) {
    memory = {};
    if (status != JobStatus::Interrupted && record.spp_done > 0) {
      std::error_code ec;
      if (!fs::exists(app.state->renders_dir() / record.image_file, ec)) throw MissingImage();
      throw std::runtime_error("its image is unusable");
    }
    record.spp_done = 0;  // an interrupted render without a usable image starts over
    record.image_file.clear();
  }
  auto job = std::make_shared<RenderJob>(std::move(record), request, nullptr, std::move(image),
                                         RenderJobContext{app.state.get(), nullptr, std::move(memory), {}});
  job->restore_ended(status, job->error());
  return job;
}

// The id a file of the renders folder belongs to: "ID.json", "ID.SPP.exr".
std::string render_id_of(const fs::path& file) {
  const std::string name = file.filename().string();
  return name.substr(0, name.find('.'));
}

// Removes the files no record names: images whose record is gone (deleted while a checkpoint wrote), or
// that a newer image replaced. The files of a record that could not be read are kept for the operator.
void remove_unrecorded_files(const StateStore& store, const std::vector<RenderRecord>& records) {
  std::set<std::string> ids, named;
  for (const auto& r : records) {
    ids.insert(r.id);
    named.insert(r.image_file);
  }
  const auto is_named = [&](const std::string& file) {
    return named.contains(RenderFiles::image_file_of(file));
  };
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(store.renders_dir(), ec)) {
    const fs::path& path = entry.path();
    if (path.extension() == ".json" || is_named(path.filename().string())) continue;
    const std::string id = render_id_of(path);
    if (ids.contains(id) || !fs::exists(store.renders_dir() / (id + ".json"))) store.remove_leftover(path);
  }
}

api::ApiError cannot_resume(const RenderJob& job, api::ErrorCode code, const std::string& why) {
  return api::ApiError(code, fmt::format("render '{}' cannot resume: {}", job.id(), why));
}

// The mesh paths as the request names them (resolving them makes them server paths).
std::map<size_t, std::string> mesh_names(const render::SceneDesc& scene) {
  std::map<size_t, std::string> out;
  for (size_t i = 0; i < scene.objects.size(); ++i)
    if (const auto* mesh = std::get_if<render::MeshObject>(&scene.objects[i].shape))
      out[i] = mesh->path.generic_string();
  return out;
}

// Refuses to continue an image rendered with other models than those the request names now.
void check_models(const RenderJob& job, const ModelHashes& kept, const render::SceneDesc& scene,
                  const std::map<size_t, std::string>& names) {
  const ModelHashes now = model_content_hashes(scene);
  for (const auto& [object, name] : names) {
    const auto was = kept.find(object);
    const auto is = now.find(object);
    const bool same = was == kept.end() ? is == now.end()
                                        : is != now.end() && !is->second.empty() && is->second == was->second;
    if (!same)
      throw cannot_resume(
          job, api::ErrorCode::ModelChanged,
          fmt::format("the model '{}' (scene.objects[{}].path) is not the one it was rendering",
                      api::excerpt(name), object));
  }
}

}  // namespace

void restore_renders(App& app) {
  std::vector<RenderRecord> records;
  for (const auto& [path, json] : app.state->read_records(app.state->renders_dir())) {
    try {
      auto record = parse_render_record(json);
      if (path.filename() != record.id + ".json") throw std::invalid_argument("its id is not its file name");
      records.push_back(std::move(record));
    } catch (const std::exception& e) {
      spdlog::warn("state: skipping {}: {}", path.string(), e.what());
    }
  }
  std::stable_sort(records.begin(), records.end(),
                   [](const auto& a, const auto& b) { return a.created < b.created; });
  remove_unrecorded_files(*app.state, records);
  std::vector<std::shared_ptr<RenderJob>> interrupted;
  size_t restored = 0;
  for (auto& record : records) {
    const std::string id = record.id;
    try {
      auto job = restore_render(app, std::move(record));
      if (job->status() == JobStatus::Interrupted) {
        job->save_record();
        interrupted.push_back(job);
      }
      app.renders.restore(job);
      ++restored;
    } catch (const MissingImage&) {
      spdlog::warn("state: dropping renders/{}.json: its image is missing", id);
      app.state->remove(app.state->renders_dir() / (id + ".json"));
    } catch (const std::exception& e) {
      spdlog::warn("state: skipping render {}: {}", id, e.what());
    }
  }
  spdlog::info("state: {} render job(s) restored, {} interrupted", restored, interrupted.size());
  if (!app.options.resume_interrupted) return;
  for (const auto& job : interrupted) {
    try {
      if (!resume_render(app, job).job) spdlog::warn("render {} not resumed: the queue is full", job->id());
    } catch (const std::exception& e) {
      spdlog::warn("render {} not resumed: {}", job->id(), e.what());
    }
  }
}

QueuedRender resume_render(App& app, const std::shared_ptr<RenderJob>& job) {
  if (job->status() != JobStatus::Interrupted)
    throw cannot_resume(*job, api::ErrorCode::NotInterrupted,
                        fmt::format("it is {}; only interrupted renders resume", enum_name(job->status())));
  RenderRecord record = job->record();
  api::RenderRequest request;
  int64_t triangles = 0;
  std::map<size_t, std::string> names;
  try {
    request = api::parse_render_request(record.request, app.options.limits);
    names = mesh_names(request.scene);
    triangles = resolve_meshes(request.scene, app);
    resolve_view(request);
  } catch (const api::ApiError& e) {
    throw cannot_resume(*job, api::ErrorCode::CannotResume, e.what());
  }
  const auto envmap = app.envmaps.find(request.envmap);
  if (!envmap)
    throw cannot_resume(
        *job, api::ErrorCode::EnvmapMissing,
        fmt::format("no map '{}' is loaded; load it under that name and retry", request.envmap));
  if (record.spp_done > 0 && envmap_content_hash(*envmap->map) != record.envmap_fingerprint)
    throw cannot_resume(
        *job, api::ErrorCode::EnvmapChanged,
        fmt::format("the map '{}' loaded now is not the one it was rendering", request.envmap));
  if (record.spp_done > 0) check_models(*job, record.model_hashes, request.scene, names);
  auto queued = queue_render(app, std::move(record), std::move(request), envmap->map, triangles, job->image(),
                             job.get());
  if (!queued.job) {
    if (app.renders.find(job->id()) != job)
      throw cannot_resume(*job, api::ErrorCode::NotInterrupted, "it was resumed already");
    return queued;
  }
  spdlog::info("render {} resumed after {} spp", queued.job->id(), queued.job->spp_done());
  return queued;
}

}  // namespace lp::server
