#pragma once

// What a receiver reads from a line driven at another baud rate or character format: each
// character is put on the line bit by bit (start, data LSB first, parity, stop) at the
// sender's rate and read back as a UART does at the receiver's (a falling edge starts a
// character, each bit sampled in its middle, the stop bit checked). A 7E1 character read as
// 8N1 keeps its parity bit as bit 7; at another baud rate it becomes other characters, or
// none. Deterministic: integer time, no randomness.

#include "model/comm/serial_line.h"

#include <QByteArray>

namespace rung::network {

struct Received {
    QByteArray bytes;
    int errors = 0; // characters with a parity or framing error (their bytes are in `bytes`)
};

// The bytes as the receiver reads them; the same bytes when both lines are the same.
Received acrossLine(QByteArrayView bytes, const model::SerialSettings &sender,
                    const model::SerialSettings &receiver);

// The time `count` characters take at the line's rate and format, in microseconds.
qint64 wireTimeUs(qsizetype count, const model::SerialSettings &line);

} // namespace rung::network
