#pragma once

namespace deepnav::sim {

// Scenario key `environment`: the water column and how the odometry frame sits in it.
struct EnvironmentConfig {
  double seabed_depth_m = 1000.0;       // flat seabed (and the panel's base) at this depth
  double odom_origin_depth_m = 1000.0;  // depth of the odometry origin: z_odom = origin depth - depth
  double water_density_kgpm3 = 1028.0;
  double gravity_mps2 = 9.80665;
  double atmospheric_pressure_pa = 101325.0;

  double seabedZInOdom_m() const { return odom_origin_depth_m - seabed_depth_m; }
  bool operator==(const EnvironmentConfig&) const = default;
};

}  // namespace deepnav::sim
