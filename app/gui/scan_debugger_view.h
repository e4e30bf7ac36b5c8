#pragma once

// The Scan Debugger dock: where a stopped scan is (the instruction it stops before, its line
// and rung, and whether a breakpoint or a step stopped it), the logic result, the block stack
// (ANB/ORB, AND LD/OR LD) and the MPS stack as the interpreter holds them, the interlock and
// step state; buttons to step one instruction, finish the scan and continue; and the list of
// breakpoints with their conditions. It shows a ScanDebugSubject (scan_debug_subject.h): the
// main window's simulation, or a station of a simulated network.

#include <QWidget>

class QLabel;
class QListWidget;
class QPushButton;
class QTreeWidget;

namespace rung::editor {
class Document;
}

namespace rung::app {

class ScanDebugSubject;
class SimulationController;

class ScanDebuggerView : public QWidget {
    Q_OBJECT

public:
    // The main window's simulation of `document`.
    ScanDebuggerView(SimulationController *simulation, editor::Document *document,
                     QWidget *parent = nullptr);
    // Any subject (kept, not owned: it must outlive the view or be its child).
    explicit ScanDebuggerView(ScanDebugSubject *subject, QWidget *parent = nullptr);

    void refresh();
    void retranslate();

    // For tests: what the view shows.
    QString positionText() const;
    QString resultText() const;
    QStringList blockStack() const; // bottom first
    QStringList memoryStack() const;
    QTreeWidget *breakpointList() const { return m_breakpoints; }
    QPushButton *removeButton() const { return m_remove; }

signals:
    // The user asks to edit the condition of the breakpoint on this instruction.
    void editConditionRequested(int instruction);
    void goToInstruction(int instruction);

private:
    void refreshBreakpoints();
    void updateButtons(); // Remove and Condition... need a breakpoint chosen in the list

    void build();

    ScanDebugSubject *m_subject;
    QLabel *m_position;
    QLabel *m_resultCaption;
    QLabel *m_result;
    QLabel *m_blocksCaption;
    QListWidget *m_blocks;
    QLabel *m_stackCaption;
    QListWidget *m_stack;
    QLabel *m_gates;
    QPushButton *m_step;
    QPushButton *m_finish;
    QPushButton *m_continue;
    QLabel *m_breakpointsCaption;
    QTreeWidget *m_breakpoints;
    QPushButton *m_condition;
    QPushButton *m_remove;
    QPushButton *m_removeAll;
};

} // namespace rung::app
