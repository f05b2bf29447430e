#pragma once
#include <cstddef>
#include <cstdint>

namespace deepnav {

// CRC-8 with polynomial x^8 + x^2 + x + 1 (0x07), initial value 0, no reflection, no final XOR
// ("CRC-8/SMBUS"; check value 0xF4 for "123456789"). Used by the Water Linked DVL serial protocol.
uint8_t crc8(const uint8_t* data, size_t n);

}  // namespace deepnav
