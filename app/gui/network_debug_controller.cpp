#include "app/gui/network_debug_controller.h"

#include "app/gui/breakpoint_dialog.h"
#include "app/gui/debug_entries.h"
#include "app/gui/debug_marks.h"
#include "app/gui/network_history_controller.h"
#include "app/gui/scan_debug_subject.h"
#include "app/gui/scan_debugger_view.h"

#include "editor/document.h"
#include "editor/il_editor.h"
#include "editor/ladder_view.h"
#include "model/listing/il.h"
#include "network/network_session.h"

#include "model/target/target_lists.h"

#include <QAction>
#include <QDockWidget>
#include <QInputDialog>
#include <QLabel>
#include <QLineEdit>
#include <QMainWindow>
#include <QMenu>
#include <QPointer>
#include <QScrollArea>
#include <QStackedWidget>
#include <QStatusBar>
#include <QStyle>
#include <QTabWidget>
#include <QTreeWidget>

namespace rung::app {

using RunState = model::MonitorSource::RunState;

// The selected station as the Scan Debugger's subject. The view owns it: whichever of the
// window's children goes first while the window is destroyed, the view never reads a subject
// that is gone, and the subject answers "nothing" once the controller is.
class StationDebugSubject final : public ScanDebugSubject {
public:
    explicit StationDebugSubject(NetworkDebugController *controller)
        : ScanDebugSubject(controller)
        , m_c(controller)
        , m_noProgram(new editor::Document(this)) {}

    editor::Document *document() const override {
        const auto *s = m_c ? m_c->find(m_c->m_current) : nullptr;
        return s ? s->parts.document : m_noProgram;
    }
    bool active() const override { return m_c && m_c->m_session != nullptr; }
    std::shared_ptr<const model::Snapshot> snapshot() const override {
        const auto *s = m_c ? m_c->find(m_c->m_current) : nullptr;
        return s ? s->parts.source->snapshot() : nullptr;
    }
    std::vector<BreakpointSpec> breakpoints() const override {
        return m_c ? m_c->breakpoints(m_c->m_current) : std::vector<BreakpointSpec>{};
    }
    int instructionOf(const BreakpointSpec &b) const override {
        return SimulationController::instructionOf(document()->listing().rungFirst, b);
    }
    QString conditionText(const BreakpointSpec &b) const override {
        return SimulationController::conditionText(document()->target(), b);
    }
    void stepInstruction() override {
        if (m_c)
            m_c->stepInstruction();
    }
    void finishScan() override {
        if (m_c)
            m_c->finishScan();
    }
    void proceed() override {
        if (m_c && m_c->m_session)
            m_c->m_session->run();
    }
    void removeBreakpoint(int instruction) override {
        if (m_c)
            m_c->removeBreakpoint(m_c->m_current, instruction);
    }
    void clearBreakpoints() override {
        if (!m_c)
            return;
        m_c->m_breakpoints.erase(m_c->m_current);
        m_c->sendBreakpoints(m_c->m_current);
    }

private:
    QPointer<NetworkDebugController> m_c;
    editor::Document *m_noProgram; // what is read while no station is chosen
};

NetworkDebugController::NetworkDebugController(QMainWindow *window, QTabWidget *tabs,
                                               NetworkHistoryController *history, QObject *parent)
    : QObject(parent)
    , m_window(window)
    , m_tabs(tabs)
    , m_history(history) {
    m_lists = new QStackedWidget(window);
    m_lists->setObjectName(QStringLiteral("networkLists"));
    m_tabs->addTab(m_lists, QString());

    m_subject = new StationDebugSubject(this);
    m_debugger = new ScanDebuggerView(m_subject);
    m_subject->setParent(m_debugger);
    m_debugger->setObjectName(QStringLiteral("networkScanDebugger"));
    // The breakpoint list takes the height the dock has left, from a few rows: its size hint
    // (192 px) made the dock scroll at 1366 x 768 with the Timing Chart below it.
    m_debugger->breakpointList()->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Ignored);
    m_debugger->breakpointList()->setMinimumHeight(m_debugger->fontMetrics().height() * 5);
    // Scrolled, as in the main window: its stacks and list must not make the window taller
    // than the screen.
    auto *scroll = new QScrollArea;
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidget(m_debugger);
    m_dock = new QDockWidget(window);
    m_dock->setObjectName(QStringLiteral("networkScanDebuggerDock"));
    m_dock->setWidget(scroll);
    window->addDockWidget(Qt::RightDockWidgetArea, m_dock);
    // Beside the watch table, behind it until a breakpoint holds.
    if (auto *watch = window->findChild<QDockWidget *>(QStringLiteral("networkWatchDock"))) {
        window->tabifyDockWidget(watch, m_dock);
        watch->raise();
    }
    connect(m_debugger, &ScanDebuggerView::editConditionRequested, this,
            &NetworkDebugController::editBreakpointCondition);
    connect(m_debugger, &ScanDebuggerView::goToInstruction, this, [this](int instruction) {
        const Station *s = find(m_current);
        const auto &origin =
            s ? s->parts.document->listing().origin : std::vector<model::CellOrigin>{};
        if (instruction >= 0 && static_cast<std::size_t>(instruction) < origin.size())
            s->parts.ladder->setCursor({origin[static_cast<std::size_t>(instruction)].rung, 0, 0});
    });

    if (m_history)
        connect(m_history, &NetworkHistoryController::historyChanged, this,
                &NetworkDebugController::updateReturnAction);

    m_held = new QLabel(window);
    m_held->setObjectName(QStringLiteral("networkHeld"));
    window->statusBar()->addPermanentWidget(m_held);
    m_held->hide();
    retranslate();
}

NetworkDebugController::~NetworkDebugController() {
    for (const auto &c : m_connections)
        disconnect(c);
}

QWidget *NetworkDebugController::listPage() const {
    return m_lists;
}

const NetworkDebugController::Station *NetworkDebugController::find(const QString &name) const {
    for (const Station &s : m_stations)
        if (s.parts.name == name)
            return &s;
    return nullptr;
}

editor::IlEditor *NetworkDebugController::listView(const QString &station) const {
    const Station *s = find(station);
    return s ? s->il : nullptr;
}

void NetworkDebugController::setSession(network::NetworkSession *session,
                                        const std::vector<StationParts> &stations) {
    for (const auto &c : m_connections)
        disconnect(c);
    m_connections.clear();
    for (Station &s : m_stations) {
        s.il->setMonitorSource(nullptr);
        delete s.il;
    }
    m_stations.clear();
    m_stopSource = nullptr;
    m_triggerStop.clear();
    m_session = session;
    for (const StationParts &parts : stations) {
        Station s;
        s.parts = parts;
        const editor::Document *doc = parts.document;
        s.il = new editor::IlEditor(doc->target(), m_lists);
        s.il->setObjectName(QStringLiteral("networkList_") + parts.name);
        s.il->setListing(doc->listingText());
        // A station's program is edited in the main window: here it is read and debugged.
        s.il->setReadOnly(true);
        std::vector<int> stepOfLine;
        const auto &list = doc->listing().list;
        for (const int i : doc->printedListing().instructionOfLine)
            stepOfLine.push_back(i < 0 ? -1 : list.instructions[static_cast<std::size_t>(i)].step);
        s.il->setStepNumbers(stepOfLine);
        s.il->setMonitorLines(doc->printedListing().instructionOfLine, doc->sharedInstructions());
        s.il->setMonitorSource(parts.source);
        m_lists->addWidget(s.il);
        m_stations.push_back(s);
    }
    // Connected once the list of stations stands (the Station entries do not move any more).
    for (Station &s : m_stations) {
        const QString name = s.parts.name;
        m_connections.push_back(connect(
            s.il, &editor::IlEditor::breakpointToggleRequested, this, [this, name](int line) {
                const Station *st = find(name);
                const int instruction =
                    st ? st->parts.document->printedListing().instructionAt(line) : -1;
                if (instruction < 0)
                    emit message(noInstructionOnLine(line));
                else
                    toggleBreakpoint(name, instruction);
            }));
        m_connections.push_back(connect(
            s.parts.ladder, &editor::LadderView::breakpointToggleRequested, this,
            [this, name](int rung) {
                const Station *st = find(name);
                if (const int first = st ? firstInstructionOfRung(*st->parts.document, rung) : -1;
                    first >= 0)
                    toggleBreakpoint(name, first);
                else
                    emit message(noInstructionInRung(rung));
            }));
        Station *station = &s;
        m_connections.push_back(connect(s.parts.source, &model::MonitorSource::snapshotChanged,
                                        this, [this, station] { snapshotArrived(*station); }));
        updateMarks(s);
    }
    if (m_session) {
        m_connections.push_back(connect(
            m_session, &network::NetworkSession::breakpointHit, this,
            [this](const QString &name, int instruction) {
                const Station *s = find(name);
                emit stationWanted(name);
                showDebugger();
                const auto &lines =
                    s ? s->parts.document->printedListing().instructionLine : std::vector<int>{};
                //: %1 station, %2 line of its instruction list
                emit message(tr("%1 stopped at its breakpoint on line %2; the "
                                "other stations wait at the end of their scan")
                                 .arg(name)
                                 .arg(instruction >= 0 && std::size_t(instruction) < lines.size()
                                          ? lines[std::size_t(instruction)]
                                          : 0));
            }));
        m_connections.push_back(connect(
            m_session, &network::NetworkSession::runStateChanged, this, [this](RunState state) {
                if (state != RunState::Paused)
                    m_triggerStop.clear(); // it runs on, or starts again
                emit m_subject->stateChanged();
                updateHeld();
            }));
        // The breakpoints kept from the network before (Stop builds it again).
        for (const Station &s : m_stations)
            sendBreakpoints(s.parts.name);
        QString ignored;
        armStopCondition(&ignored);
    }
    if (!find(m_current))
        m_current = m_stations.empty() ? QString() : m_stations.front().parts.name;
    selectStation(m_current);
    emit m_subject->breakpointsChanged();
    updateHeld();
}

void NetworkDebugController::selectStation(const QString &name) {
    for (std::size_t i = 0; i < m_stations.size(); ++i)
        if (m_stations[i].parts.name == name)
            m_lists->setCurrentIndex(int(i));
    m_current = find(name) ? name : QString();
    emit m_subject->breakpointsChanged();
    emit m_subject->stateChanged();
}

void NetworkDebugController::addActions(QMenu *menu) {
    // The main window's entries and keys (debug_entries.h).
    const std::vector<QAction *> made = addDebugEntries(menu, "network", this, this);
    for (QAction *a : made)
        if (a->objectName() == QLatin1String("networkReturnToLive"))
            m_returnAction = a;
    updateReturnAction();
    QAction *when = menu->addAction(tr("Stop &When..."), this, [this] {
        const Station *shown = find(m_current);
        if (!shown) {
            emit message(tr("No network is running"));
            return;
        }
        bool ok = false;
        QString text = m_stopCondition;
        // The example in the station's own devices.
        const model::Target &target = shown->parts.source->target();
        //: %1 a station's name, %2 a word of it, %3 a bit of it
        const QString prompt =
            tr("Stop the network after the scan in which a station's condition becomes "
               "true,\nwritten STATION/CONDITION, e.g. %1/%2 > 100 or %1/%3 rises "
               "(empty: never):")
                .arg(m_current, model::exampleWord(target, 10), model::exampleDevice(target));
        for (;;) {
            text = QInputDialog::getText(m_window, tr("Stop When"), prompt, QLineEdit::Normal, text,
                                         &ok);
            QString error;
            if (!ok || setStopCondition(text, &error))
                return;
            emit message(error);
        }
    });
    when->setObjectName(QStringLiteral("networkStopWhen"));
    menu->addSeparator();
    menu->addAction(m_dock->toggleViewAction());
}

void NetworkDebugController::retranslate() {
    m_dock->setWindowTitle(tr("Scan Debugger"));
    m_tabs->setTabText(m_tabs->indexOf(m_lists), tr("Instruction List"));
    m_debugger->retranslate();
    updateHeld();
}

void NetworkDebugController::stepInstruction() {
    if (!m_session || m_current.isEmpty())
        return;
    // The station holding is the one that steps; at a boundary, the one shown starts a scan.
    const QString held = m_session->heldStation();
    if (!held.isEmpty() && held != m_current)
        emit stationWanted(held);
    m_session->stepInstruction(held.isEmpty() ? m_current : held);
}

void NetworkDebugController::finishScan() {
    if (m_session)
        m_session->finishScan();
}

void NetworkDebugController::editBreakpointConditionHere() {
    QString where;
    const int instruction = instructionHere(&where);
    if (instruction < 0)
        emit message(noInstructionAt(where));
    else
        editBreakpointCondition(instruction);
}

void NetworkDebugController::returnToLive() {
    if (m_history)
        m_history->returnToLive();
}

void NetworkDebugController::updateReturnAction() {
    if (m_returnAction)
        m_returnAction->setEnabled(m_history && m_history->historyShown());
}

std::vector<NetworkDebugController::BreakpointSpec>
NetworkDebugController::breakpoints(const QString &station) const {
    const auto found = m_breakpoints.find(station);
    return found != m_breakpoints.end() ? found->second : std::vector<BreakpointSpec>{};
}

bool NetworkDebugController::toggleBreakpoint(const QString &station, int instruction) {
    const Station *s = find(station);
    if (!s)
        return false;
    const auto &first = s->parts.document->listing().rungFirst;
    for (const BreakpointSpec &b : breakpoints(station))
        if (SimulationController::instructionOf(first, b) == instruction) {
            removeBreakpoint(station, instruction);
            return false;
        }
    setBreakpoint(station, instruction, {});
    return true;
}

void NetworkDebugController::setBreakpoint(const QString &station, int instruction,
                                           const BreakpointSpec &condition) {
    const Station *s = find(station);
    if (!s)
        return;
    const auto &first = s->parts.document->listing().rungFirst;
    const std::optional<BreakpointSpec> b =
        SimulationController::placeBreakpoint(first, instruction, condition);
    if (!b)
        return;
    auto &list = m_breakpoints[station];
    std::erase_if(list, [&](const BreakpointSpec &x) {
        return SimulationController::instructionOf(first, x) == instruction;
    });
    list.push_back(*b);
    sendBreakpoints(station);
}

void NetworkDebugController::removeBreakpoint(const QString &station, int instruction) {
    const Station *s = find(station);
    if (!s)
        return;
    const auto &first = s->parts.document->listing().rungFirst;
    std::erase_if(m_breakpoints[station], [&](const BreakpointSpec &x) {
        return SimulationController::instructionOf(first, x) == instruction;
    });
    sendBreakpoints(station);
}

void NetworkDebugController::clearBreakpoints() {
    const auto all = std::exchange(m_breakpoints, {});
    for (const auto &[station, list] : all)
        sendBreakpoints(station);
}

void NetworkDebugController::sendBreakpoints(const QString &station) {
    const Station *s = find(station);
    if (!s)
        return;
    if (m_session)
        m_session->setBreakpoints(
            station, SimulationController::engineBreakpoints(s->parts.document->listing().rungFirst,
                                                             breakpoints(station)));
    updateMarks(*s);
    if (station == m_current)
        emit m_subject->breakpointsChanged();
}

int NetworkDebugController::instructionHere(QString *where) const {
    const Station *s = find(m_current);
    if (!s) {
        *where = tr("no station");
        return -1;
    }
    // The list is the program's own text (read-only here): always in step.
    return app::instructionHere(*s->parts.document, *s->parts.ladder, *s->il, true, where);
}

void NetworkDebugController::toggleBreakpointHere() {
    QString where;
    const int instruction = instructionHere(&where);
    if (instruction < 0) {
        emit message(noInstructionAt(where));
        return;
    }
    //: %1 the place ("line 3", "rung 2"), %2 the station
    emit message(toggleBreakpoint(m_current, instruction)
                     ? tr("Breakpoint set at %1 of %2").arg(where, m_current)
                     : tr("Breakpoint at %1 of %2 removed").arg(where, m_current));
}

void NetworkDebugController::editBreakpointCondition(int instruction) {
    const Station *s = find(m_current);
    if (!s)
        return;
    const editor::Document &doc = *s->parts.document;
    const auto &list = doc.listing().list.instructions;
    if (instruction < 0 || static_cast<std::size_t>(instruction) >= list.size())
        return;
    BreakpointSpec existing;
    for (const BreakpointSpec &b : breakpoints(m_current))
        if (SimulationController::instructionOf(doc.listing().rungFirst, b) == instruction)
            existing = b;
    const auto &printed = doc.printedListing();
    const auto i = static_cast<std::size_t>(instruction);
    //: where the breakpoint is: %1 station, %2 line, %3 the instruction
    const QString place =
        tr("Stop %1 before line %2: %3")
            .arg(m_current)
            .arg(i < printed.instructionLine.size() ? printed.instructionLine[i] : 0)
            .arg(model::printInstruction(doc.target(), list[i]));
    BreakpointDialog dialog(doc.target(), place, existing, m_window);
    if (dialog.exec() == QDialog::Accepted)
        setBreakpoint(m_current, instruction, dialog.breakpoint());
}

void NetworkDebugController::updateMarks(const Station &station) {
    markBreakpoints(*station.parts.document, breakpoints(station.parts.name), *station.parts.ladder,
                    *station.il, true);
}

void NetworkDebugController::snapshotArrived(Station &station) {
    const auto snapshot = station.parts.source->snapshot();
    const int at = snapshot && snapshot->pause ? snapshot->pause->instruction : -1;
    if (at != station.stoppedAt) {
        station.stoppedAt = at;
        showStoppedAt(station, at);
        updateHeld();
    }
    if (station.parts.name == m_current)
        emit m_subject->stateChanged();
}

void NetworkDebugController::showStoppedAt(const Station &station, int instruction) {
    markStoppedAt(*station.parts.document, instruction, *station.parts.ladder, *station.il, true);
    if (station.il->stoppedLine() > 0)
        station.il->ensureLineVisible(station.il->stoppedLine() - 1);
}

QString NetworkDebugController::heldText() const {
    for (const Station &s : m_stations)
        if (s.stoppedAt >= 0) {
            const auto &lines = s.parts.document->printedListing().instructionLine;
            const auto i = static_cast<std::size_t>(s.stoppedAt);
            //: the status bar while a station's scan is stopped inside: %1 station, %2 line
            return tr("%1 stopped before line %2")
                .arg(s.parts.name)
                .arg(i < lines.size() ? lines[i] : 0);
        }
    //: the status bar while the network's trigger holds it: %1 the condition ("s2/D10 > 100")
    return m_triggerStop.isEmpty() ? QString() : tr("Stopped: %1 became true").arg(m_triggerStop);
}

void NetworkDebugController::showDebugger() {
    m_dock->show();
    m_dock->raise();
    // As wide as its buttons and stacks need (the Hungarian and Italian ones are long), the
    // ladder or list keeping the most of the window.
    const int needed = m_debugger->minimumSizeHint().width();
    const int wanted = needed + m_debugger->style()->pixelMetric(QStyle::PM_ScrollBarExtent) +
                       4 * m_dock->style()->pixelMetric(QStyle::PM_DockWidgetFrameWidth) + 8;
    if (m_debugger->parentWidget() && m_debugger->parentWidget()->width() < needed)
        m_window->resizeDocks({m_dock}, {std::min(wanted, m_window->width() * 2 / 5)},
                              Qt::Horizontal);
}

void NetworkDebugController::updateHeld() {
    const QString text = heldText();
    m_held->setText(text);
    m_held->setVisible(!text.isEmpty());
}

} // namespace rung::app
