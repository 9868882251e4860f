#include "engine/model/gltf_source.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <set>

#include "engine/model/gltf_extensions.hpp"
#include "engine/model/tinygltf.hpp"

namespace lp::gltf {
namespace {

// Where in the document each object that can carry an extension is, with its extensions.
struct Carrier {
  std::string where;
  const tinygltf::ExtensionMap* extensions;
};

void add_material_carriers(const tinygltf::Model& model, std::vector<Carrier>& out) {
  for (size_t i = 0; i < model.materials.size(); ++i) {
    const tinygltf::Material& m = model.materials[i];
    const std::string where = fmt::format("materials[{}]", i);
    out.push_back({where, &m.extensions});
    out.push_back({where + ".pbrMetallicRoughness.baseColorTexture",
                   &m.pbrMetallicRoughness.baseColorTexture.extensions});
    out.push_back({where + ".pbrMetallicRoughness.metallicRoughnessTexture",
                   &m.pbrMetallicRoughness.metallicRoughnessTexture.extensions});
    out.push_back({where + ".normalTexture", &m.normalTexture.extensions});
    out.push_back({where + ".occlusionTexture", &m.occlusionTexture.extensions});
    out.push_back({where + ".emissiveTexture", &m.emissiveTexture.extensions});
  }
}

std::vector<Carrier> carriers(const tinygltf::Model& model) {
  std::vector<Carrier> out = {{"the document", &model.extensions}};
  add_material_carriers(model, out);
  for (size_t i = 0; i < model.meshes.size(); ++i) {
    out.push_back({fmt::format("meshes[{}]", i), &model.meshes[i].extensions});
    for (size_t j = 0; j < model.meshes[i].primitives.size(); ++j)
      out.push_back(
          {fmt::format("meshes[{}].primitives[{}]", i, j), &model.meshes[i].primitives[j].extensions});
  }
  for (size_t i = 0; i < model.nodes.size(); ++i)
    out.push_back({fmt::format("nodes[{}]", i), &model.nodes[i].extensions});
  for (size_t i = 0; i < model.textures.size(); ++i)
    out.push_back({fmt::format("textures[{}]", i), &model.textures[i].extensions});
  for (size_t i = 0; i < model.images.size(); ++i)
    out.push_back({fmt::format("images[{}]", i), &model.images[i].extensions});
  for (size_t i = 0; i < model.samplers.size(); ++i)
    out.push_back({fmt::format("samplers[{}]", i), &model.samplers[i].extensions});
  for (size_t i = 0; i < model.scenes.size(); ++i)
    out.push_back({fmt::format("scenes[{}]", i), &model.scenes[i].extensions});
  return out;
}

// Why an unread extension's content does not show, where that is more than "ignored".
std::string consequence(const std::string& extension) {
  if (extension == "KHR_materials_variants") return ": every primitive keeps its default material";
  return "";
}

class Warnings {
 public:
  void add(std::string warning) {
    ++count_;
    if (out_.size() < kMaxWarnings) out_.push_back(std::move(warning));
  }
  std::vector<std::string> finish() && {
    if (count_ > out_.size()) out_.push_back(fmt::format("and {} more warnings", count_ - out_.size()));
    return std::move(out_);
  }

 private:
  std::vector<std::string> out_;
  size_t count_ = 0;
};

// An unread extension, at each place that carries it (extensionsUsed when none does).
void warn_unread(const tinygltf::Model& model, Warnings& warnings) {
  std::set<std::string> unread;
  for (const std::string& e : model.extensionsUsed)
    if (!is_supported_extension(e)) unread.insert(e);
  if (unread.empty()) return;
  std::set<std::string> seen;
  for (const Carrier& c : carriers(model))
    for (const auto& [name, value] : *c.extensions)
      if (!is_supported_extension(name)) {
        seen.insert(name);
        warnings.add(
            fmt::format("{}: {} is not supported and is ignored{}", c.where, name, consequence(name)));
      }
  for (const std::string& e : unread)
    if (!seen.contains(e))
      warnings.add(fmt::format("extensionsUsed: {} is not supported and is ignored{}", e, consequence(e)));
}

void warn_ignored_content(const tinygltf::Model& model, const std::vector<MeshInstance>& instances,
                          Warnings& warnings) {
  if (!model.animations.empty())
    warnings.add(fmt::format("animations: {} animation(s) are ignored: the model is rendered at rest",
                             model.animations.size()));
  if (!model.skins.empty())
    warnings.add(fmt::format("skins: {} skin(s) are ignored: skinned meshes are rendered at rest",
                             model.skins.size()));
  std::set<int> placed;
  for (const MeshInstance& instance : instances) placed.insert(instance.mesh);
  for (int mesh : placed) {
    const auto& primitives = model.meshes[size_t(mesh)].primitives;
    for (size_t j = 0; j < primitives.size(); ++j) {
      const std::string where = fmt::format("meshes[{}].primitives[{}]", mesh, j);
      const int mode = primitives[j].mode;
      if (mode == TINYGLTF_MODE_POINTS || mode == TINYGLTF_MODE_LINE || mode == TINYGLTF_MODE_LINE_LOOP ||
          mode == TINYGLTF_MODE_LINE_STRIP)
        warnings.add(where + ": points and lines are not rendered");
      if (!primitives[j].targets.empty()) warnings.add(where + ": morph targets are ignored");
    }
  }
}

ModelSource::Material material_source(const tinygltf::Material& m) {
  ModelSource::Material out;
  for (const auto& [name, value] : m.extensions) out.extensions.push_back(name);
  return out;
}

}  // namespace

ModelSource describe_source(const tinygltf::Model& model, const std::vector<MeshInstance>& instances) {
  ModelSource out;
  std::set<int> meshes;
  for (const MeshInstance& instance : instances) meshes.insert(instance.mesh);
  out.meshes = int64_t(meshes.size());
  for (const tinygltf::Material& m : model.materials) out.materials.push_back(material_source(m));
  for (const tinygltf::Camera& c : model.cameras) out.cameras.push_back({c.name, c.type});
  out.extensions_used = model.extensionsUsed;
  Warnings warnings;
  warn_unread(model, warnings);
  warn_ignored_content(model, instances, warnings);
  out.warnings = std::move(warnings).finish();
  return out;
}

}  // namespace lp::gltf
