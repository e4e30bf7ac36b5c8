// The instruction list's live values: after each line of the running program, the logic
// result after its instruction and its devices' values, painted over Scintilla's drawing (the
// text, its styles and its undo stay as they are: QScintilla 2.13 has no end-of-line
// annotations, and inline annotations would push the lines apart). Each snapshot repaints
// only the lines on screen whose values changed. The context menu forces and writes the
// line's devices.

#include "il_editor.h"

#include "ladder_painter.h"
#include "model/image/power_flow.h"
#include "monitor_commands.h"

#include "model/target/address.h"

#include <QContextMenuEvent>
#include <QMenu>
#include <QPainter>

#include <algorithm>

namespace rung::editor {

namespace {

// Values start at this text column at least, so that short lines line up like a table.
constexpr int kValuesColumn = 22;

bool isDevice(const model::Operand &o) {
    return o.kind == model::Operand::Kind::Device && o.address.valid();
}

} // namespace

void IlEditor::setMonitorSource(model::MonitorSource *source) {
    if (!model::MonitorSource::switchSource(m_source, source, this))
        return;
    m_commands->setTarget(m_target);
    m_commands->setSource(source);
    m_painted.clear();
    if (source) {
        connect(source, &model::MonitorSource::snapshotChanged, this, &IlEditor::snapshotArrived);
        connect(source, &model::MonitorSource::runStateChanged, this, [this] {
            m_painted.clear();
            viewport()->update();
        });
    }
    viewport()->update();
}

void IlEditor::setMonitorLines(
    std::vector<int> instructionOfLine,
    std::shared_ptr<const std::vector<model::Instruction>> instructions) {
    m_lineInstruction = std::move(instructionOfLine);
    m_instructions = std::move(instructions);
    m_painted.clear();
    if (m_source)
        viewport()->update();
}

const model::Instruction *IlEditor::monitoredInstruction(int index) const {
    if (!m_instructions || index < 0 || static_cast<std::size_t>(index) >= m_instructions->size())
        return nullptr;
    return &(*m_instructions)[static_cast<std::size_t>(index)];
}

std::optional<IlEditor::LineValue> IlEditor::monitoredLine(int line) const {
    const std::shared_ptr<const model::Snapshot> s = m_source ? m_source->snapshot() : nullptr;
    if (!s || !s->layout || &s->layout->target() != m_target || line < 0 ||
        static_cast<std::size_t>(line) >= m_lineInstruction.size())
        return std::nullopt;
    const int index = m_lineInstruction[static_cast<std::size_t>(line)];
    const model::Instruction *found = monitoredInstruction(index);
    if (!found)
        return std::nullopt;
    const model::Instruction &ins = *found;
    LineValue v;
    if (s->powerFlow.size() == m_instructions->size())
        v.result = s->powerFlow[static_cast<std::size_t>(index)];
    QStringList parts;
    const model::Op op = ins.op();
    const bool asBit = model::isContact(op) || op == model::Op::Out || op == model::Op::Set ||
                       op == model::Op::Reset || op == model::Op::PulseRise ||
                       op == model::Op::PulseFall;
    for (std::size_t k = 0; k < ins.operands.size(); ++k) {
        const model::Operand &o = ins.operands[k];
        if (!isDevice(o))
            continue;
        if (s->forced(o.address))
            v.forced = true;
        const QString name = model::formatAddress(*m_target, o.address);
        if (k == 0 && op == model::Op::Timer)
            parts << QStringLiteral("%1 %2").arg(name,
                                                 model::ProgramFlow::timerText(*m_target, ins, *s));
        else if (k == 0 && (op == model::Op::Counter || op == model::Op::UpDownCounter))
            parts << QStringLiteral("%1 %2").arg(
                name, model::ProgramFlow::counterText(*m_target, ins, *s));
        else if (asBit && s->layout->bit(o.address).valid())
            // A contact or coil of a timer or counter is its done bit.
            parts << QStringLiteral("%1 = %2").arg(name,
                                                   model::ProgramFlow::bitText(s->bit(o.address)));
        else
            parts << QStringLiteral("%1 = %2").arg(name,
                                                   model::ProgramFlow::wordText(*s, o.address));
    }
    v.text = parts.join(QStringLiteral("  "));
    return v;
}

std::pair<int, int> IlEditor::visibleLines() const {
    const int firstVisible = static_cast<int>(SendScintilla(SCI_GETFIRSTVISIBLELINE));
    const int first =
        static_cast<int>(SendScintilla(SCI_DOCLINEFROMVISIBLE, static_cast<long>(firstVisible)));
    int last = first;
    const int height = viewport()->height();
    while (last < lines()) {
        const long pos = SendScintilla(SCI_POSITIONFROMLINE, static_cast<long>(last));
        const int y = static_cast<int>(SendScintilla(SCI_POINTYFROMPOSITION, 0UL, pos));
        if (y > height)
            break;
        ++last;
    }
    return {first, last};
}

int IlEditor::valuesX() const {
    // The text's left edge (after the margins, scrolled) plus the column's width in the
    // default style's characters.
    const long start = SendScintilla(SCI_POSITIONFROMLINE, 0UL);
    const int left = static_cast<int>(SendScintilla(SCI_POINTXFROMPOSITION, 0UL, start));
    const QByteArray column(kValuesColumn, '0');
    const int width = static_cast<int>(
        SendScintilla(SCI_TEXTWIDTH, static_cast<uintptr_t>(IlLexer::Default), column.constData()));
    return left + width;
}

QRect IlEditor::valueRect(int line) const {
    const long end = SendScintilla(SCI_GETLINEENDPOSITION, static_cast<unsigned long>(line));
    const long begin = SendScintilla(SCI_POSITIONFROMLINE, static_cast<unsigned long>(line));
    const int endX = static_cast<int>(SendScintilla(SCI_POINTXFROMPOSITION, 0UL, end));
    const int top = static_cast<int>(SendScintilla(SCI_POINTYFROMPOSITION, 0UL, begin));
    const int height =
        static_cast<int>(SendScintilla(SCI_TEXTHEIGHT, static_cast<unsigned long>(line)));
    const QByteArray gap("00");
    const int gapWidth = static_cast<int>(
        SendScintilla(SCI_TEXTWIDTH, static_cast<uintptr_t>(IlLexer::Default), gap.constData()));
    const int x = std::max(endX + gapWidth, valuesX());
    return QRect(x, top, std::max(0, viewport()->width() - x), height);
}

void IlEditor::snapshotArrived() {
    const auto [first, last] = visibleLines();
    std::erase_if(m_painted, [first = first, last = last](const auto &entry) {
        return entry.first < first || entry.first >= last;
    });
    for (int line = first; line < last; ++line) {
        const std::optional<LineValue> v = monitoredLine(line);
        const auto it = m_painted.find(line);
        const bool same = v ? (it != m_painted.end() && it->second == *v) : it == m_painted.end();
        if (same)
            continue; // unchanged: not repainted
        if (v)
            m_painted[line] = *v;
        else if (it != m_painted.end())
            m_painted.erase(it);
        viewport()->update(valueRect(line));
    }
}

void IlEditor::paintEvent(QPaintEvent *event) {
    QsciScintilla::paintEvent(event);
    if (m_source && !m_lineInstruction.empty())
        paintValues();
}

void IlEditor::paintValues() {
    QPainter p(viewport());
    p.setRenderHint(QPainter::Antialiasing, true);
    QFont font = m_lexer ? m_lexer->defaultFont(IlLexer::Default) : this->font();
    font.setBold(false);
    p.setFont(font);
    const QFontMetrics fm(font);
    const bool stale = m_source->runState() == model::MonitorSource::RunState::Offline;
    const QColor live = stale ? LadderPainter::staleColor() : LadderPainter::energisedColor();
    const auto [first, last] = visibleLines();
    for (int line = first; line < last; ++line) {
        const std::optional<LineValue> v = monitoredLine(line);
        if (!v)
            continue;
        m_painted[line] = *v;
        const QRect r = valueRect(line);
        if (r.width() <= 0)
            continue;
        // The result: a square, filled for ON, hollow for OFF; none while it is unknown.
        const int size = std::max(6, fm.ascent() - 3);
        const QRectF mark(r.left(), r.center().y() - size / 2.0, size, size);
        int x = r.left();
        if (v->result) {
            p.setPen(QPen(*v->result ? live : LadderPainter::staleColor(), 1.5));
            p.setBrush(*v->result ? QBrush(live, stale ? Qt::BDiagPattern : Qt::SolidPattern)
                                  : QBrush(Qt::white));
            p.drawRect(mark);
            x += size + fm.averageCharWidth();
        }
        if (v->forced) {
            const QRectF badge(x, mark.top(), size + 2, size);
            p.fillRect(badge, stale ? LadderPainter::staleColor() : LadderPainter::forcedColor());
            p.setPen(Qt::white);
            QFont bold = font;
            bold.setBold(true);
            bold.setPixelSize(std::max(6, size - 1));
            p.setFont(bold);
            p.drawText(badge, Qt::AlignCenter, QStringLiteral("F"));
            p.setFont(font);
            x += size + 2 + fm.averageCharWidth();
        }
        p.setPen(stale ? LadderPainter::staleColor() : QColor(0x3b, 0x4a, 0x5a));
        p.drawText(QRect(x, r.top(), r.right() - x, r.height()), Qt::AlignLeft | Qt::AlignVCenter,
                   fm.elidedText(v->text, Qt::ElideRight, std::max(0, r.right() - x)));
    }
}

QMenu *IlEditor::monitorMenu(int line, QWidget *parent) {
    if (line < 0 || static_cast<std::size_t>(line) >= m_lineInstruction.size())
        return nullptr;
    const model::Instruction *ins =
        monitoredInstruction(m_lineInstruction[static_cast<std::size_t>(line)]);
    if (!ins)
        return nullptr;
    m_commands->setTarget(m_target);
    auto *menu = new QMenu(parent);
    menu->setObjectName(QStringLiteral("monitorMenu"));
    if (!m_commands->addActions(menu, monitorTargets(*m_target, *ins))) {
        delete menu;
        return nullptr;
    }
    return menu;
}

void IlEditor::showMonitorMenu(int line, QPoint globalPos) {
    // The list's own entries (undo, cut, copy...) with the line's device commands below.
    QMenu *menu = createStandardContextMenu();
    if (!menu)
        return;
    menu->setAttribute(Qt::WA_DeleteOnClose);
    if (QMenu *devices = monitorMenu(line, menu)) {
        menu->addSeparator();
        for (QAction *a : devices->actions()) {
            a->setParent(menu);
            menu->addAction(a);
        }
        menu->setToolTipsVisible(true);
    }
    menu->popup(globalPos);
}

void IlEditor::contextMenuEvent(QContextMenuEvent *event) {
    int line = 0;
    int index = 0;
    getCursorPosition(&line, &index);
    if (event->reason() == QContextMenuEvent::Mouse) {
        const QPoint at = viewport()->mapFromGlobal(event->globalPos());
        const long pos = SendScintilla(SCI_POSITIONFROMPOINT, static_cast<unsigned long>(at.x()),
                                       static_cast<long>(at.y()));
        line =
            static_cast<int>(SendScintilla(SCI_LINEFROMPOSITION, static_cast<unsigned long>(pos)));
    }
    QPoint global = event->globalPos();
    if (event->reason() != QContextMenuEvent::Mouse)
        global = viewport()->mapToGlobal(valueRect(line).topLeft());
    showMonitorMenu(line, global);
}

void IlEditor::keyPressEvent(QKeyEvent *event) {
    // Shift+F10 opens the context menu at the caret, as on Windows (the Menu key does too).
    if (event->key() == Qt::Key_Menu ||
        (event->key() == Qt::Key_F10 && event->modifiers() == Qt::ShiftModifier)) {
        int line = 0;
        int index = 0;
        getCursorPosition(&line, &index);
        showMonitorMenu(line, viewport()->mapToGlobal(valueRect(line).topLeft()));
        return;
    }
    QsciScintilla::keyPressEvent(event);
}

} // namespace rung::editor
