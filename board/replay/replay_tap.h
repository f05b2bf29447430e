#pragma once
#include "board/loop/nav_core.h"
#include "nav/types/input_sample.h"
#include "nav/types/nav_solution.h"
#include "nav/types/time.h"

namespace deepnav {

// Hooks of a bench replay (ReplayOptions::tap) for fault injection and observation on the bench: the
// replay hands every input to the tap instead of the core, lets it release what it holds back before
// each tick, and shows it each tick's solution. A tap sits where the sensor drivers and the vision
// worker hand their samples to the loop, so it can do to them what a fault would. Never on the vehicle.
class ReplayTap {
 public:
  virtual ~ReplayTap() = default;
  // An input the replay is about to consume: pass it on (core->consume), altered or not, hold it back
  // for later, or drop it.
  virtual void onInput(const InputSample& sample, NavCore* core) = 0;
  // Before the loop tick at t_us: consume whatever held-back input is due.
  virtual void beforeTick(TimeUs t_us, NavCore* core) = 0;
  // After the tick: the solution the loop published.
  virtual void afterTick(const NavSolution& solution, const NavCore& core) = 0;
};

}  // namespace deepnav
