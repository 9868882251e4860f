#include "api/render_image_pass.hpp"

namespace lp::api {

std::vector<std::string> render_image_pass_names() {
  std::vector<std::string> names{kColorPassName};
  for (const std::string& name : enum_names<render::AuxPass>()) names.push_back(name);
  names.emplace_back(kDenoisedPassName);
  names.emplace_back(kAllPassesName);
  return names;
}

RenderImagePass parse_render_image_pass(const Query& q) {
  const std::string name = query_enum(q, "pass", kColorPassName, render_image_pass_names());
  if (name == kAllPassesName) return {true, std::nullopt};
  if (name == kDenoisedPassName) return {false, std::nullopt, true};
  return {false, parse_enum<render::AuxPass>(name)};
}

}  // namespace lp::api
