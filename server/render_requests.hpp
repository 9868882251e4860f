#pragma once
// Turning a render request body into the renderer's input under the server's limits: shared by new
// renders and by renders continued after a restart.
#include <nlohmann/json.hpp>

#include "api/render_request.hpp"
#include "server/app.hpp"

namespace lp::server {

// Mesh paths name an uploaded asset or a file in --data-dir (mesh_paths.hpp), and the files must pass the
// OBJ pre-scan (engine/render/obj_prescan.hpp). Every problem is a 400 naming the field. Returns the
// triangles of all the scene's meshes.
int64_t resolve_meshes(render::SceneDesc& scene, const App& app);

}  // namespace lp::server
