#include "cli/failure.hpp"

#include <new>

#include "api/api_error.hpp"
#include "api/error_codes.hpp"

namespace lp::cli {
namespace {

Failure with_code(api::ErrorCode code, const std::string& message) {
  const int status = api::http_status(code);
  return {std::string(api::code_name(code)), message,
          status >= 400 && status < 500 ? kExitBadInput : kExitFailure};
}

}  // namespace

Failure failure_of(std::exception_ptr error) {
  try {
    std::rethrow_exception(error);
  } catch (const api::ApiError& e) {
    return with_code(e.code(), e.what());
  } catch (const Error& e) {
    return with_code(api::error_code_for(e.kind()), e.what());
  } catch (const std::bad_alloc&) {
    return with_code(api::ErrorCode::InsufficientMemory, "out of memory");
  } catch (const std::exception& e) {
    return with_code(api::ErrorCode::Internal, e.what());
  } catch (...) {
    return with_code(api::ErrorCode::Internal, "unknown failure");
  }
}

}  // namespace lp::cli
