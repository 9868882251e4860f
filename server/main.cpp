// lightprobe-server: loads environment maps and answers HTTP/JSON requests about them.
#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <tbb/global_control.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <future>
#include <iostream>
#include <thread>

#include "server/assets/stored_assets.hpp"
#include "server/health_check.hpp"
#include "server/jobs/job_arena.hpp"
#include "server/maps/envmap_loading.hpp"
#include "server/maps/stored_maps.hpp"
#include "server/observability/logging.hpp"
#include "server/renders/render_worker.hpp"
#include "server/renders/stored_renders.hpp"
#include "server/server.hpp"
#include "server/shutdown.hpp"
#include "server/storage/data_dir.hpp"

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

// Everything before serving: the state directory taken and the port bound; false (after logging why) if
// the server cannot start.
bool prepare(lp::server::App& app, lp::server::Server& server, int& port) {
  try {
    app.state = std::make_unique<lp::server::StateStore>(app.options.state_dir);
    port = server.bind();
  } catch (const std::exception& e) {
    spdlog::error("cannot start: {}", e.what());
    return false;
  }
  return true;
}

// While the server answers (the API with 503 not_ready, the probes as they are): the maps to load at
// start and the state directory; then the server is ready. False (after logging why) if a map of --load
// cannot be loaded.
bool load(lp::server::App& app) {
  const auto start = std::chrono::steady_clock::now();
  try {
    for (const auto& [name, path] : app.options.loads)
      lp::server::register_envmap_file(app, name, path, "file:" + path);
    if (app.options.loads.empty()) lp::server::register_default_envmap(app);
  } catch (const std::exception& e) {
    spdlog::error("cannot start: {}", e.what());
    return false;
  }
  lp::server::restore_maps(app);
  lp::server::restore_assets(app);  // before the renders, whose scenes may name assets
  lp::server::restore_renders(app);
  app.ready.store(true);
  spdlog::info("ready: maps and state loaded in {:.2f} s",
               std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
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
    if (options && options->health_check_url.empty()) {
      lp::server::check_data_dir(*options);
      lp::server::load_auth_token(*options);
    }
  } catch (const std::exception& e) {
    std::cerr << "lightprobe-server: " << e.what() << "\n";
    return 2;
  }
  if (!options) return 0;
  if (!options->health_check_url.empty()) {
    try {
      return lp::server::run_health_check(
          lp::server::health_check_target(options->health_check_url, options->host, options->port));
    } catch (const std::exception& e) {
      std::cerr << "lightprobe-server: " << e.what() << "\n";
      return 2;
    }
  }
  lp::server::Logging logging(options->log.level, options->log.format);
  // Render arenas run on workers alone (jobs/job_arena.hpp): the limit counts them and one caller.
  const tbb::global_control threads(
      tbb::global_control::max_allowed_parallelism,
      lp::server::JobArena::worker_threads(options->threads, lp::server::job_arenas(*options)) + 1);

  lp::server::App app(*options);
  lp::server::Server server(app);
  if (options->list_routes) {
    for (const auto& r : server.router().routes()) std::cout << r.method << " " << r.path << "\n";
    return 0;
  }
  int port = 0;
  if (!prepare(app, server, port)) return 1;
  if (app.options.scale_out.advertise_url.empty())
    app.options.scale_out.advertise_url = fmt::format("http://{}:{}", options->host, port);
  std::optional<lp::server::RenderWorker> worker;  // with --redis, unless --role api

  std::promise<void> run_returned;
  auto signals = stop_on_signal(stop_signals, app, server, run_returned.get_future().share());
  announce_listening(options->host, port);
  std::atomic<bool> loaded{false}, failed{false};
  std::thread loading([&] {
    failed = !load(app);
    if (!failed && app.options.scale_out.redis && app.options.scale_out.role != lp::server::ServerRole::Api)
      worker.emplace(app, lp::server::worker_name());
    loaded = true;
    if (failed) pthread_kill(signals.native_handle(), SIGTERM);  // stops the server, exit status 1
  });
  server.run();
  run_returned.set_value();
  pthread_kill(signals.native_handle(), SIGTERM);  // if run() ended by itself, the sequence still runs
  signals.join();
  if (!loaded) {  // stopped while loading: a read of a large map need not be waited for
    spdlog::info("stopped while loading");
    spdlog::shutdown();
    std::_Exit(0);
  }
  loading.join();
  spdlog::info("stopped");
  return failed ? 1 : 0;
}
