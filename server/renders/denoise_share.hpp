#pragma once
// The part of a job's progress that denoising a render's colour takes: a tenth of the whole, in the
// render's own work units, counted after them.
#include <cstdint>

namespace lp::server {

inline int64_t denoise_work(int64_t render_work) {
  return (render_work + 8) / 9;
}

}  // namespace lp::server
