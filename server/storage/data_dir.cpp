#include "server/storage/data_dir.hpp"

#include <unistd.h>

#include <stdexcept>

#include "api/api_error.hpp"

namespace lp::server {

namespace fs = std::filesystem;

void check_data_dir(const Options& options) {
  if (!options.data_dir) return;
  const fs::path& dir = *options.data_dir;
  std::error_code ec;
  if (!fs::exists(dir, ec)) throw std::runtime_error("--data-dir " + dir.string() + " does not exist");
  if (!fs::is_directory(dir, ec))
    throw std::runtime_error("--data-dir " + dir.string() + " is not a directory");
  if (::access(dir.c_str(), R_OK | X_OK) != 0)
    throw std::runtime_error("--data-dir " + dir.string() + " is not readable");
}

fs::path resolve_in_data_dir(const Options& options, const std::string& relative, const std::string& field) {
  if (!options.data_dir)
    throw api::invalid_field(field, "the server was started without --data-dir; paths are not accepted");
  return resolve_inside(*options.data_dir, relative, field, "the data directory");
}

fs::path resolve_inside(const fs::path& root_dir, const std::string& relative, const std::string& field,
                        const std::string& where) {
  if (relative.empty()) throw api::invalid_field(field, "must not be empty");
  if (relative.find('\0') != std::string::npos) throw api::invalid_field(field, "must not contain NUL");
  const fs::path rel(relative);
  if (rel.is_absolute() || rel.has_root_name() || rel.has_root_directory())
    throw api::invalid_field(field, "must be relative to " + where + ", not absolute");
  for (const auto& part : rel)
    if (part == "..") throw api::invalid_field(field, "must not contain '..'");
  std::error_code ec;
  const fs::path root = fs::canonical(root_dir, ec);
  if (ec) throw api::ApiError(api::ErrorCode::Internal, where + " is not accessible");
  const fs::path full = fs::weakly_canonical(root / rel, ec);
  if (ec) throw api::invalid_field(field, "cannot be resolved");
  const auto [root_end, full_it] = std::mismatch(root.begin(), root.end(), full.begin(), full.end());
  if (root_end != root.end()) throw api::invalid_field(field, "resolves outside " + where);
  if (!fs::is_regular_file(full, ec))
    throw api::invalid_field(field, "no file '" + api::excerpt(relative) + "' in " + where);
  return full;
}

}  // namespace lp::server
