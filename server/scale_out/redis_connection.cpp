#include "server/scale_out/redis_connection.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <hiredis/hiredis.h>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "server/scale_out/redis_tls.hpp"

namespace lp::server {
namespace {

constexpr int kKeepAliveIdleS = 15;  // as hiredis's redisEnableKeepAlive
constexpr size_t kReadChunk = 16 * 1024;

// hiredis's createArray, which every reader starts with (its static defaultFunctions).
void* (*hiredis_create_array)(const redisReadTask*, int) = nullptr;

// An array over the bound is not allocated: its count goes where the reader's privdata points (if
// anywhere), and the reader fails ("Out of memory", for any null object).
void* create_bounded_array(const redisReadTask* task, int elements) {
  if (elements <= kMaxRedisArrayElements) return hiredis_create_array(task, elements);
  if (task->privdata) *static_cast<int*>(task->privdata) = elements;
  return nullptr;
}

void set_timeouts(int fd, std::chrono::milliseconds timeout) {
  const timeval tv{static_cast<time_t>(timeout.count() / 1000),
                   static_cast<suseconds_t>(timeout.count() % 1000 * 1000)};
  setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &tv, sizeof tv);
  setsockopt(fd, SOL_SOCKET, SO_SNDTIMEO, &tv, sizeof tv);
}

void keep_alive(int fd) {
  const int on = 1, idle = kKeepAliveIdleS, interval = kKeepAliveIdleS / 3, count = 3;
  setsockopt(fd, SOL_SOCKET, SO_KEEPALIVE, &on, sizeof on);
  setsockopt(fd, IPPROTO_TCP, TCP_KEEPIDLE, &idle, sizeof idle);
  setsockopt(fd, IPPROTO_TCP, TCP_KEEPINTVL, &interval, sizeof interval);
  setsockopt(fd, IPPROTO_TCP, TCP_KEEPCNT, &count, sizeof count);
  setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &on, sizeof on);
}

// A socket connected to one of `host`'s addresses within `timeout`, blocking; -1 with `why` set.
int connect_socket(const RedisAddress& address, std::chrono::milliseconds timeout, std::string& why) {
  addrinfo hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = SOCK_STREAM;
  addrinfo* found = nullptr;
  if (const int error =
          getaddrinfo(address.host.c_str(), std::to_string(address.port).c_str(), &hints, &found)) {
    why = gai_strerror(error);
    return -1;
  }
  const std::unique_ptr<addrinfo, void (*)(addrinfo*)> addresses(found, freeaddrinfo);
  for (const addrinfo* a = found; a; a = a->ai_next) {
    const int fd = socket(a->ai_family, a->ai_socktype | SOCK_CLOEXEC | SOCK_NONBLOCK, a->ai_protocol);
    if (fd < 0) continue;
    int error = connect(fd, a->ai_addr, a->ai_addrlen) == 0 ? 0 : errno;
    if (error == EINPROGRESS) {
      pollfd p{fd, POLLOUT, 0};
      socklen_t length = sizeof error;
      error =
          poll(&p, 1, int(timeout.count())) == 1 && getsockopt(fd, SOL_SOCKET, SO_ERROR, &error, &length) == 0
              ? error
              : ETIMEDOUT;
    }
    if (error == 0) {
      fcntl(fd, F_SETFL, fcntl(fd, F_GETFL) & ~O_NONBLOCK);
      return fd;
    }
    why = std::strerror(error);
    close(fd);
  }
  return -1;
}

}  // namespace

RedisReaderPtr bounded_reader(int* refused) {
  RedisReaderPtr reader(redisReaderCreate(), redisReaderFree);
  if (!reader) throw RedisError("cannot allocate a Redis reader");
  static redisReplyObjectFunctions functions = [&] {
    hiredis_create_array = reader->fn->createArray;
    redisReplyObjectFunctions f = *reader->fn;
    f.createArray = create_bounded_array;
    return f;
  }();
  reader->fn = &functions;
  reader->privdata = refused;
  return reader;
}

RedisReply copy_reply(const redisReply& r) {
  RedisReply out;
  switch (r.type) {
    case REDIS_REPLY_INTEGER:
      out.type = RedisReply::Type::Integer;
      out.integer = r.integer;
      break;
    case REDIS_REPLY_STRING:
    case REDIS_REPLY_STATUS:
      out.type = r.type == REDIS_REPLY_STRING ? RedisReply::Type::String : RedisReply::Type::Status;
      out.text.assign(r.str, r.len);
      break;
    case REDIS_REPLY_ARRAY:
      out.type = RedisReply::Type::Array;
      for (size_t i = 0; i < r.elements; ++i) out.elements.push_back(copy_reply(*r.element[i]));
      break;
    default:
      break;
  }
  return out;
}

RedisConnection::RedisConnection(const RedisAddress& address, const TlsContext& tls,
                                 std::chrono::milliseconds connect_timeout,
                                 std::chrono::milliseconds io_timeout)
    : url_(address.url()), reader_(bounded_reader(&refused_elements_)) {
  std::string why;
  fd_ = connect_socket(address, connect_timeout, why);
  if (fd_ < 0) throw RedisError(fmt::format("cannot connect to {}: {}", url_, why));
  keep_alive(fd_);
  set_timeouts(fd_, connect_timeout);
  if (address.tls) {
    bool refused = false;
    ssl_ = tls_handshake(fd_, tls, address.host, why, refused);
    if (!ssl_) {
      close(fd_);
      const std::string message = fmt::format("cannot connect to {}: {}", url_, why);
      if (refused)
        throw RedisRefusal(message +
                           (address.tls_files.ca.empty()
                                ? " (trusted: the system's CA store; see --redis-tls-ca)"
                                : " (trusted: the CAs of --redis-tls-ca " + address.tls_files.ca + ")"));
      throw RedisError(message);
    }
  }
  set_timeouts(fd_, io_timeout);
}

RedisConnection::~RedisConnection() {
  if (ssl_) tls_close(ssl_);
  if (fd_ >= 0) close(fd_);
}

void RedisConnection::fail(std::string why) {
  if (failure_.empty()) failure_ = std::move(why);
}

bool RedisConnection::send_all(const char* data, size_t size) {
  while (size > 0) {
    std::string why;
    const long sent = ssl_ ? tls_send(ssl_, data, size, why) : long(send(fd_, data, size, MSG_NOSIGNAL));
    if (sent < 0 && !ssl_ && errno == EINTR) continue;
    if (sent <= 0) {
      fail(ssl_ ? why : (errno == EAGAIN ? "timed out" : std::strerror(errno)));
      return false;
    }
    data += sent;
    size -= size_t(sent);
  }
  return true;
}

long RedisConnection::receive(char* data, size_t size) {
  for (;;) {
    std::string why;
    const long got = ssl_ ? tls_receive(ssl_, data, size, why) : long(recv(fd_, data, size, 0));
    if (got < 0 && !ssl_ && errno == EINTR) continue;
    if (got == 0) fail("connection closed");
    if (got < 0) fail(ssl_ ? why : (errno == EAGAIN ? "timed out" : std::strerror(errno)));
    return got;
  }
}

RedisReplyPtr RedisConnection::exchange(const std::vector<std::string_view>& args) {
  RedisReplyPtr none(nullptr, freeReplyObject);
  if (!failure_.empty()) return none;
  std::vector<const char*> argv;
  std::vector<size_t> lengths;
  for (const auto a : args) {
    argv.push_back(a.data());
    lengths.push_back(a.size());
  }
  char* command = nullptr;
  const int size = redisFormatCommandArgv(&command, int(argv.size()), argv.data(), lengths.data());
  if (size < 0) throw RedisError("cannot encode a Redis command");
  const std::unique_ptr<char, void (*)(char*)> encoded(command, redisFreeCommand);
  if (!send_all(command, size_t(size))) return none;
  refused_elements_ = 0;
  char buffer[kReadChunk];
  for (;;) {
    void* raw = nullptr;
    if (redisReaderGetReply(reader_.get(), &raw) != REDIS_OK) {
      if (refused_elements_ > 0) {
        fail("an array over the bound");
        throw RedisRefusal(fmt::format("{} answered an array of {} elements, over the bound of {}", url_,
                                       refused_elements_, kMaxRedisArrayElements));
      }
      fail(std::string("protocol error: ") + reader_->errstr);
      return none;
    }
    if (raw) return RedisReplyPtr(static_cast<redisReply*>(raw), freeReplyObject);
    const long got = receive(buffer, sizeof buffer);
    if (got <= 0 || redisReaderFeed(reader_.get(), buffer, size_t(got)) != REDIS_OK) {
      fail("protocol error");
      return none;
    }
  }
}

}  // namespace lp::server
