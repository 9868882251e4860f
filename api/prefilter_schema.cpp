#include "api/prefilter_schema.hpp"

#include "api/bake/bake_request.hpp"
#include "api/prefilter_files.hpp"
#include "engine/prefilter/prefilter_chain.hpp"

namespace lp::api {

void describe_prefilter(Json& out, const PrefilterRequest& request, const PrefilterDescription& d) {
  const PrefilterParams& p = request.params;
  out["envmap"] = d.envmap;
  out["levels"] = p.levels;
  out["base_size"] = p.base_size;
  out["samples"] = p.samples;
  out["texel_samples"] = prefilter_work_units(p);
  out["projection"] = enum_name(p.projection);
  out["level_roughness"] = enum_name(p.level_roughness);
  if (request.target)
    out["target"] = enum_name(*request.target);
  else
    out["format"] = enum_name(request.format);
  out["precision"] = enum_name(request.precision);
  out["source_width"] = d.source_width > 0 ? Json(d.source_width) : Json(nullptr);
  Json levels = Json::array();
  for (int i = 0; makes_chain(request) && i < p.levels; ++i) {
    const ImageShape s = prefilter_level_shape(p, i);
    const double r = p.roughness(i);
    levels.push_back({{"level", i},
                      {"roughness", r},
                      {"alpha", r * r},
                      {"size", prefilter_level_size(p, i)},
                      {"width", s.width},
                      {"height", s.height}});
  }
  out["level_info"] = std::move(levels);
  Json convention = Json::object();
  for (const auto& [key, text] : prefilter_conventions(request)) convention[key] = text;
  out["convention"] = std::move(convention);
  const auto file = [&](const std::string& name, const std::string& content_type) {
    return Json{{"name", name}, {"url", d.files_url + "/" + name}, {"content_type", content_type}};
  };
  Json files = Json::array();
  if (request.target) {
    if (d.target_files)
      for (const BakeFile& f : *d.target_files) files.push_back(file(f.name, f.content_type));
  } else {
    for (const std::string& name : prefilter_file_names(request))
      files.push_back(file(name, prefilter_file_mime_type(request.format)));
  }
  out["files"] = std::move(files);
  out["files_available"] = d.done;
}

}  // namespace lp::api
