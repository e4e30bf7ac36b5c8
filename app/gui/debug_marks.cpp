#include "app/gui/debug_marks.h"

#include "editor/document.h"
#include "editor/il_editor.h"
#include "editor/ladder_view.h"

#include <QCoreApplication>

#include <map>

namespace rung::app {

namespace {

class DebugMarksTr {
    Q_DECLARE_TR_FUNCTIONS(rung::app::DebugMarks)
};

} // namespace

int firstInstructionOfRung(const editor::Document &document, int rung) {
    const auto &first = document.listing().rungFirst;
    // A rung the list has no instruction of (a comment alone) has nowhere to stop.
    if (rung >= 0 && static_cast<std::size_t>(rung) + 1 < first.size() &&
        first[static_cast<std::size_t>(rung)] < first[static_cast<std::size_t>(rung) + 1])
        return first[static_cast<std::size_t>(rung)];
    return -1;
}

int instructionHere(const editor::Document &document, const editor::LadderView &ladder,
                    const editor::IlEditor &il, bool listInStep, QString *where) {
    if (il.hasFocus()) {
        int line = 0, index = 0;
        il.getCursorPosition(&line, &index);
        *where = DebugMarksTr::tr("line %1").arg(line + 1);
        return listInStep ? document.printedListing().instructionAt(line + 1) : -1;
    }
    const int rung = ladder.cursor().rung;
    *where = DebugMarksTr::tr("rung %1").arg(rung + 1);
    return firstInstructionOfRung(document, rung);
}

QString noInstructionOnLine(int line) {
    return DebugMarksTr::tr("No instruction on line %1 to stop at").arg(line);
}

QString noInstructionInRung(int rung) {
    return DebugMarksTr::tr("Rung %1 is not in the instruction list: no breakpoint there")
        .arg(rung + 1);
}

QString noInstructionAt(const QString &where) {
    return DebugMarksTr::tr("No instruction at %1 to stop at").arg(where);
}

void markBreakpoints(const editor::Document &document,
                     const std::vector<SimulationController::BreakpointSpec> &breakpoints,
                     editor::LadderView &ladder, editor::IlEditor &il, bool listInStep) {
    std::map<int, bool> lines;
    std::map<int, bool> rungs;
    const auto &printed = document.printedListing();
    for (const SimulationController::BreakpointSpec &b : breakpoints) {
        const int at = SimulationController::instructionOf(document.listing().rungFirst, b);
        if (at < 0)
            continue;
        const bool conditional = b.when != simulator::Breakpoint::When::Always;
        rungs[b.rung] = rungs[b.rung] || conditional;
        if (static_cast<std::size_t>(at) < printed.instructionLine.size())
            lines[printed.instructionLine[static_cast<std::size_t>(at)]] = conditional;
    }
    ladder.setBreakpointRungs(rungs);
    il.setBreakpointLines(listInStep ? lines : std::map<int, bool>{});
}

void markStoppedAt(const editor::Document &document, int instruction, editor::LadderView &ladder,
                   editor::IlEditor &il, bool listInStep) {
    const auto &origin = document.listing().origin;
    const auto &printed = document.printedListing();
    if (instruction < 0 || static_cast<std::size_t>(instruction) >= origin.size()) {
        ladder.setStoppedAt({-1, -1, -1});
        il.setStoppedLine(0);
        return;
    }
    const auto i = static_cast<std::size_t>(instruction);
    const model::CellOrigin &o = origin[i];
    editor::CellCursor at{o.rung, -1, -1};
    const auto &rungs = document.ladder().rungs;
    if (o.row >= 0 && o.rung >= 0 && static_cast<std::size_t>(o.rung) < rungs.size()) {
        // An output stands in the output column, which every rung draws at gridColumns.
        const bool output = o.column >= rungs[static_cast<std::size_t>(o.rung)].columns;
        at.row = o.row;
        at.column = output ? ladder.metrics().gridColumns : o.column;
    }
    ladder.setStoppedAt(at);
    il.setStoppedLine(listInStep && i < printed.instructionLine.size() ? printed.instructionLine[i]
                                                                       : 0);
}

} // namespace rung::app
