#pragma once
// Progress on standard error, with the rate (in samples per second, say) and the time left. On a
// terminal, a bar redrawn in place at each whole percent: "render [#####     ] 42%  3.1M samples/s  ETA
// 0:12"; elsewhere (a log file, a pipe), one line at each tenth: "render 40%  3.1M samples/s  ETA 0:12",
// from 10% to 100%, the last giving the time taken ("in 0:30") for the time left. The line's label may change
// as the work goes (a turntable's "render frame 3/36"). Thread-safe: workers report what they finished.
#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <optional>
#include <string>

namespace lp::cli {

enum class ProgressStyle { Off, Bar, Lines };

// Off when quiet, else Bar when standard error is a terminal, else Lines.
ProgressStyle progress_style(bool quiet);

class ProgressBar {
 public:
  // What the rate counts: `per_unit` of `name` ("samples") in each unit of work.
  struct Rate {
    double per_unit = 1;
    std::string name;
  };
  // `total` units of work; without a rate, only the time left is shown.
  ProgressBar(std::string label, int64_t total, ProgressStyle style, std::optional<Rate> rate = std::nullopt);

  // The label of the lines drawn from now on.
  void set_label(std::string label);
  void advance(int64_t done);
  // Draws 100% (if not drawn yet) and ends the bar's line.
  void finish();

 private:
  void draw(int percent);
  std::string figures(int percent) const;

  std::string label_;  // guarded by mutex_
  int64_t total_;
  ProgressStyle style_;
  std::optional<Rate> rate_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  std::atomic<int64_t> done_{0};
  std::atomic<int> drawn_{0};  // the highest percent a worker set out to draw
  std::mutex mutex_;
  int painted_ = 0;  // the percent shown (guarded by mutex_)
};

}  // namespace lp::cli
