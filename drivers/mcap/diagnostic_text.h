#pragma once
#include <cstdint>
#include <string>

// Numbers as the reader's warnings and errors print them.
namespace deepnav::mcap {

// A CRC as 0x89ABCDEF.
std::string hex32(uint32_t v);

// Nanoseconds as seconds with nine decimals: 12.000000345.
std::string secondsText(uint64_t ns);

}  // namespace deepnav::mcap
