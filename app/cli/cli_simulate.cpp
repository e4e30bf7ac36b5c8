#include "cli_simulate.h"

#include "cli_common.h"
#include "cli_load_program.h"
#include "cli_network.h"

#include "app/tr.h"
#include "simulator/trace.h"

#include <QCoreApplication>

namespace rung::app {

namespace {

QString simulateUsageText() {
    return SimulateTr::tr("usage: rungstudio-cli simulate FILE [--target T] [--model M] --scans N "
                          "[--period MS] [--set DEV=VALUE@SCAN]... --trace DEV[,DEV...]\n"
                          "FILE is a listing (.il), a ladder text (.ladder) or a project (.rung).");
}

} // namespace

int runSimulateCommand(const QStringList &args, QTextStream &out, QTextStream &err) {
    // A network of stations (docs/network.md): its own options, devices named NAME/DEV.
    for (qsizetype i = 0; i < args.size(); ++i) {
        if (args[i].startsWith(QLatin1String("--"))) {
            ++i;
            continue;
        }
        if (isNetworkFile(args[i]))
            return runNetworkSimulate(args[i], args.mid(0, i) + args.mid(i + 1), out, err);
        break;
    }
    ProgramOptions common;
    QStringList options; // the trace's: each with its value
    QString error;
    for (qsizetype i = 0; i < args.size(); ++i) {
        const QString &a = args[i];
        if (a.startsWith(QLatin1String("--"))) {
            if (i + 1 >= args.size()) {
                err << SimulateTr::tr("%1 needs a value").arg(a) << '\n'
                    << simulateUsageText() << '\n';
                return 2;
            }
            const QString value = args[++i];
            if (a == QLatin1String("--target"))
                common.target = value;
            else if (a == QLatin1String("--model"))
                common.model = value;
            else
                options << a << value;
        } else if (common.file.isEmpty()) {
            common.file = a;
        } else {
            err << SimulateTr::tr("unexpected argument %1").arg(a) << '\n'
                << simulateUsageText() << '\n';
            return 2;
        }
    }
    if (common.file.isEmpty()) {
        err << simulateUsageText() << '\n';
        return 2;
    }
    LoadedProgram program;
    if (const int status = loadProgram(common, &program, err); status != 0)
        return status;
    simulator::TraceRequest request;
    if (!simulator::parseTraceOptions(*program.target, options, &request, &error)) {
        err << error << '\n' << simulateUsageText() << '\n';
        return 2;
    }

    std::vector<simulator::RuntimeError> runtimeErrors;
    simulator::runTrace(program.program, request, out, &runtimeErrors);
    out.flush();
    for (const simulator::RuntimeError &e : runtimeErrors) {
        if (program.kind == InputKind::Listing) {
            err << QStringLiteral("%1:%2: ").arg(common.file).arg(e.line);
        } else if (static_cast<std::size_t>(e.instruction) < program.origin.size()) {
            err << QStringLiteral("%1:rung %2: ")
                       .arg(common.file)
                       .arg(program.origin[static_cast<std::size_t>(e.instruction)].rung + 1);
        }
        err << SimulateTr::tr("runtime error at step %1: %2").arg(e.instruction).arg(e.message)
            << '\n';
    }
    return 0;
}

} // namespace rung::app
