#include "il_editor.h"

#include "document.h"
#include "monitor_commands.h"

#include "model/target/address.h"

#include <Qsci/qsciapis.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <optional>

#include <QCoreApplication>
#include <QRegularExpression>
#include <QResizeEvent>

namespace rung::editor {

namespace {

constexpr int kErrorMarker = 1;
constexpr int kWarningMarker = 2;
// Simulation: a breakpoint (a conditional one), the line a stopped scan is at (an arrow in
// the margin and the line's background).
constexpr int kBreakpointMarker = 3;
constexpr int kConditionalMarker = 4;
constexpr int kStoppedMarker = 5;
constexpr int kStoppedLineMarker = 6;
constexpr int kDeviceList = 1;

bool isNumber(const QString &word) {
    return !word.isEmpty() &&
           std::all_of(word.begin(), word.end(), [](QChar c) { return c.isDigit(); });
}

// The line up to the caret split into the finished words (a leading step number dropped)
// and the word being typed; nullopt inside a comment.
struct Typing {
    QStringList before;
    QString word;
};
std::optional<Typing> typingAt(const QString &lineToCaret) {
    if (lineToCaret.contains(QLatin1Char(';')) || lineToCaret.contains(QLatin1String("//")))
        return std::nullopt;
    Typing t;
    const qsizetype lastSpace = lineToCaret.lastIndexOf(QRegularExpression(QStringLiteral("\\s")));
    t.word = lineToCaret.mid(lastSpace + 1);
    t.before =
        lineToCaret.left(std::max<qsizetype>(lastSpace, 0)).simplified().split(QLatin1Char(' '));
    t.before.removeAll(QString());
    if (!t.before.isEmpty() && isNumber(t.before.front()))
        t.before.removeFirst(); // a step number, as the VPC console shows it
    return t;
}

} // namespace

IlEditor::IlEditor(const model::Target &target, QWidget *parent)
    : QsciScintilla(parent)
    , m_target(&target) {
    setUtf8(true);
    setMarginType(0, QsciScintilla::NumberMargin);
    setMarginWidth(0, QStringLiteral("00000"));
    setMarginType(1, QsciScintilla::SymbolMargin);
    setMarginWidth(1, 14);
    setMarginMarkerMask(1, (1 << kErrorMarker) | (1 << kWarningMarker) | (1 << kBreakpointMarker) |
                               (1 << kConditionalMarker) | (1 << kStoppedMarker));
    // A click in this margin sets or clears a breakpoint on the line (as in CODESYS).
    setMarginSensitivity(1, true);
    connect(this, &QsciScintilla::marginClicked, this,
            [this](int margin, int line, Qt::KeyboardModifiers) {
                if (margin == 1)
                    emit breakpointToggleRequested(line + 1);
            });
    markerDefine(QsciScintilla::Circle, kBreakpointMarker);
    setMarkerBackgroundColor(QColor(0xc6, 0x28, 0x28), kBreakpointMarker);
    setMarkerForegroundColor(QColor(0xc6, 0x28, 0x28), kBreakpointMarker);
    markerDefine(QsciScintilla::CircledPlus, kConditionalMarker);
    setMarkerBackgroundColor(QColor(0xc6, 0x28, 0x28), kConditionalMarker);
    setMarkerForegroundColor(Qt::white, kConditionalMarker);
    markerDefine(QsciScintilla::RightArrow, kStoppedMarker);
    setMarkerBackgroundColor(QColor(0xe6, 0x8a, 0x00), kStoppedMarker);
    setMarkerForegroundColor(QColor(0x80, 0x4c, 0x00), kStoppedMarker);
    markerDefine(QsciScintilla::Background, kStoppedLineMarker);
    setMarkerBackgroundColor(QColor(0xff, 0xe8, 0xb0), kStoppedLineMarker);
    markerDefine(QsciScintilla::Circle, kErrorMarker);
    setMarkerBackgroundColor(QColor(0xd9, 0x3f, 0x3f), kErrorMarker);
    markerDefine(QsciScintilla::Circle, kWarningMarker);
    setMarkerBackgroundColor(QColor(0xe0, 0x9b, 0x1a), kWarningMarker);
    setMarginType(2, QsciScintilla::TextMargin);
    setMarginWidth(2, QStringLiteral("00000 "));
    setAnnotationDisplay(QsciScintilla::AnnotationBoxed);
    setCaretLineVisible(true);
    setCaretLineBackgroundColor(QColor(0xf1, 0xf5, 0xfb));
    // Completion opens from showCompletions(): mnemonics from the target's table at the start
    // of a line, the project's devices after a mnemonic (Scintilla alone would offer
    // mnemonics for operands too).
    setAutoCompletionSource(QsciScintilla::AcsAPIs);
    setAutoCompletionThreshold(-1);
    setAutoCompletionCaseSensitivity(false);
    setCallTipsStyle(QsciScintilla::CallTipsNoContext);
    setAccessibleName(tr("Instruction list"));
    m_commands = new MonitorCommands(&target, this);
    connect(m_commands, &MonitorCommands::message, this, &IlEditor::message);
    setTarget(target);
    connect(this, &QsciScintilla::textChanged, this, [this] {
        // The lines no longer hold the instructions they held: no values until the owner
        // maps them again (setMonitorLines).
        if (!m_lineInstruction.empty()) {
            m_lineInstruction.clear();
            m_painted.clear();
            viewport()->update();
        }
        if (!m_settingText)
            emit listingEdited();
    });
    connect(this, &QsciScintilla::cursorPositionChanged, this, [this] { updateCallTip(); });
    // A space after a mnemonic shows its operand form at the caret, as a call tip.
    connect(this, &QsciScintillaBase::SCN_CHARADDED, this, [this](int ch) {
        if (ch == ' ')
            showOperandTip();
        else if (ch < 128 && (std::isalnum(ch) || ch == '.' || ch == '_'))
            showCompletions();
    });
    connect(this, &QsciScintilla::userListActivated, this, &IlEditor::insertDevice);
}

void IlEditor::showCompletions() {
    int line = 0;
    int index = 0;
    getCursorPosition(&line, &index);
    const auto typing = typingAt(text(line).left(index));
    if (!typing || typing->word.isEmpty() || isNumber(typing->word)) {
        if (isListActive())
            cancelList();
        return;
    }
    if (typing->before.isEmpty()) {
        autoCompleteFromAPIs();
        return;
    }
    QStringList items;
    // The second word of a two-word mnemonic ("LD NOT") is typed where an operand would be.
    for (const model::InstructionSpec &s : m_target->instructions) {
        if (s.mnemonic.count(QLatin1Char(' ')) == 1 &&
            s.mnemonic.section(QLatin1Char(' '), 0, 0) == typing->before.join(QLatin1Char(' ')) &&
            s.mnemonic.section(QLatin1Char(' '), 1).startsWith(typing->word, Qt::CaseInsensitive))
            items << s.mnemonic.section(QLatin1Char(' '), 1);
    }
    if (m_devices) {
        for (const QString &item : m_devices())
            if (item.startsWith(typing->word, Qt::CaseInsensitive))
                items << item;
    }
    // A device typed in full with nothing longer to offer needs no list: Return then ends
    // the line instead of taking the same device again.
    if (items.isEmpty() ||
        (items.size() == 1 &&
         items.front().section(QLatin1Char(' '), 0, 0).compare(typing->word, Qt::CaseInsensitive) ==
             0)) {
        if (isListActive())
            cancelList();
        return;
    }
    if (isListActive())
        cancelList();
    showUserList(kDeviceList, items);
}

void IlEditor::insertDevice(int id, const QString &item) {
    if (id != kDeviceList)
        return;
    int line = 0;
    int index = 0;
    getCursorPosition(&line, &index);
    const auto typing = typingAt(text(line).left(index));
    if (!typing)
        return;
    const int start = index - static_cast<int>(typing->word.size());
    setSelection(line, start, line, index);
    replaceSelectedText(item.section(QLatin1Char(' '), 0, 0));
}

void IlEditor::showOperandTip() {
    int line = 0;
    int index = 0;
    getCursorPosition(&line, &index);
    // The words before the caret: an optional step number, then the mnemonic (maybe two
    // words, "LD NOT"); the tip shows only while no operand has been typed yet.
    const auto typing = typingAt(text(line).left(index));
    if (!typing || !typing->word.isEmpty())
        return;
    const QStringList &words = typing->before;
    const model::InstructionSpec *s = words.isEmpty() ? nullptr
                                      : words.size() == 2
                                          ? m_target->findInstruction(words.join(QLatin1Char(' ')))
                                          : m_target->findInstruction(words.front());
    if (!s || words.size() > 2 || !s->operandHelp)
        return;
    const QString tip =
        QStringLiteral("%1 %2").arg(s->mnemonic, QString::fromLatin1(s->operandHelp));
    const QByteArray utf8 = tip.toUtf8();
    SendScintilla(SCI_CALLTIPSHOW, SendScintilla(SCI_GETCURRENTPOS), utf8.constData());
}

bool IlEditor::operandTipShown() {
    return SendScintilla(SCI_CALLTIPACTIVE) != 0;
}

void IlEditor::setTarget(const model::Target &target) {
    if (m_lexer && m_target == &target)
        return; // a new lexer restyles the whole text
    m_target = &target;
    if (m_commands)
        m_commands->setTarget(&target);
    auto *lexer = new IlLexer(target, this);
    auto *apis = new QsciAPIs(lexer);
    for (const model::InstructionSpec &s : target.instructions) {
        // "TMR(T0..T255 K1..K32767) On-delay timer" as the completion and the call tip.
        const QString help = s.operandHelp ? QString::fromLatin1(s.operandHelp) : QString();
        const QString summary =
            s.summary ? QCoreApplication::translate("rung::model::Target", s.summary) : QString();
        apis->add(QStringLiteral("%1(%2) %3")
                      .arg(s.mnemonic.section(QLatin1Char(' '), 0, 0), help, summary));
    }
    apis->prepare();
    setLexer(lexer);
    // The margins in a small grey font: the line numbers and step addresses stay quieter
    // than the program (a lexer resets the margins' font).
    QFont margins = lexer->defaultFont(IlLexer::StepNumber);
    margins.setPointSize(std::max(7, margins.pointSize() - 2));
    setMarginsFont(margins);
    setMarginsForegroundColor(lexer->defaultColor(IlLexer::StepNumber));
    setMarginsBackgroundColor(QColor(0xf4, 0xf5, 0xf7));
    setMarginWidth(0, QStringLiteral("0000"));
    setMarginWidth(2, QStringLiteral("00000 "));
    if (m_lexer)
        m_lexer->deleteLater();
    m_lexer = lexer;
}

void IlEditor::setListing(const QString &text) {
    if (text == this->text())
        return;
    m_settingText = true;
    int line = 0;
    int index = 0;
    getCursorPosition(&line, &index);
    if (this->text() == m_shown) {
        setText(text); // the text we showed: its history need not be kept
    } else {
        // The user's own text goes: one step of the list's undo brings it back.
        beginUndoAction();
        selectAll();
        replaceSelectedText(text);
        endUndoAction();
    }
    m_shown = text;
    setCursorPosition(std::min(line, lines() - 1), index);
    m_settingText = false;
}

void IlEditor::dropHistory() {
    m_shown = text();
    SendScintilla(SCI_EMPTYUNDOBUFFER);
}

void IlEditor::showDiagnostics(const std::vector<model::Diagnostic> &diagnostics) {
    markerDeleteAll(kErrorMarker);
    markerDeleteAll(kWarningMarker);
    m_notes.clear();
    m_longestNote = 0;
    for (const model::Diagnostic &d : diagnostics) {
        if (!d.location.onListing())
            continue;
        const int line = d.location.line - 1;
        markerAdd(line, d.severity == model::Severity::Error ? kErrorMarker : kWarningMarker);
        m_notes[line] << QStringLiteral("%1 [%2]").arg(d.message, d.code);
        m_longestNote = std::max(m_longestNote, m_notes[line].back().size());
    }
    showNotes();
}

QString IlEditor::wrapNote(const QString &text, int columns) {
    columns = std::max(1, columns);
    QStringList lines;
    QString current;
    for (const QString &word : text.split(QLatin1Char(' '), Qt::SkipEmptyParts)) {
        if (!current.isEmpty() && current.size() + 1 + word.size() > columns) {
            lines << current;
            current.clear();
        }
        current += (current.isEmpty() ? QString() : QStringLiteral(" ")) + word;
    }
    if (!current.isEmpty())
        lines << current;
    return lines.join(QLatin1Char('\n'));
}

int IlEditor::noteColumns() const {
    const QFontMetrics fm(m_lexer ? m_lexer->font(IlLexer::Comment) : font());
    // The text area starts after the margins; keep a character's room for the caret.
    int margins = 0;
    for (int m = 0; m < this->margins(); ++m)
        margins += marginWidth(m);
    const int width = viewport()->width() - margins - fm.averageCharWidth();
    return std::max(20, width / std::max(1, fm.averageCharWidth()));
}

void IlEditor::showNotes() {
    // Hidden while they are written: a shown annotation changes the scroll range at once, and
    // Qt queues an event for each change (30,608 findings grew Qt's queue of posted events to
    // 5 MB, which it keeps). Shown again, they change it once.
    setAnnotationDisplay(QsciScintilla::AnnotationHidden);
    clearAnnotations();
    m_notesWrappedAt = noteColumns();
    for (const auto &[line, list] : m_notes) {
        QStringList wrapped;
        for (const QString &note : list)
            wrapped << wrapNote(note, m_notesWrappedAt);
        annotate(line, wrapped.join(QLatin1Char('\n')), IlLexer::Comment);
    }
    setAnnotationDisplay(QsciScintilla::AnnotationBoxed);
}

void IlEditor::resizeEvent(QResizeEvent *event) {
    QsciScintilla::resizeEvent(event);
    const int columns = noteColumns();
    if (m_notes.empty() || columns == m_notesWrappedAt)
        return;
    // Notes no longer than either width are one line at both: nothing to write again.
    if (m_longestNote <= std::min(columns, m_notesWrappedAt)) {
        m_notesWrappedAt = columns;
        return;
    }
    // Once for the resizes of one layout pass (a window shown resizes the list several
    // times): writing 10,000 notes is tens of milliseconds each time.
    if (m_rewrapPending)
        return;
    m_rewrapPending = true;
    QMetaObject::invokeMethod(
        this,
        [this] {
            m_rewrapPending = false;
            if (noteColumns() != m_notesWrappedAt)
                showNotes();
        },
        Qt::QueuedConnection);
}

void IlEditor::setStepNumbers(const std::vector<int> &stepOfLine) {
    // Two messages to Scintilla a numbered line (QsciScintilla::setMarginText asks the style
    // offset every time and converts a QString): a 10,000-rung listing has over 100,000
    // lines, numbered again at every change. A line without a step loses a number it had.
    const auto offset = static_cast<long>(SendScintilla(SCI_MARGINGETSTYLEOFFSET));
    const int count = lines();
    std::array<char, 12> text{};
    for (int line = 0; line < count; ++line) {
        const auto at = static_cast<unsigned long>(line);
        const int step = line < static_cast<int>(stepOfLine.size())
                             ? stepOfLine[static_cast<std::size_t>(line)]
                             : -1;
        if (step < 0) {
            if (SendScintilla(SCI_MARGINGETTEXT, at, static_cast<long>(0)) > 0)
                SendScintilla(SCI_MARGINSETTEXT, at, static_cast<const char *>(nullptr));
            continue;
        }
        // At least four digits, as the PLCs' consoles show a step ("0012").
        std::size_t digits = 0;
        for (int rest = step; rest > 0 || digits < 4; rest /= 10)
            text[text.size() - 2 - digits++] = static_cast<char>('0' + rest % 10);
        text[text.size() - 1] = '\0';
        SendScintilla(SCI_MARGINSETTEXT, at, text.data() + text.size() - 1 - digits);
        SendScintilla(SCI_MARGINSETSTYLE, at, IlLexer::StepNumber - offset);
    }
}

void IlEditor::setBreakpointLines(const std::map<int, bool> &lines) {
    markerDeleteAll(kBreakpointMarker);
    markerDeleteAll(kConditionalMarker);
    for (const auto &[line, conditional] : lines)
        if (line >= 1 && line <= this->lines())
            markerAdd(line - 1, conditional ? kConditionalMarker : kBreakpointMarker);
}

std::vector<int> IlEditor::breakpointLines() const {
    std::vector<int> lines;
    const unsigned mask = (1u << kBreakpointMarker) | (1u << kConditionalMarker);
    for (int line = markerFindNext(0, mask); line >= 0; line = markerFindNext(line + 1, mask))
        lines.push_back(line + 1);
    return lines;
}

void IlEditor::setStoppedLine(int line) {
    markerDeleteAll(kStoppedMarker);
    markerDeleteAll(kStoppedLineMarker);
    m_stoppedLine = line >= 1 && line <= lines() ? line : 0;
    if (m_stoppedLine == 0)
        return;
    markerAdd(line - 1, kStoppedMarker);
    markerAdd(line - 1, kStoppedLineMarker);
    ensureLineVisible(line - 1);
}

void IlEditor::goToLine(int line) {
    setCursorPosition(std::max(0, line - 1), 0);
    ensureLineVisible(std::max(0, line - 1));
    setFocus();
}

QString IlEditor::lineText(int line) const {
    QString t = text(line);
    while (t.endsWith(QLatin1Char('\n')) || t.endsWith(QLatin1Char('\r')))
        t.chop(1);
    return t;
}

bool IlEditor::replaceLines(int first, const QStringList &expected,
                            const QStringList &replacement) {
    const int last = first + static_cast<int>(expected.size()) - 1;
    if (first < 0 || expected.isEmpty() || last >= lines())
        return false;
    for (int i = 0; i < expected.size(); ++i)
        if (lineText(first + i) != expected[i])
            return false;
    beginUndoAction();
    // Scintilla's own positions: a line's end is a byte offset, whatever the characters.
    SendScintilla(SCI_SETSEL, SendScintilla(SCI_POSITIONFROMLINE, first),
                  SendScintilla(SCI_GETLINEENDPOSITION, last));
    replaceSelectedText(replacement.join(QLatin1Char('\n')));
    endUndoAction();
    setCursorPosition(first, 0);
    return true;
}

QString IlEditor::deviceAtCaret() const {
    int line = 0;
    int index = 0;
    getCursorPosition(&line, &index);
    const QString text = lineText(line);
    const std::vector<int> styles = m_lexer ? m_lexer->styleLine(text) : std::vector<int>{};
    // The caret may stand just after the word (where typing left it).
    qsizetype at = std::min<qsizetype>(index, text.size());
    if ((at == text.size() || text[at].isSpace()) && at > 0)
        --at;
    if (at < 0 || at >= static_cast<qsizetype>(styles.size()) ||
        styles[static_cast<std::size_t>(at)] != IlLexer::Device)
        return {};
    qsizetype first = at;
    qsizetype last = at;
    while (first > 0 && styles[static_cast<std::size_t>(first - 1)] == IlLexer::Device &&
           !text[first - 1].isSpace())
        --first;
    while (last + 1 < text.size() &&
           styles[static_cast<std::size_t>(last + 1)] == IlLexer::Device &&
           !text[last + 1].isSpace())
        ++last;
    const auto parsed = model::parseAddress(*m_target, text.mid(first, last - first + 1));
    if (const auto *address = std::get_if<model::Address>(&parsed))
        return model::formatAddress(*m_target, *address);
    return {};
}

void IlEditor::updateCallTip() {
    // The operand form of the mnemonic on the cursor's line, in the tooltip of the editor.
    int line = 0;
    int index = 0;
    getCursorPosition(&line, &index);
    const QString word =
        text(line).section(QLatin1Char(';'), 0, 0).simplified().section(QLatin1Char(' '), 0, 0);
    // An instruction without operands (END, ANB) still says what it does.
    const model::InstructionSpec *s = m_target->findInstruction(word);
    if (!s) {
        setToolTip(QString());
        return;
    }
    QString tip = s->mnemonic;
    if (s->operandHelp)
        tip += QLatin1Char(' ') + QString::fromLatin1(s->operandHelp);
    if (s->summary)
        tip +=
            QStringLiteral(" — ") + QCoreApplication::translate("rung::model::Target", s->summary);
    setToolTip(tip);
}

void IlEditor::changeEvent(QEvent *event) {
    if (event->type() == QEvent::LanguageChange) {
        setAccessibleName(tr("Instruction list"));
        updateCallTip(); // the instruction's summary, in the new language
    }
    QsciScintilla::changeEvent(event);
}

} // namespace rung::editor
