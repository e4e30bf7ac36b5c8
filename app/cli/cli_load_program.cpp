#include "cli_load_program.h"

#include "app/tr.h"
#include "model/checks/checks.h"
#include "simulator/compiler.h"

#include <QCoreApplication>

namespace rung::app {

namespace {

// The compiler's findings about a drawing's instructions (numbered by their index + 1 below)
// name the rung, row and cell, as `check` does.
model::Diagnostic onLadder(model::Diagnostic d, const std::vector<model::CellOrigin> &origin) {
    const int k = d.location.line - 1;
    if (k < 0 || static_cast<std::size_t>(k) >= origin.size())
        return d;
    const model::CellOrigin &o = origin[static_cast<std::size_t>(k)];
    d.location = {};
    d.location.rung = o.rung;
    d.location.row = std::max(0, o.row);
    d.location.cell = std::max(0, o.column);
    return d;
}

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
        err << notice << '\n' << SimulateTr::tr("the program does not start") << '\n';
        return 1;
    }
    if (!input.listValid) {
        for (const model::Diagnostic &d : input.problems)
            if (d.severity == model::Severity::Error)
                err << formatDiagnostic(input.file, d) << '\n';
        err << SimulateTr::tr("the program does not start") << '\n';
        return 1;
    }
    model::CheckOptions checks;
    checks.model = input.model;
    simulator::CompileResult compiled;
    std::vector<model::CellOrigin> origin;
    if (input.kind == InputKind::Listing) {
        checks.source = &input.text;
        compiled = simulator::prepareProgram(input.list, checks);
        for (const model::Diagnostic &d : compiled.diagnostics)
            err << formatDiagnostic(input.file, d) << '\n';
    } else {
        // The drawing's checks (they name rungs and cells), then the compiler with each
        // instruction's index as its line, so that its findings find their cells too.
        const model::ToListingResult listing = model::ladderToList(input.project.program);
        origin = listing.origin;
        for (const model::Diagnostic &d :
             model::checkLadder(input.project.program, listing, checks))
            if (d.severity == model::Severity::Error)
                compiled.diagnostics.push_back(d);
        if (compiled.diagnostics.empty()) {
            model::InstructionList numbered = listing.list;
            for (std::size_t k = 0; k < numbered.instructions.size(); ++k) {
                numbered.instructions[k].line = static_cast<int>(k) + 1;
                numbered.instructions[k].column = 1;
            }
            compiled = simulator::compileProgram(numbered);
        }
        for (const model::Diagnostic &d : compiled.diagnostics)
            err << formatDiagnostic(input.file, onLadder(d, origin)) << '\n';
    }
    if (!compiled.ok()) {
        err << SimulateTr::tr("the program does not start") << '\n';
        return 1;
    }
    loaded->program = compiled.program;
    loaded->target = input.target;
    loaded->kind = input.kind;
    loaded->origin = std::move(origin);
    loaded->model = input.model ? input.model : &input.target->defaultModel();
    loaded->ports = input.project.ports;
    return 0;
}

} // namespace rung::app
