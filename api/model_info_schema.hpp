#pragma once
// JSON shape of a model's description (engine/model/model_info.hpp): the fields an asset's record
// carries (POST and GET /api/v1/assets) and `lightprobe info MODEL` prints.
#include "api/api_error.hpp"
#include "api/params.hpp"
#include "engine/core/error.hpp"
#include "engine/model/model_info.hpp"

namespace lp::api {

// {"bounds":{"min","max","centre","radius"},"triangles","vertices","meshes","materials":[{"name",
// "features","extensions"}],"textures":[{"width","height","bytes","color_space"}],"cameras":[{"index",
// "name","type"}],"extensions_used","warnings"}
Json model_info_json(const ModelInfo& info);

// How a model that does not load is refused, by the server's upload and the command-line tool alike:
// 413 too_large past a model limit, else 422 invalid_model with the loader's message.
ApiError invalid_model(const Error& e);

}  // namespace lp::api
