#include "cli/render_fields.hpp"

#include "cli/help.hpp"

namespace lp::cli {
RequestOptions take_request_options(Arguments& args) {
  RequestOptions r;
  if (args.take_switch("ground")) {
    r.objects.objects.push_back({{"type", "ground"}, {"shadow_catcher", true}});
    r.objects.options = "--ground";
  }
  return r;
}

std::string request_options_help() {
  return option_line("--background B",
                     "map (default), transparent (PNG and EXR with alpha), or a linear colour [r,g,b]") +
         option_line("--clamp C", "bound on the radiance of indirect samples (default: none)") +
         option_line("--ground", "add a shadow-catcher ground under the model");
}

}  // namespace lp::cli
