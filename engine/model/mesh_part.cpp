#include "engine/model/mesh_part.hpp"

#include <cmath>

#include "engine/core/error.hpp"
#include "engine/model/tangents.hpp"

namespace lp {
namespace {

constexpr Vec3 kUp{0, 0, 1};

Vec3 unit_or(Vec3 v, Vec3 fallback) {
  const float len = length(v);
  return (len > 0 && std::isfinite(len)) ? v / len : fallback;
}

Vec3 face_normal(const MeshPart& p, size_t triangle) {
  const Vec3 a = p.positions[p.indices[triangle * 3]], b = p.positions[p.indices[triangle * 3 + 1]],
             c = p.positions[p.indices[triangle * 3 + 2]];
  return cross(b - a, c - a);  // length = twice the area
}

void make_flat(MeshPart& p) {
  MeshPart flat;
  for (size_t i = 0; i < p.indices.size(); ++i) {
    flat.positions.push_back(p.positions[p.indices[i]]);
    if (!p.uvs.empty()) flat.uvs.push_back(p.uvs[p.indices[i]]);
    if (!p.colors.empty()) flat.colors.push_back(p.colors[p.indices[i]]);
    if (!p.uvs1.empty()) flat.uvs1.push_back(p.uvs1[p.indices[i]]);
    flat.indices.push_back(uint32_t(i));
  }
  for (size_t t = 0; t < p.triangle_count(); ++t) {
    const Vec3 n = unit_or(face_normal(p, t), kUp);
    for (int k = 0; k < 3; ++k) flat.normals.push_back(n);
  }
  flat.triangle_materials = std::move(p.triangle_materials);
  p = std::move(flat);
}

void repair_zero_normals(MeshPart& p) {
  std::vector<Vec3> sums;
  for (size_t v = 0; v < p.normals.size(); ++v) {
    const float len = length(p.normals[v]);
    if (len > 0 && std::isfinite(len)) {
      p.normals[v] = p.normals[v] / len;
      continue;
    }
    if (sums.empty()) {
      sums.resize(p.positions.size());
      for (size_t t = 0; t < p.triangle_count(); ++t)
        for (int k = 0; k < 3; ++k) sums[p.indices[t * 3 + size_t(k)]] += face_normal(p, t);
    }
    p.normals[v] = unit_or(sums[v], kUp);
  }
}

// Copies of the vertices split_mirrored_vertices adds, appended to every per-vertex array.
void split_mirrored(MeshPart& p) {
  const std::vector<uint32_t> sources = split_mirrored_vertices(p.uvs, p.indices);
  p.positions.reserve(p.positions.size() + sources.size());
  p.normals.reserve(p.normals.size() + sources.size());
  p.uvs.reserve(p.uvs.size() + sources.size());
  for (uint32_t source : sources) {
    p.positions.push_back(p.positions[source]);
    p.normals.push_back(p.normals[source]);
    p.uvs.push_back(p.uvs[source]);
    if (!p.colors.empty()) p.colors.push_back(p.colors[source]);
    if (!p.uvs1.empty()) p.uvs1.push_back(p.uvs1[source]);
  }
}

// An optional per-vertex attribute of the part appended to the model's, each side padded with
// `fallback` where the other has it and it does not: the model allocates nothing for an attribute
// no part has.
template <class T>
void append_optional(std::vector<T>& model, size_t model_before, const std::vector<T>& part, size_t count,
                     T fallback) {
  if (part.empty() && model.empty()) return;
  model.resize(model_before, fallback);
  if (part.empty())
    model.resize(model_before + count, fallback);
  else
    model.insert(model.end(), part.begin(), part.end());
}

}  // namespace

size_t MeshPart::triangle_count() const {
  return indices.size() / 3;
}

void complete_part(MeshPart& p) {
  if (p.normals.empty()) {
    make_flat(p);
    p.tangents.clear();
  }
  repair_zero_normals(p);
  if (p.uvs.empty()) p.uvs.assign(p.positions.size(), Point2{0, 0});
  if (p.tangents.empty()) {
    split_mirrored(p);
    p.tangents = generate_tangents(p.positions, p.normals, p.uvs, p.indices);
  }
}

void append_part(Model& model, const MeshPart& p, const Mat4& to_world) {
  if (model.positions.size() + p.positions.size() > size_t(UINT32_MAX))
    throw Error(ErrorKind::TooLarge, "model has over 2^32 vertices");
  const auto base = uint32_t(model.positions.size());
  const bool mirror = to_world.determinant3() < 0;
  for (size_t v = 0; v < p.positions.size(); ++v) {
    const Vec3 n = unit_or(to_world.normal(p.normals[v]), kUp);
    Vec3 t = to_world.vector(p.tangents[v].direction);
    t = unit_or(t - n * dot(n, t), any_perpendicular(n));
    model.positions.push_back(to_world.point(p.positions[v]));
    model.normals.push_back(n);
    model.uvs.push_back(p.uvs[v]);
    model.tangents.push_back({t, mirror ? -p.tangents[v].w : p.tangents[v].w});
  }
  append_optional(model.colors, base, p.colors, p.positions.size(), Rgba{1, 1, 1, 1});
  append_optional(model.uvs1, base, p.uvs1, p.positions.size(), Point2{0, 0});
  for (size_t t = 0; t < p.triangle_count(); ++t) {
    const uint32_t a = p.indices[t * 3], b = p.indices[t * 3 + 1], c = p.indices[t * 3 + 2];
    model.indices.insert(model.indices.end(), {base + a, base + (mirror ? c : b), base + (mirror ? b : c)});
  }
  model.triangle_materials.insert(model.triangle_materials.end(), p.triangle_materials.begin(),
                                  p.triangle_materials.end());
  for (size_t v = base; v < model.positions.size(); ++v)
    if (!finite(model.positions[v]))
      throw Error(ErrorKind::InvalidData, "a vertex is not finite in world space");
}

}  // namespace lp
