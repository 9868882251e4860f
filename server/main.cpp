// lightprobe-server: loads environment maps and answers HTTP/JSON requests about them.
#include <csignal>
#include <iostream>
#include <thread>

#include <spdlog/spdlog.h>
#include <tbb/global_control.h>

#include "server/envmap_loading.hpp"
#include "server/server.hpp"

namespace {

// SIGINT/SIGTERM are blocked in every thread (so first, before any thread starts) and waited for on
// a thread of their own, so stopping is ordinary code, not a signal handler.
sigset_t block_stop_signals() {
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGINT);
  sigaddset(&set, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &set, nullptr);
  return set;
}

std::jthread stop_on_signal(sigset_t set, lp::server::Server& server) {
  return std::jthread([set, &server] {
    int sig = 0;
    sigwait(&set, &sig);
    spdlog::info("signal {}: stopping", sig);
    server.stop();
  });
}

}  // namespace

int main(int argc, char** argv) {
  const sigset_t stop_signals = block_stop_signals();
  std::optional<lp::server::Options> options;
  try {
    lp::server::Options defaults;
    defaults.web_dir = LIGHTPROBE_WEB_DIR;  // the source tree's web/, set by CMake
    options = lp::server::parse_options(argc, argv, std::move(defaults));
  } catch (const std::exception& e) {
    std::cerr << "lightprobe-server: " << e.what() << "\n";
    return 2;
  }
  if (!options) return 0;
  spdlog::set_pattern("%Y-%m-%dT%H:%M:%S.%e %^%l%$ %v");
  std::optional<tbb::global_control> threads;
  if (options->threads > 0)
    threads.emplace(tbb::global_control::max_allowed_parallelism, size_t(options->threads));

  lp::server::App app(*options);
  if (options->list_routes) {
    lp::server::Server server(app);
    for (const auto& r : server.router().routes()) std::cout << r.method << " " << r.path << "\n";
    return 0;
  }
  try {
    for (const auto& [name, path] : options->loads) lp::server::register_envmap_file(app, name, path, "file:" + path);
    if (options->loads.empty()) lp::server::register_default_envmap(app);
  } catch (const std::exception& e) {
    spdlog::error("cannot load map: {}", e.what());
    return 1;
  }

  lp::server::Server server(app);
  auto signals = stop_on_signal(stop_signals, server);
  int port = 0;
  try {
    port = server.bind();
  } catch (const std::exception& e) {
    spdlog::error("{}", e.what());
    return 1;
  }
  spdlog::info("lightprobe-server {} listening on http://{}:{}", LIGHTPROBE_VERSION, options->host, port);
  server.run();
  spdlog::info("stopped");
  if (signals.joinable()) pthread_kill(signals.native_handle(), SIGTERM);  // wake it if it still waits
  return 0;
}
