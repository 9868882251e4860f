#pragma once
// Every externally visible numeric parameter of the API and the server, declared once: name, default,
// range, help text and the layer that owns it. The server's flags and --help, the request parsers and
// their messages, the job configuration and the OpenAPI check derive from these declarations; the
// ranges the engine owns come from engine/core/limits.hpp.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "api/error_codes.hpp"
#include "engine/core/limits.hpp"

namespace lp::api {

enum class Owner { Engine, Api, Server };

// An integer setting of the server, given as --FLAG N.
struct IntParameter {
  const char* flag;      // without the dashes: "max-render-width"
  int64_t fallback;      // the default
  Range<int64_t> range;  // the values the flag accepts
  const char* help;
  Owner owner;
  const char* default_text = nullptr;   // --help shows this instead of `fallback` (a computed default)
  std::optional<ErrorCode> exceeded{};  // the answer to a request over this limit, if a 4xx
};

// Limits on requests (the request parsers enforce them).
inline constexpr IntParameter kMaxPixels{"max-pixels",          limits::kDefaultMaxImagePixels,
                                         {1, int64_t{1} << 34}, "largest map in pixels",
                                         Owner::Engine,         nullptr,
                                         ErrorCode::TooLarge};
inline constexpr IntParameter kMaxSamples{
    "max-samples", 10'000'000, {1, int64_t{1} << 32},  "most samples per request",
    Owner::Api,    nullptr,    ErrorCode::InvalidField};
inline constexpr IntParameter kMaxLights{
    "max-lights", 65536,   {1, int64_t{1} << 24},  "most median-cut lights per request",
    Owner::Api,   nullptr, ErrorCode::InvalidField};
inline constexpr IntParameter kMaxRenderWidth{"max-render-width",        4096,       {1, 65536},
                                              "widest render in pixels", Owner::Api, nullptr,
                                              ErrorCode::InvalidField};
inline constexpr IntParameter kMaxRenderHeight{"max-render-height",        4096,       {1, 65536},
                                               "tallest render in pixels", Owner::Api, nullptr,
                                               ErrorCode::InvalidField};
inline constexpr IntParameter kMaxRenderSpp{
    "max-render-spp", 65536,   {1, 1 << 24},           "most samples per pixel of a render",
    Owner::Api,       nullptr, ErrorCode::InvalidField};
inline constexpr IntParameter kMaxRenderDepth{
    "max-render-depth", 64,      limits::kMaxDepth,      "largest max_depth (path bounces) of a render",
    Owner::Api,         nullptr, ErrorCode::InvalidField};
inline constexpr IntParameter kMaxRenderObjects{
    "max-render-objects", 256,     {0, 1 << 20},           "most objects in a render's scene",
    Owner::Api,           nullptr, ErrorCode::InvalidField};
inline constexpr IntParameter kMaxMeshTriangles{
    "max-mesh-triangles",   limits::kDefaultMaxMeshTriangles,
    {1, int64_t{1} << 32},  "most triangles in one mesh of a render",
    Owner::Engine,          nullptr,
    ErrorCode::InvalidField};
inline constexpr IntParameter kMaxTexturePixels{
    "max-texture-pixels",   limits::kDefaultMaxTexturePixels,
    {1, int64_t{1} << 34},  "most pixels in one texture of a model a render names",
    Owner::Engine,          nullptr,
    ErrorCode::InvalidField};
inline constexpr IntParameter kMaxModelTexturePixels{"max-model-texture-pixels",
                                                     limits::kDefaultMaxModelTexturePixels,
                                                     {1, int64_t{1} << 34},
                                                     "most pixels in all the textures of one model together",
                                                     Owner::Engine,
                                                     nullptr,
                                                     ErrorCode::InvalidField};

// Resources of the server.
inline constexpr IntParameter kPort{
    "port", 8080, {0, 65535}, "port (0 picks a free port, printed on start)", Owner::Server};
inline constexpr IntParameter kThreads{"threads",     0,          {1, 1024}, "worker threads for computation",
                                       Owner::Server, "all cores"};
inline constexpr IntParameter kMaxUploadMb{
    "max-upload-mb",           512, {1, 1 << 20}, "largest request body in MiB", Owner::Server, nullptr,
    ErrorCode::PayloadTooLarge};
inline constexpr IntParameter kMaxEnvmaps{
    "max-envmaps", 64, {1, 100000}, "most maps held at once", Owner::Server};
inline constexpr IntParameter kMaxAssets{
    "max-assets", 64, {1, 100000}, "most model assets stored at once", Owner::Server, nullptr, std::nullopt};
inline constexpr IntParameter kMaxAssetMb{
    "max-asset-mb", 128,     {1, 1 << 20},       "largest model asset in MiB, as uploaded and as unpacked",
    Owner::Server,  nullptr, ErrorCode::TooLarge};
inline constexpr IntParameter kMaxAssetFiles{
    "max-asset-files", 1000,    {1, 1 << 20},       "most members (files and folders) in an asset's archive",
    Owner::Server,     nullptr, ErrorCode::TooLarge};
inline constexpr IntParameter kMaxMemoryMb{
    "max-memory-mb",
    0,
    {1, int64_t{1} << 30},
    "MiB for maps, their sampling tables and caches, images in flight and render results; past it, caches "
    "are evicted, then requests get 503 or 507",
    Owner::Server,
    "half the machine's memory, or of its cgroup limit"};
inline constexpr IntParameter kMaxRunningJobs{
    "max-running-jobs", 2, {1, 256}, "renders running at once, each in its own thread arena", Owner::Server};
inline constexpr IntParameter kMaxQueuedJobs{
    "max-queued-jobs", 16, {0, 1 << 20}, "renders waiting to run; a full queue answers 503", Owner::Server};
inline constexpr IntParameter kMaxFinishedJobs{"max-finished-jobs",
                                               64,
                                               {1, 1 << 20},
                                               "finished renders kept with their images, oldest dropped",
                                               Owner::Server};
inline constexpr IntParameter kMaxFinishedMb{"max-finished-mb",
                                             1024,
                                             {1, 1 << 24},
                                             "MiB of images kept by finished renders, oldest dropped",
                                             Owner::Server};
inline constexpr IntParameter kMaxEventStreams{
    "max-event-streams", 8, {0, 4096}, "concurrent render event streams", Owner::Server};
inline constexpr IntParameter kMaxConnections{"max-connections",
                                              1024,
                                              {1, 1 << 20},
                                              "open connections at once; more are refused with 503",
                                              Owner::Server};
inline constexpr IntParameter kMaxConnectionsPerClient{
    "max-connections-per-client",
    512,
    {1, 1 << 20},
    "open connections from one client address; more are refused with 503",
    Owner::Server};
inline constexpr IntParameter kHeaderTimeoutS{
    "header-timeout-s",
    10,
    {1, 3600},
    "seconds for a request line and its headers to arrive; then 408",
    Owner::Server};
inline constexpr IntParameter kIoTimeoutS{
    "io-timeout-s",
    30,
    {1, 3600},
    "seconds a body read or a response write may wait; then the connection "
    "closes",
    Owner::Server};
inline constexpr IntParameter kKeepAliveTimeoutS{
    "keep-alive-timeout-s", 5, {1, 3600}, "seconds an idle keep-alive connection stays open", Owner::Server};
inline constexpr IntParameter kShutdownGraceS{
    "shutdown-grace-s",
    10,
    {0, 3600},
    "on SIGTERM/SIGINT, seconds running renders get to finish their pass",
    Owner::Server};
inline constexpr IntParameter kAccessLogSample{
    "access-log-sample",
    1,
    {0, int64_t{1} << 40},
    "access log: one line per N requests at info level, 0 for none; a 5xx answer is always logged, at error "
    "level",
    Owner::Server};

// A render split over machines through Redis (--redis).
inline constexpr IntParameter kRedisItemSpp{
    "redis-item-spp",
    16,
    {1, 1 << 24},
    "samples per pixel of one work item of a render split over Redis (a 256x256 preset\nscene: about a "
    "second of one core)",
    Owner::Server};
inline constexpr IntParameter kRedisClaimTimeoutS{
    "redis-claim-timeout-s",
    30,
    {1, 86400},
    "seconds a worker may hold a work item before another worker takes it over (a worker\nthat died)",
    Owner::Server};

// Every integer flag, in --help order.
const std::vector<const IntParameter*>& int_parameters();

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

// Where api/openapi.yaml states a parameter, and what it must state: `location` is a path of keys from
// the document's root; in a list, "name=X" picks the parameter named X and "type=X" the schema whose
// `type` property is the enum [X]. References ($ref, allOf of one $ref) are followed.
struct DocumentedParameter {
  std::vector<std::string> location;
  std::vector<std::string> names;  // enum values (empty for a number)
  std::optional<double> minimum, maximum;
  std::optional<std::string> fallback;  // the default: an enum's name or a number
};
std::vector<DocumentedParameter> documented_parameters();

}  // namespace lp::api
