#include "engine/model/obj_loader.hpp"

#include <fmt/format.h>
#include <tiny_obj_loader.h>

#include <cmath>
#include <map>
#include <sstream>
#include <tuple>

#include "engine/core/error.hpp"
#include "engine/model/mesh_part.hpp"
#include "engine/model/model_memory.hpp"
#include "engine/model/obj_prescan.hpp"

namespace lp::obj {
namespace {

[[noreturn]] void corrupt(const std::string& name, const std::string& problem) {
  throw Error(ErrorKind::Corrupt, "OBJ " + name + ": " + problem);
}

float unit_factor(float v, const std::string& what) {
  if (!std::isfinite(v)) throw Error(ErrorKind::Corrupt, what + " is not finite");
  return std::clamp(v, 0.0f, 1.0f);
}

Rgb colour(const tinyobj::real_t* c, const std::string& what) {
  return {unit_factor(c[0], what), unit_factor(c[1], what), unit_factor(c[2], what)};
}

// Walter et al.'s Phong-Beckmann match alpha = sqrt(2 / (Ns + 2)), as perceptual roughness sqrt(alpha).
float roughness_from_shininess(float ns) {
  if (!std::isfinite(ns) || ns < 0) ns = 0;
  return std::pow(2.0f / (ns + 2.0f), 0.25f);
}

// -o and -s in OBJ's texture space (v up), as a transform of glTF's (v down): v' = s v + (1 - s - o).
TextureTransform transform(const tinyobj::texture_option_t& o, const std::string& what) {
  TextureTransform t;
  for (int i = 0; i < 2; ++i)
    if (!std::isfinite(o.origin_offset[i]) || !std::isfinite(o.scale[i]))
      throw Error(ErrorKind::Corrupt, what + " texture options are not finite");
  t.scale = {o.scale[0], o.scale[1]};
  t.offset = {o.origin_offset[0], 1.0f - o.scale[1] - o.origin_offset[1]};
  return t;
}

std::optional<TextureBinding> binding(const std::string& file, const tinyobj::texture_option_t& o,
                                      ColorSpace space, ModelTextures& textures, const std::string& what) {
  if (file.empty()) return std::nullopt;
  TextureBinding b;
  b.texture = textures.file(file, space, what + " texture " + file.substr(0, 128));
  const WrapMode wrap = o.clamp ? WrapMode::ClampToEdge : WrapMode::Repeat;
  b.sampler = {wrap, wrap};
  b.transform = transform(o, what);
  return b;
}

ModelMaterial material(const tinyobj::material_t& m, ModelTextures& textures) {
  const std::string what = "material " + m.name.substr(0, 64);
  ModelMaterial out;
  out.name = m.name;
  const Rgb kd = colour(m.diffuse, what + " Kd");
  out.base_color_factor = {kd.x, kd.y, kd.z, 1};
  out.base_color = binding(m.diffuse_texname, m.diffuse_texopt, ColorSpace::Srgb, textures, what + " map_Kd");
  out.metallic_factor = 0;
  out.roughness_factor = roughness_from_shininess(m.shininess);
  const bool norm = !m.normal_texname.empty();
  const auto& normal_options = norm ? m.normal_texopt : m.bump_texopt;
  out.normal = binding(norm ? m.normal_texname : m.bump_texname, normal_options, ColorSpace::Linear, textures,
                       what + (norm ? " norm" : " map_Bump"));
  if (!std::isfinite(normal_options.bump_multiplier)) corrupt(m.name, "-bm is not finite");
  out.normal_scale = normal_options.bump_multiplier;
  out.emissive_factor = colour(m.emission, what + " Ke");
  out.emissive = binding(m.emissive_texname, m.emissive_texopt, ColorSpace::Srgb, textures, what + " map_Ke");
  return out;
}

ModelMaterial default_material() {
  ModelMaterial m;
  m.name = "default";
  m.base_color_factor = {0.8f, 0.8f, 0.8f, 1};
  m.metallic_factor = 0;
  return m;
}

// The OBJ's faces as one part: a vertex per distinct (position, uv, normal) triple.
MeshPart read_faces(const tinyobj::ObjReader& reader, uint32_t fallback_material, const std::string& name) {
  const auto& a = reader.GetAttrib();
  bool all_normals = true;
  for (const auto& shape : reader.GetShapes())
    for (const auto& idx : shape.mesh.indices) all_normals &= idx.normal_index >= 0;
  MeshPart part;
  std::map<std::tuple<int, int, int>, uint32_t> vertices;
  const auto fetch = [&](const std::vector<tinyobj::real_t>& v, int index, int size, const char* what) {
    if (index < 0 || size_t(index) * size_t(size) + size_t(size) > v.size())
      corrupt(name, fmt::format("a face refers to a missing {}", what));
    const tinyobj::real_t* p = &v[size_t(index) * size_t(size)];
    for (int i = 0; i < size; ++i)
      if (!std::isfinite(p[i])) corrupt(name, fmt::format("a {} is not finite", what));
    return p;
  };
  const int materials = int(reader.GetMaterials().size());
  for (const auto& shape : reader.GetShapes()) {
    const auto& mesh = shape.mesh;
    size_t first = 0;
    for (size_t f = 0; f < mesh.num_face_vertices.size(); first += mesh.num_face_vertices[f], ++f) {
      if (mesh.num_face_vertices[f] != 3 || first + 3 > mesh.indices.size()) continue;
      const int mat = f < mesh.material_ids.size() ? mesh.material_ids[f] : -1;
      part.triangle_materials.push_back(mat >= 0 && mat < materials ? uint32_t(mat) : fallback_material);
      for (size_t k = first; k < first + 3; ++k) {
        const tinyobj::index_t idx = mesh.indices[k];
        const auto key =
            std::make_tuple(idx.vertex_index, idx.texcoord_index, all_normals ? idx.normal_index : -1);
        auto [it, added] = vertices.try_emplace(key, uint32_t(part.positions.size()));
        if (added) {
          const auto* p = fetch(a.vertices, idx.vertex_index, 3, "vertex");
          part.positions.push_back({p[0], p[1], p[2]});
          if (idx.texcoord_index >= 0) {
            const auto* t = fetch(a.texcoords, idx.texcoord_index, 2, "texture coordinate");
            part.uvs.push_back({t[0], 1.0f - t[1]});
          } else {
            part.uvs.push_back({0, 0});
          }
          if (all_normals) {
            const auto* n = fetch(a.normals, idx.normal_index, 3, "normal");
            part.normals.push_back({n[0], n[1], n[2]});
          }
        }
        part.indices.push_back(it->second);
      }
    }
  }
  if (part.indices.empty()) corrupt(name, "has no triangles");
  return part;
}

}  // namespace

std::vector<std::string> material_libraries(const std::string& obj) {
  std::vector<std::string> out;
  std::istringstream in(obj);
  for (std::string line; std::getline(in, line);) {
    std::istringstream words(line);
    std::string keyword;
    if (!(words >> keyword) || keyword != "mtllib") continue;
    for (std::string file; words >> file;) out.push_back(file);
  }
  return out;
}

Model load(const std::string& obj, const std::string& mtl, const std::string& name, ModelTextures& textures,
           const ModelLimits& limits) {
  const int64_t triangles = check_obj_text(obj, name, limits.max_triangles);
  check_mtl_text(mtl, name + " materials");
  if (limits.reserve)
    limits.reserve(obj_parse_bytes(triangles, int64_t(obj.size() + mtl.size())) +
                       geometry_load_bytes(3 * triangles, triangles, false),
                   fmt::format("the {} triangles", triangles));
  tinyobj::ObjReaderConfig config;
  config.triangulate = true;
  config.vertex_color = false;
  tinyobj::ObjReader reader;
  if (!reader.ParseFromString(obj, mtl, config)) corrupt(name, reader.Error().substr(0, 512));
  Model model;
  for (const auto& m : reader.GetMaterials()) model.materials.push_back(material(m, textures));
  const auto fallback = uint32_t(model.materials.size());
  MeshPart part = read_faces(reader, fallback, name);
  if (int64_t(part.triangle_count()) > limits.max_triangles)
    throw Error(ErrorKind::TooLarge, fmt::format("OBJ {} has over {} triangles", name, limits.max_triangles));
  for (uint32_t m : part.triangle_materials)
    if (m == fallback) {
      model.materials.push_back(default_material());
      break;
    }
  complete_part(part);
  append_part(model, part, Mat4{});
  model.up_axis_unstated = true;
  model.source.meshes = int64_t(reader.GetShapes().size());
  return model;
}

}  // namespace lp::obj
