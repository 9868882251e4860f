#pragma once
// The cameras of a turntable: frames orbiting the framed scene (or one of its objects) about +z. Frame i
// looks from azimuth start + i * step (default step: a full turn over the frames) and from an elevation
// that swings by the sweep over the orbit, elevation + sweep * sin(2 pi i / frames), one rise and fall
// per turn. Each frame is a CameraFit (scene_desc.hpp), so it frames the model exactly as a render does.
#include <array>
#include <optional>

#include "engine/render/scene_desc.hpp"

namespace lp::render {

struct Turntable {
  int frames = 36;
  float azimuth_start_deg = 0;
  std::optional<float> azimuth_step_deg;  // 360 / frames when absent
  float elevation_deg = 15;
  float elevation_sweep_deg = 0;
  float margin = CameraFit{}.margin;
  std::optional<uint32_t> object;  // the object framed; all bounded ones when absent

  float step_deg() const { return azimuth_step_deg.value_or(360.0f / float(frames)); }
  // Throws lp::Error(InvalidArgument) naming the field under `prefix`: frames in kTurntableFrames, every
  // frame's elevation within kElevationDeg, margin in kFitMargin.
  void validate(const std::string& prefix) const;
};

// The framing of frame `index` (0 <= index < frames).
CameraFit turntable_fit(const Turntable& turntable, int index);

// A camera's pose as a row-major 4x4 camera-to-world matrix in Blender's camera convention (the camera
// looks down its local -z with +y up), the matrix_world the Objaverse render scripts save per frame.
std::array<float, 16> camera_to_world(const Camera& camera);

}  // namespace lp::render
