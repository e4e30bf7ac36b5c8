#include "cli_simulate.h"

#include "cli_common.h"
#include "cli_load_program.h"

#include "model/checks/checks.h"
#include "model/listing/il.h"
#include "simulator/compiler.h"
#include "simulator/trace.h"

#include <QCoreApplication>

namespace rung::app {

namespace {

struct Tr {
    Q_DECLARE_TR_FUNCTIONS(rung::app::Simulate)
};

QString usage() {
    return Tr::tr("usage: rungstudio-cli simulate FILE [--target T] [--model M] --scans N "
                  "[--period MS] [--set DEV=VALUE@SCAN]... --trace DEV[,DEV...]\n"
                  "FILE is a listing (.il), a ladder text (.ladder) or a project (.rung).");
}

// A ladder or a project has no listing lines: a finding about an instruction names its rung,
// row and cell, as `check` does.
model::Diagnostic onLadder(model::Diagnostic d, const LoadedProgram &program) {
    const int k = d.location.line - 1; // the lines given to the instructions below
    if (program.kind == InputKind::Listing || k < 0 ||
        static_cast<std::size_t>(k) >= program.origin.size())
        return d;
    const model::CellOrigin &o = program.origin[static_cast<std::size_t>(k)];
    d.location = {};
    d.location.rung = o.rung;
    d.location.row = std::max(0, o.row);
    d.location.cell = std::max(0, o.column);
    return d;
}

} // namespace

int runSimulateCommand(const QStringList &args, QTextStream &out, QTextStream &err) {
    CommonOptions common;
    QStringList options; // the trace's: each with its value
    QString error;
    for (qsizetype i = 0; i < args.size(); ++i) {
        const QString &a = args[i];
        if (a.startsWith(QLatin1String("--"))) {
            if (i + 1 >= args.size()) {
                err << Tr::tr("%1 needs a value").arg(a) << '\n' << usage() << '\n';
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
            err << Tr::tr("unexpected argument %1").arg(a) << '\n' << usage() << '\n';
            return 2;
        }
    }
    if (common.file.isEmpty()) {
        err << usage() << '\n';
        return 2;
    }
    LoadedProgram program;
    QStringList problems;
    switch (loadProgram(common.file, common.target, common.model, &program, &problems)) {
    case LoadStatus::IoError:
        err << problems.join(QLatin1Char('\n')) << '\n';
        return 2;
    case LoadStatus::ProgramErrors:
        for (const QString &p : problems)
            err << p << '\n';
        err << Tr::tr("the program does not start") << '\n';
        return 1;
    case LoadStatus::Ok:
        break;
    }
    simulator::TraceRequest request;
    if (!simulator::parseTraceOptions(*program.target, options, &request, &error)) {
        err << error << '\n' << usage() << '\n';
        return 2;
    }

    model::CheckOptions checkOptions;
    checkOptions.model = program.model;
    simulator::CompileResult compiled;
    if (program.kind == InputKind::Listing) {
        compiled = simulator::prepareProgram(program.list, checkOptions);
    } else {
        // The checks of the drawing (they name rungs and cells), then the compiler with each
        // instruction's index as its line, so its findings find their cells.
        std::vector<model::Diagnostic> errors;
        for (const model::Diagnostic &d : model::checkLadder(program.ladder, checkOptions))
            if (d.severity == model::Severity::Error)
                errors.push_back(d);
        if (errors.empty()) {
            model::InstructionList numbered = program.list;
            for (std::size_t k = 0; k < numbered.instructions.size(); ++k) {
                numbered.instructions[k].line = static_cast<int>(k) + 1;
                numbered.instructions[k].column = 1;
            }
            compiled = simulator::compileProgram(numbered);
        } else {
            compiled.diagnostics = std::move(errors);
        }
    }
    for (const model::Diagnostic &d : compiled.diagnostics)
        err << formatDiagnostic(program.file, onLadder(d, program)) << '\n';
    if (!compiled.ok()) {
        err << Tr::tr("the program does not start") << '\n';
        return 1;
    }
    std::vector<simulator::RuntimeError> runtimeErrors;
    simulator::runTrace(compiled.program, request, out, &runtimeErrors);
    out.flush();
    for (const simulator::RuntimeError &e : runtimeErrors) {
        if (program.kind == InputKind::Listing) {
            err << QStringLiteral("%1:%2: ").arg(program.file).arg(e.line);
        } else if (static_cast<std::size_t>(e.instruction) < program.origin.size()) {
            err << QStringLiteral("%1:rung %2: ")
                       .arg(program.file)
                       .arg(program.origin[static_cast<std::size_t>(e.instruction)].rung + 1);
        }
        err << Tr::tr("runtime error at step %1: %2").arg(e.instruction).arg(e.message) << '\n';
    }
    return 0;
}

} // namespace rung::app
