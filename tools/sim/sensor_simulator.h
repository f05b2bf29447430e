#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "tools/sim/faults/fault_schedule.h"
#include "tools/sim/normal_rng.h"
#include "tools/sim/scenario.h"
#include "tools/sim/sensors/attitude_model.h"
#include "tools/sim/sensors/camera_rig.h"
#include "tools/sim/sensors/compass_model.h"
#include "tools/sim/sensors/depth_model.h"
#include "tools/sim/sensors/dvl_model.h"
#include "tools/sim/sensors/imu_model.h"
#include "tools/sim/sim_event.h"
#include "tools/sim/trajectory.h"

namespace deepnav::sim {

// Plays a scenario as one time-ordered stream of samples: ground truth and IMU at the IMU rate, DVL,
// compass, attitude, depth, and camera ticks at their rates, with the fault schedule applied. The same
// scenario and seed give a bit-identical stream. Trajectory time 0 is t_us = 0; sample k of a stream at
// rate r is due at round(k * 1e6 / r) us, for every due time <= duration_s.
//
// Usage:
//   SensorSimulator sim;
//   if (!sim.init(scenario, seed, &error)) ...;
//   SimEvent e;
//   while (sim.next(&e)) record(e);
class SensorSimulator {
 public:
  bool init(const Scenario& scenario, std::uint64_t seed, std::string* error);
  // The next event in stamp order (ties: SimStream order, then due time); false when all are out.
  bool next(SimEvent* out);

  // The true state and camera poses at any time, for the renderer; independent of next().
  KinematicState truthAt(TimeUs t_us) const { return trajectory_.stateAt(usToS(t_us)); }
  CameraTick cameraAt(TimeUs t_us) const { return camera_.tick(truthAt(t_us), t_us, 0); }
  const Trajectory& trajectory() const { return trajectory_; }
  const Scenario& scenario() const { return scenario_; }
  const ImuModel& imuModel() const { return imu_; }

  // Samples emitted and dropped (by the fault schedule) per stream so far.
  std::uint64_t emitted(SimStream s) const { return channels_[static_cast<int>(s)].emitted; }
  std::uint64_t dropped(SimStream s) const { return channels_[static_cast<int>(s)].dropped; }
  // Channel ticks at which the instrument did not ping (the DVL's altitude-dependent ping rate, dvl.max_ping_rate_hz),
  // apart from the fault drops.
  std::uint64_t notPinged(SimStream s) const { return channels_[static_cast<int>(s)].not_pinged; }

 private:
  struct Channel {
    bool enabled = false;
    double rate_hz = 1.0;
    std::uint64_t next_index = 0;
    std::uint64_t emitted = 0;
    std::uint64_t dropped = 0;
    std::uint64_t not_pinged = 0;
    NormalRng fault_rng;
    bool has_last = false;
    SimSample last;  // last emitted sample, for "stuck"
    TimeUs dueTime_us() const;
  };
  struct Pending {
    SimEvent event;
    std::uint64_t order = 0;  // generation order, last tie-break
  };

  int earliestChannel() const;  // -1 when every channel is past the end
  void produce(int channel);
  SimSample measure(SimStream stream, const KinematicState& truth, TimeUs t_us, std::uint64_t index);
  // Adds +-magnitude_sigma * (the stream's noise sigma) to every component of the sample.
  void applyOutlier(double magnitude_sigma, NormalRng& rng, SimSample* sample) const;
  void pushPending(SimEvent event);
  void popPending(SimEvent* out);

  Scenario scenario_;
  Trajectory trajectory_;
  ImuModel imu_;
  DvlModel dvl_;
  CompassModel compass_;
  DepthModel depth_;
  AttitudeModel attitude_;
  CameraRig camera_;
  FaultSchedule faults_;
  std::array<Channel, kSimStreamCount> channels_{};
  std::vector<Pending> pending_;  // min-heap on (t_us, stream, order)
  std::uint64_t order_ = 0;
  TimeUs end_us_ = 0;
  bool timing_active_ = false;     // scenario.timing has a non-zero term
  TimeUs timing_advance_us_ = 0;  // largest stamp advance from timing: added to the merger's horizon
  bool initialised_ = false;
};

}  // namespace deepnav::sim
