#include "cli/arguments.hpp"

#include <algorithm>
#include <map>

#include "api/api_error.hpp"

namespace lp::cli {
namespace {

api::ApiError usage_error(const std::string& message) {
  return api::ApiError(api::ErrorCode::BadRequest, message);
}

// The long name of a one-letter option.
std::string long_name(std::string_view letter) {
  static const std::map<std::string_view, std::string> kLetters = {
      {"o", "output"}, {"q", "quiet"}, {"h", "help"}};
  const auto it = kLetters.find(letter);
  if (it == kLetters.end()) throw usage_error("unknown option '-" + api::excerpt(std::string(letter)) + "'");
  return it->second;
}

// A number, a boolean or an array as JSON reads it, else the text as a string.
api::Json json_value(const std::string& text) {
  api::Json value = api::Json::parse(text, nullptr, false);
  if (value.is_number() || value.is_boolean() || value.is_array()) return value;
  return text;
}

}  // namespace

Arguments::Arguments(std::span<const std::string> args, const std::vector<std::string_view>& switches) {
  const auto is_switch = [&](std::string_view name) {
    return name == "help" || std::find(switches.begin(), switches.end(), name) != switches.end();
  };
  bool only_positional = false;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (only_positional || arg == "-" || !arg.starts_with('-')) {
      positional_.push_back(arg);
      continue;
    }
    if (arg == "--") {
      only_positional = true;
      continue;
    }
    std::string name = arg.starts_with("--") ? arg.substr(2) : long_name(std::string_view(arg).substr(1));
    std::optional<std::string> value;
    if (const size_t eq = name.find('='); arg.starts_with("--") && eq != std::string::npos) {
      value = name.substr(eq + 1);
      name.resize(eq);
    }
    if (name.empty()) throw usage_error("an option needs a name: '" + api::excerpt(arg) + "'");
    if (is_switch(name)) {
      if (value) throw usage_error("--" + name + " takes no value");
      switches_.push_back(name);
      continue;
    }
    if (!value) {
      if (i + 1 >= args.size()) throw usage_error("--" + api::excerpt(name) + " needs a value");
      value = args[++i];
    }
    if (has(name)) throw usage_error("--" + api::excerpt(name) + " is given more than once");
    options_.emplace_back(std::move(name), std::move(*value));
  }
}

void Arguments::expect_positional(size_t count, std::string_view synopsis) const {
  if (positional_.size() != count)
    throw usage_error("usage: lightprobe " + std::string(synopsis) + " (see --help)");
}

std::string Arguments::take_required(std::string_view name, std::string_view synopsis) {
  auto value = take(name);
  if (!value) throw usage_error("usage: lightprobe " + std::string(synopsis) + " (see --help)");
  return std::move(*value);
}

bool Arguments::has(std::string_view name) const {
  return std::any_of(options_.begin(), options_.end(), [&](const auto& o) { return o.first == name; });
}

bool Arguments::take_switch(std::string_view name) {
  const auto it = std::remove(switches_.begin(), switches_.end(), name);
  const bool given = it != switches_.end();
  switches_.erase(it, switches_.end());
  return given;
}

std::optional<std::string> Arguments::take(std::string_view name) {
  const auto it =
      std::find_if(options_.begin(), options_.end(), [&](const auto& o) { return o.first == name; });
  if (it == options_.end()) return std::nullopt;
  std::string value = std::move(it->second);
  options_.erase(it);
  return value;
}

api::Query Arguments::take_query(const std::vector<std::string_view>& names) {
  api::Query query;
  for (const std::string_view name : names)
    if (auto value = take(name)) query.emplace(api_name(name), std::move(*value));
  return query;
}

api::Json Arguments::take_json(const std::vector<std::string_view>& names) {
  api::Json fields = api::Json::object();
  for (const std::string_view name : names)
    if (auto value = take(name)) fields[api_name(name)] = json_value(*value);
  return fields;
}

api::Json Arguments::take_rest_as_json() {
  api::Json fields = api::Json::object();
  for (const auto& [name, value] : options_) fields[api_name(name)] = json_value(value);
  options_.clear();
  return fields;
}

api::Query Arguments::take_rest_as_query() {
  api::Query query;
  for (const auto& [name, value] : options_) query.emplace(api_name(name), value);
  options_.clear();
  return query;
}

void Arguments::expect_all_taken(std::string_view command) const {
  if (!options_.empty())
    throw usage_error("unknown option '--" + api::excerpt(options_.front().first) + "' (see lightprobe " +
                      std::string(command) + " --help)");
  if (!switches_.empty())
    throw usage_error("unknown option '--" + switches_.front() + "' (see lightprobe " + std::string(command) +
                      " --help)");
}

std::string Arguments::api_name(std::string_view option) {
  std::string name(option);
  std::replace(name.begin(), name.end(), '-', '_');
  return name;
}

}  // namespace lp::cli
