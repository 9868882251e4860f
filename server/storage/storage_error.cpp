#include "server/storage/storage_error.hpp"

#include <spdlog/spdlog.h>

#include <cerrno>
#include <cstring>
#include <system_error>

namespace lp::server {

StorageError::StorageError(const std::string& operation, std::filesystem::path path, int error_number)
    : std::runtime_error("cannot " + operation + ": " + std::strerror(error_number)),
      path_(std::move(path)),
      error_number_(error_number) {}

namespace {

int error_number_of(const std::exception& e) {
  if (const auto* s = dynamic_cast<const StorageError*>(&e)) return s->error_number();
  if (const auto* f = dynamic_cast<const std::filesystem::filesystem_error*>(&e))
    if (f->code().category() == std::generic_category() || f->code().category() == std::system_category())
      return f->code().value();
  return 0;
}

}  // namespace

bool out_of_space(const std::exception& e) {
  const int n = error_number_of(e);
  return n == ENOSPC || n == EDQUOT;
}

api::ApiError storage_refusal(const std::exception& e, const std::string& what) {
  const auto* s = dynamic_cast<const StorageError*>(&e);
  spdlog::error("state: cannot keep {}: {}{}", what, e.what(), s ? " (" + s->path().string() + ")" : "");
  if (out_of_space(e))
    return api::ApiError(api::ErrorCode::InsufficientStorage,
                         "cannot keep " + what + ": the server's storage is full");
  return api::ApiError(api::ErrorCode::WriteFailed,
                       "cannot keep " + what + ": the server could not write it (see its log)");
}

}  // namespace lp::server
