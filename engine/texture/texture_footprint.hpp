#pragma once
// The region of a texture one lookup stands for: an ellipse in texture coordinates (the image of a
// pixel's ray cone on the surface), given by two conjugate diameters, and its principal axes.
#include "engine/core/point2.hpp"

namespace lp {

// How much longer than wide a footprint may be before its width grows to match. 16 probes cover
// incidences up to acos(1/16) = 86.4 degrees unblurred, the highest setting GPUs offer (pbrt-v4 stops at
// 8, 82.8 degrees); a footprint only pays for the probes its elongation needs, so the cost falls on the
// grazing pixels, and beyond the bound the texture blurs rather than aliases.
inline constexpr float kMaxTextureAnisotropy = 16;

// The ellipse {a s + b t : s^2 + t^2 <= 1/4} about the lookup's point: `a` and `b` are the images of
// two perpendicular diameters of a disc (whole diameters, not radii; the images need not be
// perpendicular).
struct UvFootprint {
  Point2 a, b;
};

struct FootprintAxes {
  Point2 major;           // unit direction of the longest diameter
  float major_width = 0;  // its length
  float minor_width = 0;  // the shortest diameter's length
};

// The principal axes: the singular vectors and values of the matrix with columns a and b.
FootprintAxes principal_axes(const UvFootprint& footprint);

}  // namespace lp
