// Khronos glTF samples of Debian's assimp-testmodels on screen: BoxTextured's Cesium logo through its
// sampler's wrap modes, and TextureTransformTest's KHR_texture_transform offsets, rotation (its sign)
// and scale (the order offset * rotation * scale) at known pixels.
//
// Each material's base-colour texture is moved to its emission slot on a black base and only what the
// camera sees is rendered (max_depth 0): a pixel is then the texel its ray hits, through the same UV
// interpolation, texture transform, wrap mode, sRGB decoding and mip lookup as the base colour, with no
// shading to model. Points are taken in uniform regions of the images (several texels wider than the
// filter's reach), so a pixel equals the 8-bit texel decoded from sRGB up to float rounding.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "engine/core/constants.hpp"
#include "engine/model/model_loader.hpp"
#include "engine/texture/srgb.hpp"
#include "model_test_scenes.hpp"
#include "render_test_helpers.hpp"
#include "support/test_data.hpp"

namespace lp::render {
namespace {

// Pixels in uniform regions match their texel to this (linear, per channel).
constexpr float kTolerance = 1e-3f;

Model unlit(Model m) {
  for (ModelMaterial& material : m.materials) {
    material.emissive = material.base_color;
    material.emissive_factor = {1, 1, 1};
    material.base_color.reset();
    material.base_color_factor = {0, 0, 0, 1};
  }
  return m;
}

// A texel of an 8-bit sRGB colour texture, linear.
Rgb texel(int r, int g, int b) {
  return {srgb_to_linear(float(r) / 255), srgb_to_linear(float(g) / 255), srgb_to_linear(float(b) / 255)};
}

struct View {
  Camera camera;
  int width, height;

  Image render(const std::string& sample) const {
    SceneDesc scene;
    scene.camera = camera;
    scene.objects.push_back(test::model_object(unlit(load_model(lp::test::assimp_model_path(sample), {}))));
    RenderSettings s = test::settings(width, 0);
    s.height = height;
    return test::render(scene, test::lighting(LightingMode::EnvMap), s, test::constant_map(1.0f), 4);
  }

  // The pixel whose footprint holds the world point p (PerspectiveCamera::generate inverted).
  Rgb at(const Image& image, Vec3 p) const {
    const Vec3 forward = normalize(camera.look_at - camera.position);
    const Vec3 right = normalize(cross(forward, camera.up)), up = cross(right, forward);
    const float half_height = std::tan(0.5f * camera.fov_deg * kPiF / 180);
    const float half_width = half_height * float(width) / float(height);
    const Vec3 d = p - camera.position;
    const float sx = dot(d, right) / dot(d, forward) / half_width,
                sy = dot(d, up) / dot(d, forward) / half_height;
    return image.at(int((sx + 1) / 2 * float(width)), int((1 - sy) / 2 * float(height)));
  }
};

void expect_colour(const View& view, const Image& image, Vec3 p, Rgb expected, const std::string& what) {
  const Rgb got = view.at(image, p);
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(got[k], expected[k], kTolerance)
        << what << " at (" << p.x << ", " << p.y << ", " << p.z << ") channel " << k;
}

// BoxTextured's face with normal +y in its mesh, which the root node's matrix (x, y, z) -> (x, z, -y)
// turns to glTF's -z (the back) and the world frame (x, y, z) -> (x, -z, y) to world +y, seen head on
// from +y with +z up the image (so -x is to the right). Its UVs run from (6, 0) at x = -0.5, z = 0.5 to
// (5, 1) at x = 0.5, z = -0.5: v = 0.5 - z, and u = 5.5 - x wraps to 0.5 - x under REPEAT (the logo
// upright) or to x + 0.5 under MIRRORED_REPEAT (the logo mirrored).
TEST(RenderGltfSamples, BoxTexturedShowsItsLogoThroughItsSamplersWrapModes) {
  const View view{{{0, 4, 0}, {0, 0, 0}, {0, 0, 1}, 20}, 256, 256};
  // CesiumLogoFlat.png (211 x 211): grey corners, blue sky, a white sun centred at texel (137.5, 59.2)
  // (9.7 texels in radius), green ground.
  const Rgb grey = texel(220, 220, 220), sky = texel(108, 173, 223), sun = texel(255, 255, 255),
            ground = texel(92, 135, 39);
  const Point2 sun_uv{0.654f, 0.283f};
  struct Variant {
    const char* file;
    bool mirrored_u;
  };
  // The .gltf's sampler mirrors in s (and clamps in t); the .glb and the embedded .gltf repeat.
  for (const Variant& v : {Variant{"glTF2/BoxTextured-glTF/BoxTextured.gltf", true},
                           Variant{"glTF2/BoxTextured-glTF-Binary/BoxTextured.glb", false},
                           Variant{"glTF2/BoxTextured-glTF-Embedded/BoxTextured.gltf", false}}) {
    SCOPED_TRACE(v.file);
    const Image image = view.render(v.file);
    const auto face = [&](float u, float v_) {
      return Vec3{v.mirrored_u ? u - 0.5f : 0.5f - u, 0.5f, 0.5f - v_};
    };
    expect_colour(view, image, face(0.05f, 0.05f), grey, "corner");
    expect_colour(view, image, face(0.95f, 0.95f), grey, "corner");
    expect_colour(view, image, face(0.5f, 0.2f), sky, "sky");
    expect_colour(view, image, face(0.5f, 0.8f), ground, "ground");
    expect_colour(view, image, face(sun_uv.x, sun_uv.y), sun, "sun");
    expect_colour(view, image, face(1 - sun_uv.x, sun_uv.y), sky, "the sun's mirror image");
  }
}

// TextureTransformTest: six unit quads in glTF's z = 0 plane facing its front (+z), which enter the
// world in the y = 0 plane facing -y, upright as Blender shows them: seen from the default camera's
// side (-y) with +z up, they read as the sample's screenshot does. Centres (world x, z) at (-1.1, 0.55),
// (0, 0.55), (1.1, 0.55) (offsets, UVs (0, 0) to (0.5, 0.5), UV.png) and (-1.1, -0.55), (0, -0.55),
// (1.1, -0.55) (rotation, scale, all three; UVs (0, 0) to (1, 1), Arrow.png), u along +x and v along -z
// from the top-left corner. Both textures are clamped.
const View kTransformView{{{0, -10, 0}, {0, 0, 0}, {0, 0, 1}, 2 * std::atan(0.112f) * 180 / kPiF}, 640,
                          448};

const Image& transform_sample() {
  static const Image image = kTransformView.render("glTF2/textureTransform/TextureTransformTest.gltf");
  return image;
}

Vec3 on_quad(Point2 centre, Point2 local) {
  return {centre.x + local.x, 0, centre.y + local.y};
}

TEST(RenderGltfSamples, TextureTransformTestOffsetsPickTheirQuadrantOfTheUvImage) {
  const Image& image = transform_sample();
  // The point (-0.34, 0.34) from a quad's centre has UVs (0.08, 0.08): plus the offset, texel (20, 20)
  // of UV.png's quadrant it selects, inside its plain background (yellow, the top-left quadrant, says
  // that no offset was applied).
  const std::pair<Point2, Rgb> quads[] = {{{-1.1f, 0.55f}, texel(0, 192, 0)},    // offset (0.5, 0): green
                                          {{0.0f, 0.55f}, texel(0, 0, 192)},     // offset (0, 0.5): blue
                                          {{1.1f, 0.55f}, texel(0, 192, 192)}};  // offset (0.5, 0.5): cyan
  for (const auto& [centre, colour] : quads)
    expect_colour(kTransformView, image, on_quad(centre, {-0.34f, 0.34f}), colour, "offset quad");
}

// Arrow.png: white, with a black arrow from its top-left towards its bottom-right along u = v (texels
// (14, 14) to (86, 86) on the diagonal, the shaft about 10 texels across) ending in a head centred at
// texel (75, 75).
const Rgb kBlack = texel(0, 0, 0), kWhite = texel(255, 255, 255);

TEST(RenderGltfSamples, TextureTransformTestRotationTurnsTheArrowToTheCorrectMarker) {
  const Image& image = transform_sample();
  // The rotation quad (rotation pi/8) holds three markers, placed by the sample's nodes: green
  // ("Rotation - Correct") where the arrow points when the UVs turn counter-clockwise as the extension
  // says, yellow where it points unrotated, red where the opposite sign turns it. The arrow starts at
  // the quad's top-left corner: along the line from there to the green marker the quad is black, along
  // the line to the yellow one white.
  const Point2 centre{-1.1f, -0.55f}, corner{-0.5f, 0.5f};
  const auto towards = [&](Point2 marker, float r) {
    const float dx = marker.x - corner.x, dy = marker.y - corner.y, len = std::hypot(dx, dy);
    return on_quad(centre, {corner.x + r * dx / len, corner.y + r * dy / len});
  };
  const Point2 correct{-0.07904822f, -0.51626749f}, not_supported{0.27781746f, -0.27781746f};
  for (float r : {0.4f, 0.7f}) {
    expect_colour(kTransformView, image, towards(correct, r), kBlack, "towards the correct marker");
    expect_colour(kTransformView, image, towards(not_supported, r), kWhite, "towards the unrotated marker");
  }
}

TEST(RenderGltfSamples, TextureTransformTestScaleAndAllThreeInTheirOrder) {
  const Image& image = transform_sample();
  // Scale 1.5: the quad's diagonal point (0.12, -0.12) has UVs (0.62, 0.62), scaled to (0.93, 0.93),
  // past the arrow's tip (unscaled it would be on the arrow); (-0.2, 0.2) reads the shaft either way.
  const Point2 scale_quad{0.0f, -0.55f};
  expect_colour(kTransformView, image, on_quad(scale_quad, {0.12f, -0.12f}), kWhite, "past the scaled tip");
  expect_colour(kTransformView, image, on_quad(scale_quad, {-0.2f, 0.2f}), kBlack, "on the scaled shaft");
  // Offset (-0.2, -0.1), rotation 0.3, scale 1.5: uv' = T R S uv, R turning as the rotation quad shows
  // (u' = cos u + sin v, v' = -sin u + cos v). The arrowhead's centre q = (0.59, 0.59) is read at
  // uv = S^-1 R^-1 (q - offset); offset first (R S (uv + offset)) or the opposite sign would read white
  // there.
  const float c = std::cos(0.3f), s = std::sin(0.3f), qu = 0.59f + 0.2f, qv = 0.59f + 0.1f;
  const Point2 uv{(c * qu - s * qv) / 1.5f, (s * qu + c * qv) / 1.5f};
  expect_colour(kTransformView, image, on_quad({1.1f, -0.55f}, {uv.x - 0.5f, 0.5f - uv.y}), kBlack,
                "the arrowhead");
}

}  // namespace
}  // namespace lp::render
