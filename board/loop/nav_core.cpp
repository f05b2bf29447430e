#include "board/loop/nav_core.h"

namespace deepnav {

bool NavCore::init(const BoardConfig& config, RecordSink* sink, std::string* error) {
  sink_ = sink;
  counters_ = InputCounters{};
  image_quality_ = -1.0;
  solution_ = NavSolution{};
  return ekf_.init(config.ekf, error);
}

void NavCore::count(FuseResult r) {
  switch (r.status) {
    case FuseStatus::kAccepted: ++counters_.accepted; break;
    case FuseStatus::kRejected: ++counters_.rejected; break;
    case FuseStatus::kQueued: ++counters_.queued; break;
    case FuseStatus::kDroppedLate: ++counters_.dropped_late; break;
    case FuseStatus::kBadInput: ++counters_.bad_input; break;
    case FuseStatus::kNotAligned: ++counters_.not_aligned; break;
  }
}

void NavCore::consumeVision(const VisionResult& v) {
  ++counters_.vision;
  if (v.frame_ok && v.image_quality >= 0.0) image_quality_ = v.image_quality;
}

void NavCore::consume(const InputSample& sample) {
  if (sink_) sink_->recordInput(sample);
  switch (sample.index()) {
    case 0:
      ++counters_.imu;
      ekf_.setImu(std::get<ImuSample>(sample));
      break;
    case 1:
      ++counters_.dvl;
      count(ekf_.fuseDvl(std::get<DvlSample>(sample)));
      break;
    case 2:
      ++counters_.heading;
      count(ekf_.fuseHeading(std::get<HeadingSample>(sample)));
      break;
    case 3:
      ++counters_.attitude;
      count(ekf_.fuseAttitude(std::get<AttitudeSample>(sample)));
      break;
    case 4:
      ++counters_.depth;
      count(ekf_.fuseDepth(std::get<DepthSample>(sample)));
      break;
    default:
      consumeVision(std::get<VisionResult>(sample));
      break;
  }
}

const NavSolution& NavCore::tick(TimeUs t_us) {
  solution_ = ekf_.solution(t_us);
  // The solution is stamped with the tick; the filter state it holds is that of the last IMU sample
  // (at most one IMU period older at 100 Hz).
  solution_.t_us = t_us;
  solution_.image_quality = image_quality_;
  if (sink_) sink_->recordSolution(solution_);
  return solution_;
}

}  // namespace deepnav
