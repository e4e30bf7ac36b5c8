#pragma once

// A port's settings as a project or a network file gives them: what Ladder Master calls the
// "2nd COM Port Setting" (Vigor M/VB/VH communication manual, B-3-1: application, station number,
// baud rate, format and a panel per application), the PL110's port protocol (PL110
// manual 3.1, 4.2.21). JSON, documented in docs/network-format.md; the tables of Target::ports say
// what each port and model allow.

#include "model/comm/serial_line.h"
#include "model/listing/il.h"
#include "model/target/target.h"

#include <QJsonObject>

namespace rung::model {

// The ranges of the settings that are the same for every family: CPU Link's master panel
// (B-3-4: "Total Slaves" 1..7, "Transfer Range Mode" 1..3, "Retry", "Timeout unit (10mS)") and
// a start or end character (a byte). readPortConfig checks them and the port dialog offers them.
struct SettingRange {
    int lowest = 0;
    int highest = 0;
};
inline constexpr SettingRange kCpuLinkSlaves{1, 7};
inline constexpr SettingRange kCpuLinkRange{1, 3};
inline constexpr SettingRange kCpuLinkRetries{0, 255};
inline constexpr SettingRange kCpuLinkTimeout{1, 255};
inline constexpr SettingRange kCharacterCode{0, 255};

struct PortConfig {
    QString port;                                 // the port's name, as the table writes it
    const PortApplication *application = nullptr; // never null once read
    int station = 0;
    SerialSettings line;
    // CPU Link (B-3-4), on the master (station 0): "Total Slaves" 1..7, "Transfer Range Mode"
    // 1..3, "Retry", "Timeout unit (10mS)".
    int slaves = 1;
    int range = 1;
    int retries = 3;
    int timeout = 5;
    // Parallel Link (B-3-5): "Station Assign" and, on the master, the speed.
    bool parallelMaster = true;
    bool highSpeed = false;
    // MODBUS (B-3-6): ASCII or RTU.
    bool modbusAscii = false;
    // Non Protocol (B-3-9): "Start Char" / "End Char", -1 none.
    int startCode = -1;
    int endCode = -1;
};

// The settings a project brings (its "ports" object) with the network file's over them, key
// by key: `layers` from the lowest. Errors say where (the JSON path given with each layer) and
// why, translated: "stations[1].ports.CP2.baud: 12345 is not a rate of Easy Link (4800, ...)".
struct PortLayer {
    QJsonObject json;
    QString path; // "stations[1].ports.CP2"
};
bool readPortConfig(const Target &target, const ModelVariant *model, const QString &port,
                    const std::vector<PortLayer> &layers, PortConfig *config, QString *error);
// The keys as a file writes them (a project saves what the user set, not the defaults).
QJsonObject mergePortJson(const std::vector<PortLayer> &layers);

// The port an instruction drives (InstructionSpec::port and portOperand: LINK -> CP2, Vigor
// FROM K1 -> MODULE1, PL110 SEND COM1 n -> COM1); empty when it drives none or names none.
QString instructionPort(const Instruction &instruction);

// The ports of a project's "ports" object checked against the target: what, where, why.
bool checkPortsJson(const Target &target, const ModelVariant *model, const QJsonObject &ports,
                    const QString &path, QString *error);

} // namespace rung::model
