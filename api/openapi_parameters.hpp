#pragma once
// The query parameters each operation of api/openapi.yaml declares: the one list the server checks
// requests against, so the document and the code cannot disagree.
#include <string>
#include <vector>

namespace lp::api {

// Names of the `in: query` parameters of operation `method` (GET, POST, ...) on `path` (OpenAPI
// form), from the path item and the operation, `$ref`s to #/components/parameters followed.
// Throws std::logic_error if the document has no such operation.
std::vector<std::string> documented_query_parameters(const std::string& method, const std::string& path);

}  // namespace lp::api
