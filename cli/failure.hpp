#pragma once
// What a failed command reports: `error: CODE: MESSAGE` on standard error, with the code the API answers
// the same failure with, and its exit status: 2 where the API answers 4xx (bad usage or input), 1 for
// anything else (a file that cannot be written, too little memory, a bug).
#include <exception>
#include <string>

namespace lp::cli {

inline constexpr int kExitFailure = 1;
inline constexpr int kExitBadInput = 2;

struct Failure {
  std::string code, message;
  int exit_status = kExitFailure;
};

// The failure `error` (an api::ApiError, an lp::Error or any other exception) stands for.
Failure failure_of(std::exception_ptr error);

}  // namespace lp::cli
