#pragma once

namespace deepnav {

// A visitor made of one lambda per alternative, for std::visit:
//   std::visit(Overloaded{[](const ImuSample& s) { ... }, [](const DvlSample& s) { ... }}, sample);
// Dispatch is by type, so reordering a variant's alternatives changes nothing. Without a generic
// `[](const auto&)` lambda the set must name every alternative: a new alternative does not compile until
// each such visit handles it (the way sample kinds are routed: docs/adding-a-sensor-kind.md).
// Real-time safe: no allocation; std::visit throws only on a variant left valueless by a throwing
// assignment, which the sample types (plain values, no heap) never are.
template <typename... F>
struct Overloaded : F... {
  using F::operator()...;
};
template <typename... F>
Overloaded(F...) -> Overloaded<F...>;

}  // namespace deepnav
