#include "drivers/replay/replay_source.h"

#include <algorithm>
#include <type_traits>

#include "base/overloaded.h"
#include "drivers/clock/monotonic_clock.h"

namespace deepnav {

bool ReplaySource::open(const std::string& path, std::string* error) {
  path_ = path;
  if (!reader_.open(path, error)) return false;
  // One pass over the times to know the span (the loop's clock offset depends on the first sample).
  bool any = false;
  const bool ok = reader_.forEach(
      true,
      [&](const ReplayEvent& e) {
        if (e.kind == ReplayEvent::Kind::kSolution || e.kind == ReplayEvent::Kind::kTruth) return true;
        if (!any) first_us_ = e.t_us;
        any = true;
        last_us_ = std::max(last_us_, e.t_us);
        return true;
      },
      error);
  if (ok && !any && error) *error = path + ": no sensor samples to replay";
  return ok && any;
}

void ReplaySource::start(LiveInputs* inputs, const LoopClock& clock) {
  inputs_ = inputs;
  clock_ = clock;
  stop_.store(false);
  finished_.store(false);
  thread_ = std::thread([this] { run(); });
}

void ReplaySource::stop() {
  stop_.store(true, std::memory_order_release);
  if (thread_.joinable()) thread_.join();
}

bool ReplaySource::push(const ReplayEvent& e) {
  if (e.kind == ReplayEvent::Kind::kFrame) {
    const int slot = inputs_->pool.acquire();
    if (slot < 0) return false;
    StereoFrame& f = inputs_->pool.frame(slot);
    f.t_us = e.frame->t_us;
    f.exposure_us = e.frame->exposure_us;
    f.sequence = e.frame->sequence;
    f.rectified = e.frame->rectified;
    if (e.frame->left.size() != f.left.size() || e.frame->left.type() != f.left.type()) {
      inputs_->pool.release(slot);
      return false;
    }
    e.frame->left.copyTo(f.left);
    e.frame->right.copyTo(f.right);
    if (!inputs_->frames.push(slot)) {
      inputs_->pool.release(slot);
      return false;
    }
    return true;
  }
  if (e.kind != ReplayEvent::Kind::kInput) return true;
  return std::visit(Overloaded{[](const VisionResult&) { return true; },  // the live vision worker recomputes them
                               [this](const auto& s) { return inputs_->ring<std::decay_t<decltype(s)>>().push(s); }},
                    e.input);
}

void ReplaySource::run() {
  std::string error;
  const bool ok = reader_.forEach(
      true,
      [&](const ReplayEvent& e) {
        if (stop_.load(std::memory_order_acquire)) return false;
        if (e.kind == ReplayEvent::Kind::kSolution || e.kind == ReplayEvent::Kind::kTruth) return true;
        sleepUntilUs(clock_.toMono(e.t_us));
        if (push(e)) {
          pushed_.fetch_add(1, std::memory_order_relaxed);
        } else {
          refused_.fetch_add(1, std::memory_order_relaxed);
        }
        return true;
      },
      &error);
  if (!ok) error_ = error;
  finished_.store(true, std::memory_order_release);
}

}  // namespace deepnav
