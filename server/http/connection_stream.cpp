#include "server/http/connection_stream.hpp"

#include <arpa/inet.h>
#include <poll.h>
#include <sys/socket.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <utility>

#include "server/http/request_head.hpp"

namespace lp::server {
namespace {

// A body up to this size is copied behind its held head and sent with it; a larger one follows it.
constexpr size_t kCoalescedBodyBytes = 64 * 1024;

// The Content-Length a response head announces (httplib writes the name in this case), 0 if none.
uint64_t announced_length(std::string_view head) {
  constexpr std::string_view kName = "\r\nContent-Length: ";
  const size_t at = head.find(kName);
  if (at == std::string_view::npos) return 0;
  uint64_t length = 0;
  const char* begin = head.data() + at + kName.size();
  std::from_chars(begin, head.data() + head.size(), length);
  return length;
}

constexpr size_t kReadSize = 16 * 1024;
constexpr size_t kMaxChunkLine = 4096;  // a chunk-size line with its extensions, or a trailer line

int ms_until(std::chrono::steady_clock::time_point deadline) {
  const auto left =
      std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now())
          .count();
  return int(std::clamp<long long>(left, 0, 24 * 3600 * 1000));
}

// Waits for `events` on the socket; false on timeout or a socket error.
bool wait_for(int fd, short events, std::chrono::milliseconds timeout) {
  pollfd p{fd, events, 0};
  int r;
  do r = poll(&p, 1, int(timeout.count()));
  while (r < 0 && errno == EINTR);
  return r > 0 && !(p.revents & (POLLERR | POLLNVAL)) && (p.revents & (events | POLLHUP));
}

}  // namespace

void socket_address(const sockaddr_storage& addr, std::string& ip, int& port) {
  char text[INET6_ADDRSTRLEN] = "";
  if (addr.ss_family == AF_INET) {
    const auto& a = reinterpret_cast<const sockaddr_in&>(addr);
    inet_ntop(AF_INET, &a.sin_addr, text, sizeof text);
    port = ntohs(a.sin_port);
  } else if (addr.ss_family == AF_INET6) {
    const auto& a = reinterpret_cast<const sockaddr_in6&>(addr);
    inet_ntop(AF_INET6, &a.sin6_addr, text, sizeof text);
    port = ntohs(a.sin6_port);
  }
  ip = text;
}

ConnectionStream::ConnectionStream(int fd, std::string remote_ip, int remote_port,
                                   std::chrono::seconds io_timeout)
    : fd_(fd), remote_ip_(std::move(remote_ip)), remote_port_(remote_port), io_timeout_(io_timeout) {}

ConnectionStream::Fill ConnectionStream::fill(std::chrono::steady_clock::time_point deadline) {
  for (;;) {
    const size_t old = input_.size();
    input_.resize(old + kReadSize);
    const ssize_t n = recv(fd_, input_.data() + old, kReadSize, 0);
    input_.resize(old + size_t(std::max<ssize_t>(n, 0)));
    if (n > 0) return Fill::Data;
    if (n == 0) return Fill::Closed;
    if (errno == EINTR) continue;
    if (errno != EAGAIN && errno != EWOULDBLOCK) return Fill::Closed;
    pollfd fds[1] = {{fd_, POLLIN, 0}};
    const int r = poll(fds, 1, ms_until(deadline));
    if (r < 0 && errno == EINTR) continue;
    if (r < 0) return Fill::Closed;
    if (r == 0) return Fill::TimedOut;
  }
}

void ConnectionStream::consume(size_t n) {
  input_pos_ += n;
  if (input_pos_ >= input_.size()) {
    input_.clear();
    input_pos_ = 0;
  } else if (input_pos_ > kReadSize && input_pos_ * 2 > input_.size()) {
    input_.erase(0, input_pos_);
    input_pos_ = 0;
  }
}

void ConnectionStream::begin_request(std::string head, BodyFraming body) {
  head_ = std::move(head);
  expect_head_ = true;
  head_request_ = head_.starts_with("HEAD ");
  head_pos_ = 0;
  over_limit_ = false;
  decoded_ = 0;
  trailer_bytes_ = 0;
  max_body_ = body.max_body;
  remaining_ = body.length;
  switch (body.kind) {
    case BodyFraming::Kind::None:
      body_state_ = BodyState::Done;
      break;
    case BodyFraming::Kind::Length:
      body_state_ = body.length > 0 ? BodyState::Length : BodyState::Done;
      break;
    case BodyFraming::Kind::Chunked:
      body_state_ = BodyState::ChunkSize;
      break;
  }
}

ssize_t ConnectionStream::read(char* ptr, size_t size) {
  if (head_pos_ < head_.size()) {
    const size_t n = std::min(size, head_.size() - head_pos_);
    std::memcpy(ptr, head_.data() + head_pos_, n);
    head_pos_ += n;
    return ssize_t(n);
  }
  if (body_state_ == BodyState::Done) return 0;
  if (body_state_ != BodyState::Length) return read_chunked(ptr, size);
  const ssize_t n = read_buffered(ptr, size, remaining_);
  if (n > 0 && (remaining_ -= uint64_t(n)) == 0) body_state_ = BodyState::Done;
  return n;
}

bool ConnectionStream::fill_for_body() {
  return fill(std::chrono::steady_clock::now() + io_timeout_) == Fill::Data;
}

ssize_t ConnectionStream::read_buffered(char* ptr, size_t size, uint64_t limit) {
  if (input().empty() && !fill_for_body()) return -1;
  const size_t n = size_t(std::min<uint64_t>({size, limit, input().size()}));
  std::memcpy(ptr, input().data(), n);
  consume(n);
  return ssize_t(n);
}

bool ConnectionStream::take_line(std::string& line) {
  for (;;) {
    const size_t end = input().find('\n');
    if (end != std::string_view::npos) {
      line.assign(input().substr(0, end));
      if (!line.empty() && line.back() == '\r') line.pop_back();
      consume(end + 1);
      return line.size() <= kMaxChunkLine;
    }
    if (input().size() > kMaxChunkLine || !fill_for_body()) return false;
  }
}

bool ConnectionStream::start_chunk(std::string_view size_line) {
  const std::string_view digits = size_line.substr(0, size_line.find_first_of("; \t"));
  if (digits.empty() || digits.size() > 15 ||
      digits.find_first_not_of("0123456789abcdefABCDEF") != std::string_view::npos)
    return false;
  const uint64_t size = std::stoull(std::string(digits), nullptr, 16);
  if (size == 0) {
    body_state_ = BodyState::Trailer;
    return true;
  }
  if (decoded_ + size > max_body_) {
    over_limit_ = true;
    return false;
  }
  remaining_ = size;
  body_state_ = BodyState::ChunkData;
  return true;
}

// Decodes the chunked body; -1 (and the connection is closed after the response) on a malformed body or
// one over its limit, which is refused as soon as a chunk size says so, before its data is read.
ssize_t ConnectionStream::read_chunked(char* ptr, size_t size) {
  std::string line;
  for (;;) {
    switch (body_state_) {
      case BodyState::ChunkSize:
        if (!take_line(line) || !start_chunk(line)) return -1;
        break;
      case BodyState::ChunkData: {
        const ssize_t n = read_buffered(ptr, size, remaining_);
        if (n <= 0) return -1;
        decoded_ += uint64_t(n);
        if ((remaining_ -= uint64_t(n)) == 0) body_state_ = BodyState::ChunkEnd;
        return n;
      }
      case BodyState::ChunkEnd:
        if (!take_line(line) || !line.empty()) return -1;
        body_state_ = BodyState::ChunkSize;
        break;
      case BodyState::Trailer:
        if (!take_line(line)) return -1;
        if (line.empty()) {
          body_state_ = BodyState::Done;
          return 0;
        }
        if ((trailer_bytes_ += line.size()) > kMaxHeadBytes) return -1;
        break;
      default:
        return 0;
    }
  }
}

bool ConnectionStream::write_all(std::string_view data) {
  while (!data.empty()) {
    const ssize_t n = send(fd_, data.data(), data.size(), MSG_NOSIGNAL);
    if (n > 0) {
      data.remove_prefix(size_t(n));
    } else if (n < 0 && errno == EINTR) {
      continue;
    } else if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) {
      if (!wait_for(fd_, POLLOUT, io_timeout_)) return false;
    } else {
      return false;
    }
  }
  return true;
}

void ConnectionStream::close_gracefully(std::chrono::milliseconds linger) {
  shutdown(fd_, SHUT_WR);
  const auto deadline = std::chrono::steady_clock::now() + linger;
  while (fill(deadline) == Fill::Data) consume(input().size());
}

bool ConnectionStream::is_readable() const {
  return head_pos_ < head_.size() || !input().empty() || wait_for(fd_, POLLIN, io_timeout_);
}

// Writable, and the client has not closed its side (what a stream writer checks before each piece).
bool ConnectionStream::is_writable() const {
  if (!wait_for(fd_, POLLOUT, io_timeout_)) return false;
  if (!wait_for(fd_, POLLIN, std::chrono::milliseconds(0))) return true;
  char byte;
  return recv(fd_, &byte, 1, MSG_PEEK | MSG_DONTWAIT) > 0;
}

ssize_t ConnectionStream::write(const char* ptr, size_t size) {
  const std::string_view data(ptr, size);
  if (std::exchange(expect_head_, false) && !head_request_ && announced_length(data) > 0) {
    held_head_.assign(data);
    return ssize_t(size);
  }
  return send_after_held_head(data) ? ssize_t(size) : -1;
}

bool ConnectionStream::flush() {
  return send_after_held_head({});
}

bool ConnectionStream::send_after_held_head(std::string_view data) {
  if (held_head_.empty()) return write_all(data);
  bool sent = false;
  if (data.size() <= kCoalescedBodyBytes) {
    held_head_.append(data);
    sent = write_all(held_head_);
  } else {
    sent = write_all(held_head_) && write_all(data);
  }
  held_head_.clear();
  return sent;
}

void ConnectionStream::get_remote_ip_and_port(std::string& ip, int& port) const {
  ip = remote_ip_;
  port = remote_port_;
}

void ConnectionStream::get_local_ip_and_port(std::string& ip, int& port) const {
  sockaddr_storage addr{};
  socklen_t len = sizeof addr;
  if (getsockname(fd_, reinterpret_cast<sockaddr*>(&addr), &len) == 0) socket_address(addr, ip, port);
}

}  // namespace lp::server
