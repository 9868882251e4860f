#include "cli/turntable_files.hpp"

#include <fmt/format.h>

#include "api/api_error.hpp"
#include "api/engine_validation.hpp"
#include "api/turntable_schema.hpp"
#include "cli/output.hpp"
#include "engine/image/image_io.hpp"
#include "engine/render/scene_view.hpp"

namespace lp::cli {
namespace {

void write_atomically(const std::filesystem::path& file, std::string_view bytes) {
  Output out(file.string());
  out.write(bytes);
  out.finish();
}

}  // namespace

void require_turntable_folder(const std::optional<std::string>& folder) {
  if (!folder || *folder == "-")
    throw api::ApiError(api::ErrorCode::BadRequest,
                        "--turntable writes its frames into a folder: give -o DIR");
  require_folder(*folder);
}

TurntableFiles::TurntableFiles(std::filesystem::path folder, const render::Turntable& turntable,
                               const SceneRender& scene, const api::PreviewParams& image)
    : folder_(std::move(folder)), image_(image) {
  const auto& s = scene.request.settings;
  const float aspect = float(s.width) / float(s.height);
  render::SceneDesc framed = scene.request.scene;
  framed.camera.gltf.reset();
  for (int i = 0; i < turntable.frames; ++i) {
    framed.camera.fit = render::turntable_fit(turntable, i);
    api::as_invalid_field([&] { cameras_.push_back(render::resolve_camera(framed, aspect)); });
  }
}

std::string TurntableFiles::frame_name(int64_t index) const {
  return fmt::format("frame_{:04}.{}", index, enum_name(image_.format));
}

void TurntableFiles::write(int64_t index, std::span<const uint8_t> bytes) const {
  write_atomically(folder_ / frame_name(index),
                   std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

void TurntableFiles::finish() const {
  write_atomically(folder_ / "cameras.json", api::describe_turntable_cameras(cameras_).dump(2) + "\n");
}

}  // namespace lp::cli
