#include "server/reserved_content.hpp"

#include <memory>

namespace lp::server {
namespace {

struct ReservedBody {
  std::vector<uint8_t> bytes;
  MemoryReservation memory;
};

}  // namespace

void send_reserved(httplib::Response& res, std::vector<uint8_t> bytes, const std::string& content_type,
                   MemoryReservation memory) {
  memory.resize(int64_t(bytes.size()));
  auto body = std::make_shared<ReservedBody>(ReservedBody{std::move(bytes), std::move(memory)});
  const size_t size = body->bytes.size();
  res.set_content_provider(size, content_type, [body](size_t offset, size_t length, httplib::DataSink& sink) {
    return sink.write(reinterpret_cast<const char*>(body->bytes.data()) + offset, length);
  });
}

}  // namespace lp::server
