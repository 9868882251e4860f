#include "engine/model/gltf_loader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstring>

#include "engine/core/error.hpp"
#include "engine/model/glb_chunks.hpp"
#include "engine/model/gltf_accessor.hpp"
#include "engine/model/gltf_cameras.hpp"
#include "engine/model/gltf_extensions.hpp"
#include "engine/model/gltf_materials.hpp"
#include "engine/model/gltf_scene.hpp"
#include "engine/model/gltf_schema.hpp"
#include "engine/model/gltf_source.hpp"
#include "engine/model/mesh_part.hpp"
#include "engine/model/model_memory.hpp"
#include "engine/model/tinygltf.hpp"

namespace lp::gltf {
namespace {

// Keeps a data-URI image's decoded bytes (as_is) for engine/texture. Images in buffer views are read
// later through buffer_view_bytes, which checks the view against its buffer; tinygltf does not.
bool keep_encoded(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                  const unsigned char* bytes, int size, void*) {
  if (image->bufferView >= 0) return true;
  image->image.assign(bytes, bytes + size);
  image->as_is = true;
  return true;
}

// Every file "exists" for tinygltf: reading it gives our error (missing, outside the folder, too large).
bool file_exists(const std::string&, void*) {
  return true;
}
std::string expand_path(const std::string& path, void*) {
  return path;
}
bool read_file(std::vector<unsigned char>* out, std::string*, const std::string& path, void* files) {
  *out = static_cast<ModelFiles*>(files)->read(path, "buffer " + path.substr(0, 128));
  return true;
}
bool write_file(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
  *err = "models are never written";
  return false;
}

tinygltf::Model parse(std::span<const uint8_t> bytes, const std::string& name, ModelFiles& files) {
  check_schema(bytes, name);
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(keep_encoded, nullptr);
  loader.SetFsCallbacks({file_exists, expand_path, read_file, write_file, &files});
  tinygltf::Model model;
  std::string err, warn;
  const bool binary = is_glb(bytes);
  if (bytes.size() > size_t(UINT32_MAX)) throw Error(ErrorKind::TooLarge, "model " + name + " is over 4 GB");
  const bool ok =
      binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(), unsigned(bytes.size()), "")
             : loader.LoadASCIIFromString(&model, &err, &warn, reinterpret_cast<const char*>(bytes.data()),
                                          unsigned(bytes.size()), "");
  if (!ok) {
    while (!err.empty() && (err.back() == '\n' || err.back() == ' ')) err.pop_back();
    const bool missing =
        err.find("File not found") != std::string::npos || err.find("not found") != std::string::npos;
    throw Error(missing ? ErrorKind::NotFound : ErrorKind::Corrupt,
                "glTF " + name + ": " + (err.empty() ? "cannot parse" : err.substr(0, 512)));
  }
  for (const std::string& e : model.extensionsRequired)
    if (!is_supported_extension(e))
      throw Error(ErrorKind::Unsupported,
                  "glTF " + name + " requires the extension " + e.substr(0, 64) + ", which is not supported");
  return model;
}

bool is_triangles(int mode) {
  return mode == -1 || mode == TINYGLTF_MODE_TRIANGLES || mode == TINYGLTF_MODE_TRIANGLE_STRIP ||
         mode == TINYGLTF_MODE_TRIANGLE_FAN;
}

int attribute(const tinygltf::Primitive& p, const char* name) {
  const auto it = p.attributes.find(name);
  return it == p.attributes.end() ? -1 : it->second;
}

// Triangles a primitive makes, from its accessors' counts (nothing read yet).
int64_t triangle_count(const tinygltf::Model& model, const tinygltf::Primitive& p, const std::string& what) {
  if (!is_triangles(p.mode)) return 0;
  const int position = attribute(p, "POSITION");
  if (position < 0) throw Error(ErrorKind::Corrupt, what + " has no POSITION attribute");
  const auto n = int64_t(p.indices >= 0 ? accessor_count(model, p.indices, what + " indices")
                                        : accessor_count(model, position, what + " POSITION"));
  if (p.mode == TINYGLTF_MODE_TRIANGLE_STRIP || p.mode == TINYGLTF_MODE_TRIANGLE_FAN)
    return std::max<int64_t>(n - 2, 0);
  return n / 3;
}

// Vertices a primitive of `triangles` triangles makes: its POSITION count, or three per triangle when it
// has no normals (flat shading).
int64_t vertex_count(const tinygltf::Model& model, const tinygltf::Primitive& p, int64_t triangles,
                     const std::string& what) {
  if (triangles == 0) return 0;
  if (attribute(p, "NORMAL") < 0) return 3 * triangles;
  return int64_t(accessor_count(model, attribute(p, "POSITION"), what + " POSITION"));
}

// The most memory the scene's geometry holds while it loads (the model's positions are reserved for
// three vertices a triangle).
int64_t geometry_bytes(int64_t vertices, int64_t triangles) {
  return geometry_load_bytes(vertices, triangles, true) + 3 * triangles * int64_t(sizeof(Vec3));
}

// Strips and fans as lists of triangles.
std::vector<uint32_t> triangle_list(std::vector<uint32_t> in, int mode, const std::string& what) {
  if (mode != TINYGLTF_MODE_TRIANGLE_STRIP && mode != TINYGLTF_MODE_TRIANGLE_FAN) {
    if (in.size() % 3 != 0)
      throw Error(ErrorKind::Corrupt,
                  fmt::format("{} has {} vertices, not a multiple of 3 for triangles", what, in.size()));
    return in;
  }
  std::vector<uint32_t> out;
  for (size_t i = 2; i < in.size(); ++i) {
    if (mode == TINYGLTF_MODE_TRIANGLE_FAN)
      out.insert(out.end(), {in[0], in[i - 1], in[i]});
    else if (i % 2 == 0)
      out.insert(out.end(), {in[i - 2], in[i - 1], in[i]});
    else
      out.insert(out.end(), {in[i - 1], in[i - 2], in[i]});  // keeps the strip's winding
  }
  return out;
}

// True when a texture of some material samples TEXCOORD_1: only then is that set read.
bool uses_second_set(const std::vector<ModelMaterial>& materials) {
  for (const ModelMaterial& m : materials)
    for (const auto* b : m.bindings())
      if (*b && (*b)->tex_coord == 1) return true;
  return false;
}

MeshPart read_primitive(const tinygltf::Model& model, const tinygltf::Primitive& p, uint32_t material,
                        bool second_set, const std::string& what) {
  MeshPart part;
  part.positions = read_vec3(model, attribute(p, "POSITION"), what + " POSITION");
  const size_t n = part.positions.size();
  const auto same_count = [&](size_t count, const char* name) {
    if (count != n)
      throw Error(ErrorKind::Corrupt,
                  fmt::format("{} {} has {} elements but POSITION has {}", what, name, count, n));
  };
  if (const int a = attribute(p, "NORMAL"); a >= 0) {
    part.normals = read_vec3(model, a, what + " NORMAL");
    same_count(part.normals.size(), "NORMAL");
    if (const int t = attribute(p, "TANGENT"); t >= 0) {  // used only with the normals they go with
      for (const auto& v : read_vec4(model, t, what + " TANGENT"))
        part.tangents.push_back({{v[0], v[1], v[2]}, v[3] < 0 ? -1.0f : 1.0f});
      same_count(part.tangents.size(), "TANGENT");
    }
  }
  if (const int a = attribute(p, "TEXCOORD_0"); a >= 0) {
    part.uvs = read_uv(model, a, what + " TEXCOORD_0");
    same_count(part.uvs.size(), "TEXCOORD_0");
  }
  if (const int a = attribute(p, "TEXCOORD_1"); a >= 0 && second_set) {
    part.uvs1 = read_uv(model, a, what + " TEXCOORD_1");
    same_count(part.uvs1.size(), "TEXCOORD_1");
  }
  if (const int a = attribute(p, "COLOR_0"); a >= 0) {
    for (const auto& c : read_color(model, a, what + " COLOR_0"))
      part.colors.push_back({c[0], c[1], c[2], c[3]});
    same_count(part.colors.size(), "COLOR_0");
  }
  std::vector<uint32_t> indices;
  if (p.indices >= 0) {
    indices = read_indices(model, p.indices, what + " indices");
    for (uint32_t i : indices)
      if (i >= n)
        throw Error(ErrorKind::Corrupt,
                    fmt::format("{} has the index {}, out of range for its {} vertices", what, i, n));
  } else {
    for (size_t i = 0; i < n; ++i) indices.push_back(uint32_t(i));
  }
  part.indices = triangle_list(std::move(indices), p.mode, what);
  part.triangle_materials.assign(part.triangle_count(), material);
  return part;
}

}  // namespace

Model load(std::span<const uint8_t> bytes, const std::string& name, ModelFiles& files,
           ModelTextures& textures, const ModelLimits& limits) {
  const tinygltf::Model model = parse(bytes, name, files);
  const SceneNodes nodes = scene_nodes(model);
  const std::vector<MeshInstance>& instances = nodes.meshes;
  int64_t triangles = 0, vertices = 0;
  for (const MeshInstance& instance : instances) {
    const auto& mesh = model.meshes[size_t(instance.mesh)];
    for (size_t i = 0; i < mesh.primitives.size(); ++i) {
      const std::string what = fmt::format("mesh {} primitive {}", instance.mesh, i);
      const int64_t count = triangle_count(model, mesh.primitives[i], what);
      triangles += count;
      vertices += vertex_count(model, mesh.primitives[i], count, what);
      if (triangles > limits.max_triangles)
        throw Error(ErrorKind::TooLarge,
                    fmt::format("glTF {} has over {} triangles", name, limits.max_triangles));
    }
  }
  if (triangles == 0) throw Error(ErrorKind::Corrupt, "glTF " + name + " has no triangles in its scene");
  if (limits.reserve)
    limits.reserve(geometry_bytes(vertices, triangles), fmt::format("the {} triangles", triangles));

  Model out;
  out.materials = read_materials(model, textures);
  const auto fallback = uint32_t(out.materials.size());  // for primitives without a material
  bool fallback_used = false;
  const bool second_set = uses_second_set(out.materials);
  out.positions.reserve(size_t(triangles) * 3);
  for (const MeshInstance& instance : instances) {
    const auto& mesh = model.meshes[size_t(instance.mesh)];
    for (size_t i = 0; i < mesh.primitives.size(); ++i) {
      const tinygltf::Primitive& p = mesh.primitives[i];
      if (!is_triangles(p.mode)) continue;
      const std::string what = fmt::format("mesh {} primitive {}", instance.mesh, i);
      if (p.material < -1 || p.material >= int(out.materials.size()))
        throw Error(ErrorKind::Corrupt,
                    fmt::format("{} refers to material {}, which does not exist", what, p.material));
      fallback_used |= p.material < 0;
      MeshPart part =
          read_primitive(model, p, p.material < 0 ? fallback : uint32_t(p.material), second_set, what);
      complete_part(part);
      append_part(out, part, instance.to_world);
    }
  }
  if (fallback_used) out.materials.push_back(default_material());
  out.cameras = read_cameras(model, nodes.cameras);
  out.source = describe_source(model, instances);
  return out;
}

}  // namespace lp::gltf
