#pragma once
// The "target" field of a prefilter request (and `lightprobe bake --target`).
#include "api/params.hpp"
#include "api/prefilter_request.hpp"

namespace lp::api {

// Reads `target` from the body; with one, sets request.params to the target's chain (chain_params) and
// refuses (400 invalid_field naming it) a chain field the body gives another value than the target
// makes, `format` (the target writes its own files), and every chain field of a target without a chain.
void apply_bake_target(PrefilterRequest& request, const Json& body);

// Whether the request makes a prefiltered chain: always without a target, with one if it takes a chain.
bool makes_chain(const PrefilterRequest& request);

}  // namespace lp::api
