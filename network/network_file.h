#pragma once

// A network file (.rungnet, docs/network-format.md): JSON naming stations (each a program and
// its ports), simulated devices, wires, bridges to real ports and faults. Read here into a
// description; Network (network.h) builds and runs it.

#include <QJsonObject>
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
    QString where;       // "stations[0]"
};

struct DeviceDescription {
    QString name;
    QString kind; // "modbus-slave", "line"
    QJsonObject json;
    QString where;
};

struct WireDescription {
    QString name;     // "w1" unless named
    QStringList ends; // "station/PORT" or "device"
    QString where;
};

struct BridgeDescription {
    enum class Kind { Pty, Serial, Tcp, Listen };
    QString end; // "station/PORT"
    Kind kind = Kind::Pty;
    QString where; // the serial port's name, or HOST:PORT (to connect to, or to listen on)
    QString path;  // "bridges[0]"
};

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
    QString where;
};

struct NetworkDescription {
    QString file;
    qint64 periodMs = 10;
    std::vector<StationDescription> stations;
    std::vector<DeviceDescription> devices;
    std::vector<WireDescription> wires;
    std::vector<BridgeDescription> bridges;
    std::vector<FaultDescription> faults;
};

inline constexpr const char *kNetworkExtension = "rungnet";

// Reads and checks the file's shape (names, keys, types); what the programs and ports mean is
// Network::build's. False with what, where and why (translated).
bool readNetworkFile(const QString &file, NetworkDescription *description, QString *error);
bool parseNetwork(const QByteArray &json, const QString &file, NetworkDescription *description,
                  QString *error);

// False with "PATH.KEY: unknown key (this object takes: ...)" for a key not in `keys`: a
// misspelt key is said, never ignored.
bool onlyJsonKeys(const QJsonObject &o, const QStringList &keys, const QString &path,
                  QString *error);

} // namespace rung::network
