// The network window's network (network_window.h): the file it opens and saves, the simulated
// network built from it (NetworkSession) with a view of each station's program, inputs and
// outputs, the station selected, the watch table's devices and the status line. The window's
// docks and menus are network_window.cpp's.

#include "app/gui/network_window.h"

#include "app/cli/cli_network.h"
#include "app/gui/file_dialogs.h"
#include "app/gui/network_bridge_controller.h"
#include "app/gui/network_chart.h"
#include "app/gui/network_debug_controller.h"
#include "app/gui/network_document.h"
#include "app/gui/network_history_controller.h"
#include "app/gui/network_traffic_view.h"
#include "app/gui/network_view.h"
#include "app/gui/network_watch_model.h"
#include "app/gui/simulation_controller.h"

#include "editor/document.h"
#include "editor/front_panel.h"
#include "editor/io_panel.h"
#include "editor/ladder_view.h"
#include "model/convert/convert.h"
#include "model/ladder/ladder_text.h"
#include "model/listing/il.h"
#include "model/project/program_file.h"
#include "network/network_file.h"
#include "network/network_session.h"

#include <QComboBox>
#include <QDir>
#include <QFileInfo>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QStackedWidget>
#include <QStatusBar>
#include <QTabWidget>

namespace rung::app {

using RunState = model::MonitorSource::RunState;

bool NetworkWindow::loadStationDocument(StationView &view, QString *error) {
    model::ProgramFileOptions options;
    options.target = view.source->target().id;
    std::optional<model::ProgramFile> file =
        model::openProgramFile(view.source->programPath(),
                               model::programFileKind(view.source->programPath()), options, error);
    if (!file)
        return false;
    model::Project project;
    if (file->kind == model::ProgramFileKind::Project) {
        project = file->project;
    } else {
        project.target = file->target;
        if (file->kind == model::ProgramFileKind::LadderText) {
            const model::LadderTextResult ladder =
                model::parseLadderText(*file->target, file->text);
            if (!ladder.ok()) {
                *error = ladder.errors.front().message;
                return false;
            }
            project.program = ladder.ladder;
        } else {
            const model::ParseResult parsed =
                model::parseInstructionList(*file->target, file->text, view.source->model());
            const model::ToLadderResult ladder =
                parsed.ok() ? model::listToLadder(parsed.list) : model::ToLadderResult{};
            if (!parsed.ok() || !ladder.ok()) {
                *error = parsed.ok()
                             ? tr("%1: the listing does not draw as a ladder")
                                   .arg(QDir::toNativeSeparators(view.source->programPath()))
                             : parsed.errors.front().message;
                return false;
            }
            project.program = ladder.ladder;
        }
    }
    if (view.source->model())
        project.model = view.source->model()->name;
    view.document->setProject(project, view.source->programPath());
    return true;
}

bool NetworkWindow::open(const QString &path, QString *error) {
    if (!m_doc->open(path, error))
        return false;
    m_path = QFileInfo(path).absoluteFilePath();
    QString why;
    if (!buildSession(&why))
        statusBar()->showMessage(why, 15000);
    // The stations' list as tall as its rows, the inputs and outputs below it the rest; the
    // ladder the middle of a 1366x768 screen.
    const int rows = std::clamp<int>(int(m_views.size()), 1, 8);
    resizeDocks({m_stationsDock, m_ioDock},
                {rows * m_stationList->fontMetrics().height() + 12, 400}, Qt::Vertical);
    resizeDocks({m_stationsDock, m_watchDock}, {330, 300}, Qt::Horizontal);
    resizeDocks({m_chartDock}, {200}, Qt::Vertical);
    retranslate();
    return true;
}

bool NetworkWindow::newNetwork(QString *) {
    m_doc->newNetwork();
    m_path.clear();
    dropSession();
    m_tabs->setCurrentWidget(m_view);
    statusBar()->showMessage(
        tr("An empty network: add stations from the Network view's menu (right click)"), 15000);
    retranslate();
    return true;
}

void NetworkWindow::dropSession() {
    m_history->setSession(nullptr); // the views back to live while they exist
    m_panel->setMonitorSource(nullptr);
    m_debug->setSession(nullptr, {});
    for (StationView &v : m_views) {
        v.ladder->setMonitorSource(nullptr);
        v.io->setMonitorSource(nullptr);
        delete v.ladder;
        delete v.io;
        delete v.document;
    }
    m_views.clear();
    m_selector->blockSignals(true);
    m_selector->clear();
    m_selector->blockSignals(false);
    m_stationList->blockSignals(true);
    m_stationList->clear();
    m_stationList->blockSignals(false);
    m_watch->setSession(nullptr);
    m_chart->setSession(nullptr);
    m_traffic->clear();
    m_bridges->setSession(nullptr);
    m_session.reset();
    m_stale = false;
    buildFaultsMenu();
    updateActions();
    updateStatus();
}

bool NetworkWindow::buildSession(QString *error) {
    const QStringList watched = m_watch->devices();
    const QStringList charted = m_chart->devices();
    const QString station = currentStation();
    dropSession();
    const network::NetworkDescription &description = m_doc->description();
    if (description.stations.empty()) {
        *error = tr("The network has no station yet: add one from the Network view's menu");
        return false;
    }
    std::unique_ptr<network::NetworkSession> session =
        network::NetworkSession::start(description, cliProgramLoader(), error, nullptr,
                                       [this, &description](const network::Network &built) {
                                           m_traffic->setNetwork(built, description.file);
                                       });
    if (!session)
        return false;
    m_session = std::move(session);
    m_watch->setSession(m_session.get());
    m_chart->setSession(m_session.get());
    m_history->setSession(m_session.get());
    m_selector->blockSignals(true);
    for (network::StationSource *source : m_session->stations()) {
        StationView v;
        v.name = source->stationName();
        v.source = source;
        v.document = new editor::Document(this);
        QString why;
        if (!loadStationDocument(v, &why))
            statusBar()->showMessage(why, 10000);
        // The running network has the program as its file was at the start (or the last
        // Stop): the ladder here shows it, and edits are made in the main window.
        v.document->setRungEditGuard([this](int, int) {
            statusBar()->showMessage(tr("A station's program is edited in the main window: "
                                        "Network > Edit Station Program; Stop reads it again"),
                                     8000);
            return false;
        });
        v.ladder = new editor::LadderView(v.document, m_ladders);
        v.ladder->setObjectName(QStringLiteral("networkLadder_") + v.name);
        v.ladder->setMonitorSource(source);
        m_ladders->addWidget(v.ladder);
        v.io = new editor::IoPanel(v.document, m_ioPanels);
        v.io->setMonitorSource(source);
        m_ioPanels->addWidget(v.io);
        //: a station in the selector: its name, the PLC family and model, e.g. "s5 (Vigor M/VB/VH
        //: VB)"
        const QString label = tr("%1 (%2 %3)")
                                  .arg(v.name, source->target().displayName,
                                       source->model() ? source->model()->name : QString())
                                  .trimmed();
        m_selector->addItem(label);
        m_stationList->addItem(label);
        m_views.push_back(v);
    }
    m_selector->blockSignals(false);
    connect(m_session.get(), &network::NetworkSession::runStateChanged, this, [this] {
        updateActions();
        updateStatus();
    });
    connect(m_session.get(), &network::NetworkSession::clockChanged, this,
            &NetworkWindow::updateStatus);
    connect(m_session.get(), &network::NetworkSession::trafficAvailable, this, [this] {
        bool startedOver = false;
        std::vector<network::TrafficRecord> records = m_session->takeTraffic(&startedOver);
        if (startedOver)
            m_traffic->clear();
        m_traffic->append(std::move(records));
    });
    connect(m_session.get(), &network::NetworkSession::errorTextChanged, this,
            [this](const QString &text) {
                if (!text.isEmpty())
                    statusBar()->showMessage(text, 15000);
            });
    QString ignored;
    for (const QString &d : watched)
        m_watch->addDevice(d, &ignored);
    for (const QString &d : charted)
        m_chart->addDevice(d);
    std::vector<NetworkDebugController::StationParts> debugged;
    for (const StationView &v : m_views)
        debugged.push_back({v.name, v.source, v.document, v.ladder});
    m_debug->setSession(m_session.get(), debugged);
    if (!m_views.empty() && !selectStation(station))
        selectStation(m_views.front().name);
    m_bridges->setSession(m_session.get());
    buildFaultsMenu();
    updateActions();
    retranslate();
    return true;
}

void NetworkWindow::documentChanged() {
    updateTitle();
    if (m_session && m_session->runState() != RunState::Stopped) {
        // A running network goes on as it was built; Stop builds the edited one.
        m_stale = true;
        statusBar()->showMessage(tr("The network was edited: Stop builds it again with the change"),
                                 10000);
        return;
    }
    QString why;
    if (!buildSession(&why))
        statusBar()->showMessage(why, 15000);
}

void NetworkWindow::updateTitle() {
    const QString name = m_doc ? m_doc->displayName() : QString();
    //: the window's title: the network file's name, * when it has unsaved edits
    setWindowTitle(tr("%1%2 - Network - Rung Studio")
                       .arg(name, m_doc && m_doc->isModified() ? QStringLiteral("*") : QString()));
}

bool NetworkWindow::save(bool askWhere) {
    QString file;
    if (askWhere || m_doc->filePath().isEmpty()) {
        file = askSaveFile(this, tr("Save Network"), m_doc->filePath(),
                           tr("Networks of PLCs (*.rungnet)"));
        if (file.isEmpty())
            return false;
        if (QFileInfo(file).suffix().isEmpty())
            file += QStringLiteral(".rungnet");
    }
    if (!saveNetwork(this, m_doc, file))
        return false;
    m_path = m_doc->filePath();
    updateTitle();
    return true;
}

QString NetworkWindow::currentStation() const {
    const int i = m_ladders->currentIndex();
    return i >= 0 && i < int(m_views.size()) ? m_views[std::size_t(i)].name : QString();
}

bool NetworkWindow::selectStation(const QString &name) {
    for (std::size_t i = 0; i < m_views.size(); ++i)
        if (m_views[i].name == name) {
            const bool changed = m_ladders->currentIndex() != int(i);
            m_ladders->setCurrentIndex(int(i));
            m_ioPanels->setCurrentIndex(int(i));
            network::StationSource *source = m_views[i].source;
            m_session->setPowerFlowStation(name);
            m_panel->setPlc(&source->target(), source->model() ? source->model()->name : QString());
            m_panel->setContext(source->panelContext());
            m_panel->setMonitorSource(m_history->shownSource(source));
            m_debug->selectStation(name);
            const QSignalBlocker selector(m_selector), list(m_stationList);
            m_selector->setCurrentIndex(int(i));
            m_stationList->setCurrentRow(int(i));
            if (m_view->selectedStation() != name)
                m_view->select(name);
            if (changed)
                emit stationChanged(name);
            return true;
        }
    return false;
}

editor::LadderView *NetworkWindow::ladderView(const QString &station) const {
    for (const StationView &v : m_views)
        if (v.name == station)
            return v.ladder;
    return nullptr;
}

editor::Document *NetworkWindow::document(const QString &station) const {
    for (const StationView &v : m_views)
        if (v.name == station)
            return v.document;
    return nullptr;
}

bool NetworkWindow::watch(const QString &device) {
    QString error;
    if (!m_watch->addDevice(device, &error)) {
        statusBar()->showMessage(error, 10000);
        return false;
    }
    return true;
}

void NetworkWindow::addWatchedFromLine() {
    if (watch(m_watchLine->text()))
        m_watchLine->clear();
}

QString NetworkWindow::statusText() const {
    if (!m_session)
        return tr("No network");
    QString state;
    switch (m_session->runState()) {
    case RunState::Running:
        state = tr("Running");
        break;
    case RunState::Stepping:
        state = tr("Stepping");
        break;
    case RunState::Paused:
        state = tr("Paused");
        break;
    default:
        state = tr("Stopped");
        break;
    }
    //: %1 run state, %2 virtual time, %3 number of stations
    return tr("%1, %2, %n station(s)", nullptr, int(m_views.size()))
        .arg(state, SimulationController::clockText(m_session->nowUs() / 1000));
}

void NetworkWindow::updateStatus() {
    if (m_status)
        m_status->setText(statusText());
}

void NetworkWindow::updateActions() {
    const bool have = m_session != nullptr;
    const RunState s = have ? m_session->runState() : RunState::Offline;
    if (m_run) {
        m_run->setEnabled(have && s != RunState::Running);
        m_pause->setEnabled(have && (s == RunState::Running || s == RunState::Stepping));
        m_stop->setEnabled(have && s != RunState::Stopped);
        m_scan->setEnabled(have && s != RunState::Running);
        m_powerCycle->setEnabled(have);
        m_editProgram->setEnabled(have);
    }
}

} // namespace rung::app
