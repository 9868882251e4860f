#pragma once
// Memory a render takes from the budget: while it runs, the film, the image published after each pass
// (the previous one lives on while the next is made), the checkpoint's encoding, its meshes and, for a
// denoised render, the denoiser's working memory; once it ends, the images it keeps
// (RenderJob::retained_bytes).
#include <cstdint>

#include "engine/core/memory_budget.hpp"
#include "engine/denoise/denoiser.hpp"
#include "engine/envmap/envmap.hpp"
#include "engine/image/encode_memory.hpp"
#include "engine/render/embree_scene.hpp"
#include "engine/render/film.hpp"

namespace lp::server {

// The images a render publishes: its colour, each auxiliary pass it asks for and its denoised colour.
inline int64_t rendered_image_bytes(const render::RenderSettings& s, bool denoise) {
  return int64_t(1 + s.passes.list().size() + (denoise ? 1 : 0)) * EnvMap::image_bytes(s.width, s.height);
}

// What denoising a render's colour takes beyond its images.
inline int64_t denoise_bytes(const render::RenderSettings& s, bool denoise) {
  return denoise ? denoise::Denoiser::working_bytes(s.width, s.height) : 0;
}

inline int64_t running_render_bytes(const render::RenderSettings& s, int64_t triangles, bool denoise) {
  const int64_t images = int64_t(1 + s.passes.list().size() + (denoise ? 1 : 0));
  return render::Film::memory_bytes(s.width, s.height, s.passes) + 2 * rendered_image_bytes(s, denoise) +
         images * encode_bytes(ImageFormat::Exr, s.width, s.height) + render::mesh_memory_bytes(triangles) +
         denoise_bytes(s, denoise);
}

inline MemoryReservation reserve_render(const MemoryBudget& budget, const render::RenderSettings& s,
                                        int64_t triangles, bool denoise) {
  return budget.reserve(running_render_bytes(s, triangles, denoise), MemoryUse::Transient,
                        "a " + std::to_string(s.width) + "x" + std::to_string(s.height) + " render");
}

}  // namespace lp::server
