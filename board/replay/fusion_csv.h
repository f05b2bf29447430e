#pragma once
#include <string>
#include <vector>

#include "drivers/recording/record_sink.h"
#include "nav/types/fusion_diagnostic.h"

namespace deepnav {

// The bench replay's sink: everything goes on to the recording (replay.mcap, /nav/fusion included), and
// the per-fusion diagnostics are also kept for fusion.csv, which tools/eval/report.py plots (test ratio
// and normalised innovation per source over time). Bench only: it grows a vector.
class FusionCsvSink : public RecordSink {
 public:
  explicit FusionCsvSink(RecordSink* next) : next_(next) {}

  void recordInput(const InputSample& sample) override { next_->recordInput(sample); }
  void recordSolution(const NavSolution& solution) override { next_->recordSolution(solution); }
  void recordFrame(const StereoFrame& frame, int pool_index) override { next_->recordFrame(frame, pool_index); }
  void recordEstimatorStates(const EstimatorStates& states) override { next_->recordEstimatorStates(states); }
  void recordFusion(const FusionDiagnostic& diagnostic) override;

  const std::vector<FusionDiagnostic>& rows() const { return rows_; }

 private:
  RecordSink* next_;
  std::vector<FusionDiagnostic> rows_;
};

// fusion.csv: t_s, source, reason, fused, test_ratio, dim, innov_0..5, var_0..5 (diag of S), mag_state;
// one row per measurement in the order the filter fused it. False with a message when it cannot be written.
bool writeFusionCsv(const std::string& path, const std::vector<FusionDiagnostic>& rows, std::string* error);

}  // namespace deepnav
