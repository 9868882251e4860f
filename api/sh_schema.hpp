#pragma once
// The JSON answer of GET /envmaps/{id}/sh: the coefficients with the conventions they follow.
#include <string>

#include "api/sh_request.hpp"

namespace lp::api {

std::string sh_json(const ShCoefficients& full, const ShRequest& request, double elapsed_ms, bool cached);

}  // namespace lp::api
