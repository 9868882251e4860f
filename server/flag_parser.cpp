#include "server/flag_parser.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>

namespace lp::server {
namespace {

constexpr size_t kHelpWidth = 110;
constexpr size_t kNameColumn = 21;

// A switch's variable: on or off.
bool switch_value(const std::string& flag, const std::string& value) {
  for (const char* on : {"1", "true", "yes"})
    if (value == on) return true;
  for (const char* off : {"0", "false", "no"})
    if (value == off) return false;
  throw std::invalid_argument(
      fmt::format("--{} is a switch: 1, true, yes or 0, false, no, got '{}'", flag, value));
}

// "a, b,c" -> {"a", "b", "c"}: a repeatable flag's variable.
std::vector<std::string> list_items(const std::string& value) {
  std::vector<std::string> items;
  size_t start = 0;
  for (size_t end = 0; end != std::string::npos; start = end + 1) {
    end = value.find(',', start);
    std::string item = value.substr(start, end == std::string::npos ? end : end - start);
    item.erase(0, item.find_first_not_of(" \t"));
    item.erase(item.find_last_not_of(" \t") + 1);
    if (!item.empty()) items.push_back(std::move(item));
  }
  return items;
}

void set_from_environment(const Flag& flag, const Environment& environment) {
  const std::string name = environment_variable(flag.name);
  const auto value = environment(name);
  if (!value || value->empty()) return;
  try {
    if (flag.value.empty()) {
      if (switch_value(flag.name, *value)) flag.set("");
    } else if (flag.repeatable) {
      for (const std::string& item : list_items(*value)) flag.set(item);
    } else {
      flag.set(*value);
    }
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(fmt::format("{} (from {})", e.what(), name));
  }
}

template <class T>
const T* find_by(const std::vector<T>& all, const auto& matches) {
  const auto it = std::find_if(all.begin(), all.end(), matches);
  return it == all.end() ? nullptr : &*it;
}

}  // namespace

std::string Flag::usage() const {
  return value.empty() ? fmt::format("--{}", name) : fmt::format("--{} {}", name, value);
}

Environment process_environment() {
  return [](const std::string& name) -> std::optional<std::string> {
    const char* value = std::getenv(name.c_str());
    return value ? std::optional<std::string>(value) : std::nullopt;
  };
}

std::string environment_variable(std::string_view flag) {
  std::string name = "LIGHTPROBE_";
  for (const char c : flag) name += c == '-' ? '_' : char(std::toupper(static_cast<unsigned char>(c)));
  return name;
}

bool parse_command_line(int argc, char** argv, const std::vector<Flag>& flags,
                        const std::vector<Action>& actions, const Environment& environment) {
  std::vector<std::pair<const Flag*, std::string>> given;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const Action* action = find_by(actions, [&](const Action& a) {
      return std::find(a.args.begin(), a.args.end(), arg) != a.args.end();
    });
    const Flag* flag = action ? nullptr : find_by(flags, [&](const Flag& f) { return arg == "--" + f.name; });
    if (!action && !flag) throw std::invalid_argument("unknown option '" + arg + "' (see --help)");
    const bool takes_value = action ? action->takes_value : !flag->value.empty();
    if (takes_value && i + 1 >= argc) throw std::invalid_argument(arg + " needs a value");
    const std::string value = takes_value ? argv[++i] : "";
    if (!action)
      given.emplace_back(flag, value);
    else if (!action->run(value))
      return false;
  }
  for (const Flag& f : flags)
    if (std::none_of(given.begin(), given.end(), [&](const auto& g) { return g.first == &f; }))
      set_from_environment(f, environment);
  for (const auto& [flag, value] : given) flag->set(value);
  return true;
}

int64_t parse_integer_flag(std::string_view flag, const std::string& value, Range<int64_t> range) {
  try {
    size_t used = 0;
    const long long v = std::stoll(value, &used);
    if (used == value.size() && range.contains(v)) return v;
  } catch (const std::exception&) {
  }
  throw std::invalid_argument(
      fmt::format("--{} takes an integer in [{}, {}], got '{}'", flag, range.min, range.max, value));
}

std::string help_entry(const std::string& usage, const std::string& help) {
  const std::string indent(2 + kNameColumn + 2, ' ');
  std::string out;
  size_t start = 0;
  for (size_t end = 0; end != std::string::npos; start = end + 1) {
    end = help.find('\n', start);
    const std::string line = help.substr(start, end == std::string::npos ? end : end - start);
    if (start > 0)
      out += indent + line + "\n";
    else if (usage.size() > kNameColumn)
      out += fmt::format("  {}\n{}{}\n", usage, indent, line);
    else
      out += fmt::format("  {:{}}  {}\n", usage, kNameColumn, line);
  }
  return out;
}

std::string environment_list(const std::vector<Flag>& flags) {
  std::string out;
  size_t column = 0;
  for (const Flag& f : flags) {
    const std::string name = environment_variable(f.name);
    if (column > 0 && column + 1 + name.size() > kHelpWidth) {
      out += '\n';
      column = 0;
    }
    out += column == 0 ? "  " : " ";
    out += name;
    column += (column == 0 ? 2 : 1) + name.size();
  }
  return out + '\n';
}

}  // namespace lp::server
