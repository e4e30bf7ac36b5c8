#include "cli_network.h"
#include "app/tr.h"

#include "cli_load_program.h"

#include "network/net_trace.h"
#include "network/station.h"
#include "network/traffic.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QSaveFile>

namespace rung::app {

namespace {

QString usage() {
    return NetworkTr::tr("usage: rungstudio-cli simulate NET.rungnet --scans N [--period MS] "
                  "[--set STATION/DEV=VALUE@SCAN]... --trace STATION/DEV[,...] [--traffic FILE]");
}

} // namespace

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
            *error = messages.trimmed() + QLatin1Char('\n') +
                     NetworkTr::tr("station %1 (%2) does not start").arg(station.name, station.where);
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
                err << NetworkTr::tr("--traffic needs a file") << '\n' << usage() << '\n';
                return 2;
            }
            trafficFile = args[++i];
        } else if (args[i] == QLatin1String("--target") || args[i] == QLatin1String("--model")) {
            err << NetworkTr::tr("%1: a network file names each station's PLC").arg(args[i]) << '\n'
                << usage() << '\n';
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
        err << error << '\n' << usage() << '\n';
        return 2;
    }
    // The traffic goes to the file as it happens; written atomically at the end.
    QSaveFile traffic(trafficFile);
    QTextStream trafficOut(&traffic);
    if (!trafficFile.isEmpty()) {
        if (!traffic.open(QIODevice::WriteOnly | QIODevice::Text)) {
            err << NetworkTr::tr("cannot write %1: %2").arg(trafficFile, traffic.errorString()) << '\n';
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
            err << NetworkTr::tr("cannot write %1: %2").arg(trafficFile, traffic.errorString()) << '\n';
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

} // namespace rung::app
