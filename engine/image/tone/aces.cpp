#include "engine/image/tone/color_matrix.hpp"
#include "engine/image/tone/curves.hpp"

namespace lp::tone {
namespace {

// sRGB to XYZ, D65 to D60, to AP1, and the RRT's saturation (BakingLab ACES.hlsl, rows).
constexpr Mat3 kInput{
    {0.59719f, 0.35458f, 0.04823f}, {0.07600f, 0.90834f, 0.01566f}, {0.02840f, 0.13383f, 0.83777f}};
// The ODT's saturation, to XYZ, D60 to D65, to sRGB.
constexpr Mat3 kOutput{
    {1.60475f, -0.53108f, -0.07367f}, {-0.10208f, 1.10813f, -0.00605f}, {-0.00327f, -0.07276f, 1.07602f}};
// three.js's brightening of the input for a brighter viewing environment (three.js #19621).
constexpr float kInputScale = 1.0f / 0.6f;

float rrt_and_odt_fit(float v) {
  const float a = v * (v + 0.0245786f) - 0.000090537f;
  const float b = v * (0.983729f * v + 0.4329510f) + 0.238081f;
  return a / b;
}

}  // namespace

Vec3 aces_hill(Vec3 rgb) {
  const Vec3 v = kInput * (rgb * kInputScale);
  return kOutput * Vec3{rrt_and_odt_fit(v.x), rrt_and_odt_fit(v.y), rrt_and_odt_fit(v.z)};
}

}  // namespace lp::tone
