#pragma once
// A client connection driven byte by byte, for what an HTTP library would not send: pipelined, malformed,
// trickled or oversized requests. Every read waits at most `timeout`, so a server that never answers
// fails the test instead of hanging it.
#include <chrono>
#include <string>
#include <string_view>

namespace lp::test {

struct RawResponse {
  int status = 0;  // 0: the connection closed (or timed out) before a complete response
  std::string head;
  std::string body;
  bool has_header(std::string_view line) const;  // e.g. "Connection: close"
};

class RawConnection {
 public:
  explicit RawConnection(int port, std::chrono::milliseconds timeout = std::chrono::seconds(20));
  ~RawConnection();
  RawConnection(const RawConnection&) = delete;
  RawConnection& operator=(const RawConnection&) = delete;

  // Sends all of `data`; false if the server closed the connection (not an error in many tests).
  bool send(std::string_view data);
  // Reads one response (Content-Length or chunked body).
  RawResponse read_response();
  // Reads until `text` has arrived (true) or the connection closes or times out (false).
  bool read_until(std::string_view text);
  // Whether the server closed the connection (it sends nothing more and reading ends).
  bool closed_by_server();
  // Bytes received and not yet consumed by read_response().
  const std::string& received() const { return input_; }

 private:
  bool fill();

  int fd_ = -1;
  std::string input_;
};

// "GET path HTTP/1.1" with the Host header and `headers` (whole lines, each ending in \r\n).
std::string get_request(int port, const std::string& path, const std::string& headers = {});
// A POST with a JSON body and its Content-Length.
std::string post_request(int port, const std::string& path, const std::string& body);

}  // namespace lp::test
