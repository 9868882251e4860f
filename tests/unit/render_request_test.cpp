// Parsing of POST /api/v1/renders bodies: defaults, every object and material, and 400s naming the field.
#include "api/render_request.hpp"

#include <gtest/gtest.h>

#include <variant>

#include "api/api_error.hpp"
#include "api/turntable_request.hpp"
#include "engine/fresnel/metals.hpp"

namespace lp::api {
namespace {

using namespace lp::render;

RenderRequest parse(const std::string& body, const RequestLimits& limits = {}) {
  return parse_render_request(Json::parse(body), limits);
}

// The body must fail with 400 invalid_field naming exactly `field`.
void expect_field_error(const std::string& body, const std::string& field, const RequestLimits& limits = {}) {
  SCOPED_TRACE(body);
  try {
    parse(body, limits);
    ADD_FAILURE() << "accepted; expected an error naming " << field;
  } catch (const ApiError& e) {
    EXPECT_EQ(e.status(), 400);
    EXPECT_EQ(e.code(), ErrorCode::InvalidField);
    EXPECT_EQ(std::string(e.what()).rfind("field '" + field + "': ", 0), 0u) << e.what();
  }
}

TEST(RenderRequest, DefaultsAreTheSpherePresetAndTheDocumentedSettings) {
  const auto r = parse(R"({"envmap":"forest"})");
  EXPECT_EQ(r.envmap, "forest");
  ASSERT_TRUE(r.preset);
  EXPECT_EQ(*r.preset, "sphere");
  ASSERT_EQ(r.scene.objects.size(), 1u);
  const auto& sphere = std::get<SphereObject>(r.scene.objects[0].shape);
  EXPECT_EQ(sphere.center, (Vec3{0, 0, 0}));
  EXPECT_EQ(sphere.radius, 1.0f);
  EXPECT_EQ(std::get<DiffuseMaterial>(r.scene.objects[0].material).albedo, (Rgb{0.8f, 0.8f, 0.8f}));
  EXPECT_EQ(r.settings.width, 256);
  EXPECT_EQ(r.settings.height, 256);
  EXPECT_EQ(r.settings.spp, 64);
  EXPECT_EQ(r.settings.max_depth, 8);
  EXPECT_EQ(r.settings.seed, 1u);
  EXPECT_TRUE(r.settings.mipmaps);
  EXPECT_TRUE(r.settings.normal_maps);
  EXPECT_EQ(r.lighting.mode, LightingMode::EnvMap);
  EXPECT_EQ(r.lighting.lights, 64);
  EXPECT_TRUE(r.lighting.visible);
}

TEST(RenderRequest, PresetsAndCameraOverride) {
  const auto furnace = parse(R"({"envmap":"e","scene":{"preset":"furnace"}})");
  ASSERT_EQ(furnace.scene.objects.size(), 1u);
  EXPECT_EQ(std::get<DiffuseMaterial>(furnace.scene.objects[0].material).albedo, (Rgb{0.5f, 0.5f, 0.5f}));
  const auto materials = parse(R"({"envmap":"e","scene":{"preset":"materials","camera":{"fov_deg":60}}})");
  EXPECT_EQ(materials.scene.objects.size(), 5u);
  EXPECT_EQ(materials.scene.camera.fov_deg, 60.0f);
}

TEST(RenderRequest, ParsesEveryObjectMaterialAndSetting) {
  const auto r = parse(R"({
    "envmap": "studio",
    "scene": {
      "camera": {"position": [1, -5, 2], "look_at": [0, 0, 0.5], "up": [0, 0, 1], "fov_deg": 30},
      "objects": [
        {"type": "sphere", "center": [0, 0, 1], "radius": 0.5, "material": {"type": "mirror", "color": [0.9, 0.8, 0.7]}},
        {"type": "plane", "point": [0, 0, 0], "normal": [0, 0, 2], "material": {"type": "diffuse", "albedo": 0.25}},
        {"type": "mesh", "path": "meshes/bunny.obj",
         "transform": {"translate": [1, 2, 3], "scale": 4, "rotate_deg": [90, 0, 45]},
         "material": {"type": "plastic", "albedo": [0.1, 0.2, 0.3], "ior": 1.6, "roughness": 0.2}},
        {"type": "sphere", "center": [2, 0, 1], "radius": 1, "material": {"type": "dielectric", "ior": 1.33, "roughness": 0.2}},
        {"type": "sphere", "center": [-2, 0, 1], "radius": 1, "material": {"type": "conductor", "metal": "gold", "roughness": 0.3}},
        {"type": "sphere", "center": [-4, 0, 1], "radius": 1,
         "material": {"type": "conductor", "eta": [0.2, 0.9, 1.1], "k": 3}}
      ]
    },
    "lighting": {"mode": "median_cut", "lights": 16, "rotation_deg": 90, "intensity": 2.5, "visible": false},
    "width": 64, "height": 32, "spp": 8, "max_depth": 0, "seed": 77
  })");
  EXPECT_FALSE(r.preset);
  EXPECT_EQ(r.scene.camera.position, (Vec3{1, -5, 2}));
  EXPECT_EQ(r.scene.camera.look_at, (Vec3{0, 0, 0.5f}));
  EXPECT_EQ(r.scene.camera.fov_deg, 30.0f);
  ASSERT_EQ(r.scene.objects.size(), 6u);

  const auto& o = r.scene.objects;
  EXPECT_EQ(std::get<SphereObject>(o[0].shape).radius, 0.5f);
  EXPECT_EQ(std::get<MirrorMaterial>(o[0].material).color, (Rgb{0.9f, 0.8f, 0.7f}));
  EXPECT_EQ(std::get<PlaneObject>(o[1].shape).normal, (Vec3{0, 0, 1}));  // normalised
  EXPECT_EQ(std::get<DiffuseMaterial>(o[1].material).albedo, (Rgb{0.25f, 0.25f, 0.25f}));
  const auto& mesh = std::get<MeshObject>(o[2].shape);
  EXPECT_EQ(mesh.path, "meshes/bunny.obj");  // resolved later by the server
  EXPECT_EQ(mesh.translate, (Vec3{1, 2, 3}));
  EXPECT_EQ(mesh.scale, 4.0f);
  EXPECT_EQ(mesh.rotate_deg, (Vec3{90, 0, 45}));
  const auto& plastic = std::get<PlasticMaterial>(o[2].material);
  EXPECT_EQ(plastic.albedo, (Rgb{0.1f, 0.2f, 0.3f}));
  EXPECT_EQ(plastic.ior, 1.6f);
  EXPECT_EQ(plastic.roughness, 0.2f);
  EXPECT_EQ(std::get<DielectricMaterial>(o[3].material).ior, 1.33f);
  EXPECT_EQ(std::get<DielectricMaterial>(o[3].material).roughness, 0.2f);
  const auto& gold = std::get<ConductorMaterial>(o[4].material);
  EXPECT_EQ(gold.eta, lookup_metal("gold").eta_rgb());
  EXPECT_EQ(gold.k, lookup_metal("gold").k_rgb());
  EXPECT_EQ(gold.roughness, 0.3f);
  const auto& custom = std::get<ConductorMaterial>(o[5].material);
  EXPECT_EQ(custom.eta, (Rgb{0.2f, 0.9f, 1.1f}));
  EXPECT_EQ(custom.k, (Rgb{3, 3, 3}));
  EXPECT_EQ(custom.roughness, 0.0f);

  EXPECT_EQ(r.lighting.mode, LightingMode::MedianCut);
  EXPECT_EQ(r.lighting.lights, 16);
  EXPECT_EQ(r.lighting.rotation_deg, 90.0f);
  EXPECT_EQ(r.lighting.intensity, 2.5f);
  EXPECT_FALSE(r.lighting.visible);
  EXPECT_EQ(r.settings.width, 64);
  EXPECT_EQ(r.settings.height, 32);
  EXPECT_EQ(r.settings.spp, 8);
  EXPECT_EQ(r.settings.max_depth, 0);
  EXPECT_EQ(r.settings.seed, 77u);
}

TEST(RenderRequest, EveryLightingModeParses) {
  const std::pair<const char*, LightingMode> modes[] = {{"envmap", LightingMode::EnvMap},
                                                        {"uniform", LightingMode::Uniform},
                                                        {"bsdf", LightingMode::Bsdf},
                                                        {"median_cut", LightingMode::MedianCut},
                                                        {"median_cut_all", LightingMode::MedianCutAll}};
  for (const auto& [name, mode] : modes) {
    const auto r = parse(std::string(R"({"envmap":"e","lighting":{"mode":")") + name + R"("}})");
    EXPECT_EQ(r.lighting.mode, mode) << name;
    EXPECT_STREQ(enum_name(mode), name);
  }
}

TEST(RenderRequest, LimitsComeFromTheServer) {
  RequestLimits limits;
  limits.max_render_width = 100;
  limits.max_render_height = 50;
  limits.max_render_spp = 16;
  limits.max_render_depth = 3;
  limits.max_render_objects = 2;
  limits.max_lights = 8;
  limits.max_mesh_triangles = 1234;
  const auto r = parse(R"({"envmap":"e"})", limits);
  EXPECT_EQ(r.settings.width, 100);  // the default 256 is capped at the limit
  EXPECT_EQ(r.settings.height, 50);
  EXPECT_EQ(r.settings.spp, 16);
  EXPECT_EQ(r.settings.max_depth, 3);
  EXPECT_EQ(r.lighting.lights, 8);
  EXPECT_EQ(r.settings.mesh_limits.max_triangles, 1234);
  expect_field_error(R"({"envmap":"e","width":101})", "width", limits);
  expect_field_error(R"({"envmap":"e","height":51})", "height", limits);
  expect_field_error(R"({"envmap":"e","spp":17})", "spp", limits);
  expect_field_error(R"({"envmap":"e","max_depth":4})", "max_depth", limits);
  expect_field_error(R"({"envmap":"e","lighting":{"lights":9}})", "lighting.lights", limits);
  const std::string sphere = R"({"type":"sphere","center":[0,0,0],"radius":1})";
  expect_field_error(R"({"envmap":"e","scene":{"objects":[)" + sphere + "," + sphere + "," + sphere + "]}}",
                     "scene.objects", limits);
}

TEST(RenderRequest, BadFieldsAreNamedByTheirPath) {
  const std::string head =
      R"({"envmap":"e","scene":{"objects":[{"type":"sphere","center":[0,0,0],"radius":1},)";
  expect_field_error(
      head + R"({"type":"sphere","center":[0,0,0],"radius":1,"material":{"type":"dielectric","ior":9}}]}})",
      "scene.objects[1].material.ior");
  expect_field_error(
      head +
          R"({"type":"sphere","center":[0,0,0],"radius":1,"material":{"type":"dielectric","roughness":2}}]}})",
      "scene.objects[1].material.roughness");
  expect_field_error(head + R"({"type":"sphere","center":[0,0,0],"radius":-1}]}})",
                     "scene.objects[1].radius");
  expect_field_error(head + R"({"type":"sphere","center":[0,0],"radius":1}]}})", "scene.objects[1].center");
  expect_field_error(head + R"({"type":"sphere","center":[0,"x",0],"radius":1}]}})",
                     "scene.objects[1].center[1]");
  expect_field_error(head + R"({"type":"sphere","center":[0,0,0]}]}})", "scene.objects[1].radius");
  expect_field_error(head + R"({"type":"cube"}]}})", "scene.objects[1].type");
  expect_field_error(head + R"({"center":[0,0,0],"radius":1}]}})", "scene.objects[1].type");
  expect_field_error(head + R"({"type":"sphere","center":[0,0,0],"radius":1,"colour":1}]}})",
                     "scene.objects[1].colour");
  expect_field_error(head + R"(7]}})", "scene.objects[1]");
  expect_field_error(head + R"({"type":"plane","point":[0,0,0],"normal":[0,0,0]}]}})",
                     "scene.objects[1].normal");
  expect_field_error(head + R"({"type":"mesh"}]}})", "scene.objects[1].path");
  expect_field_error(head + R"({"type":"mesh","path":"m.obj","transform":{"scale":0}}]}})",
                     "scene.objects[1].transform.scale");
  expect_field_error(head + R"({"type":"mesh","path":"m.obj","transform":{"skew":1}}]}})",
                     "scene.objects[1].transform.skew");
  const std::string m = R"({"type":"sphere","center":[0,0,0],"radius":1,"material":)";
  expect_field_error(head + m + R"({"type":"diffuse","albedo":[1.5,0,0]}}]}})",
                     "scene.objects[1].material.albedo[0]");
  expect_field_error(head + m + R"({"type":"diffuse","albedo":2}}]}})", "scene.objects[1].material.albedo");
  expect_field_error(head + m + R"({"type":"velvet"}}]}})", "scene.objects[1].material.type");
  expect_field_error(head + m + R"({"type":"plastic","roughness":2}}]}})",
                     "scene.objects[1].material.roughness");
  expect_field_error(head + m + R"({"type":"mirror","ior":1.5}}]}})", "scene.objects[1].material.ior");
  expect_field_error(head + m + R"({"type":"conductor","metal":"unobtainium"}}]}})",
                     "scene.objects[1].material.metal");
  expect_field_error(head + m + R"({"type":"conductor","metal":"gold","eta":1}}]}})",
                     "scene.objects[1].material.metal");
  expect_field_error(head + m + R"({"type":"conductor","eta":1}}]}})", "scene.objects[1].material.k");
  expect_field_error(head + m + R"({"type":"conductor","eta":0,"k":1}}]}})", "scene.objects[1].material.eta");
  expect_field_error(head + m + R"("gold"}]}})", "scene.objects[1].material");
}

TEST(RenderRequest, BadTopLevelSceneCameraAndLightingFields) {
  expect_field_error(R"({})", "envmap");
  expect_field_error(R"({"envmap":""})", "envmap");
  expect_field_error(R"({"envmap":3})", "envmap");
  expect_field_error(R"({"envmap":"e","colour":1})", "colour");
  expect_field_error(R"({"envmap":"e","width":0})", "width");
  expect_field_error(R"({"envmap":"e","width":1.5})", "width");
  expect_field_error(R"({"envmap":"e","spp":"many"})", "spp");
  expect_field_error(R"({"envmap":"e","seed":-1})", "seed");
  expect_field_error(R"({"envmap":"e","scene":[]})", "scene");
  expect_field_error(R"({"envmap":"e","scene":{"preset":"teapot"}})", "scene.preset");
  expect_field_error(R"({"envmap":"e","scene":{"preset":"sphere","objects":[]}})", "scene.objects");
  expect_field_error(R"({"envmap":"e","scene":{"objects":{}}})", "scene.objects");
  expect_field_error(R"({"envmap":"e","scene":{"lights":[]}})", "scene.lights");
  expect_field_error(R"({"envmap":"e","scene":{"camera":{"position":[0,0,0],"look_at":[0,0,0]}}})",
                     "scene.camera.look_at");
  expect_field_error(R"({"envmap":"e","scene":{"camera":{"up":[0,1,0]}}})",
                     "scene.camera.up");  // along the view
  expect_field_error(R"({"envmap":"e","scene":{"camera":{"fov_deg":180}}})", "scene.camera.fov_deg");
  expect_field_error(R"({"envmap":"e","scene":{"camera":{"zoom":2}}})", "scene.camera.zoom");
  expect_field_error(R"({"envmap":"e","lighting":{"mode":"sun"}})", "lighting.mode");
  expect_field_error(R"({"envmap":"e","lighting":{"intensity":-1}})", "lighting.intensity");
  expect_field_error(R"({"envmap":"e","lighting":{"visible":"yes"}})", "lighting.visible");
  expect_field_error(R"({"envmap":"e","lighting":{"rotation":90}})", "lighting.rotation");
  expect_field_error(R"({"envmap":"e","lighting":{"sun":"keep"}})", "lighting.sun");
  expect_field_error(R"({"envmap":"e","lighting":{"mode":"median_cut","sun":"extract"}})", "lighting.sun");
}

TEST(RenderRequest, TheSunIsExtractedOnlyWhenAsked) {
  EXPECT_EQ(parse(R"({"envmap":"e"})").lighting.sun, SunMode::None);
  EXPECT_EQ(parse(R"({"envmap":"e","lighting":{"sun":"extract"}})").lighting.sun, SunMode::Extract);
  EXPECT_EQ(parse(R"({"envmap":"e","lighting":{"mode":"envmap","sun":"none"}})").lighting.sun, SunMode::None);
}

TEST(RenderRequest, MipmapsAndNormalMapsTurnOffEachAlone) {
  const auto no_mips = parse(R"({"envmap":"e","mipmaps":false})");
  EXPECT_FALSE(no_mips.settings.mipmaps);
  EXPECT_TRUE(no_mips.settings.normal_maps);
  const auto no_normals = parse(R"({"envmap":"e","normal_maps":false,"mipmaps":true})");
  EXPECT_TRUE(no_normals.settings.mipmaps);
  EXPECT_FALSE(no_normals.settings.normal_maps);
  expect_field_error(R"({"envmap":"e","mipmaps":"off"})", "mipmaps");
  expect_field_error(R"({"envmap":"e","normal_maps":0})", "normal_maps");
}

TEST(RenderRequest, SamplingIsUniformUnlessAdaptiveIsAsked) {
  EXPECT_EQ(parse(R"({"envmap":"e"})").settings.sampling, SamplingMode::Uniform);
  EXPECT_EQ(parse(R"({"envmap":"e","sampling":"adaptive"})").settings.sampling, SamplingMode::Adaptive);
  EXPECT_EQ(parse(R"({"envmap":"e","sampling":"uniform"})").settings.sampling, SamplingMode::Uniform);
  expect_field_error(R"({"envmap":"e","sampling":"auto"})", "sampling");
  expect_field_error(R"({"envmap":"e","sampling":true})", "sampling");
}

TEST(RenderRequest, AnEmptyObjectListIsAValidScene) {
  const auto r = parse(R"({"envmap":"e","scene":{"objects":[]}})");
  EXPECT_FALSE(r.preset);
  EXPECT_TRUE(r.scene.objects.empty());
}

}  // namespace
}  // namespace lp::api

namespace lp::api {
namespace {

TEST(RenderRequest, DenoiseIsOffForRendersOnForTurntablesAndBringsAlbedoAndNormal) {
  const auto plain = parse(R"({"envmap":"forest","passes":["depth"]})");
  EXPECT_FALSE(plain.denoise);
  EXPECT_EQ(plain.settings.passes.list(), std::vector<AuxPass>{AuxPass::Depth});
  const auto denoised = parse(R"({"envmap":"forest","passes":["depth"],"denoise":true})");
  EXPECT_TRUE(denoised.denoise);
  EXPECT_EQ(denoised.settings.passes.list(),
            (std::vector<AuxPass>{AuxPass::Albedo, AuxPass::Normal, AuxPass::Depth}));
  // The same field with the turntables' default; a turntable's frames are denoised unless it says false.
  const Json body = Json::parse(R"({"envmap":"forest","turntable":{"frames":2}})");
  EXPECT_TRUE(parse_turntable_request(body, {}).render.denoise);
  Json off = body;
  off["denoise"] = false;
  EXPECT_FALSE(parse_turntable_request(off, {}).render.denoise);
  EXPECT_TRUE(parse_turntable_request(off, {}).render.settings.passes.list().empty());
  expect_field_error(R"({"envmap":"forest","denoise":1})", "denoise");
}

}  // namespace
}  // namespace lp::api
