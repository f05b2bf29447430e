#include "board/replay/fusion_csv.h"

#include <cerrno>
#include <cstdio>
#include <memory>

#include "board/replay/output_file.h"
#include "drivers/recording/fusion_codec.h"

namespace deepnav {

void FusionCsvSink::recordFusion(const FusionDiagnostic& diagnostic) {
  rows_.push_back(diagnostic);
  next_->recordFusion(diagnostic);
}

bool writeFusionCsv(const std::string& path, const std::vector<FusionDiagnostic>& rows, std::string* error) {
  errno = 0;
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(path.c_str(), "w"), &std::fclose);
  if (!f) {
    if (error) *error = writeFailure(path, errno);
    return false;
  }
  std::fprintf(f.get(), "t_s,source,reason,fused,test_ratio,dim");
  for (int i = 0; i < kFusionMaxDim; ++i) std::fprintf(f.get(), ",innov_%d", i);
  for (int i = 0; i < kFusionMaxDim; ++i) std::fprintf(f.get(), ",var_%d", i);
  std::fprintf(f.get(), ",mag_state\n");
  for (const FusionDiagnostic& d : rows) {
    const bool fused = d.reason == FusionReason::kFused || d.reason == FusionReason::kFusedDeweighted;
    std::fprintf(f.get(), "%.6f,%s,%s,%d,%.6g,%d", usToS(d.t_us), std::string(sourceName(d.source)).c_str(),
                 std::string(fusionReasonName(d.reason)).c_str(), fused ? 1 : 0, d.test_ratio, d.dim);
    for (std::size_t i = 0; i < d.innovation.size(); ++i) std::fprintf(f.get(), ",%.9g", d.innovation[i]);
    for (std::size_t i = 0; i < d.innovation_variance.size(); ++i) {
      std::fprintf(f.get(), ",%.9g", d.innovation_variance[i]);
    }
    std::fprintf(f.get(), ",%d\n", d.mag_state);
  }
  // fprintf's errors stick in the stream; fclose flushes the rest and reports its own.
  const bool written = std::fflush(f.get()) == 0 && !std::ferror(f.get());
  const int write_errno = errno;
  errno = 0;
  const bool closed = std::fclose(f.release()) == 0;
  if (written && closed) return true;
  if (error) *error = writeFailure(path, written ? errno : write_errno);
  return false;
}

}  // namespace deepnav
