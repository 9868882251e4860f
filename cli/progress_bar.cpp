#include "cli/progress_bar.hpp"

#include <algorithm>
#include <cstdio>

namespace lp::cli {
namespace {

constexpr int kWidth = 40;  // characters between the brackets

}  // namespace

ProgressBar::ProgressBar(std::string label, int64_t total, bool enabled)
    : label_(std::move(label)), total_(std::max<int64_t>(total, 1)), enabled_(enabled) {
  if (enabled_) draw(0);
}

void ProgressBar::advance(int64_t done) {
  if (!enabled_) return;
  const int64_t now = done_ += done;
  const int percent = int(std::min<int64_t>(100, now * 100 / total_));
  int drawn = drawn_.load();
  while (percent > drawn)
    if (drawn_.compare_exchange_weak(drawn, percent)) {
      draw(percent);
      return;
    }
}

void ProgressBar::finish() {
  if (!enabled_) return;
  draw(100);
  std::fputc('\n', stderr);
}

void ProgressBar::draw(int percent) {
  std::lock_guard lock(mutex_);
  if (percent <= painted_) return;  // a later percent was painted first
  painted_ = percent;
  const int filled = percent * kWidth / 100;
  std::fprintf(stderr, "\r%s [%s%s] %3d%%", label_.c_str(), std::string(size_t(filled), '#').c_str(),
               std::string(size_t(kWidth - filled), ' ').c_str(), percent);
  std::fflush(stderr);
}

}  // namespace lp::cli
