#pragma once
// Before an OpenEXR reader allocates the pixels a header claims, check that the file holds them: every
// chunk of the first part's offset table lies inside the file, and the chunks' compressed bytes are
// enough to expand to the claimed pixels at the best ratio the compression can reach.
#include <cstdint>
#include <span>

namespace lp {

// Throws lp::Error(Corrupt) when the file cannot hold the pixels of its data window.
void check_exr_capacity(std::span<const uint8_t> bytes);

}  // namespace lp
