#pragma once
// Turning a render request body into the renderer's input under the server's limits: shared by new
// renders and by renders continued after a restart.
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>

#include "api/render_request.hpp"
#include "server/app.hpp"

namespace lp::server {

// Mesh paths name an uploaded asset or a file in --data-dir (assets/mesh_paths.hpp); each names a .gltf, .glb
// or .obj model, loaded here (through the server's model cache) so that a missing or malformed model is
// refused before the render is queued: a 400 naming the field and what is wrong with the file. A mesh
// whose model the engine built (a preset's) is counted in the memory budget once (ModelCache::
// hold_builtin). Throws MemoryBudgetError when a model does not fit the memory budget. Returns the
// triangles of all the scene's meshes.
int64_t resolve_meshes(render::SceneDesc& scene, App& app);

// The request's camera resolved once its models are loaded (a framed or glTF camera) and the view's
// warnings, in request.view; a 400 naming scene.camera.fit or scene.camera.gltf when it cannot be.
void resolve_view(api::RenderRequest& request);

// The model file of scene.objects[object], whose mesh path is `path`; throws api::ApiError naming `field`.
using MeshLocator =
    std::function<std::filesystem::path(size_t object, const std::string& path, const std::string& field)>;
// The same with the model files found by `locate` (a worker of a split render: in fetched bundles).
int64_t resolve_meshes(render::SceneDesc& scene, App& app, const MeshLocator& locate);

}  // namespace lp::server
