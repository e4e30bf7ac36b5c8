#pragma once

// The trace of a network (`rungstudio-cli simulate NET.rungnet`): the CSV of a program's trace
// (simulator/trace.h) with every device named NAME/DEVICE, a row every --period ms of virtual
// time (the network's period unless given), after everything up to that time.

#include "network/network.h"

#include "simulator/trace.h"

#include <QTextStream>

namespace rung::network {

struct NetTraceColumn {
    Station *station = nullptr;
    simulator::TraceColumn column;
    QString name; // "master/D20"
};

struct NetStimulus {
    Station *station = nullptr;
    simulator::TraceStimulus stimulus;
};

struct NetTraceRequest {
    quint64 rows = 0;
    qint64 periodMs = 0; // 0: the network's
    std::vector<NetStimulus> stimuli;
    std::vector<NetTraceColumn> columns;
};

// "master/D20": the station and "D20"; null with what and why (no slash, no such station:
// the stations named).
Station *stationDevice(const Network &network, const QString &text, QString *device,
                       QString *error);

// --scans N (rows), --period MS (between rows), --set NAME/DEV=VALUE@N (applied once N rows
// have run: @0 before anything), --trace NAME/DEV[,...]; false with a translated reason for
// anything else, or a station or device that is not there.
bool parseNetworkTraceOptions(const Network &network, const QStringList &args,
                              NetTraceRequest *request, QString *error);

// Row k (from 1): the virtual time k x period, the devices after everything up to that time
// (the scans ending at that instant included), as `simulate` prints a program's scan k.
void runNetworkTrace(Network &network, const NetTraceRequest &request, QTextStream &out);

} // namespace rung::network
