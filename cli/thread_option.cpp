#include "cli/thread_option.hpp"

#include <fmt/format.h>

#include "api/parameters.hpp"
#include "cli/help.hpp"

namespace lp::cli {

int take_threads(Arguments& args) {
  const auto& t = api::kThreads;
  return int(api::query_int(args.take_query({t.flag}), t.flag, 0, t.range.min, t.range.max));
}

std::string threads_help() {
  const auto& t = api::kThreads;
  return option_line("--threads N", fmt::format("{}, in [{}, {}] (default: {})", t.help, t.range.min,
                                                t.range.max, t.default_text));
}

}  // namespace lp::cli
