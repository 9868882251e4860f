#include "server/scale_out/redis_tls.hpp"

#include <arpa/inet.h>
#include <fmt/format.h>
#include <openssl/err.h>
#include <openssl/ssl.h>
#include <openssl/x509v3.h>
#include <sys/socket.h>

#include <cerrno>
#include <cstdint>
#include <cstring>

namespace lp::server {
namespace {

int socket_of(BIO* bio) {
  return int(reinterpret_cast<intptr_t>(BIO_get_data(bio)));
}

int bio_write(BIO* bio, const char* data, int size) {
  BIO_clear_retry_flags(bio);
  const ssize_t sent = send(socket_of(bio), data, size_t(size), MSG_NOSIGNAL);
  if (sent < 0 && errno == EINTR) BIO_set_retry_write(bio);
  return int(sent);
}

int bio_read(BIO* bio, char* data, int size) {
  BIO_clear_retry_flags(bio);
  const ssize_t got = recv(socket_of(bio), data, size_t(size), 0);
  if (got < 0 && errno == EINTR) BIO_set_retry_read(bio);
  return int(got);
}

long bio_ctrl(BIO*, int command, long, void*) {
  return command == BIO_CTRL_FLUSH ? 1 : 0;
}

// A socket BIO sending with MSG_NOSIGNAL (OpenSSL's own writes with write(), which raises SIGPIPE).
BIO* socket_bio(int fd) {
  static BIO_METHOD* method = [] {
    BIO_METHOD* m = BIO_meth_new(BIO_get_new_index() | BIO_TYPE_SOURCE_SINK, "lightprobe redis socket");
    BIO_meth_set_write(m, bio_write);
    BIO_meth_set_read(m, bio_read);
    BIO_meth_set_ctrl(m, bio_ctrl);
    return m;
  }();
  BIO* bio = BIO_new(method);
  if (!bio) return nullptr;
  BIO_set_data(bio, reinterpret_cast<void*>(intptr_t(fd)));
  BIO_set_init(bio, 1);
  return bio;
}

// The last OpenSSL error queued, or the system's.
std::string openssl_error() {
  const unsigned long code = ERR_get_error();
  ERR_clear_error();
  if (code != 0) {
    char text[256];
    ERR_error_string_n(code, text, sizeof text);
    return text;
  }
  return errno != 0 ? std::strerror(errno) : "connection closed";
}

std::string ssl_failure(ssl_st* ssl, int result) {
  const int error = SSL_get_error(ssl, result);
  if (error == SSL_ERROR_ZERO_RETURN) return "connection closed";
  if (error == SSL_ERROR_SYSCALL && ERR_peek_error() == 0)
    return result == 0 || errno == 0 ? "connection closed" : std::strerror(errno);
  return openssl_error();
}

bool ip_address(const std::string& host) {
  unsigned char buffer[16];
  return inet_pton(AF_INET, host.c_str(), buffer) == 1 || inet_pton(AF_INET6, host.c_str(), buffer) == 1;
}

}  // namespace

TlsContext make_tls_context(const RedisTlsFiles& files) {
  TlsContext context(SSL_CTX_new(TLS_client_method()), SSL_CTX_free);
  if (!context) throw RedisRefusal("cannot create a TLS context: " + openssl_error());
  SSL_CTX_set_min_proto_version(context.get(), TLS1_2_VERSION);
  SSL_CTX_set_verify(context.get(), SSL_VERIFY_PEER, nullptr);
  const bool cas = files.ca.empty()
                       ? SSL_CTX_set_default_verify_paths(context.get()) == 1
                       : SSL_CTX_load_verify_locations(context.get(), files.ca.c_str(), nullptr) == 1;
  if (!cas)
    throw RedisRefusal(files.ca.empty() ? "cannot read the system's CA certificates: " + openssl_error()
                                        : "cannot read --redis-tls-ca " + files.ca + ": " + openssl_error());
  if (!files.cert.empty() && SSL_CTX_use_certificate_chain_file(context.get(), files.cert.c_str()) != 1)
    throw RedisRefusal("cannot read --redis-tls-cert " + files.cert + ": " + openssl_error());
  if (!files.key.empty() &&
      (SSL_CTX_use_PrivateKey_file(context.get(), files.key.c_str(), SSL_FILETYPE_PEM) != 1 ||
       SSL_CTX_check_private_key(context.get()) != 1))
    throw RedisRefusal("cannot use --redis-tls-key " + files.key + ": " + openssl_error());
  return context;
}

ssl_st* tls_handshake(int fd, const TlsContext& context, const std::string& host, std::string& why,
                      bool& refused) {
  refused = false;
  SSL* ssl = SSL_new(context.get());
  BIO* bio = ssl ? socket_bio(fd) : nullptr;
  if (!bio) {
    if (ssl) SSL_free(ssl);
    why = "cannot start TLS: " + openssl_error();
    return nullptr;
  }
  SSL_set_bio(ssl, bio, bio);
  X509_VERIFY_PARAM* param = SSL_get0_param(ssl);
  if (ip_address(host)) {
    X509_VERIFY_PARAM_set1_ip_asc(param, host.c_str());
  } else {
    SSL_set_tlsext_host_name(ssl, host.c_str());
    SSL_set1_host(ssl, host.c_str());
  }
  errno = 0;
  const int result = SSL_connect(ssl);
  if (result == 1) return ssl;
  const long verdict = SSL_get_verify_result(ssl);
  if (verdict != X509_V_OK) {
    refused = true;
    why =
        fmt::format("TLS: the server's certificate was refused: {}", X509_verify_cert_error_string(verdict));
  } else {
    why = "TLS handshake failed: " + ssl_failure(ssl, result);
  }
  SSL_free(ssl);
  return nullptr;
}

void tls_close(ssl_st* ssl) {
  SSL_free(ssl);  // no close_notify: the socket closes next, and a peer may be gone
}

long tls_send(ssl_st* ssl, const char* data, size_t size, std::string& why) {
  errno = 0;
  size_t sent = 0;
  const int result = SSL_write_ex(ssl, data, size, &sent);
  if (result == 1) return long(sent);
  why = ssl_failure(ssl, result);
  return -1;
}

long tls_receive(ssl_st* ssl, char* data, size_t size, std::string& why) {
  errno = 0;
  size_t got = 0;
  const int result = SSL_read_ex(ssl, data, size, &got);
  if (result == 1) return long(got);
  why = ssl_failure(ssl, result);
  return -1;
}

}  // namespace lp::server
