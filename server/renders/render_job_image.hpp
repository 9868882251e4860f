#pragma once
// The pictures of a render so far: the mean colour of its finished passes and of its auxiliary passes,
// and, once a render that asked for it has finished, its colour denoised.
#include <array>
#include <memory>
#include <optional>

#include "engine/image/image.hpp"
#include "engine/render/scene_desc.hpp"

namespace lp::server {

// The means of a render's auxiliary passes (render::AuxPass), by pass; null for those it does not ask for.
using PassImages = std::array<std::shared_ptr<const Image>, 4>;

struct RenderImage {
  std::shared_ptr<const Image> image;     // the mean of the finished passes; nullptr before the first
  int spp_done = 0;                       // samples per pixel in it
  PassImages passes;                      // of the same samples
  std::shared_ptr<const Image> denoised;  // `image` denoised (only once every sample is done); or null
  std::optional<double> denoise_s;        // the seconds the denoise took, with `denoised`

  const Image* pass(render::AuxPass p) const { return passes[size_t(p)].get(); }
};

}  // namespace lp::server
