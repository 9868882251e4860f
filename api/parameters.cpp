#include "api/parameters.hpp"

#include <fmt/format.h>

#include "api/brdf_lut_request.hpp"
#include "api/fresnel_request.hpp"
#include "api/light_export.hpp"
#include "api/prefilter_request.hpp"
#include "api/render_image_pass.hpp"
#include "api/sample_request.hpp"
#include "api/sh_request.hpp"
#include "api/thumbnail_params.hpp"
#include "api/turntable_request.hpp"
#include "engine/envmap/invalid_pixels.hpp"
#include "engine/envmap/sample_set.hpp"
#include "engine/mediancut/median_cut_plot.hpp"
#include "engine/projection/cube_face.hpp"
#include "engine/projection/projection.hpp"
#include "engine/render/scene_desc.hpp"
#include "engine/sun/sun_params.hpp"

namespace lp::api {
namespace {

using Location = std::vector<std::string>;
using Doc = DocumentedParameter;

Location query(const std::string& path, const std::string& method, const std::string& name) {
  return {"paths", path, method, "parameters", "name=" + name, "schema"};
}
Location body(const std::string& path, const std::string& name) {
  return {"paths", path, "post", "requestBody", "content", "application/json", "schema", "properties", name};
}
Location schema(const std::string& name, std::initializer_list<std::string> keys) {
  Location l = {"components", "schemas", name};
  l.insert(l.end(), keys);
  return l;
}

template <class E>
Doc enum_doc(Location location, std::optional<E> fallback) {
  return {std::move(location),
          enum_names<E>(),
          {},
          {},
          fallback ? std::optional<std::string>(enum_name(*fallback)) : std::nullopt};
}

std::optional<std::string> number_text(std::optional<double> v) {
  return v ? std::optional<std::string>(fmt::format("{}", *v)) : std::nullopt;
}

template <class T>
Doc range_doc(Location location, Range<T> range, std::optional<double> fallback = std::nullopt) {
  return {std::move(location), {}, double(range.min), double(range.max), number_text(fallback)};
}

// A field whose upper bound is a server flag: the document states only the lower bound.
Doc lower_bound_doc(Location location, double minimum, std::optional<double> fallback) {
  return {std::move(location), {}, minimum, std::nullopt, number_text(fallback)};
}

Doc field_doc(Location location, const NumberField& f) {
  return range_doc(std::move(location), f.range, f.fallback);
}

Doc bool_doc(Location location, const BoolField& f) {
  return {std::move(location), {}, {}, {}, f.fallback ? "true" : "false"};
}

void add_enum_parameters(std::vector<Doc>& d) {
  const std::string samples = "/api/v1/envmaps/{id}/samples", cut = "/api/v1/envmaps/{id}/median-cut";
  d.push_back(
      enum_doc(query("/api/v1/envmaps", "post", "invalid"), std::optional(kDefaultInvalidPixelPolicy)));
  d.push_back(
      enum_doc({"components", "parameters", "Luminance", "schema"}, std::optional(LuminanceMode::Average)));
  d.push_back(
      enum_doc({"components", "parameters", "ImageFormat", "schema"}, std::optional(ImageFormat::Png)));
  d.push_back(enum_doc(body(samples, "strategy"), std::optional(SampleStrategy::Independent)));
  d.push_back(enum_doc(body(samples, "luminance"), std::optional(LuminanceMode::Average)));
  d.push_back(
      enum_doc(query(samples + ".png", "get", "strategy"), std::optional(SampleStrategy::Independent)));
  d.push_back(enum_doc(query(samples + ".png", "get", "style"), std::optional(SampleImageStyle::Marks)));
  d.push_back(enum_doc(body(cut, "placement"), std::optional(LightPlacement::Centroid)));
  d.push_back(enum_doc(body(cut, "split"), std::optional(SplitRule::Median)));
  d.push_back(enum_doc(body(cut, "luminance"), std::optional(LuminanceMode::Average)));
  d.push_back(enum_doc(query(cut + ".png", "get", "placement"), std::optional(LightPlacement::Centroid)));
  d.push_back(enum_doc(query(cut + ".png", "get", "split"), std::optional(SplitRule::Median)));
  d.push_back(enum_doc(query(cut + ".png", "get", "style"), std::optional(MedianCutStyle::Regions)));
  d.push_back(enum_doc(query("/api/v1/fresnel", "get", "format"), std::optional(TableFormat::JsonDocument)));
  d.push_back(enum_doc(query("/api/v1/brdf-lut", "get", "format"), std::optional(ImageFormat::Exr)));
  const std::string sh = "/api/v1/envmaps/{id}/sh";
  d.push_back(enum_doc(query(sh, "get", "window"), std::optional(ShWindow::None)));
  d.push_back(enum_doc(query(sh + ".png", "get", "window"), std::optional(ShWindow::None)));
  d.push_back(enum_doc(query(sh + ".png", "get", "quantity"), std::optional(ShQuantity::Radiance)));
  d.push_back({query("/api/v1/fresnel", "get", "metal"), metal_names(), {}, {}, {}});
  d.push_back({schema("RenderMaterial", {"oneOf", "type=conductor", "properties", "metal"}),
               metal_names(),
               {},
               {},
               {}});
  d.push_back(enum_doc(schema("RenderLighting", {"properties", "mode"}),
                       std::optional(render::LightingMode::EnvMap)));
  d.push_back(
      enum_doc(schema("RenderScene", {"properties", "preset"}), std::optional<render::ScenePreset>()));
  d.push_back(enum_doc(schema("RenderObject", {"oneOf", "type=mesh", "properties", "up_axis"}),
                       std::optional(kDefaultUpAxis)));
}

void add_request_ranges(std::vector<Doc>& d) {
  const std::string samples = "/api/v1/envmaps/{id}/samples", cut = "/api/v1/envmaps/{id}/median-cut";
  d.push_back(lower_bound_doc(body(samples, "count"), kSampleCount.range.min, kSampleCount.fallback));
  d.push_back(lower_bound_doc(body(samples, "seed"), kSampleSeed.range.min, kSampleSeed.fallback));
  d.push_back(lower_bound_doc(query(samples + ".png", "get", "count"), kSampleImageCount.range.min,
                              kSampleImageCount.fallback));
  d.push_back(
      lower_bound_doc(query(samples + ".png", "get", "seed"), kSampleSeed.range.min, kSampleSeed.fallback));
  d.push_back(lower_bound_doc(body(cut, "count"), kLightCount.range.min, kLightCount.fallback));
  d.push_back(
      lower_bound_doc(query(cut + ".png", "get", "count"), kLightCount.range.min, kLightCount.fallback));
  d.push_back(range_doc(query("/api/v1/brdf-lut", "get", "size"), kDfgLutSize, kDefaultDfgLutSize));
  const std::string sh = "/api/v1/envmaps/{id}/sh";
  d.push_back(range_doc(query(sh, "get", "bands"), limits::kShBands, kDefaultShBands));
  d.push_back(range_doc(query(sh + ".png", "get", "bands"), limits::kShBands, kDefaultShBands));
  d.push_back(range_doc(query(sh + ".png", "get", "width"), kShImageWidth));
  d.push_back(field_doc({"components", "parameters", "Exposure", "schema"}, kExposure));
  d.push_back(field_doc({"components", "parameters", "Gamma", "schema"}, kGamma));
  d.push_back(
      enum_doc({"components", "parameters", "ToneMapping", "schema"}, std::optional(kToneMapping.fallback)));
  d.push_back(
      enum_doc({"components", "parameters", "RenderToneMapping", "schema"}, std::optional<ToneCurve>()));
  d.push_back(enum_doc(schema("RenderRequest", {"properties", kRenderToneMapping.name}),
                       std::optional(kRenderToneMapping.fallback)));
  const std::string fresnel = "/api/v1/fresnel";
  d.push_back(range_doc(query(fresnel, "get", "eta_i"), limits::kFresnelIndex, 1.0));
  d.push_back(range_doc(query(fresnel, "get", "eta_t"), limits::kFresnelIndex));
  d.push_back(range_doc(query(fresnel, "get", "eta"), limits::kFresnelIndex));
  d.push_back(range_doc(query(fresnel, "get", "k"), limits::kFresnelExtinction));
  d.push_back(field_doc(query(fresnel, "get", "step"), kFresnelStep));
}

void add_render_ranges(std::vector<Doc>& d) {
  using namespace limits;
  const render::RenderSettings settings;
  const render::Lighting lighting;
  const render::Camera camera;
  const auto request = [](const std::string& name) { return schema("RenderRequest", {"properties", name}); };
  d.push_back(lower_bound_doc(request("width"), 1, settings.width));
  d.push_back(lower_bound_doc(request("height"), 1, settings.height));
  d.push_back(lower_bound_doc(request("spp"), 1, settings.spp));
  d.push_back(lower_bound_doc(request("max_depth"), double(kMaxDepth.min), settings.max_depth));
  d.push_back(enum_doc(request("sampling"), std::optional(settings.sampling)));
  d.push_back(bool_doc(request(kRenderDenoise.name), kRenderDenoise));
  d.push_back({query("/api/v1/renders/{id}/image", "get", "pass"),
               render_image_pass_names(),
               {},
               {},
               kColorPassName});
  d.push_back(lower_bound_doc(request("seed"), 0, double(settings.seed)));
  d.push_back(range_doc(schema("RenderCamera", {"properties", "fov_deg"}), kFovDeg, camera.fov_deg));
  const render::CameraFit fit;
  const auto fit_field = [](const std::string& name) {
    return schema("RenderCamera", {"properties", "fit", "properties", name});
  };
  d.push_back(range_doc(fit_field("azimuth_deg"), kRotationDeg, fit.azimuth_deg));
  d.push_back(range_doc(fit_field("elevation_deg"), kElevationDeg, fit.elevation_deg));
  d.push_back(range_doc(fit_field("margin"), kFitMargin, fit.margin));
  d.push_back(range_doc(schema("Vec3", {"items"}), kCoordinate));
  d.push_back(range_doc(schema("RenderColor", {"oneOf", "0"}), kReflectance));
  d.push_back(range_doc(schema("RenderObject", {"oneOf", "type=sphere", "properties", "radius"}), kSize));
  const Location transform = {"oneOf", "type=mesh", "properties", "transform", "properties"};
  auto mesh = [&](const std::string& name) {
    Location l = schema("RenderObject", {});
    l.insert(l.end(), transform.begin(), transform.end());
    l.push_back(name);
    return l;
  };
  d.push_back(range_doc(mesh("scale"), kSize, 1.0));
  Location rotate = mesh("rotate_deg");
  rotate.push_back("items");
  d.push_back(range_doc(rotate, kRotationDeg));
  const auto material = [](const std::string& type, const std::string& name) {
    return schema("RenderMaterial", {"oneOf", "type=" + type, "properties", name});
  };
  d.push_back(range_doc(material("dielectric", "ior"), kIor, render::DielectricMaterial{}.ior));
  d.push_back(
      range_doc(material("dielectric", "roughness"), kRoughness, render::DielectricMaterial{}.roughness));
  d.push_back(range_doc(material("plastic", "ior"), kIor, render::PlasticMaterial{}.ior));
  d.push_back(range_doc(material("plastic", "roughness"), kRoughness, render::PlasticMaterial{}.roughness));
  d.push_back(
      range_doc(material("conductor", "roughness"), kRoughness, render::ConductorMaterial{}.roughness));
  Location eta = material("conductor", "eta"), k = material("conductor", "k");
  eta.insert(eta.end(), {"oneOf", "0"});
  k.insert(k.end(), {"oneOf", "0"});
  d.push_back(range_doc(eta, kConductorEta));
  d.push_back(range_doc(k, kConductorK));
  const auto light = [](const std::string& name) { return schema("RenderLighting", {"properties", name}); };
  d.push_back(lower_bound_doc(light("lights"), 1, lighting.lights));
  d.push_back(range_doc(light("rotation_deg"), kRotationDeg, lighting.rotation_deg));
  d.push_back(range_doc(light("intensity"), kIntensity, lighting.intensity));
}

void add_prefilter_parameters(std::vector<Doc>& d) {
  const std::string path = "/api/v1/envmaps/{id}/prefilter";
  const PrefilterRequest r;
  d.push_back(range_doc(body(path, "levels"), limits::kPrefilterLevels, r.params.levels));
  d.push_back(range_doc(body(path, "base_size"), limits::kPrefilterBaseSize, r.params.base_size));
  d.push_back(range_doc(body(path, "samples"), limits::kPrefilterSamples, r.params.samples));
  d.push_back(range_doc(schema("PrefilterJob", {"properties", "texel_samples"}), kPrefilterTexelSamples));
  d.push_back(enum_doc(body(path, "projection"), std::optional(r.params.projection)));
  d.push_back(enum_doc(schema("PrefilterJob", {"properties", "projection"}), std::optional<Projection>()));
  d.push_back(enum_doc(body(path, "level_roughness"), std::optional(r.params.level_roughness)));
  d.push_back(
      enum_doc(schema("PrefilterJob", {"properties", "level_roughness"}), std::optional<LevelRoughness>()));
  d.push_back(enum_doc(body(path, "target"), std::optional<BakeTarget>()));
  d.push_back(enum_doc(schema("PrefilterJob", {"properties", "target"}), std::optional<BakeTarget>()));
  d.push_back(enum_doc(body(path, "format"), std::optional(r.format)));
  d.push_back(enum_doc(body(path, "precision"), std::optional(r.precision)));
  d.push_back(enum_doc(schema("PrefilterJob", {"properties", "format"}), std::optional<PrefilterFormat>()));
  d.push_back(enum_doc(schema("PrefilterJob", {"properties", "precision"}), std::optional<PixelPrecision>()));
  const Range<int> level{0, limits::kPrefilterLevels.max - 1};
  d.push_back(range_doc(query("/api/v1/prefilters/{id}/levels/{n}.png", "get", "n"), level));
}

void add_sun_parameters(std::vector<Doc>& d) {
  const SunParams p;
  for (const SunField& f : kSunFields)
    d.push_back(range_doc(schema("SunParameters", {"properties", f.name}), f.range, p.*f.member));
  d.push_back(
      enum_doc(schema("RenderLighting", {"properties", "sun"}), std::optional(render::SunMode::None)));
  for (const std::string path : {"/api/v1/envmaps/{id}/median-cut", "/api/v1/envmaps/{id}/sun"}) {
    d.push_back(enum_doc(query(path, "post", "format"), std::optional(LightFormat::Answer)));
    d.push_back(enum_doc(query(path, "post", "frame"), std::optional(MitsubaFrame::Mitsuba)));
  }
}

void add_projection_parameters(std::vector<Doc>& d) {
  const std::string image = "/api/v1/envmaps/{id}/image";
  d.push_back(enum_doc(query(image, "get", "projection"), std::optional(Projection::LatLong)));
  d.push_back(range_doc(query(image, "get", "size"), limits::kProjectionSize));
  d.push_back(enum_doc(query(image, "get", "face"), std::optional<CubeFace>()));
  d.push_back(enum_doc(query("/api/v1/envmaps", "post", "projection"), std::optional(Projection::LatLong)));
  d.push_back(enum_doc(schema("EnvMap", {"properties", "source_projection"}), std::optional<Projection>()));
}

void add_turntable_parameters(std::vector<Doc>& d) {
  const render::Turntable t;
  const auto field = [](const std::string& name) { return schema("Turntable", {"properties", name}); };
  d.push_back(range_doc(field("frames"), limits::kTurntableFrames, t.frames));
  d.push_back(range_doc(field("azimuth_start_deg"), kTurntableAzimuthDeg, t.azimuth_start_deg));
  d.push_back(range_doc(field("azimuth_step_deg"), kTurntableAzimuthDeg));
  d.push_back(range_doc(field("elevation_deg"), limits::kElevationDeg, t.elevation_deg));
  d.push_back(range_doc(field("elevation_sweep_deg"), kTurntableSweepDeg, t.elevation_sweep_deg));
  d.push_back(range_doc(field("margin"), limits::kFitMargin, t.margin));
  d.push_back(
      bool_doc(schema("TurntableRequest", {"properties", kTurntableDenoise.name}), kTurntableDenoise));
  d.push_back(field_doc({"components", "parameters", "ImageSize", "schema"}, kImageSize));
  const std::string root = "/api/v1/turntables/{id}";
  d.push_back(field_doc(query(root + "/animation.webp", "get", "fps"), kAnimationFps));
  d.push_back({query(root + "/contact-sheet", "get", "format"), eight_bit_format_names(), {}, {}, "png"});
}

}  // namespace

std::vector<DocumentedParameter> documented_parameters() {
  std::vector<Doc> d;
  add_enum_parameters(d);
  add_request_ranges(d);
  add_render_ranges(d);
  add_prefilter_parameters(d);
  add_sun_parameters(d);
  add_projection_parameters(d);
  add_turntable_parameters(d);
  return d;
}

}  // namespace lp::api
