#pragma once
// The `pass` query parameter of a render's image: "color" (the default), one of the auxiliary passes'
// names (render::AuxPass), "denoised": the colour of a render that asked for `denoise`, denoised after
// its last pass, or "all": every pass of the render as the channels of one EXR.
#include <optional>
#include <string>
#include <vector>

#include "api/params.hpp"
#include "engine/render/scene_desc.hpp"

namespace lp::api {

struct RenderImagePass {
  bool all = false;
  std::optional<render::AuxPass> aux;  // the colour when absent (and not all)
  bool denoised = false;               // the colour denoised in its place
};

inline constexpr const char* kColorPassName = "color";
inline constexpr const char* kDenoisedPassName = "denoised";
inline constexpr const char* kAllPassesName = "all";

// The names `pass` takes, in order: color, the auxiliary passes, denoised, all.
std::vector<std::string> render_image_pass_names();
// 400 invalid_parameter for another name.
RenderImagePass parse_render_image_pass(const Query& q);

}  // namespace lp::api
