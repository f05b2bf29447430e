#include "drivers/recording/fusion_codec.h"

#include <array>
#include <string>

#include "drivers/cdr/cdr_reader.h"
#include "drivers/cdr/cdr_writer.h"
#include "drivers/recording/stamped_header.h"
#include "drivers/recording/topics.h"

namespace deepnav {
namespace {

constexpr std::array<std::string_view, kSrcCount + 1> kSourceNames = {
    "imu", "dvl", "depth", "heading", "attitude", "markers", "vo_orb", "vo_planes", "camera", "unknown"};
constexpr std::array<std::string_view, 9> kReasonNames = {
    "fused", "fused_deweighted", "gate", "unusable", "bad_input", "frozen", "late", "mag_disturbance", "future_stamp"};

}  // namespace

std::string_view sourceName(NavSource source) {
  return kSourceNames[static_cast<std::size_t>(source < kSrcCount ? source : kSrcCount)];
}

std::string_view fusionReasonName(FusionReason reason) {
  const auto i = static_cast<std::size_t>(reason);
  return i < kReasonNames.size() ? kReasonNames[i] : std::string_view("unknown");
}

std::size_t encodeFusion(const FusionDiagnostic& d, std::uint8_t* out, std::size_t capacity) {
  cdr::CdrWriter w(out, capacity);
  writeStampedHeader(w, d.t_us, Topic::kFusion);
  w.u8(static_cast<std::uint8_t>(d.source));
  w.string(sourceName(d.source));
  w.u8(static_cast<std::uint8_t>(d.reason));
  w.string(fusionReasonName(d.reason));
  w.boolean(d.reason == FusionReason::kFused || d.reason == FusionReason::kFusedDeweighted);
  const std::size_t n = d.dim <= kFusionMaxDim ? d.dim : 0;
  w.sequenceLength(n);
  for (std::size_t i = 0; i < n; ++i) w.f64(d.innovation[i]);
  w.sequenceLength(n);
  for (std::size_t i = 0; i < n; ++i) w.f64(d.innovation_variance[i]);
  w.f64(d.test_ratio);
  w.u8(d.mag_state);
  return w.ok() ? w.size() : 0;
}

bool decodeFusion(const std::uint8_t* data, std::size_t size, FusionDiagnostic* d) {
  cdr::CdrReader r(data, size);
  TimeUs t_us = 0;
  std::uint32_t n = 0, n_var = 0;
  std::string source_name, reason_name;
  std::uint8_t source = 0, reason = 0;
  bool fused = false;
  if (!readStampedHeader(r, &t_us) || !r.u8(&source) || !r.string(&source_name) || !r.u8(&reason) ||
      !r.string(&reason_name) || !r.boolean(&fused) || !r.sequenceLength(&n, 8) || n > kFusionMaxDim) {
    return false;
  }
  for (std::uint32_t i = 0; i < n; ++i) {
    if (!r.f64(&d->innovation[i])) return false;
  }
  if (!r.sequenceLength(&n_var, 8) || n_var != n) return false;
  for (std::uint32_t i = 0; i < n; ++i) {
    if (!r.f64(&d->innovation_variance[i])) return false;
  }
  if (!r.f64(&d->test_ratio) || !r.u8(&d->mag_state) || source > kSrcCount ||
      reason >= kReasonNames.size()) {
    return false;
  }
  d->t_us = t_us;
  d->source = static_cast<NavSource>(source);
  d->reason = static_cast<FusionReason>(reason);
  d->dim = static_cast<std::uint8_t>(n);
  return r.ok();
}

}  // namespace deepnav
