#include "server/http/responses.hpp"

#include <algorithm>

#include "api/api_error.hpp"
#include "server/http/request_id.hpp"

namespace lp::server {

bool has_json_content_type(const httplib::Request& req) {
  std::string type = req.get_header_value("Content-Type");
  type = type.substr(0, type.find(';'));
  std::erase_if(type, [](char c) { return c == ' ' || c == '\t'; });
  std::transform(type.begin(), type.end(), type.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return type == "application/json";
}

std::string path_param(const httplib::Request& req, size_t n) {
  if (n >= req.matches.size()) throw api::ApiError(api::ErrorCode::Internal, "missing path parameter");
  return req.matches[n].str();
}

void send_json(httplib::Response& res, const nlohmann::json& body, int status) {
  res.status = status;
  res.set_content(body.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace), "application/json");
}

void send_error(httplib::Response& res, api::ErrorCode code, const std::string& message) {
  if (!res.has_header(kRequestIdHeader)) res.set_header(kRequestIdHeader, new_request_id());
  const std::string id = res.get_header_value(kRequestIdHeader);
  send_json(res, {{"error", {{"code", api::code_name(code)}, {"message", message}, {"request_id", id}}}},
            api::http_status(code));
}

}  // namespace lp::server
