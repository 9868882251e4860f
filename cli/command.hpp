#pragma once
// A subcommand of the tool: `lightprobe NAME ...`, one per file (command_NAME.cpp).
#include <string>
#include <string_view>
#include <vector>

#include "cli/arguments.hpp"

namespace lp::cli {

struct Command {
  std::string_view name;
  std::string_view synopsis;               // "sample MAP --count N [options]"
  std::string_view summary;                // one line, for `lightprobe --help`
  std::vector<std::string_view> switches;  // options without a value, besides --help
  std::string (*help)();                   // what `lightprobe NAME --help` prints after the synopsis
  void (*run)(Arguments& args);            // throws api::ApiError or lp::Error on failure
};

Command info_command();
Command sample_command();
Command median_cut_command();
Command fresnel_command();
Command render_command();
Command convert_command();
Command sh_command();
Command brdf_lut_command();
Command sun_command();
Command bake_command();
Command denoise_command();

}  // namespace lp::cli
