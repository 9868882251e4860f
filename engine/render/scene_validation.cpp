// The validate() of the scene, lighting and settings structs (scene_desc.hpp).
#include <fmt/format.h>

#include <cmath>

#include "engine/core/validate.hpp"
#include "engine/render/scene_desc.hpp"

namespace lp::render {

using namespace lp::limits;

void DiffuseMaterial::validate(const std::string& prefix) const {
  require_in(field_path(prefix, "albedo"), albedo, kReflectance);
}

void MirrorMaterial::validate(const std::string& prefix) const {
  require_in(field_path(prefix, "color"), color, kReflectance);
}

void DielectricMaterial::validate(const std::string& prefix) const {
  require_in(field_path(prefix, "ior"), ior, kIor);
  require_in(field_path(prefix, "roughness"), roughness, kRoughness);
}

void PlasticMaterial::validate(const std::string& prefix) const {
  require_in(field_path(prefix, "albedo"), albedo, kReflectance);
  require_in(field_path(prefix, "ior"), ior, kIor);
  require_in(field_path(prefix, "roughness"), roughness, kRoughness);
}

void ConductorMaterial::validate(const std::string& prefix) const {
  require_in(field_path(prefix, "eta"), eta, kConductorEta);
  require_in(field_path(prefix, "k"), k, kConductorK);
  require_in(field_path(prefix, "roughness"), roughness, kRoughness);
}

void SphereObject::validate(const std::string& prefix) const {
  require_in(field_path(prefix, "center"), center, kCoordinate);
  require_in(field_path(prefix, "radius"), radius, kSize);
}

void PlaneObject::validate(const std::string& prefix) const {
  require_in(field_path(prefix, "point"), point, kCoordinate);
  require_in(field_path(prefix, "normal"), normal, kCoordinate);
  require(length(normal) > 1e-9f, field_path(prefix, "normal"), "must not be the zero vector");
}

void MeshObject::validate(const std::string& prefix) const {
  require(!path.empty(), field_path(prefix, "path"), "must not be empty");
  require_in(field_path(prefix, "transform.translate"), translate, kCoordinate);
  require_in(field_path(prefix, "transform.scale"), scale, kSize);
  require_in(field_path(prefix, "transform.rotate_deg"), rotate_deg, kRotationDeg);
}

void SceneObject::validate(const std::string& prefix) const {
  std::visit([&](const auto& s) { s.validate(prefix); }, shape);
  std::visit([&](const auto& m) { m.validate(field_path(prefix, "material")); }, material);
  if (ground && ground->height) require_in(field_path(prefix, "height"), *ground->height, kCoordinate);
}

void Camera::validate(const std::string& prefix) const {
  require(!(fit && gltf), field_path(prefix, "fit"), "not allowed with " + field_path(prefix, "gltf"));
  if (fit) fit->validate(field_path(prefix, "fit"));
  require_in(field_path(prefix, "position"), position, kCoordinate);
  require_in(field_path(prefix, "look_at"), look_at, kCoordinate);
  require_in(field_path(prefix, "up"), up, kCoordinate);
  require_in(field_path(prefix, "fov_deg"), fov_deg, kFovDeg);
  const Vec3 view = look_at - position;
  require(length(view) > 1e-6f, field_path(prefix, "look_at"),
          "must differ from " + field_path(prefix, "position"));
  require(length(up) > 1e-9f, field_path(prefix, "up"), "must not be the zero vector");
  require(length(cross(normalize(view), normalize(up))) >= 1e-4f, field_path(prefix, "up"),
          "must not be parallel to the viewing direction (look_at - position)");
}

void CameraFit::validate(const std::string& prefix) const {
  require_in(field_path(prefix, "azimuth_deg"), azimuth_deg, kRotationDeg);
  require_in(field_path(prefix, "elevation_deg"), elevation_deg, kElevationDeg);
  require_in(field_path(prefix, "margin"), margin, kFitMargin);
}

void SceneDesc::validate(const std::string& prefix) const {
  camera.validate(field_path(prefix, "camera"));
  for (size_t i = 0; i < objects.size(); ++i)
    objects[i].validate(field_path(prefix, fmt::format("objects[{}]", i)));
  const auto check_object = [&](std::optional<uint32_t> object, const std::string& field, bool mesh_only) {
    if (!object) return;
    require(*object < objects.size(), field_path(prefix, field),
            fmt::format("must name one of the scene's {} objects, got {}", objects.size(), *object));
    const auto& shape = objects[*object].shape;
    if (mesh_only)
      require(std::holds_alternative<MeshObject>(shape), field_path(prefix, field),
              fmt::format("object {} is not a mesh", *object));
    else
      require(!std::holds_alternative<PlaneObject>(shape), field_path(prefix, field),
              fmt::format("object {} is a plane, which has no bounds to frame", *object));
  };
  if (camera.fit) check_object(camera.fit->object, "camera.fit.object", false);
  if (camera.gltf) check_object(camera.gltf->object, "camera.gltf.object", true);
}

void Lighting::validate(const std::string& prefix) const {
  require(lights >= 1, field_path(prefix, "lights"), fmt::format("must be at least 1, got {}", lights));
  require(sun == SunMode::None || mode == LightingMode::EnvMap, field_path(prefix, "sun"),
          fmt::format("'{}' needs mode 'envmap', got mode '{}'", enum_name(sun), enum_name(mode)));
  sun_parameters.validate(field_path(prefix, "sun_parameters"));
  require_in(field_path(prefix, "rotation_deg"), rotation_deg, kRotationDeg);
  require_in(field_path(prefix, "intensity"), intensity, kIntensity);
  require(importance_max_width >= 1, field_path(prefix, "importance_max_width"),
          fmt::format("must be at least 1, got {}", importance_max_width));
}

void RenderSettings::validate(const std::string& prefix) const {
  require(width >= 1, field_path(prefix, "width"), fmt::format("must be at least 1, got {}", width));
  require(height >= 1, field_path(prefix, "height"), fmt::format("must be at least 1, got {}", height));
  require(spp >= 1, field_path(prefix, "spp"), fmt::format("must be at least 1, got {}", spp));
  require_in(field_path(prefix, "max_depth"), max_depth, kMaxDepth);
  if (background.mode == BackgroundMode::Color)
    for (const float c : {background.color.x, background.color.y, background.color.z})
      require(std::isfinite(c) && c >= 0, field_path(prefix, "background"),
              fmt::format("a colour's channels must be finite and at least 0, got {}", c));
  if (clamp)
    require(std::isfinite(*clamp) && *clamp > 0, field_path(prefix, "clamp"),
            fmt::format("must be a finite number above 0, got {}", *clamp));
  require(texture_anisotropy >= 1, field_path(prefix, "texture_anisotropy"),
          fmt::format("must be at least 1, got {}", texture_anisotropy));
}

}  // namespace lp::render
