#include "engine/render/camera.hpp"

#include <cmath>

#include "engine/core/constants.hpp"
#include "engine/core/error.hpp"

namespace lp::render {

PerspectiveCamera::PerspectiveCamera(const Camera& c, int width, int height) {
  if (width < 1 || height < 1)
    throw Error(ErrorKind::InvalidArgument, "camera: the image must have at least one pixel");
  c.validate("camera");
  forward_ = normalize(c.look_at - c.position);
  const Vec3 side = cross(forward_, normalize(c.up));
  right_ = normalize(side);
  up_ = cross(right_, forward_);
  origin_ = c.position;
  half_height_ = std::tan(0.5f * c.fov_deg * kPiF / 180.0f);
  half_width_ = half_height_ * float(width) / float(height);
  inv_width_ = 1.0f / float(width);
  inv_height_ = 1.0f / float(height);
}

Ray PerspectiveCamera::generate(float px, float py) const {
  const float sx = (2.0f * px * inv_width_ - 1.0f) * half_width_;
  const float sy = (1.0f - 2.0f * py * inv_height_) * half_height_;
  return {origin_, normalize(forward_ + sx * right_ + sy * up_)};
}

}  // namespace lp::render
