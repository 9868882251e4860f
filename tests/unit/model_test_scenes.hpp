#pragma once
// In-memory models for the textured-render tests: a square in the z = 0 plane with a material whose
// textures are built from floats here (no files).
#include <cmath>
#include <functional>
#include <memory>
#include <vector>

#include "engine/core/constants.hpp"
#include "engine/model/model.hpp"
#include "engine/render/scene_desc.hpp"

namespace lp::render::test {

// A texture of w x h RGB texels given by f(x, y).
inline std::shared_ptr<const Texture> make_texture(int w, int h, const std::function<Rgb(int, int)>& f) {
  std::vector<float> texels;
  texels.reserve(size_t(w) * size_t(h) * 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const Rgb c = f(x, y);
      texels.insert(texels.end(), {c.x, c.y, c.z});
    }
  return std::make_shared<const Texture>(w, h, 3, std::move(texels));
}

// A texture of w x h RGBA texels given by f(x, y).
inline std::shared_ptr<const Texture> make_rgba_texture(int w, int h,
                                                        const std::function<Rgba(int, int)>& f) {
  std::vector<float> texels;
  texels.reserve(size_t(w) * size_t(h) * 4);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const Rgba c = f(x, y);
      texels.insert(texels.end(), {c.r, c.g, c.b, c.a});
    }
  return std::make_shared<const Texture>(w, h, 4, std::move(texels));
}

inline TextureBinding bind(std::shared_ptr<const Texture> texture) {
  TextureBinding b;
  b.texture = std::move(texture);
  return b;
}

// The square [-half, half]^2 at z = 0 facing +z, texture coordinates (x, -y) / tile (glTF's v runs
// against y), tangent +x.
inline Model square_model(float half, float tile, const ModelMaterial& material) {
  Model m;
  const float corners[4][2] = {{-half, -half}, {half, -half}, {half, half}, {-half, half}};
  for (const auto& c : corners) {
    m.positions.push_back({c[0], c[1], 0});
    m.normals.push_back({0, 0, 1});
    m.uvs.push_back({c[0] / tile, -c[1] / tile});
    m.tangents.push_back({{1, 0, 0}, 1});
  }
  m.indices = {0, 1, 2, 0, 2, 3};
  m.triangle_materials = {0, 0};
  m.materials = {material};
  return m;
}

// The unit sphere about the origin as `rings` x 2 rings triangles with smooth normals, texture
// coordinates (longitude, latitude) in [0, 1] and tangents along the parallels.
inline Model sphere_model(int rings, const ModelMaterial& material) {
  Model m;
  const int segments = 2 * rings;
  for (int i = 0; i <= rings; ++i)
    for (int j = 0; j <= segments; ++j) {
      const float theta = float(i) / float(rings) * kPiF, phi = float(j) / float(segments) * 2 * kPiF;
      const Vec3 p{std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
      m.positions.push_back(p);
      m.normals.push_back(p);
      m.uvs.push_back({float(j) / float(segments), float(i) / float(rings)});
      m.tangents.push_back({{-std::sin(phi), std::cos(phi), 0}, 1});
    }
  const auto vertex = [&](int i, int j) { return uint32_t(i * (segments + 1) + j); };
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      const uint32_t a = vertex(i, j), b = vertex(i + 1, j), c = vertex(i + 1, j + 1), d = vertex(i, j + 1);
      if (i > 0) m.indices.insert(m.indices.end(), {a, b, d});
      if (i < rings - 1) m.indices.insert(m.indices.end(), {b, c, d});
    }
  m.triangle_materials.assign(m.indices.size() / 3, 0);
  m.materials = {material};
  return m;
}

inline ModelMaterial rough_dielectric(Rgb base) {
  ModelMaterial m;
  m.base_color_factor = {base.x, base.y, base.z, 1};
  m.metallic_factor = 0;
  m.roughness_factor = 1;
  return m;
}

inline SceneObject model_object(Model model, Vec3 rotate_deg = {}) {
  MeshObject mesh;
  mesh.path = "square.gltf";
  mesh.rotate_deg = rotate_deg;
  mesh.model = std::make_shared<const Model>(std::move(model));
  mesh.model_materials = true;
  return {mesh, DiffuseMaterial{}};
}

}  // namespace lp::render::test
