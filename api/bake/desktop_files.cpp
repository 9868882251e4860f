#include "api/bake/desktop_files.hpp"

#include "api/prefilter_files.hpp"
#include "api/prefilter_request.hpp"
#include "engine/core/error.hpp"
#include "engine/image/ktx2.hpp"
#include "engine/prefilter/prefilter_chain.hpp"

namespace lp::api {

Json frame_json(const EngineFrame& frame) {
  return {{"text", frame.text}, {"world_to_engine", frame.world_to_engine}, {"sources", frame.sources}};
}

BakeFile exr_file(const std::string& name, const Image& image, ExrEnvmap envmap, const BakeInput& input) {
  return {name, format_mime_type(ImageFormat::Exr),
          write_exr_envmap(image, envmap, ExrCompression::Zip, input.request.precision)};
}

BakeFile hdr_file(const std::string& name, const Image& image) {
  return {name, format_mime_type(ImageFormat::Hdr), write_hdr(image)};
}

BakeFile astc_cube_file(const std::string& name, const BakeInput& input, bool x_mirrored) {
  if (!input.chain) throw Error(ErrorKind::Internal, "an ASTC cube needs the target's chain");
  std::vector<Image> levels;
  for (const Image& strip : input.chain->levels)
    levels.push_back(stacked_faces(x_mirrored ? cube_strip_x_mirrored(strip) : strip));
  const std::map<std::string, std::string> metadata = {{"lightprobe.map", input.name}};
  return {name, "image/ktx2", write_ktx2_astc_cube(levels, {kBakeAstcQuality, 0}, metadata)};
}

Json chain_roughness_json(const PrefilteredChain& chain) {
  Json roughness = Json::array();
  for (int i = 0; i < int(chain.levels.size()); ++i) roughness.push_back(chain.params.roughness(i));
  return {{"text",
           "the ASTC cube's level i has perceptual roughness i / (levels - 1) (alpha = roughness^2): "
           "lod = roughness x (levels - 1); the EXRs are the map itself, which the engine prefilters"},
          {"roughness", roughness}};
}

std::optional<PrefilterParams> astc_cube_chain_params(const PrefilterRequest& request) {
  PrefilterParams p = request.params;
  p.projection = Projection::Cube;
  p.level_roughness = LevelRoughness::Linear;
  return p;
}

void add_manifest(std::vector<BakeFile>& files, const BakeInput& input, BakeTarget target,
                  const DesktopManifest& manifest) {
  Json entries = Json::array();
  for (size_t i = 0; i < files.size(); ++i)
    entries.push_back({{"name", files[i].name},
                       {"bytes", files[i].bytes.size()},
                       {"content_type", files[i].content_type},
                       {"role", manifest.roles.at(i)}});
  Json json = manifest_common(input, target);
  json["frame"] = frame_json(manifest.frame);
  json["face_order"] = manifest.face_order;
  json["roughness_to_lod"] = manifest.roughness_to_lod;
  json["files"] = entries;
  json["import"] = manifest.import;
  files.push_back(manifest_file(json));
}

}  // namespace lp::api
