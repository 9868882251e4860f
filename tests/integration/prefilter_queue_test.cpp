// What prefilter jobs may take of the real server: queued jobs hold no memory until they start, one
// client's share of the queue is bounded (429) while another client is still accepted, and a chain
// over the cost limit is refused naming it.
#include <gtest/gtest.h>

#include <chrono>
#include <nlohmann/json.hpp>
#include <regex>
#include <string>
#include <thread>
#include <vector>

#include "api/prefilter_request.hpp"
#include "support/http_reply.hpp"
#include "support/process_status.hpp"
#include "support/server_process.hpp"
#include "support/white_map.hpp"

namespace lp {
namespace {

using nlohmann::json;
using test::Reply;

// A chain long to make (11 levels from 2048 texels wide: 7.2e8 texel samples with 1024 samples) and
// large to make it in (tens of MiB); `samples` apart, so that no two of them are one chain.
std::string long_chain(int samples) {
  return json({{"levels", 11}, {"base_size", 2048}, {"samples", samples}}).dump();
}

class PrefilterServer {
 public:
  explicit PrefilterServer(const std::vector<std::string>& flags)
      : server_(flags), client_(server_.client()) {
    EXPECT_EQ(test::upload_white_map(*client_, "white").status, 201);
  }
  Reply submit(const std::string& body, const std::string& client = "") const {
    httplib::Headers headers;
    if (!client.empty()) headers.emplace("X-Forwarded-For", client);
    return test::reply(client_->Post("/api/v1/envmaps/white/prefilter", headers, body, "application/json"));
  }
  Reply del(const std::string& url) const { return test::reply(client_->Delete(url.c_str())); }
  json status(const std::string& url) const { return test::reply(client_->Get(url.c_str())).body_json(); }
  // Bytes reserved from the memory budget by work in flight (GET /metrics).
  double transient_bytes() const {
    const std::string text = test::reply(client_->Get("/metrics")).body;
    std::smatch m;
    const std::regex line(R"re(lightprobe_memory_used_bytes\{use="transient"\} ([0-9.e+]+))re");
    return std::regex_search(text, m, line) ? std::stod(m[1]) : -1;
  }
  void wait_running(const std::string& url) const {
    for (int i = 0; i < 3000 && status(url)["status"] == "queued"; ++i)
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  // Cancels every job (queued at once, the running one at its next row).
  void cancel_all(const std::vector<std::string>& urls) const {
    for (const std::string& url : urls) del(url);
  }
  int pid() const { return server_.pid(); }

 private:
  test::ServerProcess server_;
  std::unique_ptr<httplib::Client> client_;
};

TEST(PrefilterQueue, QueuedJobsHoldNoMemoryUntilTheyStart) {
  PrefilterServer s({"--max-memory-mb", "256", "--max-prefilters-per-client", "16"});
  const Reply first = s.submit(long_chain(1024));
  ASSERT_EQ(first.status, 202) << first.body;
  std::vector<std::string> urls = {first.header("Location")};
  s.wait_running(urls[0]);
  const double running = s.transient_bytes();  // the one job's working memory (and little else)
  const double peak_running = test::peak_rss_mib(s.pid());
  EXPECT_GT(running, 32 << 20);
  for (int i = 1; i < 12; ++i) {
    const Reply r = s.submit(long_chain(1024 + i));
    EXPECT_EQ(r.status, 202) << "job " << i << ": " << r.body;
    if (r.status == 202) urls.push_back(r.header("Location"));
  }
  const double queued = s.transient_bytes();
  const double peak_queued = test::peak_rss_mib(s.pid());
  std::printf(
      "working memory reserved: %.1f MiB running one job, %.1f MiB with %zu more queued; VmHWM %.1f -> "
      "%.1f MiB\n",
      running / (1 << 20), queued / (1 << 20), urls.size() - 1, peak_running, peak_queued);
  EXPECT_LE(queued, running + (1 << 20)) << "bytes reserved with 11 jobs queued behind the running one";
  EXPECT_EQ(s.status(urls[1])["status"], "queued");
  s.cancel_all(urls);
}

TEST(PrefilterQueue, OneClientsShareOfTheQueueIsBoundedAnotherClientIsStillAccepted) {
  PrefilterServer s({"--trusted-proxy", "127.0.0.1", "--max-prefilters-per-client", "2"});
  const std::string a = "203.0.113.7", b = "203.0.113.8";
  const Reply running = s.submit(long_chain(1024), a);
  const Reply queued = s.submit(long_chain(1025), a);
  ASSERT_EQ(running.status, 202) << running.body;
  ASSERT_EQ(queued.status, 202) << queued.body;
  const Reply refused = s.submit(long_chain(1026), a);
  EXPECT_EQ(refused.status, 429) << refused.body;
  EXPECT_EQ(refused.body_json()["error"]["code"], "too_many_jobs");
  const std::string message = refused.body_json()["error"]["message"];
  EXPECT_NE(message.find("client 203.0.113.7 has 2 prefilter jobs queued or running"), std::string::npos)
      << message;
  EXPECT_NE(message.find("--max-prefilters-per-client"), std::string::npos) << message;
  EXPECT_FALSE(refused.header("Retry-After").empty());
  const Reply other = s.submit(long_chain(1027), b);
  EXPECT_EQ(other.status, 202) << other.body;
  // A queued job cancelled gives its place back at once.
  EXPECT_EQ(s.del(queued.header("Location")).status, 202);
  const Reply again = s.submit(long_chain(1028), a);
  EXPECT_EQ(again.status, 202) << again.body;
  s.cancel_all({running.header("Location"), other.header("Location"), again.header("Location")});
}

TEST(PrefilterQueue, AChainOverTheCostLimitIsRefusedNamingIt) {
  PrefilterServer s({});
  // The fields' largest values: 11.5e9 texel samples.
  const Reply r = s.submit(R"({"levels":11,"base_size":2048,"samples":16384})");
  EXPECT_EQ(r.status, 400) << r.body;
  EXPECT_EQ(r.body_json()["error"]["code"], "invalid_field");
  const std::string message = r.body_json()["error"]["message"];
  EXPECT_NE(message.find("11455332352 texel samples"), std::string::npos) << message;
  EXPECT_NE(message.find("texel_samples <= " + std::to_string(api::kPrefilterTexelSamples.max)),
            std::string::npos)
      << message;
  // At the limit's side: a long chain is accepted and states its cost.
  const Reply ok = s.submit(long_chain(1024));
  ASSERT_EQ(ok.status, 202) << ok.body;
  EXPECT_LE(ok.body_json()["texel_samples"].get<int64_t>(), api::kPrefilterTexelSamples.max);
  s.cancel_all({ok.header("Location")});
}

}  // namespace
}  // namespace lp
