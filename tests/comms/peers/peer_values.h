#pragma once

// What the real-peer slaves (modbus_peer.cpp, pymodbus_peer.py) hold at each address before
// any write, so a test knows every value it reads. pymodbus_peer.py repeats these formulas.

#include <cstdint>

namespace rung::comms::test::peer {

inline constexpr int Size = 40000; // covers the PL110 map up to V349 at 2349 and SM at 18079

inline std::uint16_t reg(int address) {
    return std::uint16_t((address * 7 + 3) & 0xFFFF);
}
inline bool coil(int address) {
    return address % 3 == 0;
}
inline bool input(int address) {
    return address % 5 == 0;
}

} // namespace rung::comms::test::peer
