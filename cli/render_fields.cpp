#include "cli/render_fields.hpp"

#include "cli/help.hpp"

namespace lp::cli {
namespace {

// "albedo,normal" -> ["albedo", "normal"]; a JSON array is taken as it is.
api::Json name_list(const std::string& text) {
  if (text.starts_with('[')) return api::Json::parse(text, nullptr, false);
  api::Json names = api::Json::array();
  for (size_t start = 0; start <= text.size();) {
    const size_t end = std::min(text.find(',', start), text.size());
    names.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  return names;
}

}  // namespace

RequestOptions take_request_options(Arguments& args) {
  RequestOptions r;
  if (auto passes = args.take("passes")) r.fields["passes"] = name_list(*passes);
  if (args.take_switch("ground")) {
    r.objects.objects.push_back({{"type", "ground"}, {"shadow_catcher", true}});
    r.objects.options = "--ground";
  }
  return r;
}

std::string request_options_help() {
  return option_line("--background B", "map (default), transparent, or a linear colour [r,g,b]") +
         option_line("--clamp C", "bound on the radiance of indirect samples (default: none)") +
         option_line("--passes LIST", "albedo,normal,depth,alpha: passes rendered beside the colour") +
         option_line("--ground", "add a shadow-catcher ground under the model");
}

}  // namespace lp::cli
