#pragma once
// TLS for rediss:// over OpenSSL, on a socket of our own: writes never raise SIGPIPE (a Redis that
// closed the connection is a failed command, not a dead process).
#include <string>

#include "server/scale_out/redis_connection.hpp"

namespace lp::server {

// TLS on the connected socket `fd` (blocking, with its timeouts set): the server's certificate verified
// against the context's CAs, and its host name (or IP address) checked against `host`. The session, or
// nullptr with `why` set: then `refused` says whether the certificate was refused (not worth retrying)
// rather than the connection lost.
ssl_st* tls_handshake(int fd, const TlsContext& context, const std::string& host, std::string& why,
                      bool& refused);
void tls_close(ssl_st* ssl);
// Bytes sent or received, or <= 0 on failure (`why` set).
long tls_send(ssl_st* ssl, const char* data, size_t size, std::string& why);
long tls_receive(ssl_st* ssl, char* data, size_t size, std::string& why);

}  // namespace lp::server
