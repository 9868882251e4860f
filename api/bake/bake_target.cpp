#include "api/bake/bake_target.hpp"

#include <algorithm>
#include <cctype>

#include "api/api_error.hpp"
#include "api/bake/targets.hpp"
#include "api/params.hpp"

namespace lp::api {
namespace {

const std::vector<TargetSpec>& registry() {
  static const std::vector<TargetSpec> specs = {
      gltf_target(),  filament_target(), babylon_target(), three_target(),
      unity_target(), unreal_target(),   godot_target(),
  };
  return specs;
}

}  // namespace

const TargetSpec& target_spec(BakeTarget target) {
  for (const TargetSpec& spec : registry())
    if (spec.target == target) return spec;
  throw invalid_field("target", "'" + std::string(enum_name(target)) + "' is not made by this build; " +
                                    "the targets are: " + available_target_names());
}

std::vector<BakeTarget> available_targets() {
  std::vector<BakeTarget> out;
  for (const auto& e : enum_entries(BakeTarget{}))
    if (std::any_of(registry().begin(), registry().end(),
                    [&](const TargetSpec& s) { return s.target == e.value; }))
      out.push_back(e.value);
  return out;
}

std::string available_target_names() {
  std::vector<std::string> names;
  for (BakeTarget t : available_targets()) names.emplace_back(enum_name(t));
  return names.empty() ? std::string("none") : join(names, ", ");
}

std::string bake_file_stem(const std::string& name) {
  std::string stem = name.empty() ? std::string("map") : name;
  for (char& c : stem)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_' && c != '.') c = '_';
  if (stem.front() == '.') stem.front() = '_';
  return stem;
}

int64_t bake_files_bytes(const std::vector<BakeFile>& files) {
  int64_t total = 0;
  for (const BakeFile& f : files) total += int64_t(f.bytes.size()) + int64_t(f.name.size());
  return total;
}

}  // namespace lp::api
