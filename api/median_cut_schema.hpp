#pragma once
// JSON shape of a median cut result (POST /api/v1/envmaps/{id}/median-cut), written directly as text:
// at 65,536 lights a JSON tree took most of a second to build and print.
#include <string>

#include "engine/mediancut/median_cut.hpp"

namespace lp::api {

// {"count","placement","split","luminance","lights":[{"direction","pixel","uv","region","power","energy"}],
//  "power","energy_min","energy_max","elapsed_ms","cached"}; region bounds are half-open [x0, x1) x [y0, y1).
// Numbers are printed in their shortest form that reads back exactly.
std::string median_cut_json(const MedianCutResult& result, double elapsed_ms, bool cached);

}  // namespace lp::api
