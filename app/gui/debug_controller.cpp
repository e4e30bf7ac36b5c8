#include "debug_controller.h"

#include "breakpoint_dialog.h"
#include "debug_entries.h"
#include "debug_marks.h"
#include "scan_debugger_view.h"
#include "simulation_controller.h"
#include "simulation_panel.h"

#include "editor/document.h"
#include "editor/il_editor.h"
#include "editor/ladder_view.h"

#include "simulator/session.h"

#include <QAction>
#include <QDockWidget>
#include <QMainWindow>
#include <QMenu>
#include <QMessageBox>
#include <QPushButton>
#include <QScrollArea>
#include <QStatusBar>

namespace rung::app {

DebugController::DebugController(editor::Document *document, editor::LadderView *ladder,
                                 editor::IlEditor *il, SimulationController *simulation,
                                 QStatusBar *status, QMainWindow *window, QObject *parent)
    : QObject(parent)
    , m_document(document)
    , m_ladder(ladder)
    , m_il(il)
    , m_simulation(simulation)
    , m_status(status)
    , m_window(window) {
    m_panel = new SimulationPanel(m_simulation);
    m_panel->setObjectName(QStringLiteral("simulationPanel"));
    auto *scroll = new QScrollArea;
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidget(m_panel);
    m_panelDock = new QDockWidget(tr("Simulation"), window);
    auto *panelDock = m_panelDock;
    panelDock->setObjectName(QStringLiteral("simulationDock"));
    panelDock->setWidget(scroll);
    // With the terminals and the connection (dock_layout.h).
    window->addDockWidget(Qt::LeftDockWidgetArea, panelDock);

    m_debugger = new ScanDebuggerView(m_simulation, m_document);
    m_debugger->setObjectName(QStringLiteral("scanDebugger"));
    m_debugDock = new QDockWidget(tr("Scan Debugger"), window);
    auto *debugDock = m_debugDock;
    debugDock->setObjectName(QStringLiteral("scanDebuggerDock"));
    // Scrolled: its stacks and breakpoints must not make the window taller than a 1024x600
    // screen (the window's minimum height is the docks' minimum heights added up).
    auto *debugScroll = new QScrollArea;
    debugScroll->setWidgetResizable(true);
    debugScroll->setFrameShape(QFrame::NoFrame);
    debugScroll->setWidget(m_debugger);
    debugDock->setWidget(debugScroll);
    window->addDockWidget(Qt::LeftDockWidgetArea, debugDock);
    // Out of the way until a simulation starts: the ladder keeps its width for drawing.
    panelDock->hide();
    debugDock->hide();

    connect(m_simulation, &SimulationController::sessionChanged, this,
            [this, panelDock](simulator::SimulatorSession *session) {
                if (session && !m_docksShown) {
                    m_docksShown = true;
                    panelDock->show();
                    panelDock->raise();
                    // Where the user put the two in one place, the terminals stay in front
                    // (toggle an input, see the rung); the run controls are in the toolbar too.
                    if (auto *io = m_window->findChild<QDockWidget *>(QStringLiteral("ioDock"));
                        io && io->isVisible())
                        io->raise();
                }
            });
    connect(m_il, &editor::IlEditor::breakpointToggleRequested, this, [this](int line) {
        const int instruction = instructionAtLine(line);
        if (instruction < 0) {
            statusBar()->showMessage(noInstructionOnLine(line), 5000);
            return;
        }
        m_simulation->toggleBreakpoint(instruction);
    });
    connect(m_ladder, &editor::LadderView::breakpointToggleRequested, this, [this](int rung) {
        if (const int first = firstInstructionOfRung(*m_document, rung); first >= 0)
            m_simulation->toggleBreakpoint(first);
        else
            statusBar()->showMessage(noInstructionInRung(rung), 5000);
    });
    connect(m_simulation, &SimulationController::breakpointsChanged, this,
            &DebugController::updateBreakpointMarks);
    connect(m_document, &editor::Document::programChanged, this,
            &DebugController::updateBreakpointMarks);
    connect(m_simulation, &SimulationController::stoppedAtChanged, this,
            [this, debugDock](int instruction) {
                showStoppedAt(instruction);
                if (instruction >= 0) {
                    debugDock->show();
                    debugDock->raise();
                }
                emit stoppedAtShown(instruction);
            });
    connect(m_debugger, &ScanDebuggerView::editConditionRequested, this,
            &DebugController::editBreakpointCondition);
    connect(m_debugger, &ScanDebuggerView::goToInstruction, this, [this](int instruction) {
        const auto &origin = m_document->listing().origin;
        if (instruction >= 0 && static_cast<std::size_t>(instruction) < origin.size())
            m_ladder->setCursor({origin[static_cast<std::size_t>(instruction)].rung, 0, 0});
    });
    m_simulation->setAsker([this](const QString &question, bool canKeep) {
        QMessageBox box(QMessageBox::Question, tr("Online Edit"), question, QMessageBox::NoButton,
                        m_window);
        QPushButton *keep =
            canKeep ? box.addButton(tr("Apply Keeping the Memory"), QMessageBox::AcceptRole)
                    : nullptr;
        QPushButton *restart = box.addButton(tr("Restart from Power-On"), QMessageBox::ActionRole);
        QPushButton *stop = box.addButton(tr("Stop the Simulation"), QMessageBox::RejectRole);
        box.setDefaultButton(keep ? keep : restart);
        box.exec();
        if (box.clickedButton() == keep && keep)
            return SimulationController::EditChoice::KeepImage;
        if (box.clickedButton() == restart)
            return SimulationController::EditChoice::Restart;
        Q_UNUSED(stop);
        return SimulationController::EditChoice::StopSimulation;
    });
}

DebugController::~DebugController() = default;

void DebugController::addActions(QMenu *menu) {
    addDebugEntries(menu, "simulation", this, this); // debug_entries.h
    menu->addSeparator();
    menu->addAction(m_panelDock->toggleViewAction());
    menu->addAction(m_debugDock->toggleViewAction());
}

void DebugController::stepInstruction() {
    m_simulation->stepInstruction();
}

void DebugController::finishScan() {
    m_simulation->finishScan();
}

void DebugController::editBreakpointConditionHere() {
    QString where;
    const int instruction = instructionHere(&where);
    if (instruction < 0)
        statusBar()->showMessage(noInstructionAt(where), 5000);
    else
        editBreakpointCondition(instruction);
}

void DebugController::clearBreakpoints() {
    m_simulation->clearBreakpoints();
}

void DebugController::returnToLive() {
    m_simulation->returnToLive();
}

int DebugController::instructionAtLine(int line) const {
    // Lines are counted in the canonical text; a text as typed has lines of its own.
    if (m_il->text() != m_document->listingText())
        return -1;
    return m_document->printedListing().instructionAt(line);
}

int DebugController::instructionHere(QString *where) const {
    return app::instructionHere(*m_document, *m_ladder, *m_il,
                                m_il->text() == m_document->listingText(), where);
}

void DebugController::toggleBreakpointHere() {
    QString where;
    const int instruction = instructionHere(&where);
    if (instruction < 0) {
        statusBar()->showMessage(noInstructionAt(where), 5000);
        return;
    }
    statusBar()->showMessage(m_simulation->toggleBreakpoint(instruction)
                                 ? tr("Breakpoint set at %1").arg(where)
                                 : tr("Breakpoint at %1 removed").arg(where),
                             5000);
}

void DebugController::editBreakpointCondition(int instruction) {
    const auto &list = m_document->listing().list.instructions;
    if (instruction < 0 || static_cast<std::size_t>(instruction) >= list.size())
        return;
    const SimulationController::BreakpointSpec *existing = m_simulation->breakpointAt(instruction);
    const auto &printed = m_document->printedListing();
    const auto i = static_cast<std::size_t>(instruction);
    //: where the breakpoint is: %1 line, %2 the instruction
    const QString place =
        tr("Stop before line %1: %2")
            .arg(i < printed.instructionLine.size() ? printed.instructionLine[i] : 0)
            .arg(model::printInstruction(m_document->target(), list[i]));
    BreakpointDialog dialog(m_document->target(), place,
                            existing ? *existing : SimulationController::BreakpointSpec{},
                            m_window);
    if (dialog.exec() == QDialog::Accepted)
        m_simulation->setBreakpoint(instruction, dialog.breakpoint());
}

void DebugController::retranslate() {
    m_panelDock->setWindowTitle(tr("Simulation"));
    m_debugDock->setWindowTitle(tr("Scan Debugger"));
    m_panel->retranslate();
    m_debugger->retranslate();
}

void DebugController::updateBreakpointMarks() {
    markBreakpoints(*m_document, m_simulation->breakpoints(), *m_ladder, *m_il,
                    m_il->text() == m_document->listingText());
}

void DebugController::showStoppedAt(int instruction) {
    markStoppedAt(*m_document, instruction, *m_ladder, *m_il,
                  m_il->text() == m_document->listingText());
}

} // namespace rung::app
