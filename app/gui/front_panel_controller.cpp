#include "front_panel_controller.h"

#include "editor/document.h"
#include "editor/front_panel.h"

#include <QDockWidget>
#include <QFileInfo>
#include <QMainWindow>
#include <QStatusBar>

namespace rung::app {

FrontPanelController::FrontPanelController(editor::Document *document, QMainWindow *window)
    : QObject(window)
    , m_document(document)
    , m_dock(new QDockWidget(window))
    , m_panel(new editor::FrontPanel) {
    m_dock->setObjectName(QStringLiteral("frontPanelDock"));
    m_dock->setWidget(m_panel);
    window->addDockWidget(Qt::RightDockWidgetArea, m_dock);
    m_dock->hide();
    // The ports' settings are the project's (programChanged); its name is the file's.
    for (auto signal : {&editor::Document::programChanged, &editor::Document::nameChanged})
        connect(document, signal, this, [this] {
            if (!m_pinned)
                followDocument();
        });
    connect(m_panel, &editor::FrontPanel::message, this,
            [window](const QString &text) { window->statusBar()->showMessage(text, 10000); });
    followDocument();
    retranslate();
}

void FrontPanelController::followDocument() {
    const model::ModelVariant *variant = m_document->modelVariant();
    m_panel->setPlc(&m_document->target(), variant ? variant->name : QString());
    // The simulated PLC holds the document's program under the project's name (PL110 manual
    // 5.3: "il nome dell'applicazione ladder caricata"), its ports set as the project says.
    m_panel->setContext(model::panelContext(m_document->target(), variant,
                                            QFileInfo(m_document->name()).completeBaseName(),
                                            m_document->project().ports));
}

void FrontPanelController::setSimulationSource(model::MonitorSource *source) {
    m_simulation = source;
    if (!m_pinned)
        m_panel->setMonitorSource(source);
}

void FrontPanelController::showSource(model::MonitorSource *source, const model::Target &target,
                                      const QString &modelName) {
    m_pinned = true;
    m_panel->setPlc(&target, modelName);
    m_panel->setContext(std::nullopt); // another PLC's: what it holds is not the document's
    m_panel->setMonitorSource(source);
}

void FrontPanelController::showSimulation() {
    m_pinned = false;
    followDocument();
    m_panel->setMonitorSource(m_simulation);
}

void FrontPanelController::retranslate() {
    m_dock->setWindowTitle(tr("Front Panel"));
}

} // namespace rung::app
