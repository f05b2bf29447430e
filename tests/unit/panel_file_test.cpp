#include "board/config/panel_file.h"

#include <gtest/gtest.h>

namespace deepnav {
namespace {

PanelDescription samplePanel() {
  PanelDescription p;
  p.faces.push_back({"valves", {0, 1, 0.75}, {0, 1, 0}, 2.0, 1.5});
  p.faces.push_back({"grasping", {1, 0, 0.75}, {1, 0, 0}, 2.0, 1.5});
  PanelMarker m;
  m.id = 7;
  m.face = 1;
  m.p_marker_in_panel_m = {1.0, 0.3, 1.2};
  m.q_panel_marker = Eigen::Quaterniond(Eigen::AngleAxisd(0.5 * M_PI, Eigen::Vector3d::UnitY()));
  p.markers.push_back(m);
  return p;
}

TEST(PanelFile, RoundTripsExactly) {
  const PanelDescription p = samplePanel();
  PanelDescription q;
  std::string error;
  ASSERT_TRUE(parsePanelDescription(formatPanelDescription(p), "mem", &q, &error)) << error;
  ASSERT_EQ(q.markers.size(), 1u);
  EXPECT_EQ(q.markers[0].p_marker_in_panel_m, p.markers[0].p_marker_in_panel_m);
  EXPECT_NEAR(q.markers[0].q_panel_marker.angularDistance(p.markers[0].q_panel_marker), 0.0, 1e-12);
  EXPECT_EQ(q.faces[1].name, "grasping");
  EXPECT_NE(q.marker(7), nullptr);
  EXPECT_EQ(q.marker(8), nullptr);
}

TEST(PanelFile, BadInputNamesTheKey) {
  std::string text = formatPanelDescription(samplePanel());
  PanelDescription q;
  std::string error;
  EXPECT_FALSE(parsePanelDescription(text + "colour: red\n", "p.yaml", &q, &error));
  EXPECT_NE(error.find("p.yaml: key 'colour' is unknown"), std::string::npos) << error;
  std::string bad = text;
  bad.replace(bad.find("face: 1"), 7, "face: 5");
  EXPECT_FALSE(parsePanelDescription(bad, "p.yaml", &q, &error));
  EXPECT_NE(error.find("markers[0].face' is 5, allowed [0, 1]"), std::string::npos) << error;
  EXPECT_FALSE(loadPanelDescription("/nonexistent/panel.yaml", &q, &error));
  EXPECT_NE(error.find("/nonexistent/panel.yaml"), std::string::npos);
}

}  // namespace
}  // namespace deepnav
