#pragma once
// A map of constant radiance 1 (a white furnace) uploaded to the real server.
#include <httplib.h>

#include <string>

#include "engine/image/image.hpp"
#include "engine/image/image_io.hpp"
#include "support/http_reply.hpp"

namespace lp::test {

// Uploads a 64 x 32 map of radiance 1 in every channel as `name`: 201, or 409 when a test uploaded it before.
inline Reply upload_white_map(httplib::Client& client, const std::string& name) {
  Image white(64, 32);
  for (int y = 0; y < white.height(); ++y)
    for (int x = 0; x < white.width(); ++x) white.set(x, y, {1, 1, 1});
  const auto pfm = write_pfm(white);
  return reply(client.Post(("/api/v1/envmaps?name=" + name).c_str(),
                           reinterpret_cast<const char*>(pfm.data()), pfm.size(),
                           "application/octet-stream"));
}

}  // namespace lp::test
