#pragma once
// The generic part of a command line: flags that set a value or switch something on, each also settable
// by an environment variable (LIGHTPROBE_ and its name in upper case), actions that run instead of the
// program (--help), and the help text's layout. What the flags are and what they set: options.hpp.
#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "engine/core/enum_table.hpp"
#include "engine/core/limits.hpp"

namespace lp::server {

struct Flag {
  std::string name;         // without the dashes
  std::string value;        // what it takes, as --help shows it ("ADDR"); empty for a switch
  std::string help;         // a line break starts a line under the first
  bool repeatable = false;  // every use adds a value
  std::function<void(const std::string&)> set;  // a switch's value is "" (it is only set when on)

  std::string usage() const;  // "--name VALUE"
};

// A flag of the command line only (no variable) that runs instead of the program or before it. `run`
// gets the flag's value (empty if it takes none) and returns false to end the program at once, exit 0.
struct Action {
  std::vector<std::string> args;  // as written: {"--help", "-h"}
  bool takes_value = false;
  std::function<bool(const std::string&)> run;
};

// The value of an environment variable, nullopt when it is unset.
using Environment = std::function<std::optional<std::string>(const std::string& name)>;
Environment process_environment();

// The variable that sets a flag: "max-pixels" -> "LIGHTPROBE_MAX_PIXELS".
std::string environment_variable(std::string_view flag);

// Runs the actions and sets the flags given in argv, in their order, then sets each flag not on the
// command line from its variable in `environment` (an empty variable counts as unset). False if an
// action ended the program. Throws std::invalid_argument with a message for an unknown flag, a
// missing value or a bad value (the variable's name added when it came from one).
bool parse_command_line(int argc, char** argv, const std::vector<Flag>& flags,
                        const std::vector<Action>& actions, const Environment& environment);

// An integer flag's value within `range`; throws std::invalid_argument naming --flag.
int64_t parse_integer_flag(std::string_view flag, const std::string& value, Range<int64_t> range);

// An enum flag's value, by the names of its enum_entries; throws std::invalid_argument naming --flag.
template <class E>
E parse_enum_flag(std::string_view flag, const std::string& value) {
  const auto parsed = parse_enum<E>(value);
  if (!parsed)
    throw std::invalid_argument("--" + std::string(flag) + " takes one of " + enum_names_joined<E>("|") +
                                ", got '" + value + "'");
  return *parsed;
}

// Help text: "  --name VALUE           first line of help" and its further lines under the first.
std::string help_entry(const std::string& usage, const std::string& help);
// The flags' variables, as many on a line as fit in the help's width.
std::string environment_list(const std::vector<Flag>& flags);

}  // namespace lp::server
