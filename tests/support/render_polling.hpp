#pragma once
// Waiting for a job (a render, a prefilter) to leave the queue: polls its status until it is no longer
// queued or running. The deadline only keeps a broken server from hanging the suite; nothing is timed.
// Returns the final status (empty, with a test failure, past the deadline).
#include <gtest/gtest.h>
#include <httplib.h>

#include <chrono>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>

#include "support/http_reply.hpp"

namespace lp::test {

// A job has ended once it is neither queued nor running: done, failed, cancelled or interrupted.
inline bool job_ended(const nlohmann::json& status) {
  return status["status"] != "queued" && status["status"] != "running";
}

// `url` is the job's status, e.g. "/api/v1/prefilters/3f9c0a7d12e4b856".
inline nlohmann::json finished_job(httplib::Client& client, const std::string& url) {
  using namespace std::chrono_literals;
  for (auto deadline = std::chrono::steady_clock::now() + 120s; std::chrono::steady_clock::now() < deadline;
       std::this_thread::sleep_for(20ms)) {
    const nlohmann::json st = reply(client.Get(url.c_str())).body_json();
    if (job_ended(st)) return st;
  }
  ADD_FAILURE() << url << " did not finish";
  return {};
}

inline nlohmann::json finished_render(httplib::Client& client, const std::string& id) {
  return finished_job(client, "/api/v1/renders/" + id);
}

}  // namespace lp::test
