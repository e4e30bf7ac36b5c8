#include "cli_load_program.h"

#include "cli_common.h"

#include "simulator/compiler.h"

#include <QCoreApplication>

namespace rung::app {

namespace {

struct Tr {
    Q_DECLARE_TR_FUNCTIONS(rung::app::Simulate)
};

} // namespace

int loadProgram(const ProgramOptions &options, LoadedProgram *loaded, QTextStream &err) {
    CommonOptions common;
    common.file = options.file;
    common.target = options.target;
    common.model = options.model;
    Input input;
    QString error;
    if (!loadInput(common, &input, &error)) {
        err << error << '\n';
        return 2;
    }
    // A project whose newest work is an instruction list with errors would run its older
    // rungs without saying so: it does not start.
    QString notice;
    std::vector<model::Diagnostic> typed;
    if (pendingListing(input, &notice, &typed)) {
        for (const model::Diagnostic &d : typed)
            err << formatDiagnostic(pendingLocation(input.file), d) << '\n';
        err << notice << '\n' << Tr::tr("the program does not start") << '\n';
        return 1;
    }
    if (!input.listValid) {
        for (const model::Diagnostic &d : input.problems)
            if (d.severity == model::Severity::Error)
                err << formatDiagnostic(input.file, d) << '\n';
        err << Tr::tr("the program does not start") << '\n';
        return 1;
    }
    model::CheckOptions checks;
    checks.model = input.model;
    if (input.kind == InputKind::Listing)
        checks.source = &input.text;
    const simulator::CompileResult compiled = simulator::prepareProgram(input.list, checks);
    // A ladder or a project runs as its instruction list: a finding there names the
    // instruction's line in that list.
    const QString where = input.kind == InputKind::Listing
                              ? input.file
                              : Tr::tr("%1 (as instruction list)").arg(input.file);
    for (const model::Diagnostic &d : compiled.diagnostics)
        err << formatDiagnostic(where, d) << '\n';
    if (!compiled.ok()) {
        err << Tr::tr("the program does not start") << '\n';
        return 1;
    }
    loaded->program = compiled.program;
    loaded->target = input.target;
    return 0;
}

} // namespace rung::app
