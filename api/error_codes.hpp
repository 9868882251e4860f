#pragma once
// Every error code the API answers with: its HTTP status and, for the engine's errors, the ErrorKind
// it stands for. Routes, render jobs and the transport all answer from this one table, and
// api/openapi.yaml lists the same codes (a test compares them).
#include <optional>
#include <span>
#include <string_view>

#include "engine/core/error.hpp"

namespace lp::api {

enum class ErrorCode {
  // The engine's errors (lp::ErrorKind).
  InvalidArgument,
  UnsupportedMediaType,
  Corrupt,
  InvalidImageData,
  TooLarge,
  NotFound,
  WriteFailed,
  Internal,
  // Requests.
  BadRequest,
  InvalidField,
  InvalidJson,
  JsonTooDeep,
  InvalidPath,
  InvalidModel,  // an uploaded model that does not load as a render would load it
  EmptyBody,
  MissingHost,
  HostNotAllowed,
  Unauthorized,  // --auth-token-file: no or a wrong bearer token
  OriginNotAllowed,
  MethodNotAllowed,
  RequestTimeout,
  PayloadTooLarge,
  UriTooLong,
  HeaderTooLarge,
  NotImplemented,
  HttpVersionNotSupported,
  // State of maps and render jobs.
  Conflict,
  NoImageYet,
  PassNotRendered,  // an image pass the render's request did not ask for
  NotInterrupted,
  CannotResume,
  EnvmapMissing,
  EnvmapChanged,
  ModelChanged,
  WorkerOnly,  // --role worker: renders work items of other servers, accepts no render of its own
  // Capacity.
  TooManyJobs,  // one client's share of a job queue is taken (--max-prefilters-per-client)
  QueueFull,
  TooManyStreams,
  TooManyConnections,
  ShuttingDown,
  NotReady,  // still loading its maps and state at start
  MemoryBusy,
  DenoiserUnavailable,  // a denoise asked of a server whose denoiser has no weights (--denoise-weights)
  InsufficientMemory,
  InsufficientStorage,
};

struct ErrorCodeEntry {
  ErrorCode code;
  int status;                     // HTTP status of a response with this code
  std::string_view name;          // the "code" of {"error":{"code","message"}} and of a failed job
  std::optional<ErrorKind> kind;  // the engine error this code answers, if any
};

// All codes, in the order of ErrorCode.
std::span<const ErrorCodeEntry> error_code_table();

int http_status(ErrorCode code);
std::string_view code_name(ErrorCode code);
// The code an engine error is answered with, in a response and in a failed job alike.
ErrorCode error_code_for(ErrorKind kind);

}  // namespace lp::api
