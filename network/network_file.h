#pragma once

// A network file (.rungnet, docs/network-format.md): JSON naming stations (each a program and
// its ports), simulated devices, wires, bridges to real ports and faults. Read here into a
// description; Network (network.h) builds and runs it.

#include <QJsonObject>
#include <QJsonValue>
#include <QString>
#include <QStringList>

#include <optional>
#include <vector>

namespace rung::network {

struct StationDescription {
    QString name;
    QString program;     // as written, relative to the network file
    QString path;        // the program's path, resolved
    QString target;      // "" : the program's
    QString model;       // "" : the program's
    qint64 periodMs = 0; // 0: the network's
    QJsonObject ports;   // port name -> settings (over the project's)
    QJsonValue comment;  // as written (undefined: none)
    QString where;       // "stations[0]"
    friend bool operator==(const StationDescription &, const StationDescription &) = default;
};

struct DeviceDescription {
    QString name;
    QString kind; // "modbus-slave", "line"
    QJsonObject json;
    QString where;
    friend bool operator==(const DeviceDescription &, const DeviceDescription &) = default;
};

struct WireDescription {
    QString name;       // "w1" unless named
    QStringList ends;   // "station/PORT" or "device"
    bool named = false; // the file gave the name ({"name": ..., "ends": [...]})
    QString where;
    friend bool operator==(const WireDescription &, const WireDescription &) = default;
};

struct BridgeDescription {
    enum class Kind { Pty, Serial, Tcp, Listen };
    QString end; // "station/PORT"
    Kind kind = Kind::Pty;
    QString where; // the serial port's name, or HOST:PORT (to connect to, or to listen on)
    QString path;  // "bridges[0]"
    friend bool operator==(const BridgeDescription &, const BridgeDescription &) = default;
};

// A TCP bridge's HOST:PORT split at its last colon (an IPv6 address keeps its own): none
// when there is no host or the port is not a number of 0..65535.
struct HostPort {
    QString host;
    int port = 0;
};
std::optional<HostPort> splitHostPort(const QString &where);

struct FaultDescription {
    enum class Kind { Cut, Silent, Corrupt };
    Kind kind = Kind::Cut;
    QString wire;      // Cut, Corrupt
    QString station;   // Silent: a station or a device
    qint64 fromMs = 0; // Cut, Silent: from this virtual time ...
    qint64 toMs = -1;  // ... to this one (-1: to the end)
    int frame = 0;     // Corrupt: the wire's n-th transmission (from 0)
    int byte = 0;      // ... its k-th byte
    int mask = 0x01;   // ... XORed with this
    // The optional keys the file gave (from, to, frame, byte, xor), so that a save writes them
    // back even where they hold the default.
    QStringList given;
    QString where;
    friend bool operator==(const FaultDescription &, const FaultDescription &) = default;
};

struct NetworkDescription {
    QString file;
    qint64 periodMs = 10;
    bool periodGiven = false; // the file gave "period" (a save writes it back even at 10)
    QJsonValue comment;       // the top level's "comment" and "format", as written
    QJsonValue format;
    std::vector<StationDescription> stations;
    std::vector<DeviceDescription> devices;
    std::vector<WireDescription> wires;
    std::vector<BridgeDescription> bridges;
    std::vector<FaultDescription> faults;
    friend bool operator==(const NetworkDescription &, const NetworkDescription &) = default;
};

inline constexpr const char *kNetworkExtension = "rungnet";

// Reads and checks the file's shape (names, keys, types); what the programs and ports mean is
// Network::build's. False with what, where and why (translated).
bool readNetworkFile(const QString &file, NetworkDescription *description, QString *error);
bool parseNetwork(const QByteArray &json, const QString &file, NetworkDescription *description,
                  QString *error);

// The file's JSON: every key the reader keeps, in a stable order (the order of
// docs/network-format.md's tables, then by name; a table's numbered keys in numeric order),
// programs relative to `file`'s folder (as written when the program's folder is not below
// it: "../plc/master.il"; an absolute path stays absolute). Readable: an object or a list goes
// on one line where it fits in 100 columns. parseNetwork of the result gives `description`
// back, but for `file` and the paths ("where") that say where each item sits in the file.
QByteArray networkToJson(const NetworkDescription &description, const QString &file);
// Writes networkToJson to `file` through a temporary file (a failed save leaves the old file
// whole). First it reads the JSON back: if the reading differs from `description` (something
// the file format cannot hold), `notKept` says what, and the file is written only when
// `evenIfNotKept` (the user was told and chose to); else false with the reason and nothing
// written. False with what and why when the file cannot be written.
bool writeNetworkFile(const NetworkDescription &description, const QString &file,
                      QStringList *notKept, QString *error, bool evenIfNotKept = false);
// What differs between two descriptions, as a reader would say it ("stations[1].ports": ...),
// ignoring the file and the "where" paths; empty when they are the same network.
QStringList networkDifferences(const NetworkDescription &a, const NetworkDescription &b);
// The description with its "where" paths as parseNetwork would give them for its order of
// items (after an edit moved them).
void renumberNetwork(NetworkDescription *description);

// A station's or a device's name: letters, digits, _ and -, at most 32 (network-format.md).
bool validNetworkName(const QString &name);

// False with "PATH.KEY: unknown key (this object takes: ...)" for a key not in `keys`: a
// misspelt key is said, never ignored.
bool onlyJsonKeys(const QJsonObject &o, const QStringList &keys, const QString &path,
                  QString *error);

} // namespace rung::network
