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
  ErrorKind kind() const { return kind_; }

 private:
  ErrorKind kind_;
};

}  // namespace lp
