#include "api/prefilter_schema.hpp"

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
  out["format"] = enum_name(request.format);
  out["precision"] = enum_name(request.precision);
  out["source_width"] = d.source_width > 0 ? Json(d.source_width) : Json(nullptr);
  Json levels = Json::array();
  for (int i = 0; i < p.levels; ++i) {
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
  Json files = Json::array();
  for (const std::string& name : prefilter_file_names(request))
    files.push_back({{"name", name},
                     {"url", d.files_url + "/" + name},
                     {"content_type", prefilter_file_mime_type(request.format)}});
  out["files"] = std::move(files);
  out["files_available"] = d.done;
}

}  // namespace lp::api
