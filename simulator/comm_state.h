#pragma once

// What the engine's communication instructions keep between scans (engine_comm.cpp): a value,
// copied with the engine (history checkpoints), holding no port.

#include "program.h"

#include "model/comm/master_protocol.h"

#include <QByteArray>

#include <cstdint>
#include <vector>

namespace rung::simulator {

// One frame of a LINK / MBUS set and where its reply goes.
struct MasterFrame {
    model::MasterRequest request;
    std::vector<std::int32_t> words; // Read of values: the master's words, in order
    int unitsPerWord = 1;            // link bytes (2, 4 for a 32-bit counter) or 1 register
    int wordBits = 16;               // the master words' width
    std::vector<BitRef> bits;        // Read of bits: the master's bits, in order
    int firstBit = 0;                // the reply's bit (across its units) of bits[0]
};

// A VB-1COM module's buffer memory and what it is doing (Vigor M/VB/VH communication manual,
// B-4-4).
struct ModuleState {
    std::vector<std::int32_t> bfm; // #0 .. #2256
    bool attached = false;         // the port is in the network
    bool sending = false;
    bool started = false; // receiving: the first byte came
    QByteArray received;
    qint64 lastUs = -1;
    std::int32_t command = 0; // BFM #1 as last written
};

// One communication instruction's state (Program::comms, same index).
struct CommTask {
    bool on = false;     // its input in this scan
    bool seenOn = false; // its input was ON in some scan since the last END
    // LINK / MBUS
    bool running = false; // a set is being worked through
    int set = 0;          // the set (0-based)
    std::vector<MasterFrame> frames;
    std::size_t frame = 0;
    bool waiting = false;
    qint64 deadlineUs = 0;
    bool cycleClean = true;
    int station = 0;
    std::int32_t cycles = 0;
    // PL110 SEND: the rising edge
    bool previous = false;
    // PL110 COM / EXP: consecutive failures (SM75 of them set the status bit), and for
    // read-write the values last read or written, to see what the program changed.
    int failures = 0;
    std::vector<std::int32_t> shadow;
};

// A PL110 port's free-port and COM / EXP master state (Program::ports, same index).
struct PortState {
    std::int32_t control = 0;   // SM78 as last applied
    bool freePort = false;      // its bit 8
    qint64 sendingUntilUs = -1; // SEND: the last byte leaves then; -1: not sending
    std::int32_t count = 0;     // characters in the receive buffer (SM79 as the PLC wrote it)
    // COM / EXP: one request at a time.
    int query = -1; // the task (Program::comms index) last served, -1: none yet
    bool waiting = false;
    qint64 startUs = 0; // the request's start
    qint64 readyUs = 0; // no request before this: the last reply's end + SM74
    int writeAt = -1;   // read-write: the datum being written, -1: a read
    std::int32_t writeValue = 0;
    // A slave port's link supervision (SM70): counted from the first END after power-on.
    qint64 supervisedFromUs = -1;
    quint64 requestErrorsBase = 0; // the port's count at power-on (SM77 counts from 0)
};

struct CommState {
    std::vector<CommTask> tasks;
    bool cycleDone = false; // M9199 was turned ON at the last END
    // RS (one active at a time, Vigor M/VB/VH communication manual, B-3-9)
    int serial = -1; // the RS that was ON in the last scan, -1 none
    bool sending = false;
    bool started = false;
    QByteArray received;
    qint64 lastUs = -1;
    std::vector<ModuleState> modules; // by module number - 1, sized on first use
    std::vector<PortState> ports;     // Program::ports, sized on first use
};

} // namespace rung::simulator
