#include "bench_scene_file.hpp"

#include <filesystem>
#include <fstream>
#include <iterator>

#include "api/render_request.hpp"

namespace lp::bench {

render::SceneDesc bench_scene_file(const std::string& file) {
  const auto path = std::filesystem::path(LIGHTPROBE_BENCH_SCENES) / file;
  std::ifstream in(path, std::ios::binary);
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  render::SceneDesc scene =
      api::parse_render_request(api::parse_json(text, path.string()), api::RequestLimits{}).scene;
  for (render::SceneObject& o : scene.objects)
    if (auto* mesh = std::get_if<render::MeshObject>(&o.shape)) mesh->path = path.parent_path() / mesh->path;
  return scene;
}

}  // namespace lp::bench
