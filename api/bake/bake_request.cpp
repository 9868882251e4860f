#include "api/bake/bake_request.hpp"

#include <fmt/format.h>

#include "api/api_error.hpp"

namespace lp::api {
namespace {

// The chain fields of a request, each as the JSON the body gives it.
Json chain_field(const PrefilterParams& p, const std::string& name) {
  if (name == "levels") return p.levels;
  if (name == "base_size") return p.base_size;
  if (name == "samples") return p.samples;
  if (name == "projection") return enum_name(p.projection);
  return enum_name(p.level_roughness);
}

constexpr const char* kChainFields[] = {"levels", "base_size", "samples", "projection", "level_roughness"};

}  // namespace

void apply_bake_target(PrefilterRequest& request, const Json& body) {
  if (!body.contains("target")) return;
  const BakeTarget target = json_enum(body, "target", BakeTarget::Gltf);
  const TargetSpec& spec = target_spec(target);
  const std::string name = enum_name(target);
  if (body.contains("format"))
    throw invalid_field("format", "the target '" + name + "' writes its own files; leave 'format' out");
  request.target = target;
  const std::optional<PrefilterParams> chain = spec.chain_params(request);
  for (const char* field : kChainFields) {
    if (!body.contains(field)) continue;
    if (!chain)
      throw invalid_field(field, "the target '" + name + "' ships no prefiltered chain; leave it out");
    const Json made = chain_field(*chain, field);
    if (made != body[field])
      throw invalid_field(
          field, fmt::format("the target '{}' makes it {}, got {}", name, made.dump(), body[field].dump()));
  }
  if (chain) request.params = *chain;
}

bool makes_chain(const PrefilterRequest& request) {
  return !request.target || target_spec(*request.target).chain_params(request).has_value();
}

}  // namespace lp::api
