#pragma once
// Bake targets: the files one engine loads its image-based lighting from (lightprobe bake --target, the
// prefilter job's "target"). Each target is a TargetSpec in the registry (bake_target.cpp): the chain it
// needs and the writer of its files.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "engine/core/enum_table.hpp"
#include "engine/prefilter/prefilter_params.hpp"

namespace lp {
class EnvMap;
struct PrefilteredChain;
struct ShCoefficients;
}  // namespace lp

namespace lp::api {

struct PrefilterRequest;

enum class BakeTarget { Gltf, Filament, Babylon, Three, Unity, Unreal, Godot };
constexpr auto enum_entries(BakeTarget) {
  return std::to_array<EnumEntry<BakeTarget>>({{BakeTarget::Gltf, "gltf"},
                                               {BakeTarget::Filament, "filament"},
                                               {BakeTarget::Babylon, "babylon"},
                                               {BakeTarget::Three, "three"},
                                               {BakeTarget::Unity, "unity"},
                                               {BakeTarget::Unreal, "unreal"},
                                               {BakeTarget::Godot, "godot"}});
}

struct BakeFile {
  std::string name;          // a plain file name, no folders
  std::string content_type;  // MIME type
  std::vector<uint8_t> bytes;
};

// The SH bands every target's input carries.
inline constexpr int kBakeShBands = 3;

struct BakeInput {
  std::string name;                 // the map's name: the stem of files that carry it (NAME_ibl.ktx)
  const EnvMap& map;                // the map as loaded
  const PrefilteredChain* chain;    // the chain of the spec's chain_params, or null if it takes none
  const ShCoefficients& sh;         // kBakeShBands bands of the radiance (engine/sh project_sh)
  const PrefilterRequest& request;  // the request (precision, samples, ... as the user gave them)
};

struct TargetSpec {
  BakeTarget target;
  const char* summary;  // one line: help text and the OpenAPI description derive from it
  // The chain the target needs from the user's request (its fields may override the target's defaults
  // where the target allows; a field the target cannot take throws api::invalid_field naming it);
  // nullopt when the target ships no prefiltered chain.
  std::optional<PrefilterParams> (*chain_params)(const PrefilterRequest&);
  // Every file of the target, manifest.json included (bake_manifest.hpp builds the common part).
  std::vector<BakeFile> (*write)(const BakeInput&);
};

// The registry: 400 invalid_field naming `target` for a target this build does not make.
const TargetSpec& target_spec(BakeTarget target);
// The targets the registry holds, in the enum's order.
std::vector<BakeTarget> available_targets();
// "gltf, filament, ...": the available targets' names, for messages and help.
std::string available_target_names();

// `name` as the stem of a file name: letters, digits, '-', '_' and '.' kept, anything else '_'.
std::string bake_file_stem(const std::string& name);

// The total size of a target's files (what a job keeps of them in memory).
int64_t bake_files_bytes(const std::vector<BakeFile>& files);

}  // namespace lp::api
