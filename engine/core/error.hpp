#pragma once
// One exception type for the engine. `kind` says what went wrong; api/error_codes.hpp gives each kind
// the HTTP status and code a response or a failed render job reports.
#include <stdexcept>
#include <string>

namespace lp {

enum class ErrorKind {
  InvalidArgument,  // a parameter is out of range or malformed
  Unsupported,      // not a format we read
  Corrupt,          // a format we read, but broken or truncated
  InvalidData,      // readable, but the values are unusable (NaN, Inf, negative, all zero)
  TooLarge,         // over a configured limit
  NotFound,         // a file or resource is missing
  WriteFailed,      // a file could not be written
  Internal,         // a failure of our own or of a library (the ray tracing device), not of the input
};

class Error : public std::runtime_error {
 public:
  Error(ErrorKind kind, const std::string& message) : std::runtime_error(message), kind_(kind) {}
  // An invalid parameter: `field` is its path in the structs validated ("ior", "camera.fov_deg").
  Error(ErrorKind kind, std::string field, const std::string& problem)
      : std::runtime_error(field + " " + problem), kind_(kind), field_(std::move(field)), problem_(problem) {}
  ErrorKind kind() const { return kind_; }
  const std::string& field() const { return field_; }      // empty unless a parameter is at fault
  const std::string& problem() const { return problem_; }  // the message without the field

 private:
  ErrorKind kind_;
  std::string field_, problem_;
};

}  // namespace lp
