#pragma once
// A map of constant radiance 1 (a white furnace) uploaded to the real server.
#include <gtest/gtest.h>
#include <httplib.h>

#include <string>

#include "engine/image/image.hpp"
#include "engine/image/image_io.hpp"
#include "support/http_reply.hpp"
#include "support/server_process.hpp"

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

// The white map as `name` on the server of `client`, uploaded by the first caller (201) and found by the
// next (409); returns `name`.
inline std::string ensure_white_map(httplib::Client& client, const std::string& name) {
  const Reply r = upload_white_map(client, name);
  EXPECT_TRUE(r.status == 201 || r.status == 409) << r.body;
  return name;
}

// A server of its own (default flags) for one test binary, with the white map as "white".
inline ServerProcess& white_map_server() {
  static ServerProcess s;
  static const std::string white = ensure_white_map(*s.client(), "white");
  return s;
}

}  // namespace lp::test
