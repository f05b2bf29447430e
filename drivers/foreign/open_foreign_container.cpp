#include "drivers/foreign/open_foreign_container.h"

#include <cstring>
#include <fstream>

#include "drivers/foreign/mcap_container.h"
#include "drivers/rosbag/bag_reader.h"

namespace deepnav::foreign {
namespace {

constexpr char kMcapMagic[] = "\x89MCAP0\r\n";
constexpr char kBagMagic[] = "#ROSBAG V2.0\n";

template <typename Container>
std::unique_ptr<ForeignContainer> openAs(const std::string& path, std::string* error) {
  auto container = std::make_unique<Container>();
  if (!container->open(path, error)) return nullptr;
  return container;
}

}  // namespace

std::unique_ptr<ForeignContainer> openForeignContainer(const std::string& path, std::string* error) {
  char head[16] = {};
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    if (error) *error = path + ": cannot open: " + std::strerror(errno);
    return nullptr;
  }
  in.read(head, sizeof(head));
  const auto got = static_cast<std::size_t>(in.gcount());
  const auto starts = [&](const char* magic, std::size_t n) { return got >= n && std::memcmp(head, magic, n) == 0; };
  if (starts(kMcapMagic, sizeof(kMcapMagic) - 1)) return openAs<McapContainer>(path, error);
  if (starts(kBagMagic, sizeof(kBagMagic) - 1)) return openAs<rosbag::BagReader>(path, error);
  if (error) {
    *error = path + ": neither a ROS 2 MCAP recording (magic 0x89 MCAP0) nor a ROS 1 bag (#ROSBAG V2.0)";
    if (got >= 13 && std::memcmp(head, "#ROSBAG V", 9) == 0) *error += ": bag format '" + std::string(head, 12) + "'";
  }
  return nullptr;
}

}  // namespace deepnav::foreign
