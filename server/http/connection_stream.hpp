#pragma once
// One client connection as httplib reads and writes it. The input buffer lives as long as the
// connection, so bytes of a pipelined next request are kept. Reads and writes wait with poll() up to a
// deadline. httplib reads
// the checked head of each request (request_head.hpp) and then its body as framed here: at most
// Content-Length bytes, or a chunked body decoded here and refused once it passes its limit.
#include <httplib.h>
#include <sys/socket.h>

#include <chrono>
#include <cstdint>
#include <string>
#include <string_view>

#include "server/http/body_framing.hpp"

namespace lp::server {

// The numeric address and port of a socket address (IPv4 or IPv6).
void socket_address(const sockaddr_storage& addr, std::string& ip, int& port);

class ConnectionStream final : public httplib::Stream {
 public:
  // `fd` is a connected non-blocking socket (not closed here); `io_timeout` bounds each wait of a body
  // read or a response write.
  ConnectionStream(int fd, std::string remote_ip, int remote_port, std::chrono::seconds io_timeout);

  enum class Fill { Data, Closed, TimedOut };
  // Appends what the socket has to the input, waiting until `deadline` (a past deadline: no wait).
  Fill fill(std::chrono::steady_clock::time_point deadline);
  std::string_view input() const { return std::string_view(input_).substr(input_pos_); }
  void consume(size_t n);

  // The next request: httplib reads `head`, then the body as `body` frames it, then the end of stream.
  void begin_request(std::string head, BodyFraming body);
  bool body_finished() const { return body_state_ == BodyState::Done; }
  bool body_over_limit() const { return over_limit_; }

  // Writes all of `data`; false if the client is gone or takes no data for the I/O timeout.
  bool write_all(std::string_view data);
  // Sends a response head still held back (see write()); false if the client is gone.
  bool flush();
  // Ends the connection so that a response just written reaches the client: no more writes, and what
  // the client still sends is read and dropped until it closes (at most `linger`).
  void close_gracefully(std::chrono::milliseconds linger);

  bool is_readable() const override;
  bool is_writable() const override;
  ssize_t read(char* ptr, size_t size) override;
  ssize_t write(const char* ptr, size_t size) override;
  void get_remote_ip_and_port(std::string& ip, int& port) const override;
  void get_local_ip_and_port(std::string& ip, int& port) const override;
  socket_t socket() const override { return fd_; }

 private:
  enum class BodyState { Length, ChunkSize, ChunkData, ChunkEnd, Trailer, Done };
  bool fill_for_body();
  bool take_line(std::string& line);
  ssize_t read_buffered(char* ptr, size_t size, uint64_t limit);
  ssize_t read_chunked(char* ptr, size_t size);
  bool start_chunk(std::string_view size_line);
  bool send_after_held_head(std::string_view data);

  int fd_;
  std::string remote_ip_;
  int remote_port_;
  std::chrono::seconds io_timeout_;
  std::string input_;
  size_t input_pos_ = 0;
  std::string head_;
  size_t head_pos_ = 0;
  BodyState body_state_ = BodyState::Done;
  uint64_t remaining_ = 0;  // of the Content-Length body, or of the current chunk
  uint64_t decoded_ = 0;    // chunked body bytes so far
  uint64_t max_body_ = 0;
  size_t trailer_bytes_ = 0;
  bool over_limit_ = false;
  // The first write of a response is its head. When the head announces a body of known length, it is
  // held and sent with the body's first piece: one packet instead of two for a small response, so the
  // client wakes once (with TCP_NODELAY each send is a packet). Streamed (chunked) heads go at once.
  bool expect_head_ = false;
  bool head_request_ = false;  // a HEAD request: its response head announces a body that is not sent
  std::string held_head_;
};

}  // namespace lp::server
