#pragma once
#include "nav/types/estimator_states.h"
#include "nav/types/fusion_diagnostic.h"
#include "nav/types/input_sample.h"
#include "nav/types/nav_solution.h"
#include "vision/types/stereo_frame.h"

namespace deepnav {

// Where the loop sends what it consumed and produced. Live, a queue drained by a writer thread (the
// loop never blocks on the disk); on the bench, the MCAP writer itself. Implementations never throw and
// never allocate in the steady state; a full queue drops the record and counts it.
class RecordSink {
 public:
  virtual ~RecordSink() = default;
  virtual void recordInput(const InputSample& sample) = 0;
  virtual void recordSolution(const NavSolution& solution) = 0;
  // One measurement's fusion (innovation, test ratio, accepted or why refused), topic /nav/fusion.
  virtual void recordFusion(const FusionDiagnostic& diagnostic) = 0;
  // The filter's sensor-error estimates, topic /nav/estimator_states.
  virtual void recordEstimatorStates(const EstimatorStates& states) = 0;
  // A stereo pair as captured. pool_index >= 0 names its slot in the FramePool (the sink may hold a
  // reference until it is written); -1 when the frame does not live in a pool.
  virtual void recordFrame(const StereoFrame& frame, int pool_index) = 0;
};

}  // namespace deepnav
