#pragma once
// The render options that are no plain top-level field of the request: --ground, a shadow-catcher ground
// object added to the scene, placed under the bounded objects; --denoise and --no-denoise, the request's
// `denoise` as a switch either way (its default is the request's: off for a render, on for a turntable).
#include <string>

#include "cli/arguments.hpp"
#include "cli/scene_file.hpp"

namespace lp::cli {

struct RequestOptions {
  api::Json fields = api::Json::object();  // top-level fields of the request
  ExtraObjects objects;                    // scene objects to add
};

RequestOptions take_request_options(Arguments& args);

// The switches take_request_options takes, for the command's list of switches.
inline constexpr std::string_view kGroundSwitch = "ground", kDenoiseSwitch = "denoise",
                                  kNoDenoiseSwitch = "no-denoise";

// The help lines of the request fields the render command documents by name beyond the settings.
std::string request_options_help();

}  // namespace lp::cli
