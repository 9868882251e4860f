#pragma once
#include <string_view>

namespace lp::api {
// api/openapi.yaml, embedded at build time so the server does not read it from disk.
std::string_view openapi_document();
}  // namespace lp::api
