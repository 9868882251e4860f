#pragma once
// Memory a render takes from the budget: while it runs, the film, the image published after each pass
// (the previous one lives on while the next is made), the checkpoint's encoding and its meshes; once
// it ends, the image it keeps (RenderJob::retained_bytes).
#include <cstdint>

#include "engine/core/memory_budget.hpp"
#include "engine/envmap/envmap.hpp"
#include "engine/image/encode_memory.hpp"
#include "engine/render/embree_scene.hpp"
#include "engine/render/film.hpp"

namespace lp::server {

// The images a render publishes: its colour and each auxiliary pass it asks for.
inline int64_t rendered_image_bytes(const render::RenderSettings& s) {
  return int64_t(1 + s.passes.list().size()) * EnvMap::image_bytes(s.width, s.height);
}

inline int64_t running_render_bytes(const render::RenderSettings& s, int64_t triangles) {
  const int64_t images = int64_t(1 + s.passes.list().size());
  return render::Film::memory_bytes(s.width, s.height, s.passes) + 2 * rendered_image_bytes(s) +
         images * encode_bytes(ImageFormat::Exr, s.width, s.height) + render::mesh_memory_bytes(triangles);
}

inline MemoryReservation reserve_render(const MemoryBudget& budget, const render::RenderSettings& s,
                                        int64_t triangles) {
  return budget.reserve(running_render_bytes(s, triangles), MemoryUse::Transient,
                        "a " + std::to_string(s.width) + "x" + std::to_string(s.height) + " render");
}

}  // namespace lp::server
