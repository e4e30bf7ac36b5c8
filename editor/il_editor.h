#pragma once

// The instruction-list editor: QScintilla with a lexer per target (mnemonics, devices,
// constants, comments in their own styles), step numbers in the margin, auto-completion and
// call tips from the target's instruction table, and diagnostics as markers and annotations.

#include "model/checks/diagnostic.h"
#include "model/image/monitor_source.h"
#include "model/listing/il.h"
#include "model/target/target.h"

#include "il_lexer.h"

#include <Qsci/qsciscintilla.h>

#include <QPointer>

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <vector>

namespace rung::editor {

class MonitorCommands;

class IlEditor : public QsciScintilla {
    Q_OBJECT

public:
    explicit IlEditor(const model::Target &target, QWidget *parent = nullptr);

    void setTarget(const model::Target &target);
    // Replaces the text without being taken for a user edit; text the user typed over what
    // was shown stays in the list's undo.
    void setListing(const QString &text);
    // Another program comes (new, open): what was typed before belongs to no undo any more.
    void dropHistory();
    // Markers in the margin and annotations under the lines of the listing findings.
    void showDiagnostics(const std::vector<model::Diagnostic> &diagnostics);
    void setStepNumbers(const std::vector<int> &stepOfLine); // -1: no step on that line
    // A message broken at spaces into lines of at most `columns` characters (a word longer
    // than that stands alone): annotations do not wrap by themselves.
    static QString wrapNote(const QString &text, int columns);
    // How many characters of the annotations' font fit across the view.
    int noteColumns() const;
    void goToLine(int line); // 1-based
    // Simulation: breakpoint dots in the margin (line 1-based -> conditional), and the line
    // a stopped scan is at (0: none), with an arrow and a highlighted line.
    void setBreakpointLines(const std::map<int, bool> &lines);
    std::vector<int> breakpointLines() const;
    void setStoppedLine(int line);
    int stoppedLine() const { return m_stoppedLine; }
    // The text of a line without its line break (0-based, as QScintilla counts).
    QString lineText(int line) const;
    // Replaces lines first.. (0-based) when they still read `expected`, as one step of the
    // editor's own undo; false, and nothing changed, when they do not.
    bool replaceLines(int first, const QStringList &expected, const QStringList &replacement);
    // The device the caret is on ("X0" in "LD X0 ; start"), as the target writes it; empty
    // when the caret is on no device (a mnemonic, a constant, a comment).
    QString deviceAtCaret() const;
    // The operand form of the mnemonic before the caret, as a call tip ("TMR T0..T255 ...").
    void showOperandTip();
    bool operandTipShown();
    // Where the devices offered while an operand is typed come from: the project's devices,
    // each maybe followed by its symbol name ("X0  Start"); only the device is inserted.
    void setDeviceSource(std::function<QStringList()> source) { m_devices = std::move(source); }
    // Opens the list that fits the caret: mnemonics at the start of a line, devices after one.
    void showCompletions();

    // The live values (il_editor_monitor.cpp): while a source is set, each line of the running
    // program shows after its text the logic result after its instruction (a filled square
    // for ON, a hollow one for OFF) and the values of its devices ("X0 = ON", "T0 23/50 ×0.1
    // s"), painted over the view: the text and its undo stay untouched. The context menu
    // (right button, the Menu key or Shift+F10) forces and writes the line's devices.
    void setMonitorSource(model::MonitorSource *source);
    model::MonitorSource *monitorSource() const { return m_source; }
    // Which instruction of the running program each line (0-based) holds, -1 for none, and
    // the instructions (shared with the document, not copied: a 10,000-rung listing is
    // ~18 MB); empty when the text shown is not the running program's.
    void setMonitorLines(std::vector<int> instructionOfLine,
                         std::shared_ptr<const std::vector<model::Instruction>> instructions);
    struct LineValue {
        std::optional<bool> result; // the logic result after the instruction, when known
        QString text;               // the devices' values
        bool forced = false;
        friend bool operator==(const LineValue &, const LineValue &) = default;
    };
    // What a line (0-based) shows now; nullopt for a line without an instruction or while
    // nothing is monitored.
    std::optional<LineValue> monitoredLine(int line) const;
    // The context menu's device entries for a line (0-based); nullptr where it has none.
    QMenu *monitorMenu(int line, QWidget *parent);

signals:
    void listingEdited();
    // A click in the markers' margin (1-based line).
    void breakpointToggleRequested(int line);
    void message(const QString &text); // a device command's result, for the status bar

protected:
    void resizeEvent(QResizeEvent *event) override;
    void paintEvent(QPaintEvent *event) override;
    void contextMenuEvent(QContextMenuEvent *event) override;
    void keyPressEvent(QKeyEvent *event) override;
    void changeEvent(QEvent *event) override; // LanguageChange: its own texts again

private:
    void snapshotArrived();
    void paintValues();
    std::pair<int, int> visibleLines() const; // [first, last)
    QRect valueRect(int line) const;          // where a line's values are painted
    int valuesX() const;                      // the column the values start at
    void showMonitorMenu(int line, QPoint globalPos);
    void updateCallTip();
    void showNotes();
    void insertDevice(int id, const QString &item);

    const model::Target *m_target;
    IlLexer *m_lexer = nullptr;
    bool m_settingText = false;
    QString m_shown; // the text setListing last showed
    std::function<QStringList()> m_devices;
    std::map<int, QStringList> m_notes; // the diagnostics' messages by line, unwrapped
    int m_notesWrappedAt = 0;           // the columns they were last wrapped to
    qsizetype m_longestNote = 0;        // no narrower view wraps a note
    bool m_rewrapPending = false;       // a resize asked to wrap them again, not yet done
    int m_stoppedLine = 0;
    QPointer<model::MonitorSource> m_source;
    MonitorCommands *m_commands = nullptr;
    std::vector<int> m_lineInstruction;
    std::shared_ptr<const std::vector<model::Instruction>> m_instructions;
    // The instruction at index `index` of m_instructions, or null.
    const model::Instruction *monitoredInstruction(int index) const;
    std::map<int, LineValue> m_painted; // what the lines on screen show, by line
};

} // namespace rung::editor
