#include "main_window.h"

#include "connection_panel.h"
#include "debug_controller.h"
#include "dialogs.h"
#include "eliding_label.h"
#include "file_controller.h"
#include "layout_controller.h"
#include "listing_controller.h"
#include "online_controller.h"
#include "simulation_controller.h"
#include "simulation_menu.h"
#include "status_bar.h"
#include "symbol_table.h"

#include "editor/il_editor.h"
#include "editor/ladder_view.h"
#include "editor/problems_view.h"
#include "editor/watch_list_view.h"

#include "simulator/session.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QDockWidget>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QPushButton>
#include <QStatusBar>
#include <QTimer>
#include <QVBoxLayout>

#include <algorithm>

namespace rung::app {

MainWindow::MainWindow(QWidget *parent)
    : QMainWindow(parent)
    , m_document(new editor::Document(this)) {
    setObjectName(QStringLiteral("MainWindow"));
    m_ladder = new editor::LadderView(m_document);
    m_ladder->setObjectName(QStringLiteral("ladderView"));
    m_il = new editor::IlEditor(m_document->target());
    m_il->setDeviceSource([this] { return m_document->knownDevices(true); });
    m_il->setObjectName(QStringLiteral("ilEditor"));
    m_problems = new editor::ProblemsView;
    m_problems->setObjectName(QStringLiteral("problemsView"));
    // The ladder and the list as tabs or side by side; the docks' places (layout_controller.h).
    m_layout = new LayoutController(this, m_ladder, m_il, this);
    setStatusBar(new StatusBar); // a long message ends in "…" before the fields

    m_statusTarget = new QLabel;
    m_statusSteps = new QLabel;
    m_statusCursor = new ElidingLabel; // the first to give way in a full status bar
    statusBar()->addWidget(m_statusCursor, 1);
    statusBar()->addPermanentWidget(m_statusSteps);
    statusBar()->addPermanentWidget(m_statusTarget);

    buildDocks();
    buildCrossReference();
    buildMonitorDocks(); // main_window_panels.cpp
    setupSimulation();
    setupOnline(); // main_window_monitor.cpp
    // The list as typed follows the program after the simulation and the connection did
    // (their programChanged first), as the window always had it.
    m_listing =
        new ListingController(m_document, m_ladder, m_il, m_problems, statusBar(), this, this);
    connect(m_listing, &ListingController::refreshed, this, [this] {
        m_symbols->refresh();
        refreshProjectInfo();
        updateStatus();
        updateTitle(); // the list as typed counts as unsaved work
    });
    m_files = new FileController(m_document, m_ladder, m_il, m_listing, m_symbols, statusBar(),
                                 this, this);
    connect(m_files, &FileController::saved, this, [this] {
        refreshProjectInfo();
        updateTitle();
    });
    m_files->setNetworkOpener(
        [this](const QString &path, QString *error) { return openNetwork(path, error) != nullptr; });
    buildActions();

    connect(m_document, &editor::Document::nameChanged, this, [this] {
        updateTitle();
        refreshProjectInfo();
    });
    connect(m_document->undoStack(), &QUndoStack::cleanChanged, this, &MainWindow::updateTitle);
    connect(m_ladder, &editor::LadderView::cursorMoved, this, [this](const editor::CellCursor &c) {
        updateStatus();
        const int line = m_document->firstLineOfRung(c.rung);
        // Lines are counted in the canonical text; a text as typed has lines of its own.
        if (line > 0 && !m_il->hasFocus() && m_il->text() == m_document->listingText()) {
            // The listing follows the ladder: its rung's lines come into view, selected.
            const int next = m_document->firstLineOfRung(c.rung + 1);
            m_il->setSelection(line - 1, 0, next > 0 ? next - 1 : m_il->lines() - 1, 0);
            m_il->ensureLineVisible(line - 1);
        }
    });
    connect(m_ladder, &editor::LadderView::message, this,
            [this](const QString &text) { statusBar()->showMessage(text, 5000); });
    connect(m_il, &editor::IlEditor::message, this,
            [this](const QString &text) { statusBar()->showMessage(text, 5000); });
    connect(m_il, &QsciScintilla::cursorPositionChanged, this, [this](int line, int) {
        updateStatus();
        if (!m_il->hasFocus())
            return;
        const int rung = m_document->rungOfLine(line + 1);
        if (rung >= 0 && rung != m_ladder->cursor().rung &&
            m_il->text() == m_document->listingText())
            m_ladder->setCursor({rung, 0, 0});
    });
    connect(m_problems, &editor::ProblemsView::locate, this, &MainWindow::locate);
    // The status bar's cursor is the ladder's cell or the list's line, whichever has focus.
    connect(qApp, &QApplication::focusChanged, this, [this](QWidget *, QWidget *now) {
        if (now == m_il || now == m_ladder)
            updateStatus();
    });

    m_layout->restore(); // the first start's places, or those the user left
    m_listing->refreshFromDocument();
    updateTitle();
}

SimulationPanel *MainWindow::simulationPanel() const {
    return m_debug->simulationPanel();
}

ScanDebuggerView *MainWindow::scanDebugger() const {
    return m_debug->scanDebugger();
}

ConnectionPanel *MainWindow::connectionPanel() const {
    return m_online->panel();
}

MainWindow::~MainWindow() {
    // The child widgets outlive this body and emit while they go (cursor moves, text
    // cleared): nothing of this window may answer them any more.
    // ~QWidget hides the window, which moves the application's focus: the lambda on
    // focusChanged would run on an object that is no longer a MainWindow.
    disconnect(qApp, nullptr, this, nullptr);
    m_il->disconnect(this);
    m_ladder->disconnect(this);
    m_document->disconnect(this);
    m_problems->disconnect(this);
    m_symbols->disconnect(this);
    // The menus' actions answer the stack, the list and the ladder too (undoAction, the
    // palette): they go after the members they read.
    for (QObject *o : findChildren<QObject *>()) {
        if (!qobject_cast<QAction *>(o) && !qobject_cast<QActionGroup *>(o))
            continue;
        m_document->undoStack()->disconnect(o);
        m_il->disconnect(o);
        m_ladder->disconnect(o);
    }
    m_document->undoStack()->disconnect(this);
    delete m_listing; // its answers to the document, the list and the ladder go with it
}

void MainWindow::buildDocks() {
    auto *problemsDock = new QDockWidget(tr("Problems"), this);
    problemsDock->setObjectName(QStringLiteral("problemsDock"));
    problemsDock->setWidget(m_problems);
    addDockWidget(Qt::BottomDockWidgetArea, problemsDock);

    auto *projectDock = new QDockWidget(tr("Project"), this);
    projectDock->setObjectName(QStringLiteral("projectDock"));
    auto *panel = new QWidget;
    auto *layout = new QVBoxLayout(panel);
    m_projectInfo = new QLabel;
    m_projectInfo->setWordWrap(true);
    layout->addWidget(m_projectInfo);
    m_symbolsLabel = new QLabel(tr("Symbols"));
    layout->addWidget(m_symbolsLabel);
    m_symbols = new SymbolTable(m_document);
    layout->addWidget(m_symbols, 1);
    projectDock->setWidget(panel);
    addDockWidget(Qt::LeftDockWidgetArea, projectDock);
    connect(m_symbols, &SymbolTable::message, this,
            [this](const QString &text) { statusBar()->showMessage(text, 5000); });
    connect(m_symbols, &SymbolTable::pendingChanged, this, &MainWindow::updateTitle);
}

void MainWindow::editRungComment() {
    const auto &rungs = m_document->ladder().rungs;
    const int index = m_ladder->cursor().rung;
    if (index < 0 || index >= static_cast<int>(rungs.size()))
        return;
    bool ok = false;
    const QString text =
        askMultiLineText(this, tr("Rung Comment"), tr("Comment above rung %1:").arg(index + 1),
                         rungs[static_cast<std::size_t>(index)].comment, &ok);
    if (ok)
        m_ladder->setRungComment(text);
}

void MainWindow::setSideBySide(bool sideBySide) {
    m_layout->setSideBySide(sideBySide);
}

void MainWindow::refreshProjectInfo() {
    const model::Target &t = m_document->target();
    const int rungs = static_cast<int>(m_document->ladder().rungs.size());
    m_projectInfo->setText(tr("<b>%1</b><br>Target: %2, model %3<br>%4, %5")
                               .arg(m_document->name().toHtmlEscaped(), t.displayName,
                                    m_document->modelVariant()->name,
                                    tr("%n rung(s)", nullptr, rungs),
                                    tr("%n step(s)", nullptr, m_document->stepCount())));
}

void MainWindow::updateStatus() {
    const model::Target &t = m_document->target();
    const model::ModelVariant *m = m_document->modelVariant();
    m_statusTarget->setText(tr("%1 %2").arg(t.displayName, m->name));
    const int limit = m->programSteps > 0 ? m->programSteps : t.limits.programSteps;
    m_statusSteps->setText(tr("%1 / %2 steps").arg(m_document->stepCount()).arg(limit));
    if (m_il->hasFocus()) {
        int line = 0;
        int index = 0;
        m_il->getCursorPosition(&line, &index);
        m_statusCursor->setFullText(tr("Line %1, column %2").arg(line + 1).arg(index + 1));
    } else {
        const editor::CellCursor c = m_ladder->cursor();
        m_statusCursor->setFullText(
            tr("Rung %1, row %2, column %3").arg(c.rung + 1).arg(c.row + 1).arg(c.column + 1));
    }
    // Short, and where the user is: whole ("Segmento 1, riga 1, colo..." was cut).
    m_statusCursor->setMinimumWidth(m_statusCursor->sizeHint().width());
}

void MainWindow::updateTitle() {
    const QString name = m_document->name();
    // While values are shown, the title says whose (simulation, online PLC, history).
    if (m_monitorSource)
        setWindowTitle(
            QStringLiteral("%1[*] — %2 — Rung Studio").arg(name, originText(m_monitorOrigin)));
    else
        setWindowTitle(QStringLiteral("%1[*] — Rung Studio").arg(name));
    setWindowModified(isModified());
}

void MainWindow::applyListing() {
    m_listing->applyListing();
}

bool MainWindow::openFile(const QString &path, const QString &targetId, bool quiet) {
    return m_files->openFile(path, targetId, quiet);
}

bool MainWindow::saveTo(const QString &path) {
    return m_files->saveTo(path);
}

QString MainWindow::completeSavePath(const QString &chosen, const QStringList &suffixes) {
    return m_files->completeSavePath(chosen, suffixes);
}

bool MainWindow::isModified() const {
    return m_files->isModified();
}

void MainWindow::newProject(const model::Target &target, const QString &modelName) {
    m_files->newProject(target, modelName);
}

QString MainWindow::recoveryPath() const {
    return m_files->recoveryPath();
}

void MainWindow::writeRecovery() {
    m_files->writeRecovery();
}

bool MainWindow::offerRecovery(bool ask) {
    return m_files->offerRecovery(ask);
}

void MainWindow::start(const QString &file, const QString &targetId, bool askToRecover) {
    m_files->start(file, targetId, askToRecover);
}

void MainWindow::locate(const model::Diagnostic &d) {
    if (d.location.onLadder()) {
        m_layout->showPage(m_ladder);
        m_ladder->setCursor(
            {d.location.rung, std::max(0, d.location.row), std::max(0, d.location.cell)});
        m_ladder->setFocus();
    } else if (d.location.onListing()) {
        m_layout->showPage(m_il);
        m_il->goToLine(d.location.line);
    }
}

void MainWindow::changeEvent(QEvent *event) {
    if (event->type() == QEvent::LanguageChange && m_toolBar)
        retranslate();
    QMainWindow::changeEvent(event);
}

void MainWindow::retranslate() {
    const QList<QAction *> menus = menuBar()->actions();
    menuBar()->clear();
    for (QAction *a : menus)
        delete a->menu(); // with its actions and submenus
    buildActions();
    if (auto *dock = findChild<QDockWidget *>(QStringLiteral("projectDock")))
        dock->setWindowTitle(tr("Project"));
    if (auto *dock = findChild<QDockWidget *>(QStringLiteral("crossReferenceDock")))
        dock->setWindowTitle(tr("Cross Reference"));
    m_symbolsLabel->setText(tr("Symbols"));
    m_debug->retranslate();
    m_simulationMenu->updateStatus();
    retranslatePanels();
    m_layout->retranslate();
    // The findings again, now in this language; the list as typed (errors or forms of its own)
    // stays, and its own findings are read again from it.
    m_listing->recheck();
    statusBar()->clearMessage(); // a message of the old language would stay in it
    updateStatus();
    updateMonitorLabel();
    updateTitle();
}

void MainWindow::closeEvent(QCloseEvent *event) {
    if (!m_files->maybeSave()) {
        event->ignore();
        return;
    }
    m_layout->save();
    m_files->closing();
    event->accept();
}

} // namespace rung::app
