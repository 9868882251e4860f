#pragma once
// A command's arguments, read by the same rules for every command: positional arguments; options
// `--name VALUE` or `--name=VALUE`, each at most once (a value may begin with '-', as in --exposure -2);
// the switches a command declares, `--name` alone; `-o`, `-q` and `-h` for --output, --quiet and --help;
// everything after `--` positional. A command takes the options it owns by name and hands the rest to
// the API's parsers under the API's names (dashes become underscores: --eta-i is eta_i), so the names,
// defaults, limits and messages are the API's.
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "api/params.hpp"

namespace lp::cli {

class Arguments {
 public:
  // `switches`: the names (without dashes) that take no value; "help" always is one.
  Arguments(std::span<const std::string> args, const std::vector<std::string_view>& switches);

  const std::vector<std::string>& positional() const { return positional_; }
  // Throws bad_request with the command's synopsis unless there are exactly `count` positional arguments.
  void expect_positional(size_t count, std::string_view synopsis) const;

  bool has(std::string_view name) const;
  // The switch was given (and is now taken).
  bool take_switch(std::string_view name);
  // The option's value, taken out of the arguments; nullopt if it was not given.
  std::optional<std::string> take(std::string_view name);
  // The value of an option the command cannot do without (taken); bad_request with the command's
  // synopsis if it was not given.
  std::string take_required(std::string_view name, std::string_view synopsis);
  // The options named (taken), as an API query.
  api::Query take_query(const std::vector<std::string_view>& names);
  // The options named (taken), as API fields of a JSON object (values read as take_rest_as_json reads them).
  api::Json take_json(const std::vector<std::string_view>& names);
  // An enum option, checked as the API checks an enum parameter.
  template <class E>
  requires std::is_enum_v<E> E take_enum(std::string_view name, E fallback) {
    return api::query_enum(take_query({name}), api_name(name), fallback);
  }

  // Every option not taken, as API fields: as a JSON object, a value that reads as a JSON number, boolean
  // or array becoming one and any other a string; or as a query.
  api::Json take_rest_as_json();
  api::Query take_rest_as_query();
  // Throws bad_request naming the first option no one took.
  void expect_all_taken(std::string_view command) const;

  // The API's name of an option: dashes become underscores.
  static std::string api_name(std::string_view option);

 private:
  std::vector<std::string> positional_;
  std::vector<std::pair<std::string, std::string>> options_;  // in the order given, names without dashes
  std::vector<std::string> switches_;                         // the switches given
};

}  // namespace lp::cli
