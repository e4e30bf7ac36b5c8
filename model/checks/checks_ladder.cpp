#include "model/checks/checks.h"
#include "model/checks/checks_internal.h"
#include "model/convert/convert.h"
#include "model/ladder/ladder_text.h"
#include "model/ladder/reverse_current.h"
#include "model/ladder/rung_graph.h"
#include "model/tr.h"

#include <QCoreApplication>

#include <algorithm>
#include <set>

// The ladder checks: what only the drawing can show (reverse current, open branches, elements
// that lead nowhere, outputs straight on the rail), plus every listing check placed on the
// rung its instruction came from.

namespace rung::model {

namespace {

int rungOf(const std::vector<int> &rungFirst, int instruction) {
    if (instruction < 0)
        return -1;
    const auto it = std::upper_bound(rungFirst.begin(), rungFirst.end(), instruction);
    return static_cast<int>(it - rungFirst.begin()) - 1;
}

} // namespace

std::vector<Diagnostic> checkLadder(const LadderProgram &ladder, const CheckOptions &options) {
    if (!ladder.target)
        return {};
    return checkLadder(ladder, ladderToList(ladder), options);
}

std::vector<Diagnostic> checkLadder(const LadderProgram &ladder, const ToListingResult &list,
                                    const CheckOptions &options) {
    std::vector<Diagnostic> out;
    if (!ladder.target)
        return out;
    bool inStep = false; // outputs between STL and RET may hang on the step bus
    for (std::size_t r = 0; r < ladder.rungs.size(); ++r) {
        const Rung &rung = ladder.rungs[r];
        for (const auto &o : rung.outputs) {
            if (o && o->op() == Op::StepLadder)
                inStep = true;
            else if (o && o->op() == Op::Return)
                inStep = false;
        }
        const int rungIndex = static_cast<int>(r);
        const auto networks = detail::analyzeRung(rung);
        std::set<int> used;
        for (const auto &n : networks)
            used.insert(n.cells.begin(), n.cells.end());
        const bool bridged = std::any_of(networks.begin(), networks.end(), [](const auto &n) {
            return n.connected && !n.seriesParallel;
        });
        for (const ReverseCurrentFinding &f :
             bridged ? findReverseCurrent(rung) : std::vector<ReverseCurrentFinding>{}) {
            Diagnostic d;
            d.code = QStringLiteral("RC001");
            d.severity = Severity::Error;
            d.location = Location{0, 0, rungIndex, f.row, rung.columns};
            for (const auto &[row, col] : f.cells)
                d.related.push_back(Location{0, 0, rungIndex, row, col});
            d.message =
                ChecksTr::tr(
                    "Reverse current: power would cross an element right to left to reach row %1")
                    .arg(f.row + 1);
            Fix fix;
            fix.label = ChecksTr::tr("Duplicate the shared contact into each branch");
            fix.firstRung = fix.lastRung = rungIndex;
            fix.rungs = {f.corrected};
            d.fix = fix;
            out.push_back(d);
        }
        for (const auto &n : networks) {
            if (n.connected)
                continue;
            Diagnostic d;
            d.code = QStringLiteral("LD001");
            d.location = Location{0, 0, rungIndex, n.row, rung.columns};
            d.message = ChecksTr::tr("Open branch: row %1 is not connected to the left rail")
                            .arg(n.row + 1);
            out.push_back(d);
        }
        for (int row = 0; row < rung.rows; ++row) {
            const auto &o = rung.outputs[static_cast<std::size_t>(row)];
            if (!o || !o->spec || isUnconditional(o->op()) || inStep)
                continue;
            for (const auto &n : networks)
                if (n.row == row && n.connected && n.seriesParallel && n.expr.empty()) {
                    Diagnostic d;
                    d.code = QStringLiteral("OC001");
                    d.location = Location{0, 0, rungIndex, row, rung.columns};
                    d.message =
                        ChecksTr::tr("%1 has no condition: it is wired straight to the left rail")
                            .arg(o->spec->mnemonic);
                    out.push_back(d);
                }
        }
        for (int row = 0; row < rung.rows; ++row)
            for (int col = 0; col < rung.columns; ++col) {
                if (rung.cell(row, col).kind != CellKind::Contact ||
                    used.count(row * rung.columns + col))
                    continue;
                Diagnostic d;
                d.code = QStringLiteral("LD002");
                d.severity = Severity::Warning;
                d.location = Location{0, 0, rungIndex, row, col};
                // Named, with its place: in the list this lands on its rung's first line,
                // and the list has no line of its own for a contact it leaves out.
                const Contact &contact = rung.cell(row, col).contact;
                const QString name = contact.operands.empty()
                                         ? contactToText(*ladder.target, contact)
                                         : formatOperand(*ladder.target, contact.operands.front());
                d.message =
                    ChecksTr::tr("%1 (row %2, column %3) is not on any path from the left rail "
                                 "to an output: the list leaves it out")
                        .arg(name)
                        .arg(row + 1)
                        .arg(col + 1);
                out.push_back(d);
            }
    }
    // What keeps a rung from being written as this target's listing: open branches and reverse
    // current are reported above from the drawing; the rest (a box that does not stand alone,
    // an element the target lacks) is LD003, an output with no condition OC001.
    for (const Diagnostic &p : list.problems) {
        if (p.code == QLatin1String("CV012") || p.code == QLatin1String("RC001"))
            continue;
        const bool noCondition = std::any_of(out.begin(), out.end(), [&](const Diagnostic &d) {
            return d.code == QLatin1String("OC001") && d.location.rung == p.location.rung;
        });
        if (noCondition)
            continue;
        Diagnostic d = p;
        d.code = QStringLiteral("LD003");
        if (d.location.row < 0)
            d.location.row = 0;
        d.location.cell =
            ladder.rungs.empty()
                ? 0
                : ladder.rungs[static_cast<std::size_t>(std::max(0, p.location.rung))].columns;
        out.push_back(std::move(d));
    }
    // The listing checks, on the rungs the instructions came from; without the fuzzy forms (the
    // ladder's own listing is canonical), so of the FZ codes only FZ003 (the PLC's limit on
    // ANB/ORB in a row) can come.
    for (detail::Finding &f : detail::checkListFindings(list.list, options, false)) {
        if (f.diagnostic.code == QLatin1String("OC001") ||
            f.diagnostic.code == QLatin1String("BL001"))
            continue; // the drawing-level findings above say it better
        Diagnostic d = std::move(f.diagnostic);
        d.location.line = 0;
        d.location.column = 0;
        d.location.rung = rungOf(list.rungFirst, f.instruction);
        // On the element the instruction came from (the list's origin map), so the ladder marks
        // that cell and the list that instruction's line, not the rung's first line (its comment).
        if (f.instruction >= 0 && static_cast<std::size_t>(f.instruction) < list.origin.size()) {
            const CellOrigin &from = list.origin[static_cast<std::size_t>(f.instruction)];
            if (from.rung == d.location.rung && from.row >= 0 && from.column >= 0) {
                d.location.row = from.row;
                d.location.cell = from.column;
            }
        }
        d.fix.reset();
        if (d.code == QLatin1String("EN001")) {
            // END is missing: a rung of END alone after the last one.
            if (const InstructionSpec *end = ladder.target->findInstruction(Op::End)) {
                Rung endRung(1, 0);
                Instruction ins;
                ins.spec = end;
                endRung.outputs[0] = ins;
                Fix fix;
                fix.label = ChecksTr::tr("Append %1").arg(end->mnemonic);
                fix.firstRung = static_cast<int>(ladder.rungs.size());
                fix.lastRung = fix.firstRung - 1; // nothing replaced: the rung is added
                fix.rungs = {endRung};
                d.fix = std::move(fix);
            }
        }
        d.related.clear();
        for (int i : f.related)
            d.related.push_back(Location{0, 0, rungOf(list.rungFirst, i), -1, -1});
        if (!f.ladderMessage.isEmpty() && !d.related.empty())
            d.message = f.ladderMessage.arg(d.related.front().rung + 1);
        out.push_back(std::move(d));
    }
    sortDiagnostics(out);
    return out;
}

} // namespace rung::model
