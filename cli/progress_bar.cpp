#include "cli/progress_bar.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace lp::cli {
namespace {

constexpr int kWidth = 40;  // characters between the brackets

// 950, 12.3k, 4.56M, 1.2G
std::string si(double value) {
  if (value < 1e3) return fmt::format("{:.0f}", value);
  if (value < 1e6) return fmt::format("{:.1f}k", value / 1e3);
  if (value < 1e9) return fmt::format("{:.2f}M", value / 1e6);
  return fmt::format("{:.2f}G", value / 1e9);
}

// 0:07, 12:34, 1:02:03
std::string clock_time(double seconds) {
  const int64_t s = int64_t(std::max(0.0, seconds) + 0.5);
  if (s < 3600) return fmt::format("{}:{:02}", s / 60, s % 60);
  return fmt::format("{}:{:02}:{:02}", s / 3600, s / 60 % 60, s % 60);
}

}  // namespace

ProgressStyle progress_style(bool quiet) {
  if (quiet) return ProgressStyle::Off;
  return isatty(STDERR_FILENO) ? ProgressStyle::Bar : ProgressStyle::Lines;
}

ProgressBar::ProgressBar(std::string label, int64_t total, ProgressStyle style, std::optional<Rate> rate)
    : label_(std::move(label)), total_(std::max<int64_t>(total, 1)), style_(style), rate_(std::move(rate)) {
  if (style_ == ProgressStyle::Bar) {
    painted_ = -1;
    draw(0);
  }
}

void ProgressBar::set_label(std::string label) {
  std::lock_guard lock(mutex_);
  label_ = std::move(label);
}

void ProgressBar::advance(int64_t done) {
  if (style_ == ProgressStyle::Off) return;
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
  if (style_ == ProgressStyle::Off) return;
  draw(100);
  if (style_ == ProgressStyle::Bar) std::fputc('\n', stderr);
  std::fflush(stderr);
}

std::string ProgressBar::figures(int percent) const {
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double done = double(std::min(done_.load(), total_));
  std::string out = fmt::format("{}%  ", percent);
  if (rate_)
    out += fmt::format("{} {}/s  ", si(elapsed > 0 ? done * rate_->per_unit / elapsed : 0), rate_->name);
  if (percent >= 100) return out + "in " + clock_time(elapsed);
  return out + (done > 0 ? "ETA " + clock_time(elapsed * (double(total_) - done) / done) : "ETA -:--");
}

void ProgressBar::draw(int percent) {
  std::lock_guard lock(mutex_);
  if (percent <= painted_) return;  // a later percent was drawn first
  if (style_ == ProgressStyle::Bar) {
    const int filled = percent * kWidth / 100;
    // \033[K clears what a longer line before left on the right.
    std::fprintf(stderr, "\r%s [%s%s] %s\033[K", label_.c_str(), std::string(size_t(filled), '#').c_str(),
                 std::string(size_t(kWidth - filled), ' ').c_str(), figures(percent).c_str());
  } else {
    for (int tenth = painted_ / 10 + 1; tenth <= percent / 10; ++tenth)
      std::fprintf(stderr, "%s %s\n", label_.c_str(), figures(tenth * 10).c_str());
  }
  painted_ = percent;
  std::fflush(stderr);
}

}  // namespace lp::cli
