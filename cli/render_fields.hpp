#pragma once
// The render option that is no plain top-level field of the request: --ground, a shadow-catcher ground
// object added to the scene, placed under the bounded objects.
#include <string>

#include "cli/arguments.hpp"
#include "cli/scene_file.hpp"

namespace lp::cli {

struct RequestOptions {
  api::Json fields = api::Json::object();  // top-level fields of the request
  ExtraObjects objects;                    // scene objects to add
};

RequestOptions take_request_options(Arguments& args);

// The help lines of the request fields the render command documents by name beyond the settings.
std::string request_options_help();

}  // namespace lp::cli
