#pragma once
// Names of the resources clients create (maps, model assets): ids in URLs and file names in the state
// directory, so a short safe alphabet that cannot name a parent or hidden file.
#include <string>
#include <string_view>

namespace lp::server {

// 1-64 characters of [A-Za-z0-9._-], not starting with '.'.
bool valid_resource_name(const std::string& name);

// The rule, as a refusal states it.
inline constexpr std::string_view kResourceNameRule =
    "must be 1-64 characters of A-Z a-z 0-9 . _ - and not start with '.'";

}  // namespace lp::server
