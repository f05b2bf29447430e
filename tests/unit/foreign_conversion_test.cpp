// Foreign messages into the loop's samples: NED/FRD and ENU/FLU against hand-computed values, the
// mounting, depth, tilt-compensated compass, images of every encoding read (and those refused), and the
// stereo pairing by stamp.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <opencv2/imgcodecs.hpp>

#include "drivers/foreign/frame_conventions.h"
#include "drivers/foreign/image_conversion.h"
#include "drivers/foreign/sample_conversion.h"
#include "drivers/foreign/stereo_pairing.h"

namespace deepnav::foreign {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

Eigen::Quaterniond zyx(double yaw_deg, double pitch_deg, double roll_deg) {
  return Eigen::AngleAxisd(yaw_deg * kDeg, Eigen::Vector3d::UnitZ()) *
         Eigen::AngleAxisd(pitch_deg * kDeg, Eigen::Vector3d::UnitY()) *
         Eigen::AngleAxisd(roll_deg * kDeg, Eigen::Vector3d::UnitX());
}

ros::Imu imuWithOrientation(const Eigen::Quaterniond& q) {
  ros::Imu m;
  m.orientation = {q.x(), q.y(), q.z(), q.w()};
  m.orientation_covariance[0] = m.orientation_covariance[4] = 1e-4;
  m.orientation_covariance[8] = 4e-4;
  return m;
}

TopicMapping mapping(FrameConvention c) {
  TopicMapping m;
  m.convention = c;
  return m;
}

TEST(ForeignConversion, StampsAreMicrosecondsTruncated) {
  EXPECT_EQ(stampUs({1700000000, 999999}), 1700000000LL * 1000000 + 999);
  EXPECT_EQ(stampUs({0, 1500}), 1);
}

TEST(ForeignConversion, FrdImuAtRestFacingNorthIsFluFacingNorth) {
  // An FRD IMU level and facing north (identity in NED) reads gravity's specific force as -9.81 on its z
  // (down) axis; in FLU it is +9.81 on z, the rates flip y and z, and its orientation is ENU yaw +90 deg.
  ros::Imu m = imuWithOrientation(Eigen::Quaterniond::Identity());
  m.angular_velocity = {0.01, 0.02, 0.03};
  m.linear_acceleration = {0.0, 0.0, -9.81};
  ImuSample s;
  ASSERT_TRUE(imuSampleFromRos(m, mapping(FrameConvention::kNedFrd), 42, &s));
  EXPECT_EQ(s.t_us, 42);
  EXPECT_EQ(s.w_imu_radps, Eigen::Vector3d(0.01, -0.02, -0.03));
  EXPECT_EQ(s.f_imu_mps2, Eigen::Vector3d(0.0, 0.0, 9.81));
  ASSERT_TRUE(s.has_orientation);
  EXPECT_LT(s.q_odom_imu.angularDistance(zyx(90, 0, 0)), 1e-12);
  HeadingSample h;
  ASSERT_TRUE(headingSampleFromRos(m, mapping(FrameConvention::kNedFrd), Eigen::Quaterniond::Identity(), 42, &h));
  EXPECT_NEAR(h.heading_rad, 0.0, 1e-12);
  EXPECT_NEAR(h.sigma_rad, 0.02, 1e-12);
  EXPECT_FALSE(h.is_true);
}

TEST(ForeignConversion, NedAttitudeKeepsRollFlipsPitchAndGivesTheSameHeading) {
  // NED/FRD: heading 30 deg, pitch 10 deg nose up, roll 5 deg right side down. REP-103 (FLU): roll is the
  // same rotation (+x, right side down), a nose-up pitch is negative (+y is left), and the heading is 30 deg.
  const ros::Imu m = imuWithOrientation(zyx(30, 10, 5));
  AttitudeSample a;
  ASSERT_TRUE(attitudeSampleFromRos(m, mapping(FrameConvention::kNedFrd), Eigen::Quaterniond::Identity(), 1, &a));
  EXPECT_NEAR(a.roll_rad, 5 * kDeg, 1e-12);
  EXPECT_NEAR(a.pitch_rad, -10 * kDeg, 1e-12);
  EXPECT_NEAR(a.sigma_rad, 0.01, 1e-12);
  HeadingSample h;
  ASSERT_TRUE(headingSampleFromRos(m, mapping(FrameConvention::kNedFrd), Eigen::Quaterniond::Identity(), 1, &h));
  EXPECT_NEAR(h.heading_rad, 30 * kDeg, 1e-12);
}

TEST(ForeignConversion, EnuAttitudeIsUsedAsIsAndTheMountingIsTakenOut) {
  // ENU: robot at yaw 60 deg (heading 30), pitch -10, roll 5; the AHRS is mounted turned 180 deg about z,
  // so it reports q_odom_robot * q_robot_sensor.
  const Eigen::Quaterniond q_robot_sensor = zyx(180, 0, 0);
  const ros::Imu m = imuWithOrientation(zyx(60, -10, 5) * q_robot_sensor);
  AttitudeSample a;
  ASSERT_TRUE(attitudeSampleFromRos(m, mapping(FrameConvention::kEnuFlu), q_robot_sensor, 1, &a));
  EXPECT_NEAR(a.roll_rad, 5 * kDeg, 1e-12);
  EXPECT_NEAR(a.pitch_rad, -10 * kDeg, 1e-12);
  HeadingSample h;
  ASSERT_TRUE(headingSampleFromRos(m, mapping(FrameConvention::kEnuFlu), q_robot_sensor, 1, &h));
  EXPECT_NEAR(h.heading_rad, 30 * kDeg, 1e-12);
  // Without the mounting the same message would read a heading 180 deg away.
  ASSERT_TRUE(headingSampleFromRos(m, mapping(FrameConvention::kEnuFlu), Eigen::Quaterniond::Identity(), 1, &h));
  EXPECT_NEAR(h.heading_rad, 210 * kDeg, 1e-12);
}

TEST(ForeignConversion, FieldsAnImuDoesNotProvideGiveNoSample) {
  ros::Imu m = imuWithOrientation(Eigen::Quaterniond::Identity());
  m.orientation_covariance[0] = -1.0;  // REP-145: no orientation estimate
  AttitudeSample a;
  EXPECT_FALSE(attitudeSampleFromRos(m, mapping(FrameConvention::kEnuFlu), Eigen::Quaterniond::Identity(), 1, &a));
  ImuSample s;
  ASSERT_TRUE(imuSampleFromRos(m, mapping(FrameConvention::kEnuFlu), 1, &s));
  EXPECT_FALSE(s.has_orientation);
  m.angular_velocity_covariance[0] = -1.0;  // an orientation-only message: no rates
  EXPECT_FALSE(imuSampleFromRos(m, mapping(FrameConvention::kEnuFlu), 1, &s));
  m.angular_velocity_covariance[0] = 0.0;
  m.linear_acceleration_covariance[0] = -1.0;
  EXPECT_FALSE(imuSampleFromRos(m, mapping(FrameConvention::kEnuFlu), 1, &s));
  m.orientation_covariance[0] = 0.0;
  m.orientation = {0, 0, 0, 0};  // not a rotation
  EXPECT_FALSE(attitudeSampleFromRos(m, mapping(FrameConvention::kEnuFlu), Eigen::Quaterniond::Identity(), 1, &a));
}

TEST(ForeignConversion, FrdDvlVelocityAndCovarianceTurnToFlu) {
  std::array<double, 36> cov{};
  cov[0] = 0.01;
  cov[7] = 0.02;
  cov[14] = 0.03;
  cov[1] = cov[6] = 0.001;   // xy
  cov[2] = cov[12] = 0.002;  // xz
  DvlSample s;
  ASSERT_TRUE(dvlSampleFromRos({1.0, 0.2, 0.1}, &cov, mapping(FrameConvention::kNedFrd), 7, &s));
  EXPECT_TRUE(s.valid);
  EXPECT_EQ(s.v_dvl_mps, Eigen::Vector3d(1.0, -0.2, -0.1));
  Eigen::Matrix3d expected;
  expected << 0.01, -0.001, -0.002, -0.001, 0.02, 0.0, -0.002, 0.0, 0.03;
  EXPECT_TRUE(s.cov_v_dvl_mps2.isApprox(expected, 1e-15)) << s.cov_v_dvl_mps2;
  // Unknown covariance (TwistStamped, or -1 on the diagonal): left zero, the board's dvl sigma applies.
  ASSERT_TRUE(dvlSampleFromRos({1.0, 0.2, 0.1}, nullptr, mapping(FrameConvention::kEnuFlu), 7, &s));
  EXPECT_EQ(s.v_dvl_mps, Eigen::Vector3d(1.0, 0.2, 0.1));
  EXPECT_TRUE(s.cov_v_dvl_mps2.isZero());
  cov[0] = -1;
  ASSERT_TRUE(dvlSampleFromRos({1.0, 0.2, 0.1}, &cov, mapping(FrameConvention::kEnuFlu), 7, &s));
  EXPECT_TRUE(s.cov_v_dvl_mps2.isZero());
  EXPECT_FALSE(dvlSampleFromRos({NAN, 0.2, 0.1}, nullptr, mapping(FrameConvention::kEnuFlu), 7, &s));
}

TEST(ForeignConversion, PressureIsDepthInSeaWater) {
  TopicMapping map;
  map.atmospheric_pa = 101325.0;
  map.water_density_kgpm3 = 1025.0;
  ros::FluidPressure p;
  p.fluid_pressure = 201325.0;
  p.variance = 100.0;
  DepthSample d;
  ASSERT_TRUE(depthSampleFromRos(p, map, 3, &d));
  const double rho_g = 1025.0 * 9.80665;
  EXPECT_DOUBLE_EQ(d.depth_m, 100000.0 / rho_g);  // 9.9485 m
  EXPECT_NEAR(d.depth_m, 9.9485, 1e-4);
  EXPECT_DOUBLE_EQ(d.sigma_m, 10.0 / rho_g);
  EXPECT_EQ(d.pressure_pa, 201325.0);
}

// The earth's field at mid latitude, ENU: 20 uT north, 40 uT down.
const Eigen::Vector3d kFieldEnuT(0.0, 20e-6, -40e-6);

ros::MagneticField magnetometer(const Eigen::Vector3d& m) {
  ros::MagneticField f;
  f.magnetic_field = {m.x(), m.y(), m.z()};
  return f;
}

TEST(ForeignConversion, CompassHeadingIsTiltCompensatedWithTheAttitude) {
  // Robot at heading 60 deg (ENU yaw 30), pitched -20 deg and rolled 10: the magnetometer (FLU, aligned with
  // the robot) reads R^T m_enu. Levelled with the attitude the heading is 60 deg.
  const Eigen::Quaterniond q_odom_robot = zyx(30, -20, 10);
  const Eigen::Vector3d m_robot = q_odom_robot.conjugate() * kFieldEnuT;
  AttitudeSample att;
  att.roll_rad = 10 * kDeg;
  att.pitch_rad = -20 * kDeg;
  HeadingSample h;
  ASSERT_TRUE(compassHeadingFromRos(magnetometer(m_robot), mapping(FrameConvention::kEnuFlu),
                                    Eigen::Quaterniond::Identity(), att, 5, &h));
  EXPECT_NEAR(h.heading_rad, 60 * kDeg, 1e-9);
  EXPECT_FALSE(h.is_true);
  // Without levelling (attitude zero) the same reading is off by tens of degrees: why a compass needs one.
  ASSERT_TRUE(compassHeadingFromRos(magnetometer(m_robot), mapping(FrameConvention::kEnuFlu),
                                    Eigen::Quaterniond::Identity(), AttitudeSample{}, 5, &h));
  EXPECT_GT(std::abs(h.heading_rad - 60 * kDeg), 10 * kDeg);
}

TEST(ForeignConversion, FrdMagnetometerFacingEastWithAHardIronOffset) {
  // Level, facing east: FRD axes x east, y south, z down, so the field (N 20, D 40 uT) reads (0, -20, 40) uT,
  // plus a hard-iron offset of (1, 2, 3) uT that the map subtracts.
  TopicMapping map = mapping(FrameConvention::kNedFrd);
  map.hard_iron_t = Eigen::Vector3d(1e-6, -2e-6, -3e-6);  // in FLU: the FRD offset (1, 2, 3) uT
  HeadingSample h;
  ASSERT_TRUE(compassHeadingFromRos(magnetometer(Eigen::Vector3d(1e-6, -18e-6, 43e-6)), map,
                                    Eigen::Quaterniond::Identity(), AttitudeSample{}, 5, &h));
  EXPECT_NEAR(h.heading_rad, 90 * kDeg, 1e-9);
}

TEST(ForeignConversion, ImagesOfEachEncodingBecomeGreyOrBgr) {
  ros::Image m;
  m.width = 2;
  m.height = 1;
  m.encoding = "rgb8";
  m.step = 8;  // padded rows
  m.data = {10, 20, 30, 40, 50, 60, 0, 0};
  cv::Mat out;
  std::string error;
  ASSERT_TRUE(imageFromRos(m, 3, 16, &out, &error)) << error;
  ASSERT_EQ(out.type(), CV_8UC3);
  EXPECT_EQ(out.at<cv::Vec3b>(0, 0), cv::Vec3b(30, 20, 10));
  EXPECT_EQ(out.at<cv::Vec3b>(0, 1), cv::Vec3b(60, 50, 40));
  EXPECT_EQ(m.data[0], 10);  // the message's bytes are read, never converted in place
  m.encoding = "bgr8";
  ASSERT_TRUE(imageFromRos(m, 1, 16, &out, &error)) << error;
  ASSERT_EQ(out.type(), CV_8UC1);
  EXPECT_EQ(out.at<std::uint8_t>(0, 0), 22);  // B 10, G 20, R 30: 0.114*10 + 0.587*20 + 0.299*30 = 21.85
  m.encoding = "mono8";
  m.data = {7, 9, 0, 0, 0, 0, 0, 0};
  ASSERT_TRUE(imageFromRos(m, 3, 16, &out, &error)) << error;
  EXPECT_EQ(out.at<cv::Vec3b>(0, 1), cv::Vec3b(9, 9, 9));
  // mono16, big-endian, 12 significant bits: 0x0FFF -> 255, 0x0800 -> 128.
  m.encoding = "mono16";
  m.is_bigendian = 1;
  m.step = 4;
  m.data = {0x0F, 0xFF, 0x08, 0x00};
  ASSERT_TRUE(imageFromRos(m, 1, 12, &out, &error)) << error;
  EXPECT_EQ(out.at<std::uint8_t>(0, 0), 255);
  EXPECT_EQ(out.at<std::uint8_t>(0, 1), 128);
  m.is_bigendian = 0;
  m.data = {0xFF, 0x0F, 0x00, 0x08};
  ASSERT_TRUE(imageFromRos(m, 1, 12, &out, &error)) << error;
  EXPECT_EQ(out.at<std::uint8_t>(0, 1), 128);
}

TEST(ForeignConversion, UnreadableImagesAreRefusedByName) {
  ros::Image m;
  m.width = 2;
  m.height = 2;
  m.encoding = "bayer_rggb8";
  m.step = 2;
  m.data.assign(4, 0);
  cv::Mat out;
  std::string error;
  EXPECT_FALSE(imageFromRos(m, 1, 16, &out, &error));
  EXPECT_NE(error.find("'bayer_rggb8'"), std::string::npos) << error;
  m.encoding = "mono8";
  m.data.assign(3, 0);  // one byte short
  EXPECT_FALSE(imageFromRos(m, 1, 16, &out, &error));
  EXPECT_NE(error.find("too few"), std::string::npos) << error;
  m.step = 1;  // shorter than a row
  m.data.assign(4, 0);
  EXPECT_FALSE(imageFromRos(m, 1, 16, &out, &error));
}

TEST(ForeignConversion, PngAndJpegDecodeOthersAreRefused) {
  cv::Mat grey(6, 8, CV_8UC1);
  for (int r = 0; r < grey.rows; ++r) {
    for (int c = 0; c < grey.cols; ++c) grey.at<std::uint8_t>(r, c) = static_cast<std::uint8_t>(r * 30 + c);
  }
  ros::CompressedImage m;
  m.format = "png";
  ASSERT_TRUE(cv::imencode(".png", grey, m.data));
  cv::Mat out;
  std::string error;
  ASSERT_TRUE(imageFromRos(m, 1, 16, &out, &error)) << error;
  EXPECT_EQ(cv::norm(out, grey, cv::NORM_INF), 0.0);  // lossless
  m.format = "mono8; jpeg compressed mono8";
  ASSERT_TRUE(cv::imencode(".jpg", grey, m.data, {cv::IMWRITE_JPEG_QUALITY, 100}));
  ASSERT_TRUE(imageFromRos(m, 3, 16, &out, &error)) << error;
  EXPECT_EQ(out.type(), CV_8UC3);
  EXPECT_EQ(out.size(), grey.size());
  // A 12-bit camera's image in a 16-bit PNG: 0x0FFF -> 255, 0x0800 -> 128 with mono16_bits 12.
  cv::Mat deep(1, 2, CV_16UC1);
  deep.at<std::uint16_t>(0, 0) = 0x0FFF;
  deep.at<std::uint16_t>(0, 1) = 0x0800;
  m.format = "png";
  ASSERT_TRUE(cv::imencode(".png", deep, m.data));
  ASSERT_TRUE(imageFromRos(m, 1, 12, &out, &error)) << error;
  ASSERT_EQ(out.type(), CV_8UC1);
  EXPECT_EQ(out.at<std::uint8_t>(0, 0), 255);
  EXPECT_EQ(out.at<std::uint8_t>(0, 1), 128);
  m.format = "png compressedDepth";
  EXPECT_FALSE(imageFromRos(m, 1, 16, &out, &error));
  EXPECT_NE(error.find("'png compressedDepth'"), std::string::npos) << error;
  m.format = "webp";
  EXPECT_FALSE(imageFromRos(m, 1, 16, &out, &error));
  m.format = "jpeg";
  m.data = {1, 2, 3, 4};
  EXPECT_FALSE(imageFromRos(m, 1, 16, &out, &error));
  EXPECT_NE(error.find("does not decode"), std::string::npos) << error;
  m.data.clear();
  EXPECT_FALSE(imageFromRos(m, 1, 16, &out, &error));
}

cv::Mat tagged(int value) { return cv::Mat(2, 2, CV_8UC1, cv::Scalar(value)); }

TEST(ForeignConversion, StereoPairsByNearestStampWithinTheTolerance) {
  StereoPairing pairing(5000);
  StereoFrame f;
  cv::Mat img = tagged(1);
  EXPECT_FALSE(pairing.add(true, 0, &img, &f));
  img = tagged(2);
  ASSERT_TRUE(pairing.add(false, 3000, &img, &f));  // 3 ms apart: a pair, at the left stamp
  EXPECT_EQ(f.t_us, 0);
  EXPECT_EQ(f.left.at<std::uint8_t>(0, 0), 1);
  EXPECT_EQ(f.right.at<std::uint8_t>(0, 0), 2);
  EXPECT_EQ(f.sequence, 0u);
  img = tagged(3);
  EXPECT_FALSE(pairing.add(false, 100000, &img, &f));
  img = tagged(4);
  EXPECT_FALSE(pairing.add(true, 108000, &img, &f));  // 8 ms: beyond 5
  img = tagged(5);
  ASSERT_TRUE(pairing.add(false, 109000, &img, &f));  // pairs with the left at 108 ms; the right at 100 is dropped
  EXPECT_EQ(f.t_us, 108000);
  EXPECT_EQ(f.left.at<std::uint8_t>(0, 0), 4);
  EXPECT_EQ(f.right.at<std::uint8_t>(0, 0), 5);
  EXPECT_EQ(f.sequence, 1u);
  EXPECT_EQ(pairing.pairs(), 2u);
  EXPECT_EQ(pairing.unpaired(), 1u);
}

}  // namespace
}  // namespace deepnav::foreign
