#pragma once
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <variant>

#include "nav/types/attitude_sample.h"
#include "nav/types/depth_sample.h"
#include "nav/types/dvl_sample.h"
#include "nav/types/heading_sample.h"
#include "nav/types/imu_sample.h"
#include "nav/types/vision_result.h"

namespace deepnav {

// Every input the nav loop consumes. Drivers (live or replay) produce these; the loop records each one
// it consumes, in consumption order, so that a replay reproduces the outputs bit for bit.
// Kinds are routed by type, never by position (docs/adding-a-sensor-kind.md): reordering the
// alternatives changes nothing, and a new alternative does not compile until every router handles it.
using InputSample = std::variant<ImuSample, DvlSample, HeadingSample, AttitudeSample, DepthSample, VisionResult>;

inline TimeUs sampleTimeUs(const InputSample& s) {
  return std::visit([](const auto& v) { return v.t_us; }, s);
}

// The name of each kind, for code that keeps a kind as data (the fault suite's records).
enum class InputKind : std::uint8_t { kImu, kDvl, kHeading, kAttitude, kDepth, kVision, kCount };

// The type -> kind table: one row per InputSample alternative. A type without a row does not compile.
template <typename T>
struct InputKindOf;
template <> struct InputKindOf<ImuSample> : std::integral_constant<InputKind, InputKind::kImu> {};
template <> struct InputKindOf<DvlSample> : std::integral_constant<InputKind, InputKind::kDvl> {};
template <> struct InputKindOf<HeadingSample> : std::integral_constant<InputKind, InputKind::kHeading> {};
template <> struct InputKindOf<AttitudeSample> : std::integral_constant<InputKind, InputKind::kAttitude> {};
template <> struct InputKindOf<DepthSample> : std::integral_constant<InputKind, InputKind::kDepth> {};
template <> struct InputKindOf<VisionResult> : std::integral_constant<InputKind, InputKind::kVision> {};

template <typename T>
inline constexpr InputKind kInputKind = InputKindOf<T>::value;

inline InputKind inputKind(const InputSample& s) {
  return std::visit([](const auto& v) { return kInputKind<std::decay_t<decltype(v)>>; }, s);
}

namespace input_sample_detail {
// True when every alternative has a row and no two share a kind, one kind per alternative.
template <typename... T>
constexpr bool oneKindEach(const std::variant<T...>*) {
  constexpr InputKind kinds[] = {kInputKind<T>...};
  for (std::size_t i = 0; i < sizeof...(T); ++i) {
    for (std::size_t j = i + 1; j < sizeof...(T); ++j) {
      if (kinds[i] == kinds[j]) return false;
    }
  }
  return sizeof...(T) == static_cast<std::size_t>(InputKind::kCount);
}
}  // namespace input_sample_detail
static_assert(input_sample_detail::oneKindEach(static_cast<const InputSample*>(nullptr)),
              "InputKind: one kind per InputSample alternative (docs/adding-a-sensor-kind.md)");

}  // namespace deepnav
