#pragma once
// A pinhole perspective camera. fov_deg is the vertical field of view; image x grows to the right,
// y downwards (row 0 at the top).
#include <cmath>

#include "engine/core/vec3.hpp"
#include "engine/render/scene_desc.hpp"

namespace lp::render {

struct Ray {
  Vec3 origin;
  Vec3 direction;  // unit
};

class PerspectiveCamera {
 public:
  // Throws lp::Error(InvalidArgument) for a degenerate camera (look_at == position, up parallel to
  // the view direction, fov outside (0, 180), an empty image).
  PerspectiveCamera(const Camera& camera, int width, int height);

  // The ray through the image point (px, py) in pixel units (pixel (x, y) spans [x, x+1) x [y, y+1)).
  Ray generate(float px, float py) const;
  // The angle one pixel spans at the image centre (the ray cones' starting spread).
  float pixel_spread() const { return std::atan(2.0f * half_height_ * inv_height_); }

 private:
  Vec3 origin_, forward_, right_, up_;
  float inv_width_, inv_height_;
  float half_width_, half_height_;  // of the image plane at distance 1
};

}  // namespace lp::render
