#pragma once
// An enum's names, declared once next to the enum; its name, its parse and the list of allowed names
// all derive from that one table. Declare, in the enum's namespace (found by argument-dependent lookup):
//
//   enum class Split { Median, Variance };
//   constexpr auto enum_entries(Split) {
//     return std::to_array<EnumEntry<Split>>({{Split::Median, "median"}, {Split::Variance, "variance"}});
//   }
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lp {

template <class E>
struct EnumEntry {
  E value;
  const char* name;
};

// The name of `value` ("?" for a value outside the table, e.g. a cast integer).
template <class E>
constexpr const char* enum_name(E value) {
  for (const auto& e : enum_entries(E{}))
    if (e.value == value) return e.name;
  return "?";
}

template <class E>
constexpr std::optional<E> parse_enum(std::string_view name) {
  for (const auto& e : enum_entries(E{}))
    if (std::string_view(e.name) == name) return e.value;
  return std::nullopt;
}

template <class E>
std::vector<std::string> enum_names() {
  std::vector<std::string> out;
  for (const auto& e : enum_entries(E{})) out.emplace_back(e.name);
  return out;
}

// "a, b, c": the allowed names as error messages and help text list them.
template <class E>
std::string enum_names_joined(std::string_view separator = ", ") {
  std::string out;
  for (const auto& e : enum_entries(E{})) {
    if (!out.empty()) out += separator;
    out += e.name;
  }
  return out;
}

}  // namespace lp
