#pragma once
// Pieces of --help text, so that every command describes its options alike: an option's line, and an
// enum option's choices with the default the API's parser gives.
#include <string>
#include <string_view>

#include "engine/core/enum_table.hpp"

namespace lp::cli {

// "  --count N          TEXT\n", the text in a column of its own (continued lines indented to it).
std::string option_line(std::string_view option, std::string_view text);

// "a, b, c (default b)"
template <class E>
std::string choices(E fallback) {
  return enum_names_joined<E>(", ") + " (default " + enum_name(fallback) + ")";
}

// The lines every command that writes its result has.
std::string output_help();

}  // namespace lp::cli
