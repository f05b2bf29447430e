#include "drivers/mcap/crc32.h"
#include "drivers/mcap/diagnostic_text.h"
#include "drivers/mcap/format.h"
#include "drivers/mcap/reader.h"

// readAll(): every message in file order, chunk by chunk, with the data-section CRC checked
// against the DataEnd record.
namespace deepnav::mcap {

bool Reader::readAll(const MessageCallback& callback) {
  if (data_start_ == 0) {
    error_ = "mcap reader: no file open";
    return false;
  }
  error_.clear();
  data_crc_ = header_crc_;
  return walkDataSection([&](uint64_t offset, uint8_t op, uint64_t length) {
    return readAllRecord(offset, op, length, callback);
  });
}

Reader::Visit Reader::readAllRecord(uint64_t offset, uint8_t op, uint64_t length,
                                    const MessageCallback& callback) {
  if (!readContent(offset + kRecordPrefixSize, length, &record_buffer_)) {
    fail("read error in " + opcodeName(op) + " record", offset);
    return Visit::kError;
  }
  const uint8_t* content = record_buffer_.data();
  const size_t size = record_buffer_.size();
  if (op == uint8_t(Opcode::kDataEnd)) {
    checkDataCrc(content, size, offset);
    return Visit::kStop;
  }
  uint8_t prefix[kRecordPrefixSize] = {op};
  for (size_t i = 0; i < 8; ++i) prefix[1 + i] = uint8_t(length >> (8 * i));
  data_crc_ = crc32Update(crc32Update(data_crc_, prefix, sizeof(prefix)), content, size);

  bool ok = true;
  if (op == uint8_t(Opcode::kSchema) || op == uint8_t(Opcode::kChannel)) {
    ok = definitionRecord(op, content, size, offset);
  } else if (op == uint8_t(Opcode::kMessage)) {
    MessageView m;
    ok = parseMessage(ByteCursor(content, size), &m);
    if (ok) callback(m);
  } else if (op == uint8_t(Opcode::kChunk)) {
    if (!deliverChunk(content, size, offset, callback)) return Visit::kError;
  }
  if (!ok) {
    fail("malformed " + opcodeName(op) + " record", offset);
    return Visit::kError;
  }
  return Visit::kContinue;
}

void Reader::checkDataCrc(const uint8_t* content, size_t size, uint64_t offset) {
  uint32_t expected = 0;
  if (!parseDataEnd(ByteCursor(content, size), &expected)) {
    warn("malformed DataEnd record", offset);
  } else if (expected != 0 && expected != data_crc_) {
    warn("data section CRC mismatch (DataEnd says " + hex32(expected) + ", computed " +
             hex32(data_crc_) + "): some byte before the DataEnd record is damaged",
         offset);
  }
}

bool Reader::deliverChunk(const uint8_t* content, size_t size, uint64_t offset,
                          const MessageCallback& callback) {
  const uint8_t* records = nullptr;
  size_t records_size = 0;
  if (!unpackChunk(content, size, offset, &records, &records_size)) return false;
  forEachChunkRecord(records, records_size, offset,
                     [&](uint8_t op, const uint8_t* c, size_t n, uint64_t) {
                       if (op == uint8_t(Opcode::kMessage)) {
                         MessageView m;
                         if (!parseMessage(ByteCursor(c, n), &m)) return false;
                         callback(m);
                         return true;
                       }
                       if (op == uint8_t(Opcode::kSchema) || op == uint8_t(Opcode::kChannel)) {
                         return definitionRecord(op, c, n, offset);
                       }
                       return true;
                     });
  return true;
}

}  // namespace deepnav::mcap
