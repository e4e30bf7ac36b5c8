#include "document.h"

#include "commands/document_commands.h"

#include "model/ladder/ladder_text.h"
#include "model/target/address.h"

#include <QFileInfo>

#include <algorithm>

#include <map>
#include <set>

namespace rung::editor {

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

void Document::setPorts(const QJsonObject &ports, const QString &label) {
    if (ports != m_project.ports)
        m_undo.push(new PortsCommand(this, m_project.ports, ports, label));
}

void Document::applyPorts(const QJsonObject &ports) {
    m_project.ports = ports;
    emit programChanged();
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
    model::TypedListing typed = model::readTypedListing(target(), modelVariant(), text, m_held);
    if (errors)
        *errors = std::move(typed.findings);
    if (!typed.rungs)
        return false;
    if (step == ListingStep::Check || *typed.rungs == m_project.program.rungs)
        return true;
    if (step == ListingStep::InPlace)
        applyRungs(0, static_cast<int>(m_project.program.rungs.size()), *typed.rungs);
    else
        pushRungs(0, static_cast<int>(m_project.program.rungs.size()), *typed.rungs,
                  tr("Edit instruction list"));
    return true;
}

void Document::applyRungs(int first, int count, const std::vector<model::Rung> &rungs) {
    auto &all = m_project.program.rungs;
    all.erase(all.begin() + first, all.begin() + first + count);
    all.insert(all.begin() + first, rungs.begin(), rungs.end());
    ++m_rungsRevision;
    refresh();
}

QString Document::heldRung(int index) {
    return model::holdRung(m_held, target(), index,
                           m_project.program.rungs[static_cast<std::size_t>(index)]);
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
                const auto leftOut = model::leftOutContacts(all[r], index, *m_listing);
                if (leftOut.empty())
                    continue;
                while (next < listed.size() && listed[next].first <= at)
                    comments.push_back(listed[next++]);
                const QString key = heldRung(index);
                for (const auto &[row, col] : leftOut) {
                    comments.emplace_back(
                        at,
                        QStringLiteral("[[%1@%2,%3]] ").arg(key).arg(row + 1).arg(col + 1) +
                            tr("Rung %1: %2 (row %3, column %4) is on no path to an output, "
                               "so the list leaves it out; the ladder keeps it while this "
                               "line stays.")
                                .arg(index + 1)
                                .arg(model::contactName(target(), all[r].cell(row, col).contact))
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
