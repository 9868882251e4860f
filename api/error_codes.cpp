#include "api/error_codes.hpp"

#include <array>

namespace lp::api {
namespace {

using enum ErrorCode;

constexpr std::array kTable = {
    ErrorCodeEntry{InvalidArgument, 400, "invalid_argument", ErrorKind::InvalidArgument},
    ErrorCodeEntry{UnsupportedMediaType, 415, "unsupported_media_type", ErrorKind::Unsupported},
    ErrorCodeEntry{Corrupt, 422, "corrupt", ErrorKind::Corrupt},
    ErrorCodeEntry{InvalidImageData, 422, "invalid_image_data", ErrorKind::InvalidData},
    ErrorCodeEntry{TooLarge, 413, "too_large", ErrorKind::TooLarge},
    ErrorCodeEntry{NotFound, 404, "not_found", ErrorKind::NotFound},
    ErrorCodeEntry{WriteFailed, 500, "write_failed", ErrorKind::WriteFailed},
    ErrorCodeEntry{Internal, 500, "internal", ErrorKind::Internal},
    ErrorCodeEntry{BadRequest, 400, "bad_request", {}},
    ErrorCodeEntry{InvalidField, 400, "invalid_field", {}},
    ErrorCodeEntry{InvalidJson, 400, "invalid_json", {}},
    ErrorCodeEntry{JsonTooDeep, 400, "json_too_deep", {}},
    ErrorCodeEntry{InvalidPath, 400, "invalid_path", {}},
    ErrorCodeEntry{InvalidModel, 422, "invalid_model", {}},
    ErrorCodeEntry{EmptyBody, 400, "empty_body", {}},
    ErrorCodeEntry{MissingHost, 400, "missing_host", {}},
    ErrorCodeEntry{HostNotAllowed, 403, "host_not_allowed", {}},
    ErrorCodeEntry{Unauthorized, 401, "unauthorized", {}},
    ErrorCodeEntry{OriginNotAllowed, 403, "origin_not_allowed", {}},
    ErrorCodeEntry{MethodNotAllowed, 405, "method_not_allowed", {}},
    ErrorCodeEntry{RequestTimeout, 408, "request_timeout", {}},
    ErrorCodeEntry{PayloadTooLarge, 413, "payload_too_large", {}},
    ErrorCodeEntry{UriTooLong, 414, "uri_too_long", {}},
    ErrorCodeEntry{HeaderTooLarge, 431, "header_too_large", {}},
    ErrorCodeEntry{NotImplemented, 501, "not_implemented", {}},
    ErrorCodeEntry{HttpVersionNotSupported, 505, "http_version_not_supported", {}},
    ErrorCodeEntry{Conflict, 409, "conflict", {}},
    ErrorCodeEntry{NoImageYet, 409, "no_image_yet", {}},
    ErrorCodeEntry{PassNotRendered, 409, "pass_not_rendered", {}},
    ErrorCodeEntry{NotInterrupted, 409, "not_interrupted", {}},
    ErrorCodeEntry{CannotResume, 409, "cannot_resume", {}},
    ErrorCodeEntry{EnvmapMissing, 409, "envmap_missing", {}},
    ErrorCodeEntry{EnvmapChanged, 409, "envmap_changed", {}},
    ErrorCodeEntry{ModelChanged, 409, "model_changed", {}},
    ErrorCodeEntry{WorkerOnly, 409, "worker_only", {}},
    ErrorCodeEntry{TooManyJobs, 429, "too_many_jobs", {}},
    ErrorCodeEntry{QueueFull, 503, "queue_full", {}},
    ErrorCodeEntry{TooManyStreams, 503, "too_many_streams", {}},
    ErrorCodeEntry{TooManyConnections, 503, "too_many_connections", {}},
    ErrorCodeEntry{ShuttingDown, 503, "shutting_down", {}},
    ErrorCodeEntry{NotReady, 503, "not_ready", {}},
    ErrorCodeEntry{MemoryBusy, 503, "memory_busy", {}},
    ErrorCodeEntry{DenoiserUnavailable, 503, "denoiser_unavailable", {}},
    ErrorCodeEntry{InsufficientMemory, 507, "insufficient_memory", {}},
    ErrorCodeEntry{InsufficientStorage, 507, "insufficient_storage", {}},
};

constexpr bool in_enum_order() {
  for (size_t i = 0; i < kTable.size(); ++i)
    if (size_t(kTable[i].code) != i) return false;
  return kTable.back().code == InsufficientStorage;
}
static_assert(in_enum_order(), "one row per ErrorCode, in the enum's order");

}  // namespace

std::span<const ErrorCodeEntry> error_code_table() {
  return kTable;
}

int http_status(ErrorCode code) {
  return kTable[size_t(code)].status;
}

std::string_view code_name(ErrorCode code) {
  return kTable[size_t(code)].name;
}

ErrorCode error_code_for(ErrorKind kind) {
  for (const auto& entry : kTable)
    if (entry.kind == kind) return entry.code;
  return Internal;
}

}  // namespace lp::api
