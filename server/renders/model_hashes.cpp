#include "server/renders/model_hashes.hpp"

#include <stdexcept>
#include <variant>
#include <vector>

#include "server/storage/content_hash.hpp"

namespace lp::server {

std::string model_content_hash(const Model& model) {
  if (model.files.empty()) return "";
  const auto folder = model.files.front().path.parent_path();
  std::vector<std::string> names;
  for (const auto& file : model.files) names.push_back(file.path.lexically_relative(folder).generic_string());
  std::string hash;
  try {
    hash = files_content_hash(folder, names);
  } catch (const std::runtime_error&) {
    return "";
  }
  for (const auto& file : model.files)
    if (FileStamp::of(file.path) != file) return "";
  return hash;
}

ModelHashes model_content_hashes(const render::SceneDesc& scene) {
  ModelHashes out;
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    const auto* mesh = std::get_if<render::MeshObject>(&scene.objects[i].shape);
    if (mesh && mesh->model && !mesh->model->files.empty()) out[i] = model_content_hash(*mesh->model);
  }
  return out;
}

}  // namespace lp::server
