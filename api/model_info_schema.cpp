#include "api/model_info_schema.hpp"

namespace lp::api {
namespace {

Json vec3(Vec3 v) {
  return Json::array({v.x, v.y, v.z});
}

// An empty model's bounds are all zero.
Json bounds_json(const Bounds& b, const BoundingSphere& s) {
  const Vec3 zero{0, 0, 0};
  return {{"min", vec3(b.empty() ? zero : b.min)},
          {"max", vec3(b.empty() ? zero : b.max)},
          {"centre", vec3(s.center)},
          {"radius", s.radius}};
}

Json materials_json(const std::vector<MaterialInfo>& materials) {
  Json out = Json::array();
  for (const MaterialInfo& m : materials)
    out.push_back({{"name", m.name}, {"features", m.features}, {"extensions", m.extensions}});
  return out;
}

Json textures_json(const std::vector<TextureInfo>& textures) {
  Json out = Json::array();
  for (const TextureInfo& t : textures)
    out.push_back({{"width", t.width},
                   {"height", t.height},
                   {"bytes", t.bytes},
                   {"color_space", enum_name(t.color_space)}});
  return out;
}

Json cameras_json(const std::vector<ModelSource::Camera>& cameras) {
  Json out = Json::array();
  for (size_t i = 0; i < cameras.size(); ++i)
    out.push_back({{"index", i}, {"name", cameras[i].name}, {"type", cameras[i].type}});
  return out;
}

}  // namespace

Json model_info_json(const ModelInfo& info) {
  return {{"frame", info.frame},
          {"bounds", bounds_json(info.bounds, info.sphere)},
          {"triangles", info.triangles},
          {"vertices", info.vertices},
          {"meshes", info.meshes},
          {"materials", materials_json(info.materials)},
          {"textures", textures_json(info.textures)},
          {"cameras", cameras_json(info.cameras)},
          {"extensions_used", info.extensions_used},
          {"warnings", info.warnings}};
}

ApiError invalid_model(const Error& e) {
  return ApiError(e.kind() == ErrorKind::TooLarge ? ErrorCode::TooLarge : ErrorCode::InvalidModel, e.what());
}

}  // namespace lp::api
