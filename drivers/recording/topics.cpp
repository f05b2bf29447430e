#include "drivers/recording/topics.h"

#include <array>
#include <string>

#include "drivers/cdr/ros2msg_definitions.h"

namespace deepnav {
namespace {

constexpr std::array<TopicInfo, kTopicCount> kTopics = {{
    {"/imu", "sensor_msgs/msg/Imu", "imu"},
    {"/dvl", "geometry_msgs/msg/TwistWithCovarianceStamped", "dvl"},
    {"/dvl/bottom_track", "deepnav_msgs/msg/DvlBottomTrack", "dvl"},
    {"/pressure", "sensor_msgs/msg/FluidPressure", "pressure"},
    {"/depth", "deepnav_msgs/msg/Depth", "pressure"},
    {"/heading", "deepnav_msgs/msg/Heading", "compass"},
    {"/attitude", "deepnav_msgs/msg/Attitude", "ahrs"},
    {"/vision/result", "deepnav_msgs/msg/VisionResult", "camera_left"},
    {"/camera/stereo_info", "deepnav_msgs/msg/StereoInfo", "camera_left"},
    {"/camera/left/image_raw", "sensor_msgs/msg/Image", "camera_left"},
    {"/camera/right/image_raw", "sensor_msgs/msg/Image", "camera_right"},
    {"/nav/odometry", "nav_msgs/msg/Odometry", "odom"},
    {"/nav/solution", "deepnav_msgs/msg/NavSolution", "odom"},
    {"/nav/loop_stats", "deepnav_msgs/msg/LoopStats", ""},
    {"/truth/odometry", "nav_msgs/msg/Odometry", "odom"},
    {"/truth/frame", "deepnav_msgs/msg/FrameTruth", "odom"},
    {"/truth/depth", "sensor_msgs/msg/Image", "camera_left"},
    {"/truth/disparity", "sensor_msgs/msg/Image", "camera_left"},
    {"/nav/fusion", "deepnav_msgs/msg/FusionDiagnostic", "odom"},
    {"/nav/estimator_states", "deepnav_msgs/msg/EstimatorStates", "base_link"},
}};

// The project's own messages. Units in comments, frames as in the README.
const ros::MsgDefinitions& projectDefinitions() {
  static const ros::MsgDefinitions kDefs = {
      {"deepnav_msgs/DvlBottomTrack",
       "std_msgs/Header header\n"
       "geometry_msgs/Vector3 velocity # m/s, DVL over the bottom, DVL frame\n"
       "float64[9] velocity_covariance # m^2/s^2, row-major\n"
       "float64[4] beam_range # m, slant range per beam\n"
       "uint8 beam_valid_mask # bit i: beam i locked\n"
       "bool valid # velocity usable\n"
       "float64 figure_of_merit # m/s\n"
       "float64 altitude # m\n"},
      {"deepnav_msgs/Depth",
       "std_msgs/Header header\nfloat64 depth # m, positive down\nfloat64 pressure # Pa, absolute\n"
       "float64 sigma # m, 0 = filter default\n"},
      {"deepnav_msgs/Heading",
       "std_msgs/Header header\nfloat64 heading # rad, clockwise from north\n"
       "bool is_true # true north (else magnetic)\nfloat64 sigma # rad, 0 = filter default\n"},
      {"deepnav_msgs/Attitude",
       "std_msgs/Header header\nfloat64 roll # rad, FLU\nfloat64 pitch # rad, FLU\n"
       "float64 sigma # rad, 0 = filter default\n"},
      {"deepnav_msgs/VisionResult",
       "std_msgs/Header header # stamp = capture time of the pair\nuint64 sequence\n"
       "uint32 processing_us\nbool frame_ok\nfloat64 mdm_f1\nfloat64 mdm_f2\nfloat64 mdm_f3\n"
       "float64 image_quality # [0, 1], -1 = none\nMarkerObservation[] markers\nint32 markers_dropped\n"
       "int32 orb_tracked # ORB features tracked in this pair\n"
       "uint8 vo_selected # modality chosen: 0 none, 1 orb, 2 planes\n"
       "VoMeasurement vo_orb\nVoMeasurement vo_planes\nint32 planes # extracted in this pair\n"
       "int32 map_frames # clouds in the stage-1 workspace map\nint32 map_voxels # occupied voxels\n"
       "bool map_ready\nuint32 orb_us\nuint32 planes_us\nuint32 map_us # worker time per part\n"},
      {"deepnav_msgs/VoMeasurement",
       "bool valid\nuint8 source # 1 orb, 2 planes\nint64 t_reference_us # capture time of the reference pair\n"
       "geometry_msgs/Quaternion orientation # left camera at this pair in the camera at the reference\n"
       "geometry_msgs/Vector3 position # m, same frames\nbool has_translation\n"
       "float64[36] covariance # x y z rx ry rz: translation in the reference camera, rotation about this camera\n"
       "int32 support # tracked features (orb) or matched planes (planes)\n"},
      {"deepnav_msgs/MarkerObservation",
       "int32 id # ArUco id\nfloat64[8] corners # px: u, v of top-left, top-right, bottom-right, bottom-left\n"
       "geometry_msgs/Quaternion orientation # marker in the camera optical frame (best IPPE solution)\n"
       "geometry_msgs/Vector3 position # m, marker centre in the camera optical frame\n"
       "geometry_msgs/Quaternion orientation_alt # the other IPPE solution\n"
       "geometry_msgs/Vector3 position_alt\nfloat64 reprojection_error # px RMS\n"
       "float64 reprojection_error_alt\nbool ambiguous\nfloat64 distance # m\n"
       "float64 obliqueness # rad, marker normal vs ray to the camera\n"},
      {"deepnav_msgs/StereoInfo",
       "std_msgs/Header header # stamp = capture time (mid-exposure)\nuint32 exposure_us\n"
       "uint64 sequence\nbool rectified\n"},
      {"deepnav_msgs/NavSolution",
       "std_msgs/Header header # frame odom (ENU)\n"
       "geometry_msgs/Point position # m, robot in odom\n"
       "geometry_msgs/Quaternion orientation # robot (FLU) to odom\n"
       "geometry_msgs/Vector3 velocity # m/s, in odom\n"
       "geometry_msgs/Vector3 angular_velocity # rad/s, robot frame\n"
       "float64[36] pose_covariance # x y z roll pitch yaw (about odom axes)\n"
       "float64[9] velocity_covariance # m^2/s^2\n"
       "uint8 stage # 0 init, 1 workspace definition, 2 optimised localisation\n"
       "uint32 status # NavStatusBits\nuint32 faults # stale/rejected bit pairs per source\n"
       "float64 image_quality\nuint32 rejected_total\nuint32 dropped_late_total\n"},
      {"deepnav_msgs/FrameTruth",
       "std_msgs/Header header # stamp = capture time of the stereo pair (as its StereoInfo)\n"
       "uint64 sequence # the stereo pair's sequence\n"
       "geometry_msgs/Pose robot # robot (FLU) in odom (ENU), m\n"
       "geometry_msgs/Pose camera_left # left optical frame (z forward, x right, y down) in odom\n"
       "geometry_msgs/Pose camera_right # right optical frame in odom\n"
       "int32[] visible_marker_ids # ascending; all 4 corners in the left image and unobstructed\n"},
      {"deepnav_msgs/EstimatorStates",
       "std_msgs/Header header # stamp = the loop tick\n"
       "float64[3] gyro_bias # rad/s, robot frame (FLU)\nfloat64[3] gyro_bias_sigma\n"
       "float64[3] accel_bias # m/s^2, robot frame\nfloat64[3] accel_bias_sigma\n"
       "bool dvl_scale_estimated\nfloat64 dvl_scale # fraction: v_measured = (1 + s) v_true\nfloat64 dvl_scale_sigma\n"
       "bool dvl_misalignment_estimated\n"
       "float64[3] dvl_misalignment # rad, rotation vector: R_robot_dvl_true = R_robot_dvl Exp(a)\n"
       "float64[3] dvl_misalignment_sigma\n"
       "bool compass_bias_estimated\nfloat64 compass_bias # rad, added to the heading\nfloat64 compass_bias_sigma\n"
       "bool compass_deviation_estimated\n"
       "float64[4] compass_deviation # rad: B sin psi, C cos psi, D sin 2psi, E cos 2psi (psi magnetic heading)\n"
       "float64[4] compass_deviation_sigma\n"
       "bool dvl_bias_estimated\nfloat64[3] dvl_bias # m/s, DVL axes: v_measured = ... + b\nfloat64[3] dvl_bias_sigma\n"},
      {"deepnav_msgs/FusionDiagnostic",
       "std_msgs/Header header # stamp = capture time of the measurement\n"
       "uint8 source # 0 imu, 1 dvl, 2 depth, 3 heading, 4 attitude, 5 markers, 6 vo_orb, 7 vo_planes\n"
       "string source_name\n"
       "uint8 reason # 0 fused, 1 fused_deweighted, 2 gate, 3 unusable, 4 bad_input, 5 frozen, 6 late, "
       "7 mag_disturbance, 8 future_stamp\n"
       "string reason_name\nbool fused\n"
       "float64[] innovation # z - h(x): dvl m/s (x y z, DVL frame), depth m, heading rad (ENU yaw), "
       "attitude rad (roll pitch), poses m and rad (x y z rx ry rz)\n"
       "float64[] innovation_variance # diag of S = H P H^T + R, squared units\n"
       "float64 test_ratio # innovation^2 / (gate^2 S) (chi-square form for several dof); <= 1 passes\n"
       "uint8 mag_state # compass after this sample: 0 clean, 1 suspect (de-weighted), 2 disturbed (refused)\n"},
      {"deepnav_msgs/LoopStats",
       "std_msgs/Header header\nstring[] task_names\nuint64[] runs\nuint64[] overruns\n"
       "float64[] mean_us\nint64[] max_us\nuint64 ticks\nuint64 late_ticks\nint64 max_lateness_us\n"},
  };
  return kDefs;
}

std::array<std::string, kTopicCount> buildSchemas() {
  std::array<std::string, kTopicCount> out;
  for (std::size_t i = 0; i < kTopicCount; ++i) {
    std::string error;
    ros::ros2MsgDefinition(kTopics[i].type, projectDefinitions(), &out[i], &error);
  }
  return out;
}

}  // namespace

const TopicInfo& topicInfo(Topic topic) { return kTopics[static_cast<std::size_t>(topic)]; }

Topic topicByName(std::string_view name) {
  for (std::size_t i = 0; i < kTopicCount; ++i) {
    if (kTopics[i].name == name) return static_cast<Topic>(i);
  }
  return Topic::kCount;
}

std::string_view topicSchema(Topic topic) {
  static const std::array<std::string, kTopicCount> kSchemas = buildSchemas();
  return kSchemas[static_cast<std::size_t>(topic)];
}

}  // namespace deepnav
