#pragma once
// The auxiliary passes' channels (scene_desc.hpp, AuxPass) as a film holds them: one camera sample's
// values, summed over a pixel's samples, and the pixel's mean from those sums.
#include <cstdint>
#include <span>

#include "engine/core/vec3.hpp"
#include "engine/image/image.hpp"
#include "engine/render/scene_desc.hpp"

namespace lp::render {

struct PathSample;

inline constexpr int kMaxAuxChannels = 9;

// The values sample `s` adds to the channels of `passes` (passes.channels() of them).
void aux_values(const PathSample& s, const PassSet& passes, float* out);

// Pass p of a pixel from its channel sums (those of the whole set `passes`) over `count` samples: a
// colour, or a grey for alpha and depth (+inf where no sample hit).
Rgb aux_mean(AuxPass p, const PassSet& passes, const double* sums, double count);

// The sums that give `mean` over `count` samples (a render continued from its images); the inverse of
// aux_mean, a depth counting every sample as a hit where it is finite.
void aux_sums(AuxPass p, const PassSet& passes, Rgb mean, double count, double* sums);

// The image of pass p from a film's per-pixel channel sums (`channels` per pixel) and counts.
Image aux_image(AuxPass p, const PassSet& passes, int width, int height, std::span<const double> sums,
                std::span<const uint32_t> counts);

}  // namespace lp::render
