#include "model/convert/typed_listing.h"

#include "model/tr.h"

#include "model/checks/checks.h"
#include "model/ladder/ladder_text.h"
#include "model/target/address.h"

#include <QCryptographicHash>
#include <QRegularExpression>

#include <algorithm>
#include <set>

namespace rung::model {

namespace {

const QRegularExpression &placeholderPattern() {
    static const QRegularExpression re(
        QStringLiteral("^\\s*(?:;|//)\\s*\\[\\[(\\d+:[0-9a-f]+(?:@\\d+,\\d+)?)\\]\\]"));
    return re;
}

// What a rung lists on its own: its instructions, with the cell each came from.
ToListingResult listedAlone(const Target &target, const Rung &rung) {
    LadderProgram one;
    one.target = &target;
    one.rungs = {rung};
    return ladderToList(one);
}

bool sameInstructions(const ToListingResult &a, const ToListingResult &b) {
    const auto &x = a.list.instructions;
    const auto &y = b.list.instructions;
    return a.problems.empty() && b.problems.empty() && x.size() == y.size() &&
           std::equal(x.begin(), x.end(), y.begin(),
                      [](const Instruction &i, const Instruction &j) { return i.sameAs(j); });
}

// A left-out contact whose marked line stays in the typed text.
struct KeptContact {
    int line;          // the marked line (1-based)
    int rungNumber;    // the rung it named (1-based, as the line says)
    const Rung *drawn; // that rung as drawn (held)
    int row;
    int column;
};

Diagnostic lineError(int line, const QString &message) {
    Diagnostic d;
    d.code = QStringLiteral("SYN001"); // as a line of the text that does not read
    d.severity = Severity::Error;
    d.location.line = line;
    d.location.column = 1;
    d.message = message;
    return d;
}

// Puts each kept contact into the rung below its line; what finds no place is returned as an
// error on its line, and nothing may change then.
std::vector<Diagnostic> keepContacts(const Target &target, const std::vector<KeptContact> &kept,
                                     ToLadderResult &ladder) {
    std::vector<Diagnostic> lost;
    const auto name = [&target](const KeptContact &k) {
        return contactName(target, k.drawn->cell(k.row, k.column).contact);
    };
    // Each contact joins the rung below its line.
    auto &rungs = ladder.ladder.rungs;
    std::map<std::size_t, std::vector<const KeptContact *>> byRung;
    for (const KeptContact &k : kept) {
        const auto below = static_cast<std::size_t>(
            std::upper_bound(ladder.rungLine.begin(), ladder.rungLine.end(), k.line) -
            ladder.rungLine.begin());
        if (below < rungs.size())
            byRung[below].push_back(&k);
        else
            lost.push_back(lineError(
                k.line, TypedListingTr::tr("This line keeps %1 (row %2, column %3) of rung %4, "
                                           "but no rung follows it: delete the line to let the "
                                           "contact go, or undo")
                            .arg(name(k))
                            .arg(k.row + 1)
                            .arg(k.column + 1)
                            .arg(k.rungNumber)));
    }
    for (const auto &[index, marks] : byRung) {
        Rung &typed = rungs[index];
        const ToListingResult wanted = listedAlone(target, typed);
        const Rung *drawn = marks.front()->drawn;
        const bool oneDrawing = std::all_of(marks.begin(), marks.end(),
                                            [drawn](const auto *k) { return k->drawn == drawn; });
        if (oneDrawing && sameInstructions(listedAlone(target, *drawn), wanted)) {
            // The rung lists as it did: its drawing comes back whole, less the left-out
            // contacts whose lines were deleted.
            Rung back = *drawn;
            back.comment = typed.comment;
            for (const auto &[row, col] : leftOutContacts(*drawn, 0, listedAlone(target, *drawn)))
                if (std::none_of(marks.begin(), marks.end(), [row = row, col = col](const auto *k) {
                        return k->row == row && k->column == col;
                    }))
                    back.cell(row, col) = Cell{};
            typed = back;
            continue;
        }
        // The rung was edited: each contact goes back to its cell when that is free, else to
        // a new row below the rung, where it stays off every path as it was.
        for (const KeptContact *k : marks) {
            const Cell &drawnCell = k->drawn->cell(k->row, k->column);
            if (k->row < typed.rows && k->column < typed.columns &&
                typed.cell(k->row, k->column) == drawnCell)
                continue; // typed in where it stood (linked now, or as it was)
            Rung merged = typed;
            int row = k->row;
            if (row >= merged.rows || k->column >= merged.columns ||
                merged.cell(row, k->column).kind != CellKind::Empty || merged.coveredByBox(row))
                row = merged.rows;
            merged.widenKeepingWires(std::max(merged.rows, row + 1),
                                     std::max(merged.columns, k->column + 1));
            merged.cell(row, k->column) = drawnCell;
            if (merged.cell(row, k->column).kind == CellKind::Contact &&
                sameInstructions(listedAlone(target, merged), wanted))
                typed = merged;
            else
                lost.push_back(lineError(
                    k->line,
                    TypedListingTr::tr("%1 (row %2, column %3) of rung %4 finds no place in the "
                                       "rung typed below this line: delete the line to let it "
                                       "go, or undo")
                        .arg(name(*k))
                        .arg(k->row + 1)
                        .arg(k->column + 1)
                        .arg(k->rungNumber)));
        }
    }
    return lost;
}

} // namespace

QString holdRung(HeldRungs &held, const Target &target, int index, const Rung &rung) {
    LadderProgram one;
    one.target = &target;
    one.rungs = {rung};
    const QByteArray hash =
        QCryptographicHash::hash(printLadderText(one).toUtf8(), QCryptographicHash::Sha1);
    const QString key =
        QStringLiteral("%1:%2").arg(index + 1).arg(QString::fromLatin1(hash.toHex().left(6)));
    held.insert_or_assign(key, rung);
    return key;
}

QString placeholderKey(const QString &line) {
    const QRegularExpressionMatch m = placeholderPattern().match(line);
    return m.hasMatch() ? m.captured(1) : QString();
}

std::vector<std::pair<int, int>> leftOutContacts(const Rung &rung, int index,
                                                 const ToListingResult &listing) {
    std::set<std::pair<int, int>> listed;
    const auto r = static_cast<std::size_t>(index);
    if (r + 1 < listing.rungFirst.size()) // the rung's own instructions only: no pass over all
        for (auto i = static_cast<std::size_t>(listing.rungFirst[r]);
             i < static_cast<std::size_t>(listing.rungFirst[r + 1]) && i < listing.origin.size();
             ++i)
            if (const CellOrigin &o = listing.origin[i]; o.row >= 0 && o.column >= 0)
                listed.emplace(o.row, o.column);
    std::vector<std::pair<int, int>> out;
    for (int row = 0; row < rung.rows; ++row)
        for (int col = 0; col < rung.columns; ++col)
            if (rung.cell(row, col).kind == CellKind::Contact && !listed.count({row, col}))
                out.emplace_back(row, col);
    return out;
}

QString contactName(const Target &target, const Contact &contact) {
    return contact.operands.empty() ? contactToText(target, contact)
                                    : formatOperand(target, contact.operands.front());
}

TypedListing readTypedListing(const Target &target, const ModelVariant *model, const QString &text,
                              const HeldRungs &held) {
    TypedListing result;
    ParseResult parsed = parseInstructionList(target, text, model);
    std::vector<Diagnostic> problems;
    // The marked lines: each puts back the rung it stands for, at its place; one this list
    // never showed (pasted from elsewhere) is an error rather than a lost rung.
    std::vector<std::pair<int, const Rung *>> rungsBack; // line (1-based), rung
    std::vector<KeptContact> kept;                       // the left-out contacts whose lines stay
    {
        const QStringList lines = text.split(QLatin1Char('\n'));
        for (int i = 0; i < lines.size(); ++i) {
            const QString key = placeholderKey(lines[i]);
            if (key.isEmpty())
                continue;
            const QString rungKey = key.section(QLatin1Char('@'), 0, 0);
            if (const auto it = held.find(rungKey); it != held.end()) {
                if (!key.contains(QLatin1Char('@'))) {
                    rungsBack.emplace_back(i + 1, &it->second);
                    continue;
                }
                const QString cell = key.section(QLatin1Char('@'), 1);
                const int row = cell.section(QLatin1Char(','), 0, 0).toInt() - 1;
                const int col = cell.section(QLatin1Char(','), 1).toInt() - 1;
                const Rung &rung = it->second;
                if (row >= 0 && col >= 0 && row < rung.rows && col < rung.columns &&
                    rung.cell(row, col).kind == CellKind::Contact) {
                    kept.push_back(
                        {i + 1, rungKey.section(QLatin1Char(':'), 0, 0).toInt(), &rung, row, col});
                    continue;
                }
            }
            problems.push_back(
                lineError(i + 1, TypedListingTr::tr("This line stood for a rung of another "
                                                    "program: delete the line or undo the paste")));
        }
        std::erase_if(parsed.list.comments, [](const std::pair<int, QString> &c) {
            return !placeholderKey(QLatin1String("; ") + c.second).isEmpty();
        });
    }
    for (const ParseError &e : parsed.errors) {
        Diagnostic d;
        d.code = QStringLiteral("SYN001");
        d.location.line = e.line;
        d.location.column = e.column;
        d.message = e.message;
        problems.push_back(d);
    }
    if (!parsed.ok()) {
        // What the lines that did parse show already (an output to an input, a coil driven
        // twice), beside the lines that did not.
        CheckOptions partial;
        partial.model = model;
        partial.source = &text;
        partial.parsedLinesOnly = true;
        for (Diagnostic &d : checkList(parsed.list, partial))
            problems.push_back(std::move(d));
    }
    if (!parsed.ok() || !problems.empty()) {
        sortDiagnostics(problems);
        result.findings = std::move(problems);
        return result;
    }
    ToLadderResult ladder = listToLadder(parsed.list);
    CheckOptions options;
    options.model = model;
    options.source = &text;
    if (hasErrors(ladder.problems)) {
        // A text that parses but cannot be drawn is checked whole, as `check` does: why it
        // cannot be drawn by the documented codes (BL001, OC001, ST002, ...), next to every
        // other finding, which the ladder (the last valid program) cannot give for this text.
        result.findings = checkList(parsed.list, options);
        return result;
    }
    if (std::vector<Diagnostic> lost = keepContacts(target, kept, ladder); !lost.empty()) {
        result.findings = std::move(lost);
        return result;
    }
    // The text stays as typed until the ladder is edited: its fuzzy forms are worth a warning
    // with the canonical rewrite as a fix, and never stop the ladder following.
    options.formOnly = true;
    result.findings = checkList(parsed.list, options);
    // Each held rung goes before the first rung whose instructions start below its line.
    auto &rungs = ladder.ladder.rungs;
    for (std::size_t h = 0; h < rungsBack.size(); ++h) {
        const auto [line, rung] = rungsBack[h];
        const auto before = std::count_if(ladder.rungLine.begin(), ladder.rungLine.end(),
                                          [line = line](int first) { return first < line; });
        const auto at = std::min<std::size_t>(static_cast<std::size_t>(before) + h, rungs.size());
        rungs.insert(rungs.begin() + static_cast<std::ptrdiff_t>(at), *rung);
    }
    result.rungs = std::move(rungs);
    return result;
}

} // namespace rung::model
