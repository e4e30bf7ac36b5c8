#pragma once

// A PLC's serial ports as target data (Target::ports): which ports a model has, the
// applications each can run (what Ladder Master's "2nd COM Port Setting" offers, Vigor M/VB/VH
// communication manual, B-3-1; the PL110's protocols, PL110 manual chapter 3 and 4.2.19 / 4.2.21;
// the CPM1's peripheral port, Omron CPM1 guide 2.1, and its Host Link),
// their rates, formats and station numbers. The network file, a project's port settings and the
// wiring checks read these tables and nothing else. target.h includes this header, so it must not
// include target.h.

#include "model/target/protocol_map.h"

#include <QString>
#include <QStringList>

#include <optional>
#include <vector>

namespace rung::model {

// One station's share of a link that exchanges memory without published frames (CPU Link,
// Parallel Link): elements first + stride x station, count of them, of the devices written
// with `prefix` (station 0 is the master).
struct SharedArea {
    const char *prefix = "";
    int first = 0;
    int stride = 0;
    int count = 0;
};

// A transfer range (CPU Link's "Transfer Range Mode", Parallel Link's speed): the areas, and
// the time of one exchange in ms: CPU Link's network scan time by the number of stations
// (cycleMs[stations - 2], B-3-4's table), Parallel Link's communication time at 19200 bps
// (B-3-5), to which both stations' scan times add.
struct SharedMode {
    std::vector<SharedArea> areas;
    std::vector<int> cycleMs;
};

// What a port runs and how.
struct PortApplication {
    const char *id = "";        // as files spell it: "easy-link"
    const char *name = nullptr; // QT_TRANSLATE_NOOP("rung::model::Target", "Easy Link")
    QStringList models;         // the models that have it; empty: every model
    std::vector<int> bauds;     // the rates it takes; the first is the default
    const char *frame = "8N1";  // the default character format
    bool fixedFrame = false;    // the format cannot be changed (Computer Link: 7E1)
    int stationMin = 0;         // station numbers it takes
    int stationMax = 0;
    int station = 0; // the default
    // The port answers a master as a slave would, with this protocol through the target's map
    // of it (Vigor Computer Link, MODBUS slave, Omron Host Link); nullopt: it answers nobody.
    // answersAt() says at which station numbers.
    std::optional<ProtocolId> answers;
    // The port's program is a master of this protocol (LINK: Computer Link; MBUS, COM/EXP:
    // MODBUS), so a wire may carry only one such port.
    bool master = false;
    // The manual publishes the frames of this application. False for CPU Link and Parallel
    // Link ("dedicated protocol", Vigor M/VB/VH communication manual, B-3-4, B-3-5): the simulation
    // exchanges their data at the level the manual publishes and never puts a frame of its own on a
    // real port.
    bool published = true;
    // The program drives the port byte by byte (RS, VB-1COM, PL110 free-port).
    bool programDriven = false;
    // CPU Link (by range mode 1..3) and Parallel Link (low, high speed): what is exchanged.
    std::vector<SharedMode> sharedModes;
    int sharedLink = 0; // 1: CPU Link (stations 0..7), 2: Parallel Link (a master, a slave)
    // The words the PLC's own display writes it with (PL110 system page 3: "MODBUS SLAVE"),
    // not translated; null: `name` untranslated.
    const char *displayName = nullptr;
};

// The special markers and byte areas through which a PL110 program drives a port (PL110
// manual 2.1.2, 2.1.14, 2.1.15, 4.2.19, 4.2.21), as the target writes them; nullptr: none. The
// simulator resolves them once (Program::ports) and runs the COM / EXP master and free-port
// from them; the network's checks read them too.
struct PortMarkers {
    const char *status = nullptr;       // SM70: master: bit i-1 = COM_i / EXP_i in error
    const char *replyTimeout = nullptr; // SM73: ms from the start of a request to the whole reply
    const char *requestGap = nullptr;   // SM74: ms from the end of a reply to the next request
    const char *errorLimit = nullptr;   // SM75: consecutive errors before the status bit
    const char *timeouts = nullptr;     // SM76: time-outs counted
    const char *errors = nullptr;       // SM77: errors counted (CRC, data count, exception)
    const char *freePort = nullptr;     // SM78: bits 0-3 baud code, 4-7 format code, bit 8 on
    const char *received = nullptr; // SM79: characters in the receive buffer; a write empties it
    const char *sending = nullptr;  // SM0.6: ON while the port transmits
    const char *transmit = nullptr; // COM1_TX: the transmit buffer's area (bytes)
    const char *receive = nullptr;  // COM1_RX: the receive buffer's area (bytes)
    // The power-on values of SM73, SM74, SM75 (2.1.2: 20 ms, 5 ms, 10; COM2's SM73: 0).
    int replyTimeoutMs = 20;
    int requestGapMs = 5;
    int errorLimitCount = 10;
    // The free-port codes of SM78: bauds[code] and formats[code] ("8N1"), 2.1.2's lists.
    std::vector<int> bauds;
    std::vector<const char *> formats;
};

struct PortSpec {
    QString name;                              // "CP2", "COM1", "MODULE1"
    const char *description = nullptr;         // QT_TRANSLATE_NOOP("rung::model::Target", ...)
    QStringList models;                        // the models that have the port; empty: every model
    std::vector<PortApplication> applications; // the first is the port's default
    const PortApplication *application(QStringView id) const {
        for (const PortApplication &a : applications)
            if (id == QLatin1String(a.id))
                return &a;
        return nullptr;
    }
    bool on(const QString &model) const { return models.isEmpty() || models.contains(model); }
    PortMarkers markers; // the PL110's port markers; empty elsewhere
};

// A device type code of the LINK / MBUS communication table (Vigor M/VB/VH communication manual,
// B-3-3: 1 X, 2 Y, 3 M, 4 S, 5 T contact, 6 C contact, 10 timer present value, 11 16-bit counter
// present value, 12 32-bit counter present value, 13 D; B-3-6: MBUS takes them but 12).
struct LinkDeviceCode {
    int code = 0;
    const char *prefix = ""; // the devices' prefix, as the target writes it
    bool bits = false;       // bit devices (contacts), else values
    int valueBits = 0;       // values of this width only (16 or 32); 0: any
    bool modbus = true;      // MBUS takes it too
};

inline bool applicationOn(const PortApplication &a, const QString &model) {
    return a.models.isEmpty() || a.models.contains(model);
}

// Whether a port running `a` at station number `station` answers a master: the one rule the
// network's slaves, its wiring checks and its traffic decoder read. MODBUS station 0 is the
// broadcast address, which no slave answers (the Vigor's MBUS master is station 0, Vigor M/VB/VH
// communication manual, B-3-6); Computer Link and Host Link number their stations from 0.
inline bool answersAt(const PortApplication &a, int station) {
    return a.answers && !(*a.answers == ProtocolId::Modbus && station == 0);
}

} // namespace rung::model
