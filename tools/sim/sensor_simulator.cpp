#include "tools/sim/sensor_simulator.h"

#include <algorithm>
#include <cmath>

#include "tools/sim/faults/garbage_values.h"
#include "tools/sim/rotation.h"

namespace deepnav::sim {

namespace {

// Sub-stream ids of the seed: one for each model's noise, one for each stream's fault choices.
constexpr std::uint64_t kNoiseStreamBase = 1;
constexpr std::uint64_t kFaultStreamBase = 100;

std::uint64_t noiseSeed(std::uint64_t seed, SimStream s) {
  return NormalRng::subSeed(seed, kNoiseStreamBase + static_cast<std::uint64_t>(s));
}

double randomSign(NormalRng& rng) { return rng.uniform() <= 0.5 ? -1.0 : 1.0; }

// Orders the pending heap so that its front is the smallest (t_us, stream, order).
struct LaterFirst {
  template <typename P>
  bool operator()(const P& a, const P& b) const {
    if (a.event.t_us != b.event.t_us) return a.event.t_us > b.event.t_us;
    if (a.event.stream != b.event.stream) return a.event.stream > b.event.stream;
    return a.order > b.order;
  }
};

}  // namespace

TimeUs SensorSimulator::Channel::dueTime_us() const {
  return static_cast<TimeUs>(std::llround(static_cast<double>(next_index) * 1e6 / rate_hz));
}

bool SensorSimulator::init(const Scenario& scenario, std::uint64_t seed, std::string* error) {
  initialised_ = false;
  scenario_ = scenario;
  if (!(scenario.duration_s > 0.0)) {
    if (error) *error = "duration_s must be > 0";
    return false;
  }
  const EnvironmentConfig& env = scenario.environment;
  if (!trajectory_.init(scenario.trajectory, scenario.panel, env.odom_origin_depth_m, env.gravity_mps2, error) ||
      !imu_.init(scenario.imu, noiseSeed(seed, SimStream::kImu), error) ||
      !dvl_.init(scenario.dvl, env.seabedZInOdom_m(), noiseSeed(seed, SimStream::kDvl), error) ||
      (scenario.dvl.ray_cast && !dvl_.attachScene(scenario, seed, error)) ||  // the renderer's scene and seed
      !compass_.init(scenario.compass, scenario.panel, env.seabedZInOdom_m(), noiseSeed(seed, SimStream::kCompass),
                     error) ||
      !depth_.init(scenario.depth, env, noiseSeed(seed, SimStream::kDepth), error) ||
      !attitude_.init(scenario.attitude, noiseSeed(seed, SimStream::kAttitude), error) ||
      !camera_.init(scenario.camera, error) || !faults_.init(scenario.faults, error))
    return false;

  const std::array<std::pair<bool, double>, kSimStreamCount> enabled_rate{{
      {true, scenario.imu.rate_hz},  // ground truth: always, at the IMU rate
      {scenario.imu.enabled, scenario.imu.rate_hz},
      {scenario.dvl.enabled, scenario.dvl.rate_hz},
      {scenario.compass.enabled, scenario.compass.rate_hz},
      {scenario.attitude.enabled, scenario.attitude.rate_hz},
      {scenario.depth.enabled, scenario.depth.rate_hz},
      {scenario.camera.enabled, scenario.camera.rate_hz},
  }};
  for (int i = 0; i < kSimStreamCount; ++i) {
    Channel& c = channels_[i];
    c = Channel{};
    c.enabled = enabled_rate[i].first;
    c.rate_hz = enabled_rate[i].second;
    c.fault_rng = NormalRng(NormalRng::subSeed(seed, kFaultStreamBase + static_cast<std::uint64_t>(i)));
  }
  end_us_ = sToUs(scenario.duration_s);
  timing_active_ = scenario.timing.active();
  timing_advance_us_ = timing_active_ ? scenario.timing.maxAdvance_us(end_us_) : 0;
  pending_.clear();
  pending_.reserve(4 * kSimStreamCount);
  order_ = 0;
  initialised_ = true;
  return true;
}

int SensorSimulator::earliestChannel() const {
  int best = -1;
  TimeUs best_us = 0;
  for (int i = 0; i < kSimStreamCount; ++i) {
    const Channel& c = channels_[i];
    if (!c.enabled) continue;
    const TimeUs due_us = c.dueTime_us();
    if (due_us > end_us_) continue;
    if (best < 0 || due_us < best_us) {
      best = i;
      best_us = due_us;
    }
  }
  return best;
}

bool SensorSimulator::next(SimEvent* out) {
  if (!initialised_) return false;
  const TimeUs horizon_us = faults_.maxJitter_us() + timing_advance_us_;
  while (true) {
    const int c = earliestChannel();
    // Every event not yet produced will be stamped at or after due - horizon: the front is safe before that.
    if (!pending_.empty() && (c < 0 || pending_.front().event.t_us < channels_[c].dueTime_us() - horizon_us)) {
      popPending(out);
      return true;
    }
    if (c < 0) return false;
    produce(c);
  }
}

void SensorSimulator::produce(int channel) {
  Channel& c = channels_[channel];
  const SimStream stream = static_cast<SimStream>(channel);
  const std::uint64_t index = c.next_index++;
  const TimeUs t_us = static_cast<TimeUs>(std::llround(static_cast<double>(index) * 1e6 / c.rate_hz));
  if (stream == SimStream::kDvl && !dvl_.pingDue(t_us)) {  // still waiting for the last ping's echo
    ++c.not_pinged;
    return;
  }
  const KinematicState truth = trajectory_.stateAt(usToS(t_us));
  // Measure first, even if the sample is then dropped, so faults never shift the noise sequence.
  SimSample sample = measure(stream, truth, t_us, index);
  TimeUs arrival_us = t_us;  // when the sample reaches the vehicle's computer
  if (stream != SimStream::kGroundTruth) {
    const FaultDecision d = faults_.decide(stream, usToS(t_us), index, c.fault_rng);
    if (d.drop) {
      ++c.dropped;
      return;
    }
    if (d.stuck && c.has_last) sample = c.last;
    if (d.outlier_sigma > 0.0) applyOutlier(d.outlier_sigma, c.fault_rng, &sample);
    if (d.garbage) fillGarbage(c.fault_rng, &sample);
    c.last = sample;
    c.has_last = true;
    TimeUs stamp_us = t_us + d.jitter_us;
    if (timing_active_) stamp_us += scenario_.timing.of(stream).shift_us(t_us);  // content stays at t_us
    arrival_us = stamp_us;
    // A sensor whose clock jumped still delivers each sample when it is measured; only the stamp it
    // carries is wrong. So the sample keeps its place in the stream (delivery order, the recording's log
    // time) and the loop can see the stamp disagree with its own clock, as it would on the vehicle.
    // Camera frames are delivered at their stamp (the recording orders frames by stamp).
    stamp_us += d.clock_offset_us;
    if (stream == SimStream::kCamera) arrival_us = stamp_us;
    std::visit([stamp_us](auto& s) { s.t_us = stamp_us; }, sample);
  }
  ++c.emitted;
  SimEvent event;
  event.t_us = arrival_us;
  event.stream = stream;
  event.sample = std::move(sample);
  pushPending(std::move(event));
}

SimSample SensorSimulator::measure(SimStream stream, const KinematicState& truth, TimeUs t_us, std::uint64_t index) {
  switch (stream) {
    case SimStream::kImu:
      return imu_.measure(truth, t_us);
    case SimStream::kDvl:
      return dvl_.measure(truth, t_us);
    case SimStream::kCompass:
      return compass_.measure(truth, t_us);
    case SimStream::kAttitude:
      return attitude_.measure(truth, t_us);
    case SimStream::kDepth:
      return depth_.measure(truth, t_us);
    case SimStream::kCamera:
      return camera_.tick(truth, t_us, static_cast<std::uint32_t>(index));
    case SimStream::kGroundTruth:
    case SimStream::kCount:
      break;
  }
  GroundTruthSample g;
  g.t_us = t_us;
  g.p_robot_in_odom_m = truth.p_robot_in_odom_m;
  g.q_odom_robot = truth.q_odom_robot;
  g.v_robot_in_odom_mps = truth.v_robot_in_odom_mps;
  g.w_robot_radps = truth.w_robot_radps;
  if (scenario_.imu.enabled) {
    // Produced just before the IMU sample of the same instant: these are the biases in that sample.
    g.gyro_bias_radps = imu_.gyroBias_radps();
    g.accel_bias_mps2 = imu_.accelBias_mps2();
  }
  return g;
}

void SensorSimulator::applyOutlier(double magnitude_sigma, NormalRng& rng, SimSample* sample) const {
  auto kick = [&](double sigma) { return randomSign(rng) * magnitude_sigma * sigma; };
  if (auto* imu = std::get_if<ImuSample>(sample)) {
    for (int i = 0; i < 3; ++i) imu->w_imu_radps[i] += kick(imu_.gyroNoiseSigma_radps());
    for (int i = 0; i < 3; ++i) imu->f_imu_mps2[i] += kick(imu_.accelNoiseSigma_mps2());
  } else if (auto* dvl = std::get_if<DvlSample>(sample)) {
    if (dvl->valid)
      for (int i = 0; i < 3; ++i) dvl->v_dvl_mps[i] += kick(dvl->fom_mps);
  } else if (auto* heading = std::get_if<HeadingSample>(sample)) {
    heading->heading_rad = wrapTo2Pi(heading->heading_rad + kick(compass_.noiseSigma_rad()));
  } else if (auto* att = std::get_if<AttitudeSample>(sample)) {
    att->roll_rad += kick(attitude_.noiseSigma_rad());
    att->pitch_rad += kick(attitude_.noiseSigma_rad());
  } else if (auto* depth = std::get_if<DepthSample>(sample)) {
    const double delta_pa = kick(depth_.noiseSigma_pa());
    const double rho_g = scenario_.environment.water_density_kgpm3 * scenario_.environment.gravity_mps2;
    depth->pressure_pa += delta_pa;
    depth->depth_m += delta_pa / rho_g;
  }
}

void SensorSimulator::pushPending(SimEvent event) {
  pending_.push_back(Pending{std::move(event), order_++});
  std::push_heap(pending_.begin(), pending_.end(), LaterFirst{});
}

void SensorSimulator::popPending(SimEvent* out) {
  std::pop_heap(pending_.begin(), pending_.end(), LaterFirst{});
  *out = std::move(pending_.back().event);
  pending_.pop_back();
}

}  // namespace deepnav::sim
