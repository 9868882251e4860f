#pragma once
// Every externally visible parameter of requests, declared once: name, default, range, help text. The
// request limits are also flags of the server (server/options.cpp lists them with its own, which its
// subsystems declare); the request parsers and their messages, the flags and --help, and the OpenAPI
// check derive from these declarations; the ranges the engine owns come from engine/core/limits.hpp.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "api/error_codes.hpp"
#include "engine/core/limits.hpp"
#include "engine/image/image_io.hpp"

namespace lp::api {

// An integer setting of the server, given as --FLAG N or its environment variable.
struct IntParameter {
  const char* flag;      // without the dashes: "max-render-width"
  int64_t fallback;      // the default
  Range<int64_t> range;  // the values the flag accepts
  const char* help;
  const char* default_text = nullptr;   // --help shows this instead of `fallback` (a computed default)
  std::optional<ErrorCode> exceeded{};  // the answer to a request over this limit, if a 4xx
};

// Limits on requests (the request parsers enforce them).
inline constexpr IntParameter kMaxPixels{"max-pixels",
                                         limits::kDefaultMaxImagePixels,
                                         {1, int64_t{1} << 34},
                                         "largest map in pixels",
                                         nullptr,
                                         ErrorCode::TooLarge};
inline constexpr IntParameter kMaxSamples{
    "max-samples",          10'000'000, {1, int64_t{1} << 32}, "most samples per request", nullptr,
    ErrorCode::InvalidField};
inline constexpr IntParameter kMaxLights{
    "max-lights",           65536, {1, int64_t{1} << 24}, "most median-cut lights per request", nullptr,
    ErrorCode::InvalidField};
inline constexpr IntParameter kMaxRenderWidth{"max-render-width",        4096,    {1, 65536},
                                              "widest render in pixels", nullptr, ErrorCode::InvalidField};
inline constexpr IntParameter kMaxRenderHeight{"max-render-height",        4096,    {1, 65536},
                                               "tallest render in pixels", nullptr, ErrorCode::InvalidField};
inline constexpr IntParameter kMaxRenderSpp{"max-render-spp", 65536,
                                            {1, 1 << 24},     "most samples per pixel of a render",
                                            nullptr,          ErrorCode::InvalidField};
inline constexpr IntParameter kMaxRenderDepth{
    "max-render-depth",     64, limits::kMaxDepth, "largest max_depth (path bounces) of a render", nullptr,
    ErrorCode::InvalidField};
inline constexpr IntParameter kMaxRenderObjects{
    "max-render-objects",   256, {0, 1 << 20}, "most objects in a render's scene", nullptr,
    ErrorCode::InvalidField};
inline constexpr IntParameter kMaxMeshTriangles{"max-mesh-triangles",
                                                limits::kDefaultMaxMeshTriangles,
                                                {1, int64_t{1} << 32},
                                                "most triangles in one mesh of a render",
                                                nullptr,
                                                ErrorCode::InvalidField};
inline constexpr IntParameter kMaxTexturePixels{"max-texture-pixels",
                                                limits::kDefaultMaxTexturePixels,
                                                {1, int64_t{1} << 34},
                                                "most pixels in one texture of a model a render names",
                                                nullptr,
                                                ErrorCode::InvalidField};
inline constexpr IntParameter kMaxModelTexturePixels{"max-model-texture-pixels",
                                                     limits::kDefaultMaxModelTexturePixels,
                                                     {1, int64_t{1} << 34},
                                                     "most pixels in all the textures of one model together",
                                                     nullptr,
                                                     ErrorCode::InvalidField};

// The threads computation may use: the server's and the command-line tool's --threads.
inline constexpr IntParameter kThreads{
    "threads", 0, {1, 1024}, "worker threads for computation", "all cores"};

// The request limits as one value: the server sets them from its flags, the request parsers read them.
struct RequestLimits {
  int64_t max_pixels = kMaxPixels.fallback;
  int64_t max_samples = kMaxSamples.fallback;
  int64_t max_lights = kMaxLights.fallback;
  int64_t max_render_width = kMaxRenderWidth.fallback;
  int64_t max_render_height = kMaxRenderHeight.fallback;
  int64_t max_render_spp = kMaxRenderSpp.fallback;
  int64_t max_render_depth = kMaxRenderDepth.fallback;
  int64_t max_render_objects = kMaxRenderObjects.fallback;
  int64_t max_mesh_triangles = kMaxMeshTriangles.fallback;
  int64_t max_texture_pixels = kMaxTexturePixels.fallback;
  int64_t max_model_texture_pixels = kMaxModelTexturePixels.fallback;
};

// A numeric field of a request body or query, the range it may take before a server limit caps it.
struct NumberField {
  const char* name;
  std::optional<double> fallback;
  Range<double> range;
};

inline constexpr int64_t kMaxSeed = int64_t{1} << 53;  // every seed is exact in a JSON number
inline constexpr NumberField kSampleCount{"count", std::nullopt, {1, double(kMaxSamples.range.max)}};
inline constexpr NumberField kSampleImageCount{"count", 256, {1, double(kMaxSamples.range.max)}};
inline constexpr NumberField kSampleSeed{"seed", 0, {0, double(kMaxSeed)}};
inline constexpr NumberField kLightCount{"count", 64, {1, double(kMaxLights.range.max)}};
inline constexpr NumberField kExposure{"exposure", 0, {-64, 64}};
inline constexpr NumberField kGamma{"gamma", std::nullopt, {0, 10}};  // 0 itself excluded: > 0
inline constexpr NumberField kFresnelStep{"step", 1, limits::kFresnelStepDeg};

// An enumerated field of a request body or query, and its default (the names are the enum's table).
template <class E>
struct EnumField {
  const char* name;
  E fallback;
};
// The tone curve of 8-bit pictures: `standard` unless the picture is a render's, whose default is its
// request's `tone_mapping`, itself `neutral` when absent.
inline constexpr EnumField<ToneCurve> kToneMapping{"tone_mapping", ToneCurve::Standard};
inline constexpr EnumField<ToneCurve> kRenderToneMapping{"tone_mapping", ToneCurve::Neutral};

// A boolean field of a request body, and its default.
struct BoolField {
  const char* name;
  bool fallback;
};
// A render's colour denoised after its last pass (which then also computes the albedo and normal passes):
// off for renders, whose raw colour stays the result one measures error on; on for turntables' frames and
// for `lightprobe render MODEL`, the one-command thumbnail of a model file.
inline constexpr BoolField kRenderDenoise{"denoise", false};
inline constexpr BoolField kTurntableDenoise{"denoise", true};
inline constexpr BoolField kThumbnailDenoise{"denoise", true};

// Where api/openapi.yaml states a parameter, and what it must state: `location` is a path of keys from
// the document's root; in a list, "name=X" picks the parameter named X and "type=X" the schema whose
// `type` property is the enum [X]. References ($ref, allOf of one $ref) are followed.
struct DocumentedParameter {
  std::vector<std::string> location;
  std::vector<std::string> names;  // enum values (empty for a number)
  std::optional<double> minimum, maximum;
  std::optional<std::string> fallback;  // the default: an enum's name, a number, or true / false
};
std::vector<DocumentedParameter> documented_parameters();

}  // namespace lp::api
