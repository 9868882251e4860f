#pragma once
// One log line per answered request ("GET /api/v1/health 200 0.3 ms"), at info level, for one request
// in `sample_every` (0: none); a 5xx answer is always logged, at error level. Lines go through spdlog,
// so --log-level above info also silences the sampled ones.
#include <httplib.h>

#include <atomic>
#include <cstdint>

namespace lp::server {

class AccessLog {
 public:
  explicit AccessLog(int64_t sample_every) : sample_every_(sample_every) {}

  // Marks the start of a request on this thread (a request is handled start to end on one worker).
  static void start_request();
  void record(const httplib::Request& req, const httplib::Response& res);

 private:
  bool sampled();

  const int64_t sample_every_;
  std::atomic<uint64_t> seen_{0};
};

}  // namespace lp::server
