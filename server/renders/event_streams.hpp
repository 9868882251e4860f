#pragma once
// Render event streams (GET /api/v1/renders/{id}/events): how many may be open at once, and the slot one
// holds while it is. The flag of the limit is declared here.
#include <atomic>

#include "api/parameters.hpp"

namespace lp::server {

inline constexpr api::IntParameter kMaxEventStreams{
    "max-event-streams", 8, {0, 4096}, "concurrent render event streams"};

// One slot of the bounded number of event streams; released when the stream (and its provider) goes.
class StreamSlot {
 public:
  StreamSlot(std::atomic<int>& count, int max) : count_(&count) {
    if (count_->fetch_add(1) >= max) {
      count_->fetch_sub(1);
      count_ = nullptr;
    }
  }
  ~StreamSlot() {
    if (count_) count_->fetch_sub(1);
  }
  StreamSlot(const StreamSlot&) = delete;
  StreamSlot& operator=(const StreamSlot&) = delete;
  bool acquired() const { return count_ != nullptr; }

 private:
  std::atomic<int>* count_;
};

}  // namespace lp::server
