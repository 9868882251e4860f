#pragma once
// Polls a job's status until a condition holds, failing the test after a generous deadline (not a timing
// assertion: it only keeps a broken server from hanging the suite).
#include <gtest/gtest.h>

#include <chrono>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>

namespace lp::test {

// `status()` fetches the status JSON, `done(status)` says whether to stop; returns the last status.
template <class Status, class Pred>
nlohmann::json poll_until(const std::string& what, Status&& status, Pred&& done) {
  using namespace std::chrono_literals;
  const auto deadline = std::chrono::steady_clock::now() + 120s;
  nlohmann::json st;
  while (std::chrono::steady_clock::now() < deadline) {
    st = status();
    if (done(st)) return st;
    std::this_thread::sleep_for(20ms);
  }
  ADD_FAILURE() << what << " did not reach the awaited state: " << st.dump();
  return st;
}

}  // namespace lp::test
