#include "document.h"

#include <algorithm>

#include "model/ladder/ladder_text.h"

#include <QCryptographicHash>
#include <QFileInfo>
#include <QRegularExpression>
#include <QUndoCommand>

#include <map>
#include <set>

namespace rung::editor {

namespace {

// Replaces rungs [first, first + oldRungs.size()) by newRungs; stores both as values (the
// serialized state of the rungs), never pointers into the document.
class ReplaceRungsCommand : public QUndoCommand {
public:
    ReplaceRungsCommand(Document *doc, int first, std::vector<model::Rung> oldRungs,
                        std::vector<model::Rung> newRungs, const QString &label)
        : QUndoCommand(label)
        , m_doc(doc)
        , m_first(first)
        , m_old(std::move(oldRungs))
        , m_new(std::move(newRungs)) {}

    void redo() override { m_doc->applyRungs(m_first, static_cast<int>(m_old.size()), m_new); }
    void undo() override { m_doc->applyRungs(m_first, static_cast<int>(m_new.size()), m_old); }

private:
    Document *m_doc;
    int m_first;
    std::vector<model::Rung> m_old;
    std::vector<model::Rung> m_new;
};

class SymbolsCommand : public QUndoCommand {
public:
    SymbolsCommand(Document *doc, std::vector<model::Symbol> oldSymbols,
                   std::vector<model::Symbol> newSymbols)
        : QUndoCommand(Document::tr("Edit symbols"))
        , m_doc(doc)
        , m_old(std::move(oldSymbols))
        , m_new(std::move(newSymbols)) {}
    void redo() override { m_doc->applySymbols(m_new); }
    void undo() override { m_doc->applySymbols(m_old); }

private:
    Document *m_doc;
    std::vector<model::Symbol> m_old;
    std::vector<model::Symbol> m_new;
};

class WatchListsCommand : public QUndoCommand {
public:
    WatchListsCommand(Document *doc, std::vector<model::WatchList> oldLists,
                      std::vector<model::WatchList> newLists, const QString &label)
        : QUndoCommand(label)
        , m_doc(doc)
        , m_old(std::move(oldLists))
        , m_new(std::move(newLists)) {}
    void redo() override { m_doc->applyWatchLists(m_new); }
    void undo() override { m_doc->applyWatchLists(m_old); }

private:
    Document *m_doc;
    std::vector<model::WatchList> m_old;
    std::vector<model::WatchList> m_new;
};

// "; [[3:9f2c41]] ...": the marker is the same in every language, so the list's text reads back
// whatever the UI language was when it was shown.
const QRegularExpression &placeholderPattern() {
    static const QRegularExpression re(
        QStringLiteral("^\\s*(?:;|//)\\s*\\[\\[(\\d+:[0-9a-f]+(?:@\\d+,\\d+)?)\\]\\]"));
    return re;
}

// What a rung lists on its own: its instructions, with the cell each came from.
model::ToListingResult listedAlone(const model::Target &target, const model::Rung &rung) {
    model::LadderProgram one;
    one.target = &target;
    one.rungs = {rung};
    return model::ladderToList(one);
}

bool sameInstructions(const model::ToListingResult &a, const model::ToListingResult &b) {
    const auto &x = a.list.instructions;
    const auto &y = b.list.instructions;
    return a.problems.empty() && b.problems.empty() && x.size() == y.size() &&
           std::equal(x.begin(), x.end(), y.begin(),
                      [](const model::Instruction &i, const model::Instruction &j) {
                          return i.sameAs(j);
                      });
}

// The contacts of listed rung `index` that the list leaves out, being on no path to an output
// (LD002): (row, column), in reading order.
std::vector<std::pair<int, int>> leftOutContacts(const model::Rung &rung, int index,
                                                 const model::ToListingResult &listing) {
    std::set<std::pair<int, int>> listed;
    const auto r = static_cast<std::size_t>(index);
    if (r + 1 < listing.rungFirst.size()) // the rung's own instructions only: no pass over all
        for (auto i = static_cast<std::size_t>(listing.rungFirst[r]);
             i < static_cast<std::size_t>(listing.rungFirst[r + 1]) && i < listing.origin.size();
             ++i)
            if (const model::CellOrigin &o = listing.origin[i]; o.row >= 0 && o.column >= 0)
                listed.emplace(o.row, o.column);
    std::vector<std::pair<int, int>> out;
    for (int row = 0; row < rung.rows; ++row)
        for (int col = 0; col < rung.columns; ++col)
            if (rung.cell(row, col).kind == model::CellKind::Contact && !listed.count({row, col}))
                out.emplace_back(row, col);
    return out;
}

QString contactName(const model::Target &target, const model::Contact &contact) {
    return contact.operands.empty() ? model::contactToText(target, contact)
                                    : model::formatOperand(target, contact.operands.front());
}

} // namespace

QString Document::placeholderKey(const QString &line) {
    const QRegularExpressionMatch m = placeholderPattern().match(line);
    return m.hasMatch() ? m.captured(1) : QString();
}

Document::Document(QObject *parent)
    : QObject(parent) {
    reset(model::Target::defaultTarget(), QString());
}

void Document::reset(const model::Target &target, const QString &modelName) {
    model::Project p;
    p.target = &target;
    p.model = modelName.isEmpty() ? target.defaultModel().name : modelName;
    p.program.target = &target;
    // A new program ends with END where the target has one.
    if (const model::InstructionSpec *end = target.findInstruction(model::Op::End)) {
        model::Rung r(1, 0);
        model::Instruction ins;
        ins.spec = end;
        r.outputs[0] = ins;
        p.program.rungs.push_back(r);
    }
    setProject(p, QString());
}

void Document::setProject(const model::Project &project, const QString &path) {
    m_project = project;
    m_project.program.target = m_project.target;
    m_undo.clear();
    m_held.clear();
    const bool named = !m_untitledName.isEmpty();
    m_untitledName.clear();
    m_suggestedPath.clear();
    if (path != m_path)
        setPath(path);
    else if (named)
        emit nameChanged();
    ++m_rungsRevision;
    refresh();
    emit projectReplaced();
}

const model::ModelVariant *Document::modelVariant() const {
    const model::ModelVariant *m = m_project.target->model(m_project.model);
    return m ? m : &m_project.target->defaultModel();
}

void Document::setPath(const QString &path) {
    if (path == m_path)
        return;
    m_path = path;
    emit pathChanged(path);
    emit nameChanged();
}

void Document::setUntitledName(const QString &name, const QString &suggestedPath) {
    m_untitledName = name;
    m_suggestedPath = suggestedPath;
    emit nameChanged();
}

QString Document::name() const {
    if (!m_path.isEmpty())
        return QFileInfo(m_path).fileName();
    return m_untitledName.isEmpty() ? tr("Untitled") : m_untitledName;
}

int Document::rungOfLine(int line) const {
    int rung = -1;
    for (std::size_t r = 0; r < m_rungLine.size(); ++r)
        if (m_rungLine[r] > 0 && m_rungLine[r] <= line)
            rung = static_cast<int>(r);
    return rung;
}

int Document::firstLineOfRung(int rung) const {
    if (rung < 0 || rung >= static_cast<int>(m_rungLine.size()))
        return -1;
    return m_rungLine[static_cast<std::size_t>(rung)];
}

int Document::lineOf(const model::Location &location) const {
    if (const auto it = m_leftOutLine.find({location.rung, location.row, location.cell});
        it != m_leftOutLine.end())
        return it->second;
    const auto listed = [&](int rung) {
        const auto r = static_cast<std::size_t>(rung);
        return r + 1 < m_listing->rungFirst.size() &&
               m_listing->rungFirst[r] < m_listing->rungFirst[r + 1];
    };
    if (location.rung >= 0 && location.row >= 0 && location.cell >= 0 && listed(location.rung)) {
        const model::CellOrigin cell{location.rung, location.row, location.cell};
        const auto &origin = m_listing->origin;
        const auto first =
            static_cast<std::size_t>(m_listing->rungFirst[static_cast<std::size_t>(location.rung)]);
        const auto end = std::min(
            origin.size(), static_cast<std::size_t>(
                               m_listing->rungFirst[static_cast<std::size_t>(location.rung) + 1]));
        for (std::size_t i = first; i < end; ++i)
            if (origin[i] == cell && i < m_printed.instructionLine.size())
                return m_printed.instructionLine[i];
    }
    return firstLineOfRung(location.rung);
}

int Document::stepCount() const {
    int steps = 0;
    for (const model::Instruction &i : m_listing->list.instructions)
        steps += model::instructionSteps(*m_project.target, i);
    return steps;
}

void Document::replaceRungs(int first, int count, const std::vector<model::Rung> &rungs,
                            const QString &label) {
    if (m_rungEditGuard && !m_rungEditGuard(first, count))
        return;
    pushRungs(first, count, rungs, label);
}

bool Document::stepChangesRungs(int index) const {
    return dynamic_cast<const ReplaceRungsCommand *>(m_undo.command(index)) != nullptr;
}

void Document::pushRungs(int first, int count, const std::vector<model::Rung> &rungs,
                         const QString &label) {
    const auto &all = m_project.program.rungs;
    first = std::clamp(first, 0, static_cast<int>(all.size()));
    count = std::clamp(count, 0, static_cast<int>(all.size()) - first);
    std::vector<model::Rung> old(all.begin() + first, all.begin() + first + count);
    m_undo.push(new ReplaceRungsCommand(this, first, std::move(old), rungs, label));
}

void Document::setRung(int index, const model::Rung &rung, const QString &label) {
    replaceRungs(index, 1, {rung}, label);
}

void Document::insertRung(int index, const model::Rung &rung) {
    replaceRungs(index, 0, {rung}, tr("Insert rung"));
}

void Document::removeRungs(int first, int count) {
    replaceRungs(first, count, {},
                 count == 1 ? tr("Delete rung") : tr("Delete %n rungs", nullptr, count));
}

void Document::setSymbols(const std::vector<model::Symbol> &symbols) {
    if (symbols == m_project.symbols)
        return; // an undo step that changes nothing would only be in the way
    m_undo.push(new SymbolsCommand(this, m_project.symbols, symbols));
}

void Document::setWatchLists(const std::vector<model::WatchList> &lists, const QString &label) {
    m_undo.push(new WatchListsCommand(this, m_project.watchLists, lists, label));
}

void Document::applyWatchLists(const std::vector<model::WatchList> &lists) {
    m_project.watchLists = lists;
    emit programChanged();
}

void Document::applySymbols(const std::vector<model::Symbol> &symbols) {
    m_project.symbols = symbols;
    emit programChanged();
}

bool Document::setListing(const QString &text, std::vector<model::Diagnostic> *errors,
                          ListingStep step) {
    model::ParseResult parsed =
        model::parseInstructionList(*m_project.target, text, modelVariant());
    std::vector<model::Diagnostic> problems;
    // The placeholder lines: each puts back the rung it stands for, at its place; one this
    // document never showed (pasted from elsewhere) is an error rather than a lost rung.
    std::vector<std::pair<int, const model::Rung *>> held; // line (1-based), rung
    std::vector<KeptContact> kept;                         // the left-out contacts whose lines stay
    {
        const QStringList lines = text.split(QLatin1Char('\n'));
        for (int i = 0; i < lines.size(); ++i) {
            const QString key = placeholderKey(lines[i]);
            if (key.isEmpty())
                continue;
            const QString rungKey = key.section(QLatin1Char('@'), 0, 0);
            if (const auto it = m_held.find(rungKey); it != m_held.end()) {
                if (!key.contains(QLatin1Char('@'))) {
                    held.emplace_back(i + 1, &it->second);
                    continue;
                }
                const QString cell = key.section(QLatin1Char('@'), 1);
                const int row = cell.section(QLatin1Char(','), 0, 0).toInt() - 1;
                const int col = cell.section(QLatin1Char(','), 1).toInt() - 1;
                const model::Rung &rung = it->second;
                if (row >= 0 && col >= 0 && row < rung.rows && col < rung.columns &&
                    rung.cell(row, col).kind == model::CellKind::Contact) {
                    kept.push_back(
                        {i + 1, rungKey.section(QLatin1Char(':'), 0, 0).toInt(), &rung, row, col});
                    continue;
                }
            }
            model::Diagnostic d;
            d.code = QStringLiteral("SYN001");
            d.location.line = i + 1;
            d.location.column = 1;
            d.message = tr("This line stood for a rung of another program: delete the line or "
                           "undo the paste");
            problems.push_back(d);
        }
        std::erase_if(parsed.list.comments, [](const std::pair<int, QString> &c) {
            return !placeholderKey(QLatin1String("; ") + c.second).isEmpty();
        });
    }
    for (const model::ParseError &e : parsed.errors) {
        model::Diagnostic d;
        d.code = QStringLiteral("SYN001");
        d.location.line = e.line;
        d.location.column = e.column;
        d.message = e.message;
        problems.push_back(d);
    }
    if (!parsed.ok()) {
        // What the lines that did parse show already (an output to an input, a coil driven
        // twice), beside the lines that did not.
        model::CheckOptions partial;
        partial.model = modelVariant();
        partial.source = &text;
        partial.parsedLinesOnly = true;
        for (model::Diagnostic &d : model::checkList(parsed.list, partial))
            problems.push_back(std::move(d));
    }
    if (!parsed.ok() || !problems.empty()) {
        model::sortDiagnostics(problems);
        if (errors)
            *errors = problems;
        return false;
    }
    model::ToLadderResult ladder = model::listToLadder(parsed.list);
    model::CheckOptions options;
    options.model = modelVariant();
    options.source = &text;
    if (model::hasErrors(ladder.problems)) {
        // A text that parses but cannot be drawn is checked whole, as `check` does: why it
        // cannot be drawn by the documented codes (BL001, OC001, ST002, ...), next to every
        // other finding, which the ladder (the last valid program) cannot give for this text.
        if (errors)
            *errors = model::checkList(parsed.list, options);
        return false;
    }
    // The text stays as typed until the ladder is edited: its fuzzy forms are worth a warning
    // with the canonical rewrite as a fix, and never stop the ladder following.
    options.formOnly = true;
    if (errors)
        *errors = model::checkList(parsed.list, options);
    auto &rungs = ladder.ladder.rungs;
    if (std::vector<model::Diagnostic> lost = keepContacts(kept, ladder); !lost.empty()) {
        if (errors)
            *errors = lost;
        return false;
    }
    // Each held rung goes before the first rung whose instructions start below its line.
    for (std::size_t h = 0; h < held.size(); ++h) {
        const auto [line, rung] = held[h];
        const auto before = std::count_if(ladder.rungLine.begin(), ladder.rungLine.end(),
                                          [line = line](int first) { return first < line; });
        const auto at = std::min<std::size_t>(static_cast<std::size_t>(before) + h, rungs.size());
        rungs.insert(rungs.begin() + static_cast<std::ptrdiff_t>(at), *rung);
    }
    if (step == ListingStep::Check || ladder.ladder.rungs == m_project.program.rungs)
        return true;
    if (step == ListingStep::InPlace)
        applyRungs(0, static_cast<int>(m_project.program.rungs.size()), ladder.ladder.rungs);
    else
        pushRungs(0, static_cast<int>(m_project.program.rungs.size()), ladder.ladder.rungs,
                  tr("Edit instruction list"));
    return true;
}

std::vector<model::Diagnostic> Document::keepContacts(const std::vector<KeptContact> &kept,
                                                      model::ToLadderResult &ladder) const {
    std::vector<model::Diagnostic> lost;
    const auto problem = [&lost](const KeptContact &k, const QString &message) {
        model::Diagnostic d;
        d.code = QStringLiteral("SYN001"); // as a line that stood for another program's rung
        d.severity = model::Severity::Error;
        d.location.line = k.line;
        d.location.column = 1;
        d.message = message;
        lost.push_back(d);
    };
    const auto name = [this](const KeptContact &k) {
        return contactName(target(), k.drawn->cell(k.row, k.column).contact);
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
            problem(k, tr("This line keeps %1 (row %2, column %3) of rung %4, but no rung "
                          "follows it: delete the line to let the contact go, or undo")
                           .arg(name(k))
                           .arg(k.row + 1)
                           .arg(k.column + 1)
                           .arg(k.rungNumber));
    }
    for (const auto &[index, marks] : byRung) {
        model::Rung &typed = rungs[index];
        const model::ToListingResult wanted = listedAlone(target(), typed);
        const model::Rung *drawn = marks.front()->drawn;
        const bool oneDrawing = std::all_of(marks.begin(), marks.end(),
                                            [drawn](const auto *k) { return k->drawn == drawn; });
        if (oneDrawing && sameInstructions(listedAlone(target(), *drawn), wanted)) {
            // The rung lists as it did: its drawing comes back whole, less the left-out
            // contacts whose lines were deleted.
            model::Rung back = *drawn;
            back.comment = typed.comment;
            for (const auto &[row, col] : leftOutContacts(*drawn, 0, listedAlone(target(), *drawn)))
                if (std::none_of(marks.begin(), marks.end(), [row = row, col = col](const auto *k) {
                        return k->row == row && k->column == col;
                    }))
                    back.cell(row, col) = model::Cell{};
            typed = back;
            continue;
        }
        // The rung was edited: each contact goes back to its cell when that is free, else to
        // a new row below the rung, where it stays off every path as it was.
        for (const KeptContact *k : marks) {
            const model::Cell &drawnCell = k->drawn->cell(k->row, k->column);
            if (k->row < typed.rows && k->column < typed.columns &&
                typed.cell(k->row, k->column) == drawnCell)
                continue; // typed in where it stood (linked now, or as it was)
            model::Rung merged = typed;
            int row = k->row;
            if (row >= merged.rows || k->column >= merged.columns ||
                merged.cell(row, k->column).kind != model::CellKind::Empty ||
                merged.coveredByBox(row))
                row = merged.rows;
            merged.widenKeepingWires(std::max(merged.rows, row + 1),
                                     std::max(merged.columns, k->column + 1));
            merged.cell(row, k->column) = drawnCell;
            if (merged.cell(row, k->column).kind == model::CellKind::Contact &&
                sameInstructions(listedAlone(target(), merged), wanted))
                typed = merged;
            else
                problem(*k, tr("%1 (row %2, column %3) of rung %4 finds no place in the rung "
                               "typed below this line: delete the line to let it go, or undo")
                                .arg(name(*k))
                                .arg(k->row + 1)
                                .arg(k->column + 1)
                                .arg(k->rungNumber));
        }
    }
    return lost;
}

void Document::applyRungs(int first, int count, const std::vector<model::Rung> &rungs) {
    auto &all = m_project.program.rungs;
    all.erase(all.begin() + first, all.begin() + first + count);
    all.insert(all.begin() + first, rungs.begin(), rungs.end());
    ++m_rungsRevision;
    refresh();
}

QString Document::heldRung(int index) {
    const model::Rung &rung = m_project.program.rungs[static_cast<std::size_t>(index)];
    model::LadderProgram one;
    one.target = m_project.target;
    one.rungs = {rung};
    const QByteArray hash =
        QCryptographicHash::hash(model::printLadderText(one).toUtf8(), QCryptographicHash::Sha1);
    const QString key =
        QStringLiteral("%1:%2").arg(index + 1).arg(QString::fromLatin1(hash.toHex().left(6)));
    m_held.insert_or_assign(key, rung);
    return key;
}

void Document::refresh() {
    m_listing =
        std::make_shared<const model::ToListingResult>(model::ladderToList(m_project.program));
    // The list as shown: a placeholder comment where a rung could not be listed (a rung that
    // lists nothing and is not blank), so the two views never disagree silently. Only the
    // comments are the document's own: the instructions are printed from the listing, not
    // copied (a copy of a 10,000-rung list was a fifth of the ladder view's memory).
    const auto &listed = m_listing->list.comments;
    std::vector<std::pair<int, QString>> shownComments;
    std::vector<std::pair<int, std::size_t>> placeholders; // rung, its comment in shownComments
    // A left-out contact (rung, row, column) and its comment in shownComments.
    std::vector<std::pair<std::tuple<int, int, int>, std::size_t>> contactMarks;
    m_unlisted.clear();
    {
        std::vector<std::pair<int, QString>> comments;
        std::size_t next = 0;
        const auto &all = m_project.program.rungs;
        for (std::size_t r = 0; r < all.size() && r + 1 < m_listing->rungFirst.size(); ++r) {
            const int at = m_listing->rungFirst[r];
            if (at < m_listing->rungFirst[r + 1]) {
                // A listed rung: a marked line for each contact it leaves out, after the
                // rung's own comment, before its first instruction.
                const int index = static_cast<int>(r);
                const auto leftOut = leftOutContacts(all[r], index, *m_listing);
                if (leftOut.empty())
                    continue;
                while (next < listed.size() && listed[next].first <= at)
                    comments.push_back(listed[next++]);
                const QString key = heldRung(index);
                for (const auto &[row, col] : leftOut) {
                    comments.emplace_back(
                        at, QStringLiteral("[[%1@%2,%3]] ").arg(key).arg(row + 1).arg(col + 1) +
                                tr("Rung %1: %2 (row %3, column %4) is on no path to an output, "
                                   "so the list leaves it out; the ladder keeps it while this "
                                   "line stays.")
                                    .arg(index + 1)
                                    .arg(contactName(target(), all[r].cell(row, col).contact))
                                    .arg(row + 1)
                                    .arg(col + 1));
                    contactMarks.push_back({{index, row, col}, comments.size() - 1});
                }
                continue;
            }
            const auto problem = std::find_if(
                m_listing->problems.begin(), m_listing->problems.end(),
                [r](const model::Diagnostic &d) { return d.location.rung == static_cast<int>(r); });
            const model::Rung &rung = all[r];
            const bool blank =
                std::none_of(rung.outputs.begin(), rung.outputs.end(),
                             [](const auto &o) { return o.has_value(); }) &&
                std::all_of(rung.cells.begin(), rung.cells.end(),
                            [](const model::Cell &c) { return c.kind == model::CellKind::Empty; });
            if (problem == m_listing->problems.end() && blank)
                continue;
            while (next < listed.size() && listed[next].first < at)
                comments.push_back(listed[next++]);
            const QString why = problem != m_listing->problems.end()
                                    ? problem->message
                                    : tr("it has nothing to list yet");
            comments.emplace_back(
                at, QStringLiteral("[[%1]] ").arg(heldRung(static_cast<int>(r))) +
                        tr("Rung %1 is not in the list: %2. Edit it in the ladder; this line "
                           "keeps its place.")
                            .arg(r + 1)
                            .arg(why));
            placeholders.emplace_back(static_cast<int>(r), comments.size() - 1);
            m_unlisted.push_back({static_cast<int>(r), why});
        }
        comments.insert(comments.end(), listed.begin() + static_cast<std::ptrdiff_t>(next),
                        listed.end());
        shownComments = std::move(comments);
    }
    m_printed = model::printListing(m_listing->list, shownComments);
    m_listingText = m_printed.text;
    // Lines of the printed listing: comments come before their rung's first instruction; a
    // placeholder is its rung's line.
    m_rungLine.assign(m_project.program.rungs.size(), -1);
    {
        const auto &ins = m_listing->list.instructions;
        const auto &comments = shownComments;
        // The comments before instruction i fill the lines from firstLine[i] on (the printer's
        // map), in their order.
        std::vector<int> commentLine(comments.size(), 0);
        for (std::size_t k = 0; k < comments.size(); ++k) {
            const auto at = static_cast<std::size_t>(comments[k].first);
            commentLine[k] = k > 0 && comments[k - 1].first == comments[k].first
                                 ? commentLine[k - 1] + 1
                                 : m_printed.firstLine[at];
        }
        const std::vector<int> &instructionLine = m_printed.instructionLine;
        std::vector<bool> isPlaceholder(comments.size(), false);
        for (const auto &[rung, comment] : placeholders) {
            isPlaceholder[comment] = true;
            m_rungLine[static_cast<std::size_t>(rung)] = commentLine[comment];
        }
        m_leftOutLine.clear();
        for (const auto &[cell, comment] : contactMarks)
            m_leftOutLine[cell] = commentLine[comment];
        // A listed rung starts at its own first comment, else at its first instruction.
        std::vector<int> firstOwnComment(ins.size() + 1, 0);
        for (std::size_t k = 0; k < comments.size(); ++k) {
            int &first = firstOwnComment[static_cast<std::size_t>(comments[k].first)];
            if (!isPlaceholder[k] && first == 0)
                first = commentLine[k];
        }
        for (std::size_t r = 0; r + 1 < m_listing->rungFirst.size() && r < m_rungLine.size(); ++r) {
            const auto at = static_cast<std::size_t>(m_listing->rungFirst[r]);
            if (m_listing->rungFirst[r] < m_listing->rungFirst[r + 1])
                m_rungLine[r] = firstOwnComment[at] > 0 ? firstOwnComment[at] : instructionLine[at];
        }
    }
    model::CheckOptions options;
    options.model = modelVariant();
    // The checks report what keeps a rung from being listed (the listing's own problems) by
    // the documented codes, RC001 with its fix: those problems are not added a second time.
    m_diagnostics = model::checkLadder(m_project.program, *m_listing, options);
    emit programChanged();
}

QStringList Document::knownDevices(bool withNames) const {
    std::set<model::Address> devices;
    const auto add = [&devices](const std::vector<model::Operand> &operands) {
        for (const model::Operand &o : operands)
            if (o.kind == model::Operand::Kind::Device)
                devices.insert(o.address);
    };
    for (const model::Rung &r : m_project.program.rungs) {
        for (const model::Cell &c : r.cells)
            add(c.contact.operands);
        for (const auto &out : r.outputs)
            if (out)
                add(out->operands);
        if (devices.size() > 2000)
            break; // enough to choose from in a huge program
    }
    std::map<model::Address, QString> names;
    for (const model::Symbol &sym : m_project.symbols) {
        devices.insert(sym.address);
        if (withNames && !sym.name.isEmpty())
            names.emplace(sym.address, sym.name);
    }
    QStringList words;
    words.reserve(static_cast<qsizetype>(devices.size()));
    for (const model::Address &a : devices) {
        QString word = model::formatAddress(target(), a);
        if (const auto name = names.find(a); name != names.end())
            word += QLatin1String("  ") + name->second;
        words << word;
    }
    return words;
}

} // namespace rung::editor
