#include "server/storage/named_registry.hpp"

#include "api/api_error.hpp"
#include "api/excerpt.hpp"

namespace lp::server {

void refuse_taken(const RegistryWording& wording, const std::string& name) {
  throw api::ApiError(api::ErrorCode::Conflict, wording.one + " named '" + name + "' exists");
}

void refuse_full(const RegistryWording& wording) {
  throw api::ApiError(api::ErrorCode::InsufficientStorage,
                      "the server holds the maximum number of " + wording.limit + "; delete one first");
}

void refuse_absent(const RegistryWording& wording, const std::string& name) {
  throw api::not_found("no " + wording.kind + " " + wording.lookup + " '" + api::excerpt(name) + "'");
}

}  // namespace lp::server
