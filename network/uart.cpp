#include "network/uart.h"

#include <vector>

namespace rung::network {

namespace {

using Parity = model::SerialSettings::Parity;

bool parityBit(std::uint32_t data, int bits, Parity parity) {
    int ones = 0;
    for (int k = 0; k < bits; ++k)
        ones += (data >> k) & 1;
    return parity == Parity::Even ? (ones & 1) : !(ones & 1);
}

} // namespace

qint64 wireTimeUs(qsizetype count, const model::SerialSettings &line) {
    const qint64 baud = line.baud > 0 ? line.baud : 1;
    return (qint64(count) * line.bitsPerCharacter() * 1000000 + baud - 1) / baud;
}

Received acrossLine(QByteArrayView bytes, const model::SerialSettings &tx,
                    const model::SerialSettings &rx) {
    Received out;
    if (tx.sameLine(rx)) {
        out.bytes = bytes.toByteArray();
        if (tx.dataBits == 7) // seven data bits carry no bit 7
            for (char &c : out.bytes)
                c = char(c & 0x7F);
        return out;
    }
    // The sender's line as cells of one bit each: level 1 idle / mark, 0 space.
    std::vector<std::uint8_t> cells;
    for (char c : bytes) {
        const auto v = static_cast<std::uint32_t>(static_cast<quint8>(c));
        cells.push_back(0); // start
        for (int k = 0; k < tx.dataBits; ++k)
            cells.push_back((v >> k) & 1);
        if (tx.parity != Parity::None)
            cells.push_back(parityBit(v, tx.dataBits, tx.parity));
        for (int k = 0; k < tx.stopBits; ++k)
            cells.push_back(1);
    }
    // Time in ticks: one second is txBaud * rxBaud ticks, so a sender's bit lasts rxBaud
    // ticks and a receiver's txBaud.
    const qint64 txBit = rx.baud;
    const qint64 rxBit = tx.baud;
    const qint64 end = qint64(cells.size()) * txBit;
    auto level = [&](qint64 t) -> int {
        if (t < 0 || t >= end)
            return 1;
        return cells[std::size_t(t / txBit)];
    };
    // The receiver looks for a falling edge at each of the sender's cell boundaries after t.
    auto nextStart = [&](qint64 t) -> qint64 {
        for (qint64 cell = (t + txBit - 1) / txBit; cell * txBit < end; ++cell)
            if (cells[std::size_t(cell)] == 0 && level(cell * txBit - 1) == 1 && cell * txBit >= t)
                return cell * txBit;
        return -1;
    };
    qint64 t = 0;
    while (true) {
        const qint64 start = nextStart(t);
        if (start < 0)
            break;
        qint64 sample = start + rxBit / 2 + rxBit; // the middle of data bit 0
        std::uint32_t v = 0;
        for (int k = 0; k < rx.dataBits; ++k, sample += rxBit)
            v |= std::uint32_t(level(sample)) << k;
        bool bad = false;
        if (rx.parity != Parity::None) {
            bad = level(sample) != int(parityBit(v, rx.dataBits, rx.parity));
            sample += rxBit;
        }
        bad = bad || level(sample) != 1; // the (first) stop bit
        out.bytes += char(v);
        out.errors += bad ? 1 : 0;
        t = sample; // a new start is looked for after the stop bit's middle
        if (t >= end)
            break;
    }
    return out;
}

} // namespace rung::network
