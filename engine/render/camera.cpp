#include "engine/render/camera.hpp"

#include <cmath>

#include "engine/core/constants.hpp"
#include "engine/core/error.hpp"

namespace lp::render {
namespace {

void require(bool ok, const char* what) {
  if (!ok) throw Error(ErrorKind::InvalidArgument, std::string("camera: ") + what);
}

}  // namespace

PerspectiveCamera::PerspectiveCamera(const Camera& c, int width, int height) {
  require(width >= 1 && height >= 1, "the image must have at least one pixel");
  require(finite(c.position) && finite(c.look_at) && finite(c.up), "position, look_at and up must be finite");
  require(std::isfinite(c.fov_deg) && c.fov_deg > 0 && c.fov_deg < 180, "fov_deg must be in (0, 180)");
  const Vec3 view = c.look_at - c.position;
  require(length(view) > 1e-6f, "look_at must differ from position");
  require(length(c.up) > 1e-6f, "up must not be zero");
  forward_ = normalize(view);
  const Vec3 side = cross(forward_, normalize(c.up));
  require(length(side) > 1e-4f, "up must not be parallel to the view direction");
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
