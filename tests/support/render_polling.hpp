#pragma once
// Waiting for a render job to leave the queue: polls GET /api/v1/renders/{id} until its status is no
// longer queued or running. The deadline only keeps a broken server from hanging the suite; nothing is
// timed. Returns the final status (empty, with a test failure, past the deadline).
#include <gtest/gtest.h>
#include <httplib.h>

#include <chrono>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>

#include "support/http_reply.hpp"

namespace lp::test {

inline nlohmann::json finished_render(httplib::Client& client, const std::string& id) {
  using namespace std::chrono_literals;
  for (auto deadline = std::chrono::steady_clock::now() + 120s; std::chrono::steady_clock::now() < deadline;
       std::this_thread::sleep_for(20ms)) {
    const nlohmann::json st = reply(client.Get(("/api/v1/renders/" + id).c_str())).body_json();
    if (st["status"] != "queued" && st["status"] != "running") return st;
  }
  ADD_FAILURE() << "render " << id << " did not finish";
  return {};
}

}  // namespace lp::test
