#include "bench_data.hpp"

#include "engine/fresnel/metals.hpp"
#include "engine/image/image_io.hpp"
#include "support/test_data.hpp"

namespace lp::bench {
namespace {

std::filesystem::path prefer_full_size(const std::string& folder, const std::string& file,
                                       const std::filesystem::path& fallback) {
  const auto full = std::filesystem::path(LIGHTPROBE_SHARED_DATA) / folder / file;
  return std::filesystem::exists(full) ? full : fallback;
}

}  // namespace

std::filesystem::path envmap_path(const std::string& file) {
  return prefer_full_size("envmaps", file, test::envmap_path(file));
}

std::filesystem::path mesh_path(const std::string& file) {
  return prefer_full_size("meshes", file, test::mesh_path(file));
}

render::SceneDesc glass_on_plane() {
  using namespace render;
  SceneDesc s;
  s.camera = {{0, -4.5f, 2.5f}, {0, 0, -0.3f}, {0, 0, 1}, 40};
  s.objects = {
      {SphereObject{{0, 0, 0}, 0.5f}, DielectricMaterial{1.5f}},
      {PlaneObject{{0, 0, -0.5f}, {0, 0, 1}}, DiffuseMaterial{{0.5f, 0.5f, 0.5f}}},
  };
  return s;
}

}  // namespace lp::bench

namespace lp::bench {

const Image& forest(int width) {
  static const Image small = read_image_file(envmap_path("forest.exr")).image;
  if (width == small.width()) return small;
  static const Image large = resize_box(small, 8192, 4096);
  return large;
}

}  // namespace lp::bench

namespace lp::bench {

render::SceneDesc diffuse_and_glossy() {
  using namespace render;
  const ConductorPreset& gold = lookup_metal("gold");
  SceneDesc s;
  s.camera = {{0, -6.5f, 2.2f}, {0, 0, -0.2f}, {0, 0, 1}, 35};
  s.objects = {
      {SphereObject{{-1.2f, 0, 0}, 0.5f}, DiffuseMaterial{{0.8f, 0.8f, 0.8f}}},
      {SphereObject{{0, 0, 0}, 0.5f}, PlasticMaterial{{0.7f, 0.1f, 0.08f}, 1.5f, 0.15f}},
      {SphereObject{{1.2f, 0, 0}, 0.5f}, ConductorMaterial{gold.eta_rgb(), gold.k_rgb(), 0.3f}},
      {PlaneObject{{0, 0, -0.5f}, {0, 0, 1}}, DiffuseMaterial{{0.5f, 0.5f, 0.5f}}},
  };
  return s;
}

}  // namespace lp::bench
