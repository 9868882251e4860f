#include "engine/model/model_loader.hpp"

#include <algorithm>
#include <cctype>

#include "engine/core/error.hpp"
#include "engine/model/gltf_loader.hpp"
#include "engine/model/model_files.hpp"
#include "engine/model/model_textures.hpp"
#include "engine/model/obj_loader.hpp"

namespace lp {
namespace {

// The material libraries an OBJ names, read next to it and joined.
std::string read_material_libraries(const std::string& obj, ModelFiles& files) {
  std::string mtl;
  for (const std::string& library : obj::material_libraries(obj)) {
    const auto bytes = files.read(library, "material library " + library.substr(0, 128));
    mtl.append(bytes.begin(), bytes.end());
    mtl += '\n';
  }
  return mtl;
}

}  // namespace

std::string model_format(const std::filesystem::path& path) {
  std::string e = path.extension().string();
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return e == ".gltf" || e == ".glb" || e == ".obj" ? e.substr(1) : "";
}

Model load_model(const std::filesystem::path& path, const ModelLimits& limits, TextureCache* cache) {
  const std::string format = model_format(path), name = path.filename().string();
  if (format.empty())
    throw Error(ErrorKind::Unsupported, "model " + name + " is not a .gltf, .glb or .obj file");
  ModelFiles files(path.parent_path().empty() ? "." : path.parent_path(), limits.max_file_bytes,
                   limits.reserve);
  const std::string model_key = files.cache_key(name);  // stamps the model file before reading it
  const auto bytes = files.read_model(path, name);
  TextureCache local;
  ModelTextures textures(files, cache ? *cache : local, limits, model_key);
  Model model;
  if (format == "obj") {
    const std::string text(bytes.begin(), bytes.end());
    model = obj::load(text, read_material_libraries(text, files), name, textures, limits);
  } else {
    model = gltf::load(bytes, name, files, textures, limits);
  }
  model.files = files.stamps();
  return model;
}

Model load_gltf_memory(std::span<const uint8_t> bytes, const std::string& name, const ModelLimits& limits) {
  ModelFiles files({}, limits.max_file_bytes);
  files.count(int64_t(bytes.size()), name);
  TextureCache cache;
  ModelTextures textures(files, cache, limits, "memory");
  return gltf::load(bytes, name, files, textures, limits);
}

Model load_obj_memory(const std::string& obj, const std::string& mtl, const std::string& name,
                      const ModelLimits& limits) {
  ModelFiles files({}, limits.max_file_bytes);
  files.count(int64_t(obj.size() + mtl.size()), name);
  TextureCache cache;
  ModelTextures textures(files, cache, limits, "memory");
  return obj::load(obj, mtl, name, textures, limits);
}

}  // namespace lp
