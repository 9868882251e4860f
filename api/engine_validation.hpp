#pragma once
// Engine parameter structs validate themselves (engine/core/validate.hpp); here an invalid parameter
// becomes the API's 400 naming the same field path.
#include "api/api_error.hpp"
#include "engine/core/error.hpp"

namespace lp::api {

template <class Validate>
void as_invalid_field(Validate&& validate) {
  try {
    validate();
  } catch (const Error& e) {
    if (e.field().empty()) throw;
    throw invalid_field(e.field(), e.problem());
  }
}

}  // namespace lp::api
