// lightprobe: the engine from the command line, for scripts and batch work; no server. Every command
// reads its options as the HTTP API reads its parameters (api/), and fails as the API does.
#include <fmt/format.h>

#include <iostream>
#include <string>
#include <vector>

#include "api/api_error.hpp"
#include "api/params.hpp"
#include "cli/command.hpp"
#include "cli/failure.hpp"

namespace lp::cli {
namespace {

const std::vector<Command>& commands() {
  static const std::vector<Command> all = {info_command(),    sample_command(),   median_cut_command(),
                                           fresnel_command(), render_command(),   convert_command(),
                                           sh_command(),      brdf_lut_command(), sun_command(),
                                           bake_command(),    denoise_command()};
  return all;
}

std::string tool_help() {
  std::string out =
      R"(lightprobe: image-based lighting from the command line (the engine of lightprobe-server, no server)

Usage: lightprobe COMMAND [ARGUMENTS] [OPTIONS]

Commands:
)";
  for (const Command& c : commands()) out += fmt::format("  {:12} {}\n", c.name, c.summary);
  out += R"(
MAP is an image file (OpenEXR, PFM or Radiance HDR, told by its bytes) or `default`, the built-in
procedural sky. Options have the API's parameter names, with dashes: --eta-i sets eta_i. Results go to
standard output unless -o FILE. `lightprobe COMMAND --help` lists a command's options.

Failures print `error: CODE: MESSAGE` with the API's error code, and exit with 2 for bad usage or
input, 1 for anything else.
)";
  return out;
}

const Command& find_command(const std::string& name) {
  for (const Command& c : commands())
    if (c.name == name) return c;
  std::vector<std::string> names;
  for (const Command& c : commands()) names.emplace_back(c.name);
  throw api::ApiError(api::ErrorCode::BadRequest, "unknown command '" + api::excerpt(name) +
                                                      "' (expected one of: " + api::join(names, ", ") + ")");
}

int run(const std::vector<std::string>& args) {
  if (args.empty()) {
    std::cerr << tool_help();
    return kExitBadInput;
  }
  if (args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
    std::cout << tool_help();
    return 0;
  }
  if (args[0] == "--version") {
    std::cout << "lightprobe " << LIGHTPROBE_VERSION << "\n";
    return 0;
  }
  const Command& command = find_command(args[0]);
  Arguments arguments(std::span<const std::string>(args).subspan(1), command.switches);
  if (arguments.take_switch("help")) {
    std::cout << "Usage: lightprobe " << command.synopsis << "\n\n" << command.help();
    return 0;
  }
  command.run(arguments);
  return 0;
}

}  // namespace
}  // namespace lp::cli

int main(int argc, char** argv) {
  try {
    return lp::cli::run(std::vector<std::string>(argv + 1, argv + argc));
  } catch (...) {
    const lp::cli::Failure failure = lp::cli::failure_of(std::current_exception());
    std::cerr << "error: " << failure.code << ": " << failure.message << "\n";
    return failure.exit_status;
  }
}
