#include "ladder_view.h"

#include "monitor_commands.h"

#include "model/target/address.h"
#include "model/target/target_lists.h"

#include <QCompleter>
#include <QKeyEvent>
#include <QLineEdit>
#include <QPainter>
#include <QScrollBar>
#include <QStringListModel>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>

namespace rung::editor {

namespace {

// A contact cell: the contacts and INV / NOT.
bool isContactOp(model::Op op) {
    return model::isContact(op) || op == model::Op::Invert;
}

} // namespace

LadderView::LadderView(Document *document, QWidget *parent)
    : QAbstractScrollArea(parent)
    , m_document(document) {
    setFocusPolicy(Qt::StrongFocus);
    viewport()->setBackgroundRole(QPalette::Base);
    viewport()->setAutoFillBackground(true);
    QPalette pal = viewport()->palette();
    pal.setColor(QPalette::Base, Qt::white);
    viewport()->setPalette(pal);
    setAccessibleName(tr("Ladder diagram"));
    connect(document, &Document::programChanged, this, [this] {
        if (m_anchorRung >= static_cast<int>(m_document->ladder().rungs.size()))
            m_anchorRung = -1;
        relayout();
        // An edit of the rungs shows where it was made; a change of the symbols or the watch
        // lists (a row added to the watch table) leaves the view where the user scrolled it.
        if (m_document->rungsRevision() != m_shownRevision) {
            m_shownRevision = m_document->rungsRevision();
            setCursor(m_cursor);
        }
        m_overlays.clear(); // the rungs the overlays were computed for are gone
        tellWatched();
        viewport()->update();
    });
    m_commands = new MonitorCommands(&document->target(), this);
    connect(m_commands, &MonitorCommands::message, this, &LadderView::message);
    m_editor = new QLineEdit(viewport());
    m_editor->hide();
    m_editor->setObjectName(QStringLiteral("cellEditor"));
    // Completion follows what is typed: mnemonics of the project's target first, then the
    // devices the program and the symbol table use ("LD X" offers "LD X0", "LD X1", ...).
    m_completions = new QStringListModel(this);
    auto *completer = new QCompleter(m_completions, m_editor);
    completer->setCaseSensitivity(Qt::CaseInsensitive);
    completer->setCompletionMode(QCompleter::PopupCompletion);
    m_editor->setCompleter(completer);
    connect(m_editor, &QLineEdit::textEdited, this, &LadderView::updateCompletions);
    // Return commits here (eventFilter): a Return the line edit ignores would reach the view
    // and open the editor again. With the completion list open, the completer hands Return
    // to the line edit itself, which reports it as returnPressed.
    m_editor->installEventFilter(this);
    connect(m_editor, &QLineEdit::returnPressed, this, &LadderView::commitEditor);
    relayout();
}

LadderMetrics LadderView::metrics() const {
    return metricsAt(m_zoom);
}

LadderMetrics LadderView::metricsAt(double zoom) const {
    LadderMetrics m;
    int widest = std::max(1, m_document->target().limits.contactsPerRow);
    for (const model::Rung &r : m_document->ladder().rungs)
        widest = std::max(widest, r.columns);
    m.gridColumns = widest;
    m.foldColumns = std::max(0, m_document->target().limits.contactsPerRow);
    m.zoomTo(zoom);
    return m;
}

void LadderView::relayout() {
    const LadderMetrics m = metrics();
    const auto &rungs = m_document->ladder().rungs;
    m_top.assign(rungs.size() + 1, 0.0);
    double y = 8;
    for (std::size_t i = 0; i < rungs.size(); ++i) {
        m_top[i] = y;
        y += m.rungHeight(rungs[i]);
        if (static_cast<int>(i) == m_cursor.rung)
            y += m.rowHeight; // a spare row under the rung being edited, for new branches
    }
    m_top.back() = y + 40;
    verticalScrollBar()->setRange(0, std::max(0, static_cast<int>(y + 40) - viewport()->height()));
    verticalScrollBar()->setPageStep(viewport()->height());
    verticalScrollBar()->setSingleStep(static_cast<int>(m.rowHeight));
    horizontalScrollBar()->setRange(0,
                                    std::max(0, static_cast<int>(m.width()) - viewport()->width()));
    horizontalScrollBar()->setPageStep(viewport()->width());
}

void LadderView::setZoom(double zoom) {
    setFitWidth(false);
    applyZoom(zoom);
}

void LadderView::applyZoom(double zoom) {
    m_zoom = std::clamp(zoom, 0.4, 3.0);
    relayout();
    viewport()->update();
}

void LadderView::setNamesFirst(bool on) {
    m_namesFirst = on;
    viewport()->update();
}

void LadderView::setRungComment(const QString &comment) {
    const auto &rungs = m_document->ladder().rungs;
    if (m_cursor.rung < 0 || m_cursor.rung >= static_cast<int>(rungs.size()))
        return;
    model::Rung rung = rungs[static_cast<std::size_t>(m_cursor.rung)];
    const QString text = comment.trimmed();
    if (rung.comment == text)
        return;
    rung.comment = text;
    m_document->setRung(m_cursor.rung, rung, tr("Edit rung comment"));
}

void LadderView::setFitWidth(bool on) {
    if (on == m_fitWidth)
        return;
    m_fitWidth = on;
    if (on)
        fitZoomToWidth();
    emit fitWidthChanged(on);
}

void LadderView::fitZoomToWidth() {
    // The drawing's width at 100 %, and what the viewport leaves for it (the zoomed cells
    // round down to whole pixels, so the drawing never comes out wider).
    const double full = metricsAt(1.0).width() - LadderMetrics::kRightMargin;
    const double available = viewport()->width() - LadderMetrics::kRightMargin - 2;
    if (full > 0 && available > 0)
        // Never below readable text (LadderMetrics::fontSizes): a drawing wider than that
        // scrolls sideways instead of shrinking into text nobody can read.
        applyZoom(std::clamp(available / full, LadderMetrics::minReadableZoom(), 1.0));
}

int LadderView::rungAt(double y) const {
    if (m_top.size() < 2)
        return -1;
    const auto it = std::upper_bound(m_top.begin(), m_top.end() - 1, y);
    return std::clamp(static_cast<int>(it - m_top.begin()) - 1, 0,
                      static_cast<int>(m_top.size()) - 2);
}

model::Rung LadderView::currentRung() const {
    const auto &rungs = m_document->ladder().rungs;
    if (m_cursor.rung < 0 || m_cursor.rung >= static_cast<int>(rungs.size()))
        return model::Rung(1, 1);
    return rungs[static_cast<std::size_t>(m_cursor.rung)];
}

void LadderView::setCursor(const CellCursor &cursor) {
    const auto &rungs = m_document->ladder().rungs;
    CellCursor c = cursor;
    const LadderMetrics m = metrics();
    c.rung = std::clamp(c.rung, 0, std::max(0, static_cast<int>(rungs.size()) - 1));
    const int rows = rungs.empty() ? 1 : rungs[static_cast<std::size_t>(c.rung)].rows;
    c.row = std::clamp(c.row, 0, rows); // rows: the spare row
    c.column = std::clamp(c.column, 0, m.gridColumns);
    const bool rungChanged = c.rung != m_cursor.rung;
    const bool changed = !(c == m_cursor);
    m_cursor = c;
    if (rungChanged)
        relayout();
    ensureCursorVisible();
    viewport()->update();
    if (changed)
        emit cursorMoved(m_cursor);
}

QRect LadderView::cellRectOnScreen(const CellCursor &cell) const {
    const auto &rungs = m_document->ladder().rungs;
    if (cell.rung < 0 || cell.rung >= static_cast<int>(rungs.size()))
        return {};
    const LadderMetrics m = metrics();
    LadderPainter painter(m_document->project(), m);
    const QRectF r =
        painter.cellRect(rungs[static_cast<std::size_t>(cell.rung)], cell.row, cell.column)
            .translated(-horizontalScrollBar()->value(),
                        m_top[static_cast<std::size_t>(cell.rung)] * 1.0 -
                            verticalScrollBar()->value());
    return r.toAlignedRect();
}

void LadderView::ensureCursorVisible() {
    if (m_top.empty() || m_cursor.rung >= static_cast<int>(m_top.size()) - 1)
        return;
    const QRect r = cellRectOnScreen(m_cursor);
    if (r.top() < 0)
        verticalScrollBar()->setValue(verticalScrollBar()->value() + r.top() - 8);
    else if (r.bottom() > viewport()->height())
        verticalScrollBar()->setValue(verticalScrollBar()->value() + r.bottom() -
                                      viewport()->height() + 8);
    if (r.left() < 0)
        horizontalScrollBar()->setValue(horizontalScrollBar()->value() + r.left() - 8);
    else if (r.right() > viewport()->width())
        horizontalScrollBar()->setValue(horizontalScrollBar()->value() + r.right() -
                                        viewport()->width() + 8);
}

void LadderView::paintEvent(QPaintEvent *) {
    QPainter p(viewport());
    const LadderMetrics m = metrics();
    LadderPainter painter(m_document->project(), m);
    painter.setNamesFirst(m_namesFirst);
    const auto &rungs = m_document->ladder().rungs;
    const double top = verticalScrollBar()->value();
    const double bottom = top + viewport()->height();
    const auto &listing = m_document->listing();
    // Only the visible rungs are painted: a 10,000-rung program scrolls as fast as a small one.
    // Their findings are gathered in one pass over the diagnostics.
    const int firstVisible = std::max(0, rungAt(top));
    // The overlay of each rung on screen, computed here for a rung snapshotArrived has not
    // seen (scrolled into view since).
    std::optional<model::ProgramFlow> flow;
    if (!m_source || (m_shown && &m_shown->layout->target() != &m_document->target()))
        m_shown.reset();
    std::multimap<int, const model::Diagnostic *> findings;
    for (const model::Diagnostic &diag : m_document->diagnostics()) {
        const int rung = diag.location.rung;
        if (rung >= firstVisible && rung < static_cast<int>(rungs.size()) &&
            m_top[static_cast<std::size_t>(rung)] <= bottom)
            findings.emplace(rung, &diag);
    }
    for (int i = firstVisible; i < static_cast<int>(rungs.size()); ++i) {
        const double y = m_top[static_cast<std::size_t>(i)];
        if (y > bottom)
            break;
        RungDecorations d;
        if (i == m_cursor.rung) {
            d.cursorRow = m_cursor.row;
            d.cursorColumn = m_cursor.column;
            if (const CellRun run = selectedCells(); run.valid())
                for (int c = run.first; c <= run.last; ++c)
                    d.selected.insert({run.row, c});
        }
        if (m_anchorRung >= 0 && i >= selectedRungs().first &&
            i < selectedRungs().first + selectedRungs().second)
            p.fillRect(QRectF(0, y - top, viewport()->width(),
                              m.rungHeight(rungs[static_cast<std::size_t>(i)]) - m.rungGap / 2),
                       QColor(0xe3, 0xee, 0xfb));
        if (static_cast<std::size_t>(i) + 1 < listing.rungFirst.size()) {
            const int first = listing.rungFirst[static_cast<std::size_t>(i)];
            if (first < static_cast<int>(listing.list.instructions.size()) &&
                first < listing.rungFirst[static_cast<std::size_t>(i) + 1])
                d.firstStep = listing.list.instructions[static_cast<std::size_t>(first)].step;
        }
        if (const auto b = m_breakpoints.find(i); b != m_breakpoints.end())
            d.breakpoint = b->second ? RungDecorations::Breakpoint::Conditional
                                     : RungDecorations::Breakpoint::Plain;
        if (m_stoppedAt.rung == i) {
            d.stopped = true;
            d.stoppedAt = {m_stoppedAt.row, m_stoppedAt.column};
        }
        for (auto [at, end] = findings.equal_range(i); at != end; ++at) {
            const model::Diagnostic &diag = *at->second;
            if (diag.severity == model::Severity::Error)
                d.hasError = true;
            else if (diag.severity == model::Severity::Warning)
                d.hasWarning = true;
            if (diag.code == QLatin1String("RC001"))
                for (const model::Location &l : diag.related)
                    d.marked.insert({l.row, l.cell});
        }
        if (m_shown) {
            auto it = m_overlays.find(i);
            if (it == m_overlays.end()) {
                if (!flow)
                    flow.emplace(m_document->ladder(), listing, *m_shown);
                it = m_overlays.emplace(i, flow->rung(i, staleValues())).first;
            }
            d.overlay = &it->second;
        }
        painter.paintRung(p, QPointF(-horizontalScrollBar()->value(), y - top), i, d);
    }
}

void LadderView::setBreakpointRungs(const std::map<int, bool> &rungs) {
    if (rungs == m_breakpoints)
        return;
    m_breakpoints = rungs;
    viewport()->update();
}

void LadderView::setStoppedAt(const CellCursor &at) {
    if (at == m_stoppedAt)
        return;
    m_stoppedAt = at;
    if (at.rung >= 0 && at.rung < static_cast<int>(m_top.size()) - 1) {
        // Bring the stopped rung into view, as a debugger shows the current line, and the
        // element it stops before (an output may stand right of a narrow view).
        const double top = m_top[static_cast<std::size_t>(at.rung)];
        const double bottom = m_top[static_cast<std::size_t>(at.rung) + 1];
        const int view = verticalScrollBar()->value();
        if (top < view || bottom > view + viewport()->height())
            verticalScrollBar()->setValue(static_cast<int>(top));
        if (at.row >= 0) {
            const QRect cell = cellRectOnScreen({at.rung, at.row, at.column});
            if (cell.right() > viewport()->width() || cell.left() < 0)
                horizontalScrollBar()->setValue(horizontalScrollBar()->value() + cell.left() -
                                                std::max(0, viewport()->width() - cell.width()) /
                                                    2);
        } else {
            horizontalScrollBar()->setValue(0);
        }
    }
    viewport()->update();
}

QString LadderView::mnemonicFor(model::Op op, model::ContactMode mode) const {
    const model::InstructionSpec *s = m_document->target().findInstruction(op, mode);
    return s ? s->mnemonic : QString();
}

bool LadderView::enterInstruction(const QString &text, QString *error) {
    const model::Target &t = m_document->target();
    const model::ParseResult parsed =
        model::parseInstructionList(t, text, m_document->modelVariant());
    auto fail = [&](const QString &why) {
        if (error)
            *error = why;
        emit message(why);
        return false;
    };
    if (!parsed.ok())
        return fail(parsed.errors.front().message);
    if (parsed.list.instructions.size() != 1)
        return fail(
            tr("Type one instruction, for example \"%1 %2\"")
                .arg(mnemonicFor(model::Op::Load), model::exampleDevice(m_document->target())));
    model::Instruction ins = parsed.list.instructions.front();
    ins.line = ins.column = ins.step = 0;
    const model::Op op = ins.op();
    const LadderMetrics m = metrics();
    model::Rung rung = currentRung();
    int rungIndex = m_cursor.rung;
    bool insertBefore = false;
    // Typing on the END rung adds a rung in front of it: END stays last.
    const bool onEnd = rung.outputs[0] && model::isUnconditional(rung.outputs[0]->op()) &&
                       rung.columns == 0 && !model::isUnconditional(op);
    if (onEnd) {
        rung = model::Rung(1, 1);
        insertBefore = true;
    }
    if (model::joinsBlocks(op) || model::isStackOp(op))
        return fail(
            tr("%1 is drawn with vertical links, not typed into a cell").arg(ins.spec->mnemonic));
    QString label;
    if (isContactOp(op)) {
        if (m_cursor.column >= m.gridColumns)
            return fail(tr("Contacts go in the grid; the right-hand column holds coils and boxes"));
        const int row = insertBefore ? 0 : m_cursor.row;
        rung.resize(std::max(rung.rows, row + 1), std::max(rung.columns, m_cursor.column + 1));
        model::Cell &cell = rung.cell(row, m_cursor.column);
        cell.kind = model::CellKind::Contact;
        cell.contact = model::Contact{};
        cell.contact.invert = op == model::Op::Invert;
        if (!cell.contact.invert) {
            cell.contact.mode = ins.spec->mode;
            cell.contact.compare = ins.spec->compare;
            cell.contact.operands = ins.operands;
        }
        // OR (ORI, ORP, ...) below the first row: in parallel with the cell above, linked to
        // its row at the contact's right node and, away from the rail, at its left node.
        if (op == model::Op::Or && row > 0) {
            rung.setLink(row - 1, m_cursor.column + 1, true);
            if (m_cursor.column > 0)
                rung.setLink(row - 1, m_cursor.column, true);
        }
        // The first row is the main circuit: a gap on it from the rail becomes a wire.
        if (row == 0)
            for (int c = 0; c < m_cursor.column; ++c)
                if (rung.cell(0, c).kind == model::CellKind::Empty)
                    rung.cell(0, c).kind = model::CellKind::Wire;
        label = tr("Place %1").arg(model::printInstruction(t, ins));
    } else {
        const int row = insertBefore ? 0 : m_cursor.row;
        rung.resize(std::max(rung.rows, row + 1), rung.columns);
        rung.outputs[static_cast<std::size_t>(row)] = ins;
        // Wire the row from its last element to the output column.
        int last = -1;
        for (int c = 0; c < rung.columns; ++c)
            if (rung.cell(row, c).kind != model::CellKind::Empty)
                last = c;
        if (last >= 0 || row == 0)
            for (int c = last + 1; c < rung.columns; ++c)
                rung.cell(row, c).kind = model::CellKind::Wire;
        label = tr("Place %1").arg(model::printInstruction(t, ins));
    }
    if (insertBefore)
        m_document->replaceRungs(rungIndex, 0, {rung}, label);
    else
        m_document->setRung(rungIndex, rung, label);
    CellCursor next = m_cursor;
    if (isContactOp(op))
        next.column = std::min(m_cursor.column + 1, m.gridColumns);
    if (insertBefore)
        next.row = 0;
    setCursor(next);
    return true;
}

void LadderView::placeWire() {
    const LadderMetrics m = metrics();
    if (m_cursor.column >= m.gridColumns)
        return;
    model::Rung rung = currentRung();
    rung.resize(std::max(rung.rows, m_cursor.row + 1), std::max(rung.columns, m_cursor.column + 1));
    rung.cell(m_cursor.row, m_cursor.column) = model::Cell{model::CellKind::Wire, {}};
    m_document->setRung(m_cursor.rung, rung, tr("Draw a wire"));
    setCursor({m_cursor.rung, m_cursor.row, m_cursor.column + 1});
}

void LadderView::toggleLink() {
    const LadderMetrics m = metrics();
    model::Rung rung = currentRung();
    const int node =
        m_cursor.column >= m.gridColumns ? rung.columns : std::min(m_cursor.column, rung.columns);
    rung.resize(std::max(rung.rows, m_cursor.row + 2), rung.columns);
    rung.setLink(m_cursor.row, node, !rung.link(m_cursor.row, node));
    m_document->setRung(m_cursor.rung, rung, tr("Toggle a vertical link"));
}

void LadderView::clearCell() {
    const LadderMetrics m = metrics();
    model::Rung rung = currentRung();
    if (m_cursor.row >= rung.rows)
        return;
    if (m_cursor.column >= m.gridColumns) {
        if (!rung.outputs[static_cast<std::size_t>(m_cursor.row)])
            return;
        rung.outputs[static_cast<std::size_t>(m_cursor.row)].reset();
    } else {
        if (m_cursor.column >= rung.columns ||
            rung.cell(m_cursor.row, m_cursor.column).kind == model::CellKind::Empty)
            return;
        rung.cell(m_cursor.row, m_cursor.column) = model::Cell{};
    }
    m_document->setRung(m_cursor.rung, rung, tr("Delete"));
}

void LadderView::insertColumn() {
    model::Rung rung = currentRung();
    if (m_cursor.column > rung.columns)
        return;
    rung.insertColumn(m_cursor.column);
    m_document->setRung(m_cursor.rung, rung, tr("Insert a cell"));
}

void LadderView::insertRow() {
    model::Rung rung = currentRung();
    rung.insertRow(std::min(m_cursor.row, rung.rows));
    m_document->setRung(m_cursor.rung, rung, tr("Insert a row"));
}

void LadderView::deleteRow() {
    model::Rung rung = currentRung();
    if (rung.rows <= 1 || m_cursor.row >= rung.rows)
        return;
    rung.removeRow(m_cursor.row);
    m_document->setRung(m_cursor.rung, rung, tr("Delete a row"));
}

void LadderView::insertRung() {
    m_document->insertRung(m_cursor.rung, model::Rung(1, 1));
    setCursor({m_cursor.rung, 0, 0});
}

void LadderView::deleteRung() {
    if (m_document->ladder().rungs.empty())
        return;
    const auto [first, count] = selectedRungs();
    clearSelection();
    m_document->removeRungs(first, count);
}

int LadderView::lastColumn(int rung) const {
    const LadderMetrics m = metrics();
    const auto &rungs = m_document->ladder().rungs;
    if (rung < 0 || rung >= static_cast<int>(rungs.size()) || m.foldColumns <= 0)
        return m.gridColumns - 1;
    return std::min(m.gridColumns,
                    m.blocks(rungs[static_cast<std::size_t>(rung)]) * m.shownColumns()) -
           1;
}

void LadderView::openEditor(const QString &initial) {
    const QRect r = cellRectOnScreen(m_cursor);
    m_editor->setGeometry(r.left(), r.top() + r.height() / 4, std::max(r.width() * 2, 180),
                          r.height() / 2);
    m_editor->setText(initial);
    updateCompletions(initial);
    m_editor->setStyleSheet(QString());
    m_editor->show();
    m_editor->setFocus();
}

void LadderView::commitEditor() {
    QString error;
    if (enterInstruction(m_editor->text(), &error)) {
        m_editor->hide();
        setFocus();
    } else {
        m_editor->setStyleSheet(QStringLiteral("border: 2px solid #d93f3f;"));
        m_editor->setToolTip(error);
    }
}

void LadderView::resizeEvent(QResizeEvent *event) {
    QAbstractScrollArea::resizeEvent(event);
    placeNotice();
    if (m_fitWidth)
        fitZoomToWidth();
    else
        relayout();
    tellWatched();
}

void LadderView::changeEvent(QEvent *event) {
    if (event->type() == QEvent::LanguageChange)
        setAccessibleName(tr("Ladder diagram"));
    QAbstractScrollArea::changeEvent(event);
}

} // namespace rung::editor
