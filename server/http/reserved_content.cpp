#include "server/http/reserved_content.hpp"

#include <memory>

#include "engine/image/encode_memory.hpp"
#include "engine/image/image_io.hpp"
#include "server/http/conditional_get.hpp"

namespace lp::server {
namespace {

struct ReservedBody {
  std::vector<uint8_t> bytes;
  MemoryReservation memory;
};

}  // namespace

void send_reserved(httplib::Response& res, std::vector<uint8_t> bytes, const std::string& content_type,
                   MemoryReservation memory) {
  const std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  if (answer_not_modified(res, text, content_type)) return;
  memory.resize(int64_t(bytes.size()));
  auto body = std::make_shared<ReservedBody>(ReservedBody{std::move(bytes), std::move(memory)});
  const size_t size = body->bytes.size();
  res.set_content_provider(size, content_type, [body](size_t offset, size_t length, httplib::DataSink& sink) {
    return sink.write(reinterpret_cast<const char*>(body->bytes.data()) + offset, length);
  });
}

void send_png_picture(httplib::Response& res, const MemoryBudget& budget, int64_t width, int64_t height,
                      int64_t drawing_bytes, std::string_view what,
                      const std::function<std::vector<uint8_t>()>& draw) {
  auto memory =
      budget.reserve(drawing_bytes + png_rgb8_encode_bytes(width, height), MemoryUse::Transient, what);
  send_reserved(res, encode_png_rgb8(draw(), int(width), int(height)), "image/png", std::move(memory));
}

}  // namespace lp::server
