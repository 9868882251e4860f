#include "engine/render/textured_preset.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>

#include "engine/core/constants.hpp"
#include "engine/model/tangents.hpp"

namespace lp::render {
namespace {

constexpr int kBrickRows = 16, kBrickColumns = 24;  // around the sphere: rows pole to pole
constexpr float kMortar = 0.08f;                    // mortar width, as a fraction of a brick's height
constexpr float kGround = 6;                        // half the side of the ground square
constexpr int kSegments = 96, kRings = 48;          // of the sphere

Texture make_texture(int width, int height, const std::function<Rgb(float x, float y)>& texel) {
  std::vector<float> texels;
  texels.reserve(size_t(width) * size_t(height) * 3);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const Rgb c = texel(float(x) + 0.5f, float(y) + 0.5f);
      texels.insert(texels.end(), {c.x, c.y, c.z});
    }
  return Texture(width, height, 3, std::move(texels));
}

// Distance in brick heights from a point of the brick texture (in texels) to the nearest mortar line,
// and the brick it lies in.
struct BrickPoint {
  float edge;
  int row, column;
};
BrickPoint brick_at(float x, float y) {
  const float h = float(kBrickTextureHeight) / kBrickRows, w = float(kBrickTextureWidth) / kBrickColumns;
  const float row = y / h;
  const int r = int(std::floor(row));
  const float column = x / w + (r % 2 ? 0.5f : 0.0f);
  const int c = int(std::floor(column));
  const float fy = row - float(r), fx = (column - float(c)) * w / h;
  const float edge = std::min({fy, 1 - fy, fx, w / h - fx});
  return {edge, r, c % kBrickColumns};
}

// Brick height: 0 in the mortar, rising over one mortar width to 1 on the brick.
float brick_height(float x, float y) {
  const float t = std::clamp((brick_at(x, y).edge - kMortar) / kMortar, 0.0f, 1.0f);
  return t * t * (3 - 2 * t);
}

Rgb brick_colour(float x, float y) {
  const BrickPoint b = brick_at(x, y);
  if (b.edge < kMortar) return {0.55f, 0.55f, 0.5f};
  const uint32_t hash = uint32_t(b.row * 73856093) ^ uint32_t(b.column * 19349663);
  const float shade = 0.75f + 0.25f * float(hash % 97) / 96.0f;
  return Rgb{0.6f, 0.22f, 0.12f} * shade;
}

// The normal of the brick height field in tangent space (x along u, y up the image), stored as
// (n + 1) / 2. Central differences over one texel; the relief is 1.5 texels high.
Rgb brick_normal(float x, float y) {
  constexpr float kRelief = 1.5f;
  const float du = (brick_height(x + 1, y) - brick_height(x - 1, y)) * 0.5f * kRelief;
  const float drow = (brick_height(x, y + 1) - brick_height(x, y - 1)) * 0.5f * kRelief;
  const Vec3 n = normalize(Vec3{-du, drow, 1});
  return (n + Vec3{1, 1, 1}) * 0.5f;
}

Rgb checker_colour(float x, float y) {
  const int squares = 8, size = kCheckerTextureSize / squares;
  const bool light = (int(x) / size + int(y) / size) % 2 == 0;
  return light ? Rgb{0.8f, 0.78f, 0.7f} : Rgb{0.08f, 0.1f, 0.14f};
}

TextureBinding binding(Texture texture, Point2 scale = {1, 1}) {
  TextureBinding b;
  b.texture = std::make_shared<const Texture>(std::move(texture));
  b.transform.scale = scale;
  return b;
}

void add_triangle(Model& m, uint32_t a, uint32_t b, uint32_t c, uint32_t material) {
  m.indices.insert(m.indices.end(), {a, b, c});
  m.triangle_materials.push_back(material);
}

void add_vertex(Model& m, Vec3 p, Vec3 n, Point2 uv) {
  m.positions.push_back(p);
  m.normals.push_back(n);
  m.uvs.push_back(uv);
}

// Rings from the north pole (v = 0) to the south pole (v = 1), u once around; the seam's vertices are
// doubled so that u runs from 0 to 1.
void add_sphere(Model& m, uint32_t material) {
  const auto first = uint32_t(m.positions.size());
  for (int i = 0; i <= kRings; ++i)
    for (int j = 0; j <= kSegments; ++j) {
      const float theta = kPiF * float(i) / kRings, phi = 2 * kPiF * float(j) / kSegments;
      const Vec3 n{std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
      add_vertex(m, n, n, {float(j) / kSegments, float(i) / kRings});
    }
  const auto at = [&](int i, int j) { return first + uint32_t(i * (kSegments + 1) + j); };
  for (int i = 0; i < kRings; ++i)
    for (int j = 0; j < kSegments; ++j) {
      const uint32_t a = at(i, j), b = at(i, j + 1), c = at(i + 1, j), d = at(i + 1, j + 1);
      if (i > 0) add_triangle(m, a, d, b, material);  // the pole rows keep only the triangle with area
      if (i < kRings - 1) add_triangle(m, a, c, d, material);
    }
}

void add_ground(Model& m, uint32_t material) {
  const auto first = uint32_t(m.positions.size());
  const Vec3 up{0, 0, 1};
  add_vertex(m, {-kGround, -kGround, -1}, up, {0, 1});
  add_vertex(m, {kGround, -kGround, -1}, up, {1, 1});
  add_vertex(m, {kGround, kGround, -1}, up, {1, 0});
  add_vertex(m, {-kGround, kGround, -1}, up, {0, 0});
  add_triangle(m, first, first + 1, first + 2, material);
  add_triangle(m, first, first + 2, first + 3, material);
}

Model build() {
  Model m;
  ModelMaterial bricks;
  bricks.name = "bricks";
  bricks.base_color_factor = {1, 1, 1, 1};
  bricks.base_color = binding(make_texture(kBrickTextureWidth, kBrickTextureHeight, brick_colour));
  bricks.normal = binding(make_texture(kBrickTextureWidth, kBrickTextureHeight, brick_normal));
  bricks.metallic_factor = 0;
  bricks.roughness_factor = 0.6f;
  ModelMaterial ground;
  ground.name = "checkerboard";
  ground.base_color_factor = {1, 1, 1, 1};
  ground.base_color = binding(make_texture(kCheckerTextureSize, kCheckerTextureSize, checker_colour), {6, 6});
  ground.metallic_factor = 0;
  ground.roughness_factor = 0.8f;
  m.materials = {std::move(bricks), std::move(ground)};
  add_sphere(m, 0);
  add_ground(m, 1);
  m.tangents = generate_tangents(m.positions, m.normals, m.uvs, m.indices);
  return m;
}

}  // namespace

std::shared_ptr<const Model> textured_preset_model() {
  static const auto model = std::make_shared<const Model>(build());
  return model;
}

}  // namespace lp::render
