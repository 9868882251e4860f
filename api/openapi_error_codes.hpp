#pragma once
// The error codes api/openapi.yaml declares (the enum of #/components/schemas/ErrorCode), in its order.
#include <string>
#include <vector>

namespace lp::api {

std::vector<std::string> documented_error_codes();

}  // namespace lp::api
