#pragma once

// The PDU's fields as the Modbus codec reads and writes them, shared by modbus.cpp, the
// master's side (modbus_master.cpp) and the slave's (modbus_slave.cpp). Not part of the
// codec's interface: include modbus_master.h or modbus_slave.h instead.

#include "comms/protocol/modbus.h"

#include <QByteArray>

#include <cstddef>
#include <vector>

namespace rung::comms::modbus::detail {

inline void put16(QByteArray &out, int value) {
    out += char((value >> 8) & 0xFF);
    out += char(value & 0xFF);
}

inline int get16(QByteArrayView bytes, qsizetype at) {
    return static_cast<quint8>(bytes[at]) << 8 | static_cast<quint8>(bytes[at + 1]);
}

inline int byte(QByteArrayView bytes, qsizetype at) {
    return static_cast<quint8>(bytes[at]);
}

inline void putBits(QByteArray &out, const std::vector<bool> &bits) {
    const auto bytes = (bits.size() + 7) / 8;
    out += char(bytes & 0xFF);
    for (std::size_t b = 0; b < bytes; ++b) {
        int value = 0;
        for (std::size_t i = 0; i < 8 && b * 8 + i < bits.size(); ++i)
            if (bits[b * 8 + i])
                value |= 1 << i;
        out += char(value);
    }
}

inline std::vector<bool> getBits(QByteArrayView bytes, qsizetype at, int count) {
    std::vector<bool> bits(static_cast<std::size_t>(count));
    for (int i = 0; i < count; ++i)
        bits[std::size_t(i)] = (byte(bytes, at + i / 8) >> (i % 8)) & 1;
    return bits;
}

inline bool isRead(int function) {
    return function >= ReadCoils && function <= ReadInputRegisters;
}

inline bool isBitRead(int function) {
    return function == ReadCoils || function == ReadDiscreteInputs;
}

} // namespace rung::comms::modbus::detail
