#include "cli_simulate.h"

#include "cli_common.h"

#include "model/listing/il.h"
#include "simulator/compiler.h"
#include "simulator/trace.h"

#include <QCoreApplication>
#include <QFile>

namespace rung::app {

namespace {

struct Tr {
    Q_DECLARE_TR_FUNCTIONS(rung::app::Simulate)
};

QString usage() {
    return Tr::tr("usage: rungstudio-cli simulate FILE [--target T] --scans N [--period MS] "
                  "[--set DEV=VALUE@SCAN]... --trace DEV[,DEV...]");
}

} // namespace

int runSimulateCommand(const QStringList &args, QTextStream &out, QTextStream &err) {
    QString file;
    QString targetId;
    QStringList options;
    for (qsizetype i = 0; i < args.size(); ++i) {
        if (args[i] == QLatin1String("--target") && i + 1 < args.size()) {
            targetId = args[++i];
        } else if (args[i].startsWith(QLatin1String("--"))) {
            options << args[i];
            if (i + 1 < args.size())
                options << args[++i];
        } else if (file.isEmpty()) {
            file = args[i];
        } else {
            err << Tr::tr("unexpected argument %1").arg(args[i]) << '\n' << usage() << '\n';
            return 2;
        }
    }
    if (file.isEmpty()) {
        err << usage() << '\n';
        return 2;
    }
    QByteArray bytes;
    QString readError;
    if (!readInputFile(file, &bytes, &readError)) {
        err << readError << '\n';
        return 2;
    }
    const QString text =
        QString::fromUtf8(bytes).replace(QLatin1String("\r\n"), QLatin1String("\n"));
    if (targetId.isEmpty())
        targetId = model::declaredTarget(text);
    if (targetId.isEmpty()) {
        err << Tr::tr("%1: no target; give --target or a \"; target: NAME\" first line").arg(file)
            << '\n';
        return 2;
    }
    const model::Target *target = model::Target::byId(targetId);
    if (!target) {
        err << Tr::tr("unknown target %1").arg(targetId) << '\n';
        return 2;
    }
    simulator::TraceRequest request;
    QString error;
    if (!simulator::parseTraceOptions(*target, options, &request, &error)) {
        err << error << '\n' << usage() << '\n';
        return 2;
    }

    const model::ParseResult parsed = model::parseInstructionList(*target, text);
    if (!parsed.ok()) {
        for (const model::ParseError &e : parsed.errors)
            err << QStringLiteral("%1:%2:%3: ").arg(file).arg(e.line).arg(e.column)
                << Tr::tr("error: %1").arg(e.message) << '\n';
        err << Tr::tr("the program does not start") << '\n';
        return 1;
    }
    const simulator::CompileResult compiled = simulator::prepareProgram(parsed.list);
    for (const model::Diagnostic &d : compiled.diagnostics)
        err << QStringLiteral("%1:%2:%3: ").arg(file).arg(d.location.line).arg(d.location.column)
            << (d.severity == model::Severity::Error ? Tr::tr("error: %1").arg(d.message)
                                                     : Tr::tr("warning: %1").arg(d.message))
            << QStringLiteral(" [%1]").arg(d.code) << '\n';
    if (!compiled.ok()) {
        err << Tr::tr("the program does not start") << '\n';
        return 1;
    }
    std::vector<simulator::RuntimeError> runtimeErrors;
    simulator::runTrace(compiled.program, request, out, &runtimeErrors);
    out.flush();
    for (const simulator::RuntimeError &e : runtimeErrors)
        err << QStringLiteral("%1:%2: ").arg(file).arg(e.line)
            << Tr::tr("runtime error at step %1: %2").arg(e.instruction).arg(e.message) << '\n';
    return 0;
}

} // namespace rung::app
