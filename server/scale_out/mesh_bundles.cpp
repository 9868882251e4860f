#include "server/scale_out/mesh_bundles.hpp"

#include <algorithm>
#include <stdexcept>
#include <variant>

#include "server/scale_out/bundle_hash.hpp"

namespace lp::server {
namespace {

std::vector<FileStamp> stamps_now(const Model& model) {
  std::vector<FileStamp> out;
  for (const auto& file : model.files) out.push_back(FileStamp::of(file.path));
  return out;
}

}  // namespace

MeshBundle mesh_bundle(const Model& model) {
  if (model.files.empty()) throw std::runtime_error("a model built in memory has no files to send");
  MeshBundle bundle;
  bundle.folder = model.files.front().path.parent_path();
  for (const auto& file : model.files) {
    const std::string inside = file.path.lexically_relative(bundle.folder).generic_string();
    if (inside.empty() || inside.starts_with(".."))
      throw std::runtime_error("the model file " + file.path.filename().string() +
                               " refers to a file outside its folder");
    if (std::find(bundle.files.begin(), bundle.files.end(), inside) == bundle.files.end())
      bundle.files.push_back(inside);
  }
  bundle.model = bundle.files.front();
  bundle.hash = bundle_hash(bundle.folder, bundle.files);
  return bundle;
}

MeshBundle MeshBundles::bundle_of(const Model& model) {
  const auto stamps = stamps_now(model);
  {
    std::lock_guard lock(mutex_);
    if (const auto* kept = kept_.use(stamps)) return *kept;
  }
  // Hashed without the lock: reading the files holds up no other render.
  MeshBundle bundle = mesh_bundle(model);
  std::lock_guard lock(mutex_);
  kept_.add(stamps, bundle);
  return bundle;
}

std::vector<MeshReference> MeshBundles::publish(const render::SceneDesc& scene) {
  std::vector<MeshReference> out;
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    const auto* mesh = std::get_if<render::MeshObject>(&scene.objects[i].shape);
    if (!mesh || !mesh->model || mesh->model->files.empty()) continue;
    const MeshBundle bundle = bundle_of(*mesh->model);
    out.push_back({i, bundle.hash, bundle.model});
  }
  return out;
}

std::optional<MeshBundle> MeshBundles::find(const std::string& hash) const {
  std::lock_guard lock(mutex_);
  const auto* kept = kept_.find_if([&](const MeshBundle& bundle) { return bundle.hash == hash; });
  return kept ? std::optional<MeshBundle>(*kept) : std::nullopt;
}

}  // namespace lp::server
