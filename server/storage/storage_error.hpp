#pragma once
// Failures of the state directory. A refusal a client sees names the client's resource, never a server
// path: the path goes to the server's log only.
#include <filesystem>
#include <stdexcept>
#include <string>

#include "api/api_error.hpp"

namespace lp::server {

// A system call on a file of the state directory failed. what() names the operation and the system's
// error but not the path (path() keeps it for the log).
class StorageError : public std::runtime_error {
 public:
  StorageError(const std::string& operation, std::filesystem::path path, int error_number);
  const std::filesystem::path& path() const { return path_; }
  int error_number() const { return error_number_; }

 private:
  std::filesystem::path path_;
  int error_number_;
};

// Whether a failure of a write (StorageError, std::filesystem::filesystem_error) means the disk or the
// quota is full.
bool out_of_space(const std::exception& e);

// The refusal of a request whose `what` (e.g. "the map 'sky'") could not be kept because of `e`: 507
// insufficient_storage when the disk is full, else 500 write_failed. Logs `e` with its path.
api::ApiError storage_refusal(const std::exception& e, const std::string& what);

}  // namespace lp::server
