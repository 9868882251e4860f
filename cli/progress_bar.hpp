#pragma once
// A progress bar on standard error, redrawn in place at each whole percent: "render [#####   ] 42%".
// Thread-safe: workers report what they finished.
#include <atomic>
#include <cstdint>
#include <mutex>
#include <string>

namespace lp::cli {

class ProgressBar {
 public:
  // A disabled bar draws nothing.
  ProgressBar(std::string label, int64_t total, bool enabled);

  void advance(int64_t done);
  // Draws 100% and ends the line.
  void finish();

 private:
  void draw(int percent);

  std::string label_;
  int64_t total_;
  bool enabled_;
  std::atomic<int64_t> done_{0};
  std::atomic<int> drawn_{-1};  // the highest percent a worker set out to draw
  std::mutex mutex_;
  int painted_ = -1;  // the percent on screen (guarded by mutex_)
};

}  // namespace lp::cli
