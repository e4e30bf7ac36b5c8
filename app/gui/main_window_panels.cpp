#include "main_window.h"

#include "file_controller.h"
#include "front_panel_controller.h"
#include "online_controller.h"
#include "simulation_controller.h"
#include "tests_panel.h"

#include "comms/driver/online_session.h"

#include "editor/io_panel.h"
#include "editor/timing_chart.h"
#include "editor/watch_list_view.h"
#include "editor/watch_panel.h"

#include "simulator/session.h"

#include <QDir>
#include <QDockWidget>
#include <QMenu>
#include <QMessageBox>
#include <QStatusBar>

// The monitoring docks: the watch table, the inputs and outputs panel and the timing chart.
// Each reads a model::MonitorSource only (setPanelsSource): the simulation now, an online PLC
// later.

namespace rung::app {

void MainWindow::buildMonitorDocks() {
    const auto dock = [this](const char *name, QWidget *content, Qt::DockWidgetArea area) {
        auto *d = new QDockWidget(this);
        d->setObjectName(QString::fromLatin1(name));
        d->setWidget(content);
        addDockWidget(area, d);
        return d;
    };
    m_watchPanel = new editor::WatchPanel(m_document);
    m_watch = m_watchPanel->view();
    m_ioPanel = new editor::IoPanel(m_document);
    m_chart = new editor::TimingChart(m_document);
    // The table and the chart below the ladder with the problems, the terminals with the
    // live docks (dock_layout.h). The terminals are hidden until a simulation starts (or
    // View shows them): the ladder keeps the width.
    dock("watchDock", m_watchPanel, Qt::BottomDockWidgetArea);
    dock("timingChartDock", m_chart, Qt::BottomDockWidgetArea);
    dock("ioDock", m_ioPanel, Qt::LeftDockWidgetArea)->hide();
    m_frontPanel = new FrontPanelController(m_document, this); // "frontPanelDock", hidden
    // The scenario tests of the project, a tab with the findings and records (dock_layout.h).
    auto *tests = new TestsPanel(m_document);
    tests->setHistory([this] {
        return m_simulation->session() ? m_simulation->session()->scanHistory() : nullptr;
    });
    tests->setOnlineSource(
        [this]() -> model::MonitorSource * { return m_online ? m_online->session() : nullptr; });
    connect(tests, &TestsPanel::message, this,
            [this](const QString &t) { statusBar()->showMessage(t, 10000); });
    dock("testsDock", tests, Qt::BottomDockWidgetArea);
    const auto say = [this](const QString &text) { statusBar()->showMessage(text, 10000); };
    connect(m_watchPanel, &editor::WatchPanel::message, this, say);
    connect(m_ioPanel, &editor::IoPanel::message, this, say);
    connect(m_chart, &editor::TimingChart::message, this, say);
    connect(m_chart, &editor::TimingChart::exportRequested, this, [this](const QString &format) {
        const QString path = m_files->askSavePath(tr("Export Timing Chart"),
                                                  QStringLiteral("*.%1").arg(format), {format});
        QString error;
        if (path.isEmpty())
            return;
        if (m_chart->exportTo(path, format, &error))
            statusBar()->showMessage(
                tr("Timing chart exported to %1").arg(QDir::toNativeSeparators(path)), 10000);
        else
            QMessageBox::critical(this, tr("Cannot export"), error);
    });
    retranslatePanels();
}

void MainWindow::retranslatePanels() {
    const auto title = [this](const char *name, const QString &text) {
        if (auto *d = findChild<QDockWidget *>(QString::fromLatin1(name)))
            d->setWindowTitle(text);
    };
    title("watchDock", tr("Watch"));
    title("ioDock", tr("Inputs and Outputs"));
    title("timingChartDock", tr("Timing Chart"));
    title("testsDock", tr("Tests"));
    m_frontPanel->retranslate();
}

void MainWindow::addPanelActions(QMenu *menu) {
    menu->addSeparator();
    // Every dock of the window can be opened again from here (the live ones from the
    // Simulation menu and Online's entry below): a closed Project or Problems had no way back.
    for (const char *name : {"projectDock", "crossReferenceDock", "problemsDock", "watchDock",
                             "ioDock", "frontPanelDock", "timingChartDock", "testsDock"})
        if (auto *d = findChild<QDockWidget *>(QString::fromLatin1(name)))
            menu->addAction(d->toggleViewAction());
}

void MainWindow::setPanelsSource(model::MonitorSource *source) {
    // The front panel is the simulated PLC's (a real PLC has its own): an online session does
    // not feed it, nor is it polled for the panel's words.
    const bool online = m_online && m_online->session() && source == m_online->session();
    if (!online)
        m_frontPanel->setSimulationSource(source);
    // Online, the PLC keeps the panels (main_window_online.cpp).
    if (m_online && m_online->session() && source != m_online->session())
        return;
    m_watchPanel->setMonitorSource(source);
    m_ioPanel->setMonitorSource(source);
    m_chart->setMonitorSource(source);
    // The first simulation of the window shows its terminals, and its front panel as a tab
    // behind the docks in front (closed again, they stay so).
    if (source && !m_panelsShown) {
        m_panelsShown = true;
        if (auto *d = findChild<QDockWidget *>(QStringLiteral("frontPanelDock"));
            d && !d->isVisible() && !online)
            d->show();
        if (auto *d = findChild<QDockWidget *>(QStringLiteral("ioDock")); d && !d->isVisible()) {
            d->show();
            d->raise();
        }
    }
}

} // namespace rung::app
