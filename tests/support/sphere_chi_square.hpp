#pragma once
// Chi-square test of a sampler of directions against its solid-angle density over the whole sphere.
// Cells are uniform in theta and phi (small about the poles, where the lobes of normal incidence sit),
// and each cell's expected count is the density integrated adaptively (Simpson's rule, refined where
// the estimate is unsure), so that lobes narrower than a cell are counted accurately. A last cell holds
// the samples the sampler refuses; it expects the mass the density lacks.
#include <cstdint>
#include <functional>
#include <optional>

#include "engine/core/rng.hpp"
#include "engine/core/vec3.hpp"
#include "support/chi_square.hpp"

namespace lp::test {

// One sample: a direction, or nullopt for none. It draws its random numbers from the generator.
using DirectionSampler = std::function<std::optional<Vec3>(Rng&)>;
using DirectionPdf = std::function<float(Vec3)>;

ChiSquareResult sphere_chi_square(const DirectionSampler& sample, const DirectionPdf& pdf, int samples,
                                  uint64_t seed);

}  // namespace lp::test
