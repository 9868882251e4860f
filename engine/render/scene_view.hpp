#pragma once
// The view a scene asks for, once its models are loaded: a framed camera (CameraFit) or a camera of a
// glTF model becomes a plain position, look_at, up and field of view; and what the caller should be
// told about that view: a camera inside an object's bounds, or one whose view holds none of the scene's
// objects (their bounding spheres all outside its field of view; a scene with a plane is not judged).
#include <optional>
#include <string>
#include <vector>

#include "engine/core/bounds.hpp"
#include "engine/render/scene_desc.hpp"

namespace lp::render {

struct SceneView {
  Camera camera;                      // neither fit nor gltf
  std::vector<std::string> warnings;  // sentences naming the objects as scene.objects[i]
};

// The world bounds of an object: a sphere's, or a mesh's placed vertices; empty for a plane, which is
// unbounded, and for a mesh whose model is not loaded.
Bounds object_bounds(const SceneObject& object);

// The sphere framing the bounded objects (or one of them): centred on their bounds, holding every
// placed vertex and sphere. Its radius is 0 when nothing is bounded.
BoundingSphere framing_sphere(const SceneDesc& scene, std::optional<uint32_t> object);

// The camera `fit` places to frame `sphere` with a vertical field of view `fov_deg` in an image of
// `aspect` = width / height.
Camera fit_camera(const CameraFit& fit, const BoundingSphere& sphere, float fov_deg, float aspect);

// The camera alone, a framed or glTF camera placed. Throws lp::Error(InvalidArgument) naming
// `scene.camera.fit` when nothing is bounded to frame, and `scene.camera.gltf` for a camera the model
// does not have or an orthographic one. Every mesh whose model a fit or a glTF camera needs must be
// loaded.
Camera resolve_camera(const SceneDesc& scene, float aspect);

// The camera and the view's warnings (which read every mesh's placed vertices); throws as resolve_camera.
SceneView resolve_view(const SceneDesc& scene, float aspect);

// Places every ground (SceneObject::ground) as its plane: at its height, or at the lowest z of the bounded
// objects' world bounds (0 when nothing is bounded). The models of mesh objects must be loaded for a
// ground without a height (needs_models).
void resolve_grounds(SceneDesc& scene);
// Whether resolve_camera or resolve_grounds reads the scene's models.
bool needs_models(const SceneDesc& scene);

// Models of mesh objects not yet loaded, loaded (what resolve_view needs when the scene names files).
void load_missing_models(SceneDesc& scene, const MeshLimits& limits);

}  // namespace lp::render
