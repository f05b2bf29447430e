// Our MCAP files read by someone else's reader: tools/mcapcheck/check.mjs runs Foxglove's
// @mcap/core (indexed and streaming, CRCs validated) on recordings written by
// deepnav::mcap::Writer with every compression, holding real CDR-encoded ROS 2 messages.
//
// This binary also replaces operator new to count allocations (which it can do as its own
// executable without touching other tests): Writer::write() must not allocate in steady state.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <new>
#include <string>
#include <vector>

#include "drivers/cdr/ros2msg_definitions.h"
#include "drivers/cdr/ros_msg_codec.h"
#include "drivers/mcap/reader.h"
#include "drivers/mcap/writer.h"
#include "tests/support/mcap_test_util.h"
#include "tests/support/source_paths.h"
#include "tests/support/temp_path.h"

// GCC 12 inlines the replaced operator delete into gtest's code and then flags free() on memory
// from operator new, not seeing that this operator new is malloc.
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"

namespace {
std::atomic<bool> g_counting{false};
std::atomic<size_t> g_allocations{0};
}  // namespace

void* operator new(size_t size) {
  if (g_counting.load(std::memory_order_relaxed))
    g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void* operator new[](size_t size) { return operator new(size); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, size_t) noexcept { std::free(p); }
void operator delete[](void* p, size_t) noexcept { std::free(p); }

namespace deepnav::mcap {
namespace {

const std::string kSourceDir = deepnav::testing::sourceDir();
const std::string kCheckScript = kSourceDir + "/tools/mcapcheck/check.mjs";

// ctest runs each parameterised case as its own process, in parallel: the per-process directory keeps their
// files apart.
std::string tempPath(const std::string& name) { return deepnav::testing::tempPath("mcapcheck_" + name); }

bool independentReaderAvailable(std::string* why) {
  if (std::system("command -v node >/dev/null 2>&1") != 0) {
    *why = "node is not installed";
    return false;
  }
  if (!std::filesystem::exists(kSourceDir + "/tools/mcapcheck/node_modules/@mcap/core")) {
    *why = "tools/mcapcheck/node_modules is missing (run tools/setup.sh)";
    return false;
  }
  return true;
}

struct CheckResult {
  int exit_code = -1;
  std::string output;
};

CheckResult runCheck(const std::string& file) {
  CheckResult r;
  const std::string command = "node '" + kCheckScript + "' '" + file + "' 2>&1";
  std::FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) return r;
  char buf[4096];
  size_t n = 0;
  while ((n = std::fread(buf, 1, sizeof(buf), pipe)) > 0) r.output.append(buf, n);
  const int status = ::pclose(pipe);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

// The count check.mjs reports for `topic`, or -1. Its JSON is compact with a fixed key order.
long reportedCount(const std::string& json, const std::string& topic, const std::string& schema) {
  const std::string key = "{\"topic\":\"" + topic + "\",\"schema\":\"" + schema + "\",\"count\":";
  const size_t at = json.find(key);
  return at == std::string::npos ? -1 : std::strtol(json.c_str() + at + key.size(), nullptr, 10);
}

struct Topic {
  std::string name;
  std::string_view type;
  uint16_t channel = 0;
  long count = 0;
};

// Writes IMU at 200 Hz, depth and DVL at 10 Hz, odometry at 50 Hz and small images at 4 Hz for
// 5 s of log time, all CDR-encoded with their ros2msg schemas.
std::vector<Topic> writeRecording(const std::string& path, Compression compression) {
  WriterOptions options;
  options.compression = compression;
  options.chunk_size_bytes = 16 * 1024;
  Writer writer;
  std::string error;
  EXPECT_TRUE(writer.open(path, options, &error)) << error;
  std::vector<Topic> topics = {{"/imu", ros::Imu::kTypeName},
                               {"/depth", ros::FluidPressure::kTypeName},
                               {"/dvl", ros::TwistWithCovarianceStamped::kTypeName},
                               {"/odom", ros::Odometry::kTypeName},
                               {"/camera/left", ros::Image::kTypeName}};
  const std::map<std::string, std::string> qos = {{"offered_qos_profiles", ""}};
  for (Topic& t : topics) {
    const std::string definition = ros::ros2MsgDefinition(t.type);
    EXPECT_FALSE(definition.empty()) << t.type;
    const uint16_t schema = writer.addSchema(t.type, ros::kRos2MsgEncoding, definition);
    t.channel = writer.addChannel(schema, t.name, ros::kCdrEncoding, qos);
  }
  std::vector<uint8_t> bytes;
  const auto put = [&](Topic& t, uint64_t t_ns, const auto& msg) {
    EXPECT_TRUE(ros::encode(msg, &bytes));
    EXPECT_TRUE(
        writer.write(t.channel, uint32_t(t.count++), t_ns, t_ns, bytes.data(), bytes.size()))
        << writer.lastError();
  };
  for (uint64_t ms = 0; ms < 5000; ms += 5) {
    const uint64_t t_ns = 1'000'000'000ull + ms * 1'000'000ull;
    ros::Header header;
    header.stamp = ros::Time{int32_t(t_ns / 1'000'000'000), uint32_t(t_ns % 1'000'000'000)};
    header.frame_id = "base_link";
    ros::Imu imu;
    imu.header = header;
    imu.linear_acceleration.z = 9.81 + double(ms % 7) * 1e-3;
    put(topics[0], t_ns, imu);
    if (ms % 100 == 0) {
      ros::FluidPressure depth;
      depth.header = header;
      depth.fluid_pressure = 101325.0 + double(ms);
      put(topics[1], t_ns, depth);
      ros::TwistWithCovarianceStamped dvl;
      dvl.header = header;
      dvl.twist.twist.linear.x = 0.3;
      put(topics[2], t_ns, dvl);
    }
    if (ms % 20 == 0) {
      ros::Odometry odom;
      odom.header = header;
      odom.child_frame_id = "base_link";
      odom.pose.pose.position.z = -double(ms) / 1000.0;
      put(topics[3], t_ns, odom);
    }
    if (ms % 250 == 0) {
      ros::Image image;
      image.header = header;
      image.height = 24;
      image.width = 32;
      image.encoding = "mono8";
      image.step = 32;
      image.data.assign(24 * 32, uint8_t(ms));
      put(topics[4], t_ns, image);
    }
  }
  EXPECT_TRUE(writer.close(&error)) << error;
  return topics;
}

class McapIndependentReader : public ::testing::TestWithParam<Compression> {};

TEST_P(McapIndependentReader, FoxgloveReaderAgreesOnEveryTopic) {
  std::string why;
  if (!independentReaderAvailable(&why)) GTEST_SKIP() << why;
  const std::string name(compressionName(GetParam()));
  const std::string path = tempPath((name.empty() ? "none" : name) + ".mcap");
  const std::vector<Topic> topics = writeRecording(path, GetParam());

  const CheckResult result = runCheck(path);
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("\"profile\":\"ros2\""), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("\"agree\":true"), std::string::npos) << result.output;
  long total = 0;
  for (const Topic& t : topics) {
    EXPECT_EQ(reportedCount(result.output, t.name, std::string(t.type)), t.count)
        << t.name << " in " << result.output;
    total += t.count;
  }
  EXPECT_NE(result.output.find("\"messages\":" + std::to_string(total) + ","), std::string::npos)
      << result.output;
  std::filesystem::remove(path);
}

TEST_P(McapIndependentReader, FoxgloveReaderRejectsACutOffFile) {
  std::string why;
  if (!independentReaderAvailable(&why)) GTEST_SKIP() << why;
  const std::string path = tempPath("cut.mcap");
  writeRecording(path, GetParam());
  std::filesystem::resize_file(path, std::filesystem::file_size(path) / 2);
  const CheckResult result = runCheck(path);
  EXPECT_EQ(result.exit_code, 2) << result.output;
  std::filesystem::remove(path);
}

INSTANTIATE_TEST_SUITE_P(McapEveryCompression, McapIndependentReader, everyCompression(), compressionTestName);

TEST(McapWriterSteadyState, WriteDoesNotAllocateAfterWarmUp) {
  for (const Compression compression :
       {Compression::kNone, Compression::kZstd, Compression::kLz4}) {
    SCOPED_TRACE(std::string(compressionName(compression)));
    // GIVEN a writer past its first chunks (every channel has seen its busiest chunk)
    const std::string path = tempPath("steady.mcap");
    WriterOptions options;
    options.compression = compression;
    options.chunk_size_bytes = 8 * 1024;
    Writer writer;
    std::string error;
    ASSERT_TRUE(writer.open(path, options, &error)) << error;
    const uint16_t imu =
        writer.addChannel(writer.addSchema("a", "ros2msg", "int32 x\n"), "/imu", "cdr");
    const uint16_t depth = writer.addChannel(0, "/depth", "cdr");
    const std::vector<uint8_t> data(100, 0x42);
    uint32_t sequence = 0;
    const auto writeSome = [&](int n) {
      for (int i = 0; i < n; ++i, ++sequence) {
        const uint64_t t_ns = uint64_t(sequence) * 5'000'000ull;
        ASSERT_TRUE(writer.write(imu, sequence, t_ns, t_ns, data.data(), data.size()));
        if (sequence % 10 == 0) {
          ASSERT_TRUE(writer.write(depth, sequence, t_ns, t_ns, data.data(), 16));
        }
      }
    };
    writeSome(1000);
    const size_t chunks_before = writer.chunkCount();

    // WHEN thousands more messages are written, closing many chunks (and flushing one by hand)
    g_allocations = 0;
    g_counting = true;
    writeSome(3000);
    const bool flushed = writer.flush();
    g_counting = false;

    // THEN nothing was allocated (and the counter does see allocations)
    g_counting = true;
    const auto* probe = new std::vector<uint8_t>(64);
    g_counting = false;
    delete probe;
    EXPECT_TRUE(flushed);
    EXPECT_GT(writer.chunkCount(), chunks_before + 20);
    EXPECT_EQ(g_allocations.load(), 2u);  // the probe: the vector and its storage
    ASSERT_TRUE(writer.close(&error)) << error;
    std::filesystem::remove(path);
  }
}

}  // namespace
}  // namespace deepnav::mcap
