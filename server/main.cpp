// lightprobe-server: loads environment maps and answers HTTP/JSON requests about them.
#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <tbb/global_control.h>

#include <csignal>
#include <cstdlib>
#include <future>
#include <iostream>
#include <thread>

#include "server/data_dir.hpp"
#include "server/envmap_loading.hpp"
#include "server/logging.hpp"
#include "server/server.hpp"
#include "server/shutdown.hpp"
#include "server/stored_assets.hpp"
#include "server/stored_maps.hpp"
#include "server/stored_renders.hpp"

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

// Waits for a stop signal (or the end of run(), which raises one), runs the shutdown sequence, and
// ends the process itself if connections hold the transport past the bound.
std::jthread stop_on_signal(sigset_t set, lp::server::App& app, lp::server::Server& server,
                            std::shared_future<void> stopped) {
  return std::jthread([set, &app, &server, stopped] {
    int sig = 0;
    sigwait(&set, &sig);
    spdlog::info("signal {}: stopping", sig);
    lp::server::shut_down(app, server);
    if (stopped.wait_for(lp::server::kConnectionDrain) == std::future_status::ready) return;
    spdlog::warn("connections still open {} ms after the stop: exiting without them",
                 lp::server::kConnectionDrain.count());
    spdlog::shutdown();
    std::_Exit(0);
  });
}

// Everything before serving; false (after logging why) if the server cannot start.
bool prepare(lp::server::App& app, lp::server::Server& server, int& port) {
  const auto& options = app.options;
  try {
    app.state = std::make_unique<lp::server::StateStore>(options.state_dir);
    port = server.bind();  // before loading anything, so a port in use fails at once
    for (const auto& [name, path] : options.loads)
      lp::server::register_envmap_file(app, name, path, "file:" + path);
    if (options.loads.empty()) lp::server::register_default_envmap(app);
  } catch (const std::exception& e) {
    spdlog::error("cannot start: {}", e.what());
    return false;
  }
  lp::server::restore_maps(app);
  lp::server::restore_assets(app);  // before the renders, whose scenes may name assets
  lp::server::restore_renders(app);
  return true;
}

// The address is logged, and printed on stdout when the log level hides it: with --port 0 it is how
// a process manager or a test learns the port.
void announce_listening(const std::string& host, int port) {
  const std::string line =
      fmt::format("lightprobe-server {} listening on http://{}:{}", LIGHTPROBE_VERSION, host, port);
  if (spdlog::should_log(spdlog::level::info))
    spdlog::info("{}", line);
  else
    std::cout << line << std::endl;
}

}  // namespace

int main(int argc, char** argv) {
  const sigset_t stop_signals = block_stop_signals();
  std::optional<lp::server::Options> options;
  try {
    lp::server::Options defaults;
    defaults.web_dir = LIGHTPROBE_WEB_DIR;  // the source tree's web/, set by CMake
    options = lp::server::parse_options(argc, argv, std::move(defaults));
    if (options) lp::server::check_data_dir(*options);
  } catch (const std::exception& e) {
    std::cerr << "lightprobe-server: " << e.what() << "\n";
    return 2;
  }
  if (!options) return 0;
  lp::server::Logging logging(options->log_level);
  std::optional<tbb::global_control> threads;
  if (options->threads > 0)
    threads.emplace(tbb::global_control::max_allowed_parallelism, size_t(options->threads));

  lp::server::App app(*options);
  lp::server::Server server(app);
  if (options->list_routes) {
    for (const auto& r : server.router().routes()) std::cout << r.method << " " << r.path << "\n";
    return 0;
  }
  int port = 0;
  if (!prepare(app, server, port)) return 1;

  std::promise<void> run_returned;
  auto signals = stop_on_signal(stop_signals, app, server, run_returned.get_future().share());
  announce_listening(options->host, port);
  server.run();
  run_returned.set_value();
  pthread_kill(signals.native_handle(), SIGTERM);  // if run() ended by itself, the sequence still runs
  signals.join();
  spdlog::info("stopped");
  return 0;
}
