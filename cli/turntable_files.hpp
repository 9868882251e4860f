#pragma once
// The files of a turntable rendered by the tool, in the folder of -o DIR: DIR/frame_0000.png ... (each
// written under a temporary name and renamed when complete) and DIR/cameras.json, each frame's camera as
// a turntable's status gives it: [{index, position, look_at, up, fov_deg, matrix}], matrix the row-major
// 4x4 camera-to-world matrix in Blender's camera convention (16 numbers), written once every frame is.
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "api/preview_params.hpp"
#include "cli/scene_file.hpp"
#include "engine/image/image.hpp"
#include "engine/render/turntable.hpp"

namespace lp::cli {

// Refuses a turntable without -o DIR (bad_request), or whose DIR does not exist (not_found).
void require_turntable_folder(const std::optional<std::string>& folder);

class TurntableFiles {
 public:
  // Resolves each frame's camera (throws invalid_field as a render whose fit has nothing to frame).
  TurntableFiles(std::filesystem::path folder, const render::Turntable& turntable, const SceneRender& scene,
                 const api::PreviewParams& image);

  const std::vector<render::Camera>& cameras() const { return cameras_; }
  std::string frame_name(int64_t index) const;
  void write(int64_t index, std::span<const uint8_t> picture) const;
  // Writes cameras.json.
  void finish() const;

 private:
  std::filesystem::path folder_;
  api::PreviewParams image_;
  std::vector<render::Camera> cameras_;
};

}  // namespace lp::cli
