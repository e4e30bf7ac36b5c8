#pragma once

// Line settings of a serial port (by default Vigor 7E1 19200, Vigor M/VB/VH communication
// manual, B-5-1; Host Link 7E2 9600, Omron CPM1/SRM1 programming manual W353; PL110 8N1 19200,
// PL110 manual 2.1.2 and 3.1). Below comms and the simulator: a real port (comms/transport), a
// PLC's port in a simulated network (network/) and the program that sets its port (a VB-1COM's
// BFM #0, Vigor communication manual B-4) speak of the same line.

#include <QString>

#include <cstdint>

namespace rung::model {

struct SerialSettings {
    enum class Parity : std::uint8_t { None, Odd, Even };
    enum class Flow : std::uint8_t { None, RtsCts, XonXoff };
    int baud = 19200;
    int dataBits = 8;
    Parity parity = Parity::None;
    int stopBits = 1;
    Flow flow = Flow::None;

    // Bits one character takes on the wire: start, data, parity, stop.
    int bitsPerCharacter() const {
        return 1 + dataBits + (parity == Parity::None ? 0 : 1) + stopBits;
    }
    // Time one character takes on the wire (start + data + parity + stop bits), in
    // microseconds: the Modbus RTU 3.5-character gap is 3.5 of these (at most 1750 us above
    // 19200 bps, Modbus over serial line 2.5.1.1).
    int characterMicroseconds() const {
        return int(1'000'000LL * bitsPerCharacter() / (baud > 0 ? baud : 1));
    }
    int rtuGapMicroseconds() const { return baud > 19200 ? 1750 : characterMicroseconds() * 7 / 2; }
    // The same characters on the wire: baud rate, data bits, parity and stop bits.
    bool sameLine(const SerialSettings &o) const {
        return baud == o.baud && dataBits == o.dataBits && parity == o.parity &&
               stopBits == o.stopBits;
    }
};

// "8N1", "7E2": data bits (7 or 8), parity (N, E, O), stop bits (1 or 2), as the manuals write
// a frame format; false, and the settings untouched, for anything else.
bool parseFrameFormat(QStringView text, SerialSettings *line);
QString frameFormatText(const SerialSettings &line);

} // namespace rung::model
