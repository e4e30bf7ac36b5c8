#pragma once

// Line settings of a serial port (by default Vigor 7E1 19200, Vigor M/VB/VH communication
// manual, B-5-1; Host Link 7E2 9600, Omron CPM1/SRM1 programming manual W353; PL110 8N1 19200,
// PL110 manual 2.1.2 and 3.1).

#include <QString>

#include <cstdint>

namespace rung::comms {

struct SerialSettings {
    enum class Parity : std::uint8_t { None, Odd, Even };
    enum class Flow : std::uint8_t { None, RtsCts, XonXoff };
    int baud = 19200;
    int dataBits = 8;
    Parity parity = Parity::None;
    int stopBits = 1;
    Flow flow = Flow::None;

    // Time one character takes on the wire (start + data + parity + stop bits), in
    // microseconds: the Modbus RTU 3.5-character gap is 3.5 of these (at most 1750 us above
    // 19200 bps, Modbus over serial line 2.5.1.1).
    int characterMicroseconds() const {
        const int bits = 1 + dataBits + (parity == Parity::None ? 0 : 1) + stopBits;
        return int(1'000'000LL * bits / (baud > 0 ? baud : 1));
    }
    int rtuGapMicroseconds() const { return baud > 19200 ? 1750 : characterMicroseconds() * 7 / 2; }
};

// "8N1", "7E2": data bits (7 or 8), parity (N, E, O), stop bits (1 or 2), as the manuals write
// a frame format; false, and the settings untouched, for anything else.
bool parseFrameFormat(QStringView text, SerialSettings *line);
QString frameFormatText(const SerialSettings &line);

} // namespace rung::comms
