#include <algorithm>
#include <cmath>

#include "engine/image/tone/color_matrix.hpp"
#include "engine/image/tone/curves.hpp"

namespace lp::tone {
namespace {

// Rec. 2020 to Rec. 709 (ITU-R BT.2407), and its inverse.
constexpr Mat3 kRec2020ToRec709{
    {1.6605f, -0.5876f, -0.0728f}, {-0.1246f, 1.1329f, -0.0083f}, {-0.0182f, -0.1006f, 1.1187f}};
constexpr Mat3 kRec709ToRec2020 = inverse(kRec2020ToRec709);
// Blender's AgX inset, and the inverse of its outset (rows; each row sums to 1, so grey stays grey).
constexpr Mat3 kInset{{0.856627153315983f, 0.0951212405381588f, 0.0482516061458583f},
                      {0.137318972929847f, 0.761241990602591f, 0.101439036467562f},
                      {0.11189821299995f, 0.0767994186031903f, 0.811302368396859f}};
constexpr Mat3 kOutset = inverse(Mat3{{0.899796955911611f, 0.0871996192028351f, 0.013003424885555f},
                                      {0.11142098895748f, 0.875575586156966f, 0.0130034248855548f},
                                      {0.11142098895748f, 0.0871996192028349f, 0.801379391839686f}});
// The log2 encoding's range: log2(2^-10 * 0.18) to log2(2^6.5 * 0.18).
constexpr float kMinEv = -12.47393f, kMaxEv = 4.026069f;

// The default contrast sigmoid on the encoded [0, 1] value (mean squared error 3.7e-6 to Blender's).
float contrast(float x) {
  const float x2 = x * x, x4 = x2 * x2;
  return 15.5f * x4 * x2 - 40.14f * x4 * x + 31.96f * x4 - 6.868f * x2 * x + 0.4298f * x2 + 0.1191f * x -
         0.00232f;
}

float encode_log(float v) {
  const float ev = std::log2(std::max(v, 1e-10f));
  return contrast(std::clamp((ev - kMinEv) / (kMaxEv - kMinEv), 0.0f, 1.0f));
}

float linearize(float v) {
  return std::pow(std::max(v, 0.0f), 2.2f);
}

Vec3 max0(Vec3 v) {
  return {std::max(v.x, 0.0f), std::max(v.y, 0.0f), std::max(v.z, 0.0f)};
}

}  // namespace

Vec3 agx(Vec3 rgb) {
  const Vec3 inset = kInset * max0(kRec709ToRec2020 * rgb);
  const Vec3 sigmoid{encode_log(inset.x), encode_log(inset.y), encode_log(inset.z)};
  const Vec3 outset = kOutset * sigmoid;
  return kRec2020ToRec709 * Vec3{linearize(outset.x), linearize(outset.y), linearize(outset.z)};
}

}  // namespace lp::tone
