#pragma once
#include <string>
#include <vector>

#include "drivers/foreign/foreign_message.h"
#include "drivers/rosbag/bag_file.h"
#include "drivers/rosbag/bag_index.h"

// A ROS 1 bag (format 2.0, http://wiki.ros.org/Bags/Format/2.0) read without ROS: chunks
// uncompressed, bz2 or lz4; the index (connection and chunk info records after index_pos) when the
// bag was closed, a scan of the chunks when it was not (index_pos 0, past the end, or damaged).
// Messages come in log-time order, merged across chunks and connections, ties in file order.
// See drivers/rosbag/README.md for what is supported and the limits.
namespace deepnav::rosbag {

class BagReader : public foreign::ForeignContainer {
 public:
  // Checks the magic and version, reads the bag header and the index (or scans the chunks),
  // checks every chunk header (compression known, sizes within the file) and every connection of
  // a type deepnav decodes against its standard md5sum. False with *error naming the file, the
  // byte offset and the field.
  bool open(const std::string& path, std::string* error);

  const std::vector<foreign::ForeignTopic>& topics() const override { return topics_; }
  // Every message in log-time order. False with *error when part of the bag could not be read
  // (a bag cut short: the messages before the cut are delivered first) or a chunk is damaged.
  bool forEach(const Callback& callback, std::string* error) override;

  // Empty when the index was used; otherwise why the chunks were scanned.
  const std::string& notice() const { return index_.notice; }
  // What a bag cut short lost (empty when nothing); forEach reports it as its error.
  const std::string& loss() const { return index_.loss; }
  const std::map<uint32_t, Connection>& connections() const { return index_.connections; }

 private:
  bool readBagHeader(BagHeaderFields* header, uint64_t* chunks_start, std::string* error);
  bool readChunks(const BagHeaderFields& header, uint64_t chunks_start, std::string* error);
  bool checkConnections(std::string* error) const;
  void listTopics();

  BagFile file_;
  BagIndex index_;
  std::vector<foreign::ForeignTopic> topics_;
};

}  // namespace deepnav::rosbag
