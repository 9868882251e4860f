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

inline int64_t running_render_bytes(int64_t width, int64_t height, int64_t triangles) {
  return render::Film::memory_bytes(width, height) + 2 * EnvMap::image_bytes(width, height) +
         encode_bytes(ImageFormat::Exr, width, height) + render::mesh_memory_bytes(triangles);
}

inline MemoryReservation reserve_render(const MemoryBudget& budget, int width, int height,
                                        int64_t triangles) {
  return budget.reserve(running_render_bytes(width, height, triangles), MemoryUse::Transient,
                        "a " + std::to_string(width) + "x" + std::to_string(height) + " render");
}

}  // namespace lp::server
