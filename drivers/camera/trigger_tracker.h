#pragma once
#include <cstdint>

#include "nav/types/time.h"

namespace deepnav {

// Which software trigger a camera's frame answers, for one camera. Pure logic, no clock, no lock (the
// driver guards it with a mutex shared by its trigger thread and its frame thread).
//
// Why: timestamps alone cannot tell the frames of two triggers apart once a frame is delayed by more
// than the trigger period minus the pairing tolerance (a loaded host, a slow camera thread): the left
// frame of trigger n+1 then lands within tolerance of the late right frame of trigger n and the two
// were paired (seen under CPU load: 1 mixed pair in 25). A camera does not tell which trigger a frame
// answers, and may merge two triggers that reach it while it is busy, so frame counters do not tell
// either. So the trigger side makes the answer unambiguous: at most one trigger is outstanding per
// camera (handshake), and the next frame (any status) answers it. A tick that comes while the
// previous trigger is unanswered is skipped for that camera (counted; the other camera's frame of that
// tick then finds no partner and is dropped, counted). A trigger unanswered for `timeout_us`, or
// whose write failed, is abandoned; at most one late frame can still come for it (handshake), so the
// camera is not triggered again until that frame has come or the line has been quiet for `quiet_us`.
// A frame whose leader packet arrived before the outstanding trigger was written cannot answer it and
// is dropped (the trigger stays outstanding): an incomplete GigE frame is handed over only when the
// next frame's packets arrive. Residual risk: a frame whose leader packet is stamped more than
// timeout_us + quiet_us after its trigger (the Aravis driver: 4 trigger periods, 200 ms at 20 Hz), after the next trigger's write, is taken for that trigger's; the pairing tolerance on the
// two cameras' frame times is the last check then.
class TriggerTracker {
 public:
  struct Counts {
    std::uint64_t skipped = 0;       // ticks not triggered: previous trigger unanswered, or waiting for quiet
    std::uint64_t timeouts = 0;      // triggers never answered within timeout_us
    std::uint64_t unattributed = 0;  // frames that answer no known trigger (dropped)
  };

  void configure(TimeUs timeout_us, TimeUs quiet_us) {
    timeout_us_ = timeout_us;
    quiet_us_ = quiet_us;
  }
  // Acquisition (re)started: nothing outstanding, no frame expected.
  void reset() {
    outstanding_ = -1;
    late_frame_possible_ = false;
  }
  // Trigger thread, before writing the trigger of `tick` at now_us: true when it may be written (it
  // becomes the outstanding trigger), false when the tick is skipped for this camera.
  bool beginTrigger(std::int64_t tick, TimeUs now_us);
  // The trigger write failed: the camera may or may not have received it.
  void triggerFailed(TimeUs now_us) { abandon(now_us); }
  // Frame thread: a buffer of this camera (any status) whose leader packet arrived at arrival_us.
  // Returns the tick it answers, or -1 (counted as unattributed; drop it); *written_us (optional):
  // when that trigger was written, the host's best time for the exposure start.
  std::int64_t onFrame(TimeUs arrival_us, TimeUs* written_us = nullptr);

  std::int64_t outstanding() const { return outstanding_; }
  const Counts& counts() const { return counts_; }

 private:
  void abandon(TimeUs now_us) {
    outstanding_ = -1;
    late_frame_possible_ = true;
    quiet_until_us_ = now_us + quiet_us_;
  }

  TimeUs timeout_us_ = 200'000;
  TimeUs quiet_us_ = 100'000;
  std::int64_t outstanding_ = -1;  // tick of the trigger written and not yet answered
  TimeUs outstanding_since_us_ = 0;
  bool late_frame_possible_ = false;  // an abandoned trigger's frame may still come
  TimeUs quiet_until_us_ = 0;
  Counts counts_;
};

}  // namespace deepnav
