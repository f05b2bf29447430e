#include "nav/types/nav_solution.h"

namespace deepnav {

bool isFinite(const NavSolution& s) {
  return s.p_robot_in_odom_m.allFinite() && s.q_odom_robot.coeffs().allFinite() &&
         s.v_robot_in_odom_mps.allFinite() && s.w_robot_radps.allFinite() && s.cov_pose.allFinite() &&
         s.cov_v_mps2.allFinite();
}

}  // namespace deepnav
