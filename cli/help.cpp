#include "cli/help.hpp"

#include <fmt/format.h>

namespace lp::cli {
namespace {

constexpr size_t kOptionColumn = 22;

}  // namespace

std::string option_line(std::string_view option, std::string_view text) {
  std::string out = fmt::format("  {:{}}", option, kOptionColumn - 2);
  if (option.size() + 2 >= kOptionColumn) out += "\n" + std::string(kOptionColumn, ' ');
  for (size_t start = 0; start <= text.size();) {
    const size_t end = std::min(text.find('\n', start), text.size());
    if (start > 0) out += std::string(kOptionColumn, ' ');
    out += fmt::format("{}\n", text.substr(start, end - start));
    start = end + 1;
  }
  return out;
}

std::string output_help() {
  return option_line("-o, --output FILE", "write to FILE instead of standard output (- for standard output)");
}

}  // namespace lp::cli
