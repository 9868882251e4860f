#include "support/raw_connection.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <stdexcept>

namespace lp::test {

bool RawResponse::has_header(std::string_view line) const {
  return head.find(std::string("\r\n") + std::string(line) + "\r\n") != std::string::npos;
}

RawConnection::RawConnection(int port, std::chrono::milliseconds timeout)
    : fd_(socket(AF_INET, SOCK_STREAM, 0)) {
  timeval tv{timeout.count() / 1000, (timeout.count() % 1000) * 1000};
  setsockopt(fd_, SOL_SOCKET, SO_RCVTIMEO, &tv, sizeof tv);
  setsockopt(fd_, SOL_SOCKET, SO_SNDTIMEO, &tv, sizeof tv);
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  addr.sin_port = htons(uint16_t(port));
  if (fd_ < 0 || connect(fd_, reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0)
    throw std::runtime_error("cannot connect to port " + std::to_string(port));
}

RawConnection::~RawConnection() {
  close(fd_);
}

bool RawConnection::send(std::string_view data) {
  while (!data.empty()) {
    const ssize_t n = ::send(fd_, data.data(), data.size(), MSG_NOSIGNAL);
    if (n <= 0) return false;
    data.remove_prefix(size_t(n));
  }
  return true;
}

bool RawConnection::fill() {
  char buf[65536];
  const ssize_t n = recv(fd_, buf, sizeof buf, 0);
  if (n <= 0) return false;
  input_.append(buf, size_t(n));
  return true;
}

RawResponse RawConnection::read_response() {
  size_t head_end;
  while ((head_end = input_.find("\r\n\r\n")) == std::string::npos)
    if (!fill()) return {};
  RawResponse r;
  r.head = input_.substr(0, head_end + 2);
  size_t at = head_end + 4;
  r.status = std::stoi(r.head.substr(9, 3));
  const size_t length_at = r.head.find("\r\nContent-Length: ");
  if (length_at != std::string::npos) {
    const size_t length = std::stoul(r.head.substr(length_at + 18));
    while (input_.size() < at + length)
      if (!fill()) return {};
    r.body = input_.substr(at, length);
    input_.erase(0, at + length);
    return r;
  }
  for (;;) {  // chunked
    size_t line_end;
    while ((line_end = input_.find("\r\n", at)) == std::string::npos)
      if (!fill()) return {};
    const size_t size = std::stoul(input_.substr(at, line_end - at), nullptr, 16);
    while (input_.size() < line_end + 2 + size + 2)
      if (!fill()) return {};
    r.body += input_.substr(line_end + 2, size);
    at = line_end + 2 + size + 2;
    if (size == 0) break;
  }
  input_.erase(0, at);
  return r;
}

bool RawConnection::read_until(std::string_view text) {
  while (input_.find(text) == std::string::npos)
    if (!fill()) return false;
  return true;
}

bool RawConnection::closed_by_server() {
  char byte;
  return recv(fd_, &byte, 1, 0) == 0;
}

std::string get_request(int port, const std::string& path, const std::string& headers) {
  return "GET " + path + " HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(port) + "\r\n" + headers + "\r\n";
}

std::string post_request(int port, const std::string& path, const std::string& body) {
  return "POST " + path + " HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(port) +
         "\r\nContent-Type: application/json\r\nContent-Length: " + std::to_string(body.size()) + "\r\n\r\n" +
         body;
}

}  // namespace lp::test
