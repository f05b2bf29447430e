// /nav/estimator_states (drivers/recording/estimator_states_codec.h): every field round-trips bit for bit,
// truncated messages are refused, the topic is registered with its schema.
#include <gtest/gtest.h>

#include <vector>

#include "drivers/recording/estimator_states_codec.h"
#include "drivers/recording/topics.h"

namespace deepnav {
namespace {

EstimatorStates sample() {
  EstimatorStates e;
  e.t_us = 123'456'789;
  for (int k = 0; k < 3; ++k) {
    e.gyro_bias_radps[k] = 1e-5 * (k + 1);
    e.gyro_bias_sigma_radps[k] = 2e-6 * (k + 1);
    e.accel_bias_mps2[k] = -3e-3 * (k + 1);
    e.accel_bias_sigma_mps2[k] = 4e-4 * (k + 1);
    e.dvl_misalignment_rad[k] = 0.003 * (k - 1);
    e.dvl_misalignment_sigma_rad[k] = 0.001 * (k + 2);
  }
  e.dvl_scale_estimated = true;
  e.dvl_scale = -0.0042;
  e.dvl_scale_sigma = 0.0007;
  e.dvl_misalignment_estimated = true;
  e.heading_bias_estimated = true;
  e.heading_bias_rad = 0.012;
  e.heading_bias_sigma_rad = 0.002;
  e.heading_deviation_estimated = false;
  for (int k = 0; k < 4; ++k) e.heading_deviation_rad[k] = 0.001 * k;
  e.dvl_bias_estimated = true;
  for (int k = 0; k < 3; ++k) e.dvl_bias_mps[k] = -0.001 * (k + 1);
  for (int k = 0; k < 3; ++k) e.dvl_bias_sigma_mps[k] = 0.0005 * (k + 1);
  return e;
}

TEST(EstimatorStatesCodec, RoundTripsEveryFieldAndRefusesTruncation) {
  // GIVEN estimates with every field set
  const EstimatorStates in = sample();
  std::vector<std::uint8_t> buf(1024);
  // WHEN encoded and decoded
  const std::size_t n = encodeEstimatorStates(in, buf.data(), buf.size());
  ASSERT_GT(n, 0u);
  EstimatorStates out;
  ASSERT_TRUE(decodeEstimatorStates(buf.data(), n, &out));
  // THEN every field is back bit for bit
  EXPECT_EQ(out.t_us, in.t_us);
  EXPECT_EQ(out.gyro_bias_radps, in.gyro_bias_radps);
  EXPECT_EQ(out.gyro_bias_sigma_radps, in.gyro_bias_sigma_radps);
  EXPECT_EQ(out.accel_bias_mps2, in.accel_bias_mps2);
  EXPECT_EQ(out.accel_bias_sigma_mps2, in.accel_bias_sigma_mps2);
  EXPECT_EQ(out.dvl_scale_estimated, in.dvl_scale_estimated);
  EXPECT_EQ(out.dvl_scale, in.dvl_scale);
  EXPECT_EQ(out.dvl_scale_sigma, in.dvl_scale_sigma);
  EXPECT_EQ(out.dvl_misalignment_estimated, in.dvl_misalignment_estimated);
  EXPECT_EQ(out.dvl_misalignment_rad, in.dvl_misalignment_rad);
  EXPECT_EQ(out.dvl_misalignment_sigma_rad, in.dvl_misalignment_sigma_rad);
  EXPECT_EQ(out.heading_bias_estimated, in.heading_bias_estimated);
  EXPECT_EQ(out.heading_bias_rad, in.heading_bias_rad);
  EXPECT_EQ(out.heading_bias_sigma_rad, in.heading_bias_sigma_rad);
  EXPECT_EQ(out.heading_deviation_estimated, in.heading_deviation_estimated);
  EXPECT_EQ(out.heading_deviation_rad, in.heading_deviation_rad);
  EXPECT_EQ(out.dvl_bias_estimated, in.dvl_bias_estimated);
  EXPECT_EQ(out.dvl_bias_mps, in.dvl_bias_mps);
  EXPECT_EQ(out.dvl_bias_sigma_mps, in.dvl_bias_sigma_mps);
  // AND every truncation is refused, and a buffer too small gives 0
  for (std::size_t cut = 0; cut < n; ++cut) EXPECT_FALSE(decodeEstimatorStates(buf.data(), cut, &out)) << cut;
  EXPECT_EQ(encodeEstimatorStates(in, buf.data(), n - 1), 0u);
}

TEST(EstimatorStatesCodec, TopicIsRegisteredWithItsSchema) {
  EXPECT_EQ(topicByName("/nav/estimator_states"), Topic::kEstimatorStates);
  const std::string_view schema = topicSchema(Topic::kEstimatorStates);
  EXPECT_NE(schema.find("float64[4] compass_deviation"), std::string_view::npos);
  EXPECT_NE(schema.find("float64[3] dvl_bias"), std::string_view::npos);
  EXPECT_NE(schema.find("bool dvl_scale_estimated"), std::string_view::npos);
}

}  // namespace
}  // namespace deepnav
