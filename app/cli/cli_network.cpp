#include "cli_network.h"
#include "app/tr.h"

#include "cli_common.h"
#include "cli_load_program.h"
#include "cli_stop_signals.h"

#include "network/bridge.h"
#include "network/check.h"
#include "network/net_trace.h"
#include "network/station.h"
#include "network/traffic.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QSaveFile>

namespace rung::app {

namespace {

QString networkUsageText() {
    return NetworkTr::tr("usage:") + QLatin1Char('\n') + networkUsage();
}

// lupdate files a tr() inside a lambda under the struct's name: kept out of the loader's.
QString stationDoesNotStart(const network::StationDescription &station) {
    return NetworkTr::tr("station %1 (%2) does not start").arg(station.name, station.where);
}

} // namespace

QString networkUsage() {
    return NetworkTr::tr("  rungstudio-cli check NET.rungnet\n"
                         "  rungstudio-cli serve NET.rungnet\n"
                         "  rungstudio-cli simulate NET.rungnet --scans N [--period MS] "
                         "[--set STATION/DEV=VALUE@SCAN]... --trace STATION/DEV[,...] "
                         "[--traffic FILE]");
}

bool isNetworkFile(const QString &file) {
    return QFileInfo(file).suffix().compare(QLatin1String(network::kNetworkExtension),
                                            Qt::CaseInsensitive) == 0;
}

network::ProgramLoader cliProgramLoader() {
    return [](const network::StationDescription &station, network::LoadedStation *loaded,
              QString *error) {
        ProgramOptions options;
        options.file = station.path;
        options.target = station.target;
        options.model = station.model;
        QString messages;
        QTextStream err(&messages);
        LoadedProgram program;
        const int status = loadProgram(options, &program, err);
        err.flush();
        if (status != 0) {
            *error = messages.trimmed() + QLatin1Char('\n') + stationDoesNotStart(station);
            return false;
        }
        loaded->program = program.program;
        loaded->target = program.target;
        loaded->model = program.model;
        loaded->ports = program.ports;
        return true;
    };
}

int runNetworkSimulate(const QString &file, const QStringList &args, QTextStream &out,
                       QTextStream &err) {
    QStringList options;
    QString trafficFile;
    for (qsizetype i = 0; i < args.size(); ++i) {
        if (args[i] == QLatin1String("--traffic")) {
            if (i + 1 >= args.size()) {
                err << NetworkTr::tr("--traffic needs a file") << '\n'
                    << networkUsageText() << '\n';
                return 2;
            }
            trafficFile = args[++i];
        } else if (args[i] == QLatin1String("--target") || args[i] == QLatin1String("--model")) {
            err << NetworkTr::tr("%1: a network file names each station's PLC").arg(args[i]) << '\n'
                << networkUsageText() << '\n';
            return 2;
        } else {
            options << args[i];
        }
    }
    network::NetworkDescription description;
    QString error;
    if (!network::readNetworkFile(file, &description, &error)) {
        err << error << '\n';
        return 2;
    }
    std::unique_ptr<network::Network> net =
        network::Network::build(description, cliProgramLoader(), &error);
    if (!net) {
        err << error << '\n';
        return 1;
    }
    network::NetTraceRequest request;
    if (!network::parseNetworkTraceOptions(*net, options, &request, &error)) {
        err << error << '\n' << networkUsageText() << '\n';
        return 2;
    }
    // The traffic goes to the file as it happens; written atomically at the end.
    QSaveFile traffic(trafficFile);
    QTextStream trafficOut(&traffic);
    if (!trafficFile.isEmpty()) {
        if (!traffic.open(QIODevice::WriteOnly | QIODevice::Text)) {
            err << NetworkTr::tr("cannot write %1: %2").arg(trafficFile, traffic.errorString())
                << '\n';
            return 2;
        }
        trafficOut << network::trafficHeader(file) << '\n';
        net->setTrafficSink([&trafficOut](const network::TrafficRecord &r) {
            trafficOut << network::formatTraffic(r) << '\n';
        });
    }
    network::runNetworkTrace(*net, request, out);
    out.flush();
    if (!trafficFile.isEmpty()) {
        trafficOut.flush();
        if (!traffic.commit()) {
            err << NetworkTr::tr("cannot write %1: %2").arg(trafficFile, traffic.errorString())
                << '\n';
            return 2;
        }
    }
    // Runtime errors of every station, named by station and line.
    for (const auto &s : net->stations())
        for (const simulator::RuntimeError &e : s->engine().runtimeErrors())
            err << NetworkTr::tr("%1: line %2: runtime error at step %3: %4")
                       .arg(s->name())
                       .arg(e.line)
                       .arg(e.instruction)
                       .arg(e.message)
                << '\n';
    return 0;
}

// `check` and `serve` take the file alone: read into *description, 0; else 2, said on err.
static int readNetworkOnly(const QString &file, const QStringList &args,
                           network::NetworkDescription *description, QTextStream &err) {
    if (!args.isEmpty()) {
        err << CliTr::tr("unexpected argument %1").arg(args.front()) << '\n'
            << networkUsageText() << '\n';
        return 2;
    }
    QString error;
    if (!network::readNetworkFile(file, description, &error)) {
        err << error << '\n';
        return 2;
    }
    return 0;
}

int runNetworkCheck(const QString &file, const QStringList &args, QTextStream &out,
                    QTextStream &err) {
    network::NetworkDescription description;
    if (const int status = readNetworkOnly(file, args, &description, err); status != 0)
        return status;
    QString error;
    // Every station's program, as `check FILE` checks it.
    bool errors = false;
    for (const network::StationDescription &station : description.stations) {
        CommonOptions options;
        options.file = station.path;
        options.target = station.target;
        options.model = station.model;
        Input input;
        if (!loadInput(options, &input, &error)) {
            err << NetworkTr::tr("%1: %2: %3").arg(file, station.where, error) << '\n';
            return 2;
        }
        const std::vector<model::Diagnostic> found = findings(input);
        for (const model::Diagnostic &d : found)
            out << formatDiagnostic(station.path, d) << '\n';
        errors = errors || model::hasErrors(found);
    }
    if (errors) {
        err << NetworkTr::tr("%1: a station's program has errors; the wiring is checked once "
                             "every program starts")
                   .arg(file)
            << '\n';
        return 1;
    }
    // The ports, the wires and the tables.
    std::unique_ptr<network::Network> net =
        network::Network::build(description, cliProgramLoader(), &error);
    if (!net) {
        out << error << '\n';
        return 1;
    }
    for (const network::NetworkFinding &f : network::checkNetwork(*net)) {
        //: %1 the network file, %2 where in it (a wire, a station's line), %3 error or warning
        out << NetworkTr::tr("%1: %2: %3: %4")
                   .arg(file, f.where, f.error ? CliTr::tr("error") : CliTr::tr("warning"),
                        f.message)
            << '\n';
        errors = errors || f.error;
    }
    return errors ? 1 : 0;
}

int runNetworkServe(const QString &file, const QStringList &args, QTextStream &out,
                    QTextStream &err) {
    network::NetworkDescription description;
    if (const int status = readNetworkOnly(file, args, &description, err); status != 0)
        return status;
    QString error;
    if (description.bridges.empty()) {
        err << NetworkTr::tr("%1: no bridges: nothing of the network reaches a real line "
                             "(\"bridges\", docs/network-format.md); simulate runs it on "
                             "virtual time")
                   .arg(file)
            << '\n';
        return 2;
    }
    std::unique_ptr<network::Network> net =
        network::Network::build(description, cliProgramLoader(), &error);
    if (!net) {
        err << error << '\n';
        return 1;
    }
    StopSignals stopSignals;
    network::RealTime realTime(*net);
    for (const network::BridgeDescription &b : description.bridges) {
        QString where;
        if (!realTime.addBridge(b, &where, &error)) {
            err << file << ": " << error << '\n';
            return 2;
        }
        // A script reads where each port is reached before anything else.
        out << b.end << ' ' << where << Qt::endl;
    }
    err << NetworkTr::tr("%1 runs in real time; stop it with Ctrl+C").arg(file) << Qt::endl;
    QString failure;
    while (!stopSignals.wait(0))
        if (!realTime.turn(5, &failure)) {
            err << failure << '\n';
            return 2;
        }
    return 0;
}

} // namespace rung::app
