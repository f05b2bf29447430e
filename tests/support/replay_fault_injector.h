#pragma once
#include <cstdint>
#include <vector>

#include "board/replay/replay_tap.h"
#include "nav/markers/marker_pose_covariance.h"

namespace deepnav {

// Faults injected on replay, where no sensor stream of the simulator can carry them: results of the
// vision worker (markers, visual odometry) that are wrong, late or out of order, and samples whose
// stated uncertainty is not a usable number.
enum class InjectedFault : std::uint8_t {
  kNone = 0,        // observe only
  kVoOutlier,       // every VO component +- magnitude_sigma x its stated sigma (translation and rotation)
  kMarkerOutlier,   // every marker moved by magnitude_sigma x its position sigma (marker_pose_covariance.h)
  kVisionDelay,     // vision results reach the loop delay_ms later than they would
  kVisionReorder,   // every second vision result is held back and handed over after the next one
  kBadCovariance,   // the covariance (or sigma) of the target is replaced by `value`
};

// kNegative: negative variances (or sigma); kIndefinite: positive variances with correlations > 1, a
// matrix that is not a covariance (scalar sigmas have none: it acts as kNegative); kHuge: 1e300 m^2.
enum class CovarianceValue : std::uint8_t { kNan = 0, kInf, kNegative, kIndefinite, kHuge };
enum class CovarianceTarget : std::uint8_t { kDvl = 0, kDepth, kHeading, kAttitude, kVo };

struct InjectedFaultSpec {
  InjectedFault kind = InjectedFault::kNone;
  double t_start_s = 0.0;  // window on the sample's capture time (recording clock)
  double t_end_s = 0.0;
  int every_n = 1;                 // hit one eligible sample in every_n
  double magnitude_sigma = 10.0;   // outliers
  double delay_ms = 100.0;         // kVisionDelay
  CovarianceValue value = CovarianceValue::kNan;
  CovarianceTarget target = CovarianceTarget::kDvl;
  MarkerCovarianceConfig markers;  // the board's marker sigmas (kMarkerOutlier)
  std::uint64_t seed = 1;          // signs of the outliers
};

// What the injector did and what the loop made of it.
struct InjectionCounters {
  std::uint32_t injected = 0;          // samples altered (or held back)
  std::uint32_t accepted_injected = 0; // altered samples the filter accepted when they were consumed
  std::uint32_t released = 0;          // held-back results handed over
};

// One solution per tick, as the loop published it.
struct TickRecord {
  TimeUs t_us = 0;
  Eigen::Vector3d p_robot_in_odom_m = Eigen::Vector3d::Zero();
  Eigen::Quaterniond q_odom_robot = Eigen::Quaterniond::Identity();
  std::uint32_t status = 0;
  std::uint32_t faults = 0;
  double position_sigma_m = 0.0;  // sqrt of the largest horizontal position variance
  bool finite = true;
  bool aligned = false;           // stage beyond kInit
};

// One navigation-sensor sample as the loop consumed it, and whether the filter accepted it then (a
// sample newer than the last IMU sample is queued and counts as not accepted here).
struct InputRecord {
  InputKind kind = InputKind::kDvl;  // DVL, heading, attitude or depth
  TimeUs t_us = 0;
  Eigen::Vector3d value = Eigen::Vector3d::Zero();  // DVL velocity; heading; roll, pitch; depth
  bool accepted = false;
};

// A ReplayTap applying one InjectedFaultSpec and recording every tick and every navigation-sensor
// sample with its outcome (the fault suite's instrument).
class ReplayFaultInjector final : public ReplayTap {
 public:
  explicit ReplayFaultInjector(const InjectedFaultSpec& spec = {});

  void onInput(const InputSample& sample, NavCore* core) override;
  void beforeTick(TimeUs t_us, NavCore* core) override;
  void afterTick(const NavSolution& solution, const NavCore& core) override;

  const InjectionCounters& counters() const { return counters_; }
  const std::vector<TickRecord>& ticks() const { return ticks_; }
  const std::vector<InputRecord>& inputs() const { return inputs_; }

 private:
  struct Held {
    TimeUs due_us = 0;
    VisionResult result;
  };
  bool hits(TimeUs t_us);
  void consumeCounted(const InputSample& sample, NavCore* core);
  void consumeRecorded(const InputSample& sample, NavCore* core);
  void onVision(const VisionResult& v, NavCore* core);
  VisionResult withOutliers(const VisionResult& v);
  InputSample withBadCovariance(const InputSample& sample) const;
  double badValue() const;
  double randomSign();

  InjectedFaultSpec spec_;
  InjectionCounters counters_;
  std::vector<TickRecord> ticks_;
  std::vector<InputRecord> inputs_;
  std::vector<Held> held_;
  std::uint64_t eligible_ = 0;
  std::uint64_t rng_state_ = 0;
  TimeUs last_tick_us_ = 0;
};

}  // namespace deepnav
