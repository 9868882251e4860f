#include "server/scale_out/content_download.hpp"

#include <fmt/format.h>
#include <httplib.h>

#include <algorithm>
#include <charconv>
#include <exception>
#include <stdexcept>

namespace lp::server {
namespace {

constexpr time_t kConnectTimeoutS = 5;
constexpr time_t kReadTimeoutS = 60;

// Receives the body: bounded, and reserved in the budget ahead of the bytes (doubling, as the string grows).
class Receiver {
 public:
  Receiver(App& app, int64_t max_bytes, std::string what)
      : app_(app), max_bytes_(max_bytes), what_(std::move(what)) {}

  bool head(const httplib::Response& res) {
    status_ = res.status;
    if (status_ != 200) return false;
    // Without a length (or with one that does not parse) the bytes are counted as they arrive.
    const std::string text = res.get_header_value("Content-Length");
    int64_t length = 0;
    if (std::from_chars(text.data(), text.data() + text.size(), length).ec != std::errc()) return true;
    if (length > max_bytes_) return too_large(length);
    return make_room(length);
  }

  bool body(const char* data, size_t n) {
    const int64_t size = int64_t(download_.bytes.size() + n);
    if (size > max_bytes_) return too_large(size);
    if (size > download_.memory.bytes() && !make_room(std::min(max_bytes_, 2 * size))) return false;
    download_.bytes.append(data, n);
    return true;
  }

  // The download, or what went wrong.
  Download result(const httplib::Result& res, const std::string& from) {
    if (failure_) std::rethrow_exception(failure_);
    if (status_ != 0 && status_ != 200)
      throw std::runtime_error(fmt::format("cannot fetch {} from {}: status {}", what_, from, status_));
    if (!res)
      throw std::runtime_error(
          fmt::format("cannot fetch {} from {}: {}", what_, from, httplib::to_string(res.error())));
    download_.memory.resize(int64_t(download_.bytes.capacity()));  // what the string holds
    return std::move(download_);
  }

 private:
  bool too_large(int64_t bytes) {
    failure_ = std::make_exception_ptr(
        std::runtime_error(fmt::format("{} is over {} bytes ({} bytes)", what_, max_bytes_, bytes)));
    return false;
  }

  bool make_room(int64_t bytes) {
    try {
      if (download_.memory)
        download_.memory.resize(bytes);
      else
        download_.memory = app_.memory.reserve(bytes, MemoryUse::Transient, "downloading " + what_);
      download_.bytes.reserve(size_t(bytes));
      return true;
    } catch (...) {
      failure_ = std::current_exception();
      return false;
    }
  }

  App& app_;
  const int64_t max_bytes_;
  const std::string what_;
  int status_ = 0;
  Download download_;
  std::exception_ptr failure_;
};

}  // namespace

Download download_content(App& app, const std::string& source_url, const std::string& hash, int64_t max_bytes,
                          const std::string& what) {
  httplib::Client client(source_url);
  client.set_connection_timeout(kConnectTimeoutS);
  client.set_read_timeout(kReadTimeoutS);
  httplib::Headers headers;
  if (!app.options.auth_token.empty()) headers.emplace("Authorization", "Bearer " + app.options.auth_token);
  Receiver receiver(app, max_bytes, what);
  const auto res = client.Get(
      "/api/v1/content/" + hash, headers, [&](const httplib::Response& r) { return receiver.head(r); },
      [&](const char* data, size_t n) { return receiver.body(data, n); });
  return receiver.result(res, source_url);
}

}  // namespace lp::server
