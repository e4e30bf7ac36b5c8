#include "main_window.h"

#include "dialogs.h"
#include "dock_layout.h"
#include "eliding_label.h"
#include "recovery.h"
#include "status_bar.h"
#include "symbol_table.h"

#include "editor/il_editor.h"
#include "editor/ladder_view.h"
#include "editor/listing_lines_command.h"
#include "editor/problems_view.h"
#include "editor/watch_list_view.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QDockWidget>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QPushButton>
#include <QScreen>
#include <QSettings>
#include <QSplitter>
#include <QStatusBar>
#include <QTabBar>
#include <QTabWidget>
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
    m_tabs = new QTabWidget;
    m_split = new QSplitter(Qt::Horizontal);
    auto *central = new QWidget;
    auto *layout = new QVBoxLayout(central);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_tabs);
    layout->addWidget(m_split);
    setCentralWidget(central);
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
    setupOnline(); // main_window_online.cpp
    // Editing docks left, live ones together, findings below (dock_layout.h); a saved
    // layout, restored below, keeps the user's own.
    const bool wide = screen()->availableGeometry().width() >= kWideScreen;
    arrangeDocks(this, wide);
    // The layout took its minimum size while the docks were added one beside the other
    // (four below the ladder: wider than an 800 px screen); grouped, they need less, and the
    // resize below must not be held to the old minimum.
    QMainWindow::layout()->activate();
    buildActions();

    m_ilTimer.setSingleShot(true);
    m_ilTimer.setInterval(500);
    connect(&m_ilTimer, &QTimer::timeout, this, &MainWindow::applyListing);
    connect(m_il, &editor::IlEditor::listingEdited, this, [this] { m_ilTimer.start(); });
    connect(m_document, &editor::Document::programChanged, this, &MainWindow::refreshFromDocument);
    m_document->setRungEditGuard(
        [this](int first, int count) { return mayReplaceTypedList(first, count); });
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
    connect(m_problems, &editor::ProblemsView::applyFix, this, &MainWindow::applyFix);

    m_recovery = std::make_unique<RecoveryFile>();
    m_recoveryTimer.setInterval(60 * 1000);
    connect(&m_recoveryTimer, &QTimer::timeout, this, &MainWindow::writeRecovery);
    m_recoveryTimer.start();

    QSettings settings;
    setSideBySide(settings.value(QStringLiteral("view/sideBySide"), false).toBool());
    m_split->restoreState(settings.value(QStringLiteral("view/split")).toByteArray());
    // Roomy where the screen allows, never larger than it: on a 1366x768 laptop a 1400x900
    // window would hide the problems and the status bar below the screen's edge.
    const QSize available = screen()->availableGeometry().size();
    resize(QSize(1400, 900).boundedTo(available - QSize(16, 32)));
    resizeDocks({findChild<QDockWidget *>(QStringLiteral("problemsDock"))}, {150}, Qt::Vertical);
    resizeDocks({findChild<QDockWidget *>(QStringLiteral("projectDock"))}, {230}, Qt::Horizontal);
    restoreGeometry(settings.value(QStringLiteral("window/geometry")).toByteArray());
    if (!restoreState(settings.value(QStringLiteral("window/state")).toByteArray(),
                      kDockLayoutVersion)) {
        // First start (or a layout of the docks before issue 31): the columns as wide as the
        // ladder leaves them. Docks take sizes once laid out.
        QTimer::singleShot(0, this, [this, wide] { sizeDocks(this, wide); });
    }
    refreshFromDocument();
    updateTitle();
}

MainWindow::~MainWindow() {
    // The child widgets outlive this body and emit while they go (cursor moves, text
    // cleared): nothing of this window may answer them any more.
    m_ilTimer.stop();
    m_recoveryTimer.stop();
    m_document->setRungEditGuard({});
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
    m_sideBySide = sideBySide;
    QSettings().setValue(QStringLiteral("view/sideBySide"), sideBySide);
    m_tabs->clear();
    if (sideBySide) {
        m_split->addWidget(m_ladder);
        m_split->addWidget(m_il);
        // The list's comment lines want about 60 characters; the ladder keeps the larger part.
        m_split->setStretchFactor(0, 3);
        m_split->setStretchFactor(1, 2);
        // Out of the tabs the pages come hidden (a tab widget hides all but its current one).
        m_ladder->show();
        m_il->show();
        m_split->show();
        m_tabs->hide();
    } else {
        m_tabs->addTab(m_ladder, tr("Ladder"));
        m_tabs->addTab(m_il, tr("Instruction List"));
        m_tabs->show();
        m_split->hide();
    }
}

void MainWindow::refreshFromDocument() {
    // The list pane takes the ladder's listing when the rungs changed, or when it shows the
    // listing it was given (in another language, say); a change of the symbols or the watch
    // lists leaves the list as typed as it is.
    const bool rungsChanged = m_document->rungsRevision() != m_shownRevision;
    if (!m_editingListing && (rungsChanged || m_il->text() == m_shownListing)) {
        if (model::hasErrors(m_listingErrors))
            statusBar()->showMessage(tr("The list as typed had errors and now shows the "
                                        "ladder's program; Ctrl+Z in the list brings it back"),
                                     10000);
        m_il->setListing(m_document->listingText());
        m_shownListing = m_document->listingText();
        m_listingErrors.clear();
        m_ladder->setNotice(QString()); // it spoke of the errors of a list no longer shown
    }
    m_shownRevision = m_document->rungsRevision();
    // The list pane shows the text as typed (with errors or forms of its own), or the listing.
    const bool typed =
        m_editingListing || !m_listingErrors.empty() || m_il->text() != m_document->listingText();
    std::vector<model::Diagnostic> all = m_document->diagnostics();
    all.insert(all.end(), m_listingErrors.begin(), m_listingErrors.end());
    m_problems->setDiagnostics(all);
    if (auto *dock = findChild<QDockWidget *>(QStringLiteral("problemsDock")))
        dock->setWindowTitle(m_problems->summary());
    if (!typed) {
        // Listing findings of the canonical text: map each rung's findings to its lines.
        std::vector<model::Diagnostic> onLines;
        for (model::Diagnostic d : m_document->diagnostics()) {
            if (d.location.rung < 0)
                continue;
            d.location.line = m_document->lineOf(d.location);
            if (d.location.line > 0)
                onLines.push_back(d);
        }
        m_il->showDiagnostics(onLines);
    } else {
        m_il->showDiagnostics(m_listingErrors);
    }
    std::vector<int> stepOfLine;
    if (typed) {
        // The text as typed (with errors, or in a form of its own): its lines that parse
        // keep their step numbers, as the parser counts them. A typing pause refreshes twice
        // (the document's change, then the apply): the text is parsed for this once.
        const QString typed = m_il->text();
        if (typed != m_typedSteps.text || m_document->modelVariant() != m_typedSteps.model) {
            const model::ParseResult parsed = model::parseInstructionList(
                m_document->target(), typed, m_document->modelVariant());
            std::vector<int> steps(static_cast<std::size_t>(std::max(0, m_il->lines())), -1);
            for (const model::Instruction &ins : parsed.list.instructions)
                if (ins.line >= 1 && ins.line <= static_cast<int>(steps.size()))
                    steps[static_cast<std::size_t>(ins.line - 1)] = ins.step;
            // A text of the program's own instructions, written its own way (spacing,
            // comments, aliases): its lines can show the running program's values.
            std::vector<int> lineOf;
            const auto &program = m_document->listing().list.instructions;
            const auto &read = parsed.list.instructions;
            if (parsed.ok() && read.size() == program.size() &&
                std::equal(read.begin(), read.end(), program.begin(),
                           [](const model::Instruction &a, const model::Instruction &b) {
                               return a.sameAs(b);
                           })) {
                lineOf.assign(steps.size(), -1);
                for (std::size_t i = 0; i < read.size(); ++i)
                    if (read[i].line >= 1 && read[i].line <= static_cast<int>(lineOf.size()))
                        lineOf[static_cast<std::size_t>(read[i].line - 1)] = static_cast<int>(i);
            }
            m_typedSteps = {m_document->modelVariant(), typed, std::move(steps), std::move(lineOf)};
        }
        stepOfLine = m_typedSteps.steps;
    } else {
        // The printer's line map: comment lines have no step.
        const auto &list = m_document->listing().list;
        for (const int i : m_document->printedListing().instructionOfLine)
            stepOfLine.push_back(i < 0 ? -1 : list.instructions[static_cast<std::size_t>(i)].step);
    }
    m_il->setStepNumbers(stepOfLine);
    updateMonitorLines(typed);
    m_symbols->refresh();
    refreshProjectInfo();
    updateStatus();
    updateTitle(); // the list as typed counts as unsaved work
}

bool MainWindow::mayReplaceTypedList(int first, int count) {
    if (m_editingListing)
        return true; // the list's own change
    if (m_ilTimer.isActive()) {
        // Typed just now, not yet checked. Text with errors is taken as such (the program
        // stays), so that the question below knows of it. A valid text becomes the program
        // now, its own undo step, so the edit adds to it instead of printing over it.
        std::vector<model::Diagnostic> errors;
        const bool valid =
            m_document->setListing(m_il->text(), &errors, editor::Document::ListingStep::Check);
        const std::vector<model::Rung> before =
            valid ? m_document->ladder().rungs : std::vector<model::Rung>{};
        applyListing();
        if (valid) {
            const std::vector<model::Rung> &after = m_document->ladder().rungs;
            const auto [b, a] =
                std::mismatch(before.begin(), before.end(), after.begin(), after.end());
            const auto unchanged = static_cast<int>(b - before.begin());
            if (unchanged < first + std::max(count, 0)) {
                statusBar()->showMessage(
                    tr("The list as typed was taken first and changed rung %1, so the ladder "
                       "edit was not made: make it again on the rung as it is now.")
                        .arg(unchanged + 1),
                    10000);
                return false;
            }
        }
    }
    const auto firstError = std::find_if(
        m_listingErrors.begin(), m_listingErrors.end(),
        [](const model::Diagnostic &d) { return d.severity == model::Severity::Error; });
    if (firstError == m_listingErrors.end())
        return true;
    QMessageBox box(QMessageBox::Question, tr("Replace the Instruction List?"),
                    tr("The instruction list as typed has errors (line %1: %2).")
                        .arg(firstError->location.line)
                        .arg(firstError->message),
                    QMessageBox::NoButton, this);
    box.setInformativeText(
        tr("This change to the ladder replaces the list with the ladder's program; Ctrl+Z in "
           "the list brings the typed text back. Cancel keeps the list as typed and leaves the "
           "ladder as it is."));
    QPushButton *replace = box.addButton(tr("Replace the List"), QMessageBox::AcceptRole);
    QPushButton *cancel = box.addButton(QMessageBox::Cancel);
    box.setDefaultButton(cancel);
    box.setEscapeButton(cancel);
    box.exec();
    return box.clickedButton() == replace;
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

void MainWindow::applyListing() {
    applyListingAs(editor::Document::ListingStep::Own);
}

void MainWindow::applyListingAs(editor::Document::ListingStep step) {
    m_ilTimer.stop(); // what is typed is applied now
    std::vector<model::Diagnostic> errors;
    m_editingListing = true;
    const bool ok = m_document->setListing(m_il->text(), &errors, step);
    m_listingErrors = errors; // when ok: the fuzzy forms of the text as typed
    if (ok || errors.empty()) {
        m_ladder->setNotice(QString());
        if (ok && !m_errorsMessage.isEmpty() && statusBar()->currentMessage() == m_errorsMessage)
            statusBar()->clearMessage();
    } else {
        const model::Diagnostic &first = errors.front();
        m_ladder->setNotice(
            tr("The instruction list has %1: line %2: %3. The ladder shows the last valid "
               "program.")
                .arg(errors.size() == 1 ? tr("an error") : tr("%1 errors").arg(errors.size()))
                .arg(first.location.line)
                .arg(first.message));
    }
    // While the text is invalid the ladder keeps the last valid program; the errors show in
    // the listing and in the problems panel.
    refreshFromDocument();
    m_editingListing = false;
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

QString MainWindow::pendingListing() const {
    return model::hasErrors(m_listingErrors) ? m_il->text() : QString();
}

bool MainWindow::isModified() const {
    return m_document->isModified() || pendingListing() != m_savedPending ||
           m_symbols->pending() != m_savedPendingSymbols;
}

model::Project MainWindow::projectToKeep() const {
    model::Project project = m_document->project();
    project.pendingListing = pendingListing();
    project.pendingSymbols = m_symbols->pending();
    return project;
}

void MainWindow::locate(const model::Diagnostic &d) {
    if (d.location.onLadder()) {
        if (m_tabs->isVisible())
            m_tabs->setCurrentWidget(m_ladder);
        m_ladder->setCursor(
            {d.location.rung, std::max(0, d.location.row), std::max(0, d.location.cell)});
        m_ladder->setFocus();
    } else if (d.location.onListing()) {
        if (m_tabs->isVisible())
            m_tabs->setCurrentWidget(m_il);
        m_il->goToLine(d.location.line);
    }
}

void MainWindow::applyFix(const model::Diagnostic &d) {
    if (!d.fix)
        return;
    if (d.fix->firstRung >= 0) {
        m_document->replaceRungs(d.fix->firstRung, d.fix->lastRung - d.fix->firstRung + 1,
                                 d.fix->rungs, d.fix->label);
        return;
    }
    // A listing fix rewrites the lines of the text as typed, the rest of it untouched, as one
    // step of the project's undo (Edit > Undo) and of the list's own (Ctrl+Z there). FZ001/FZ002
    // keep the program, FZ004-FZ006 reorder it: the step's redo and undo bring the program along
    // with the text in place, so that no second step ("Edit instruction list") is pushed.
    if (m_ilTimer.isActive())
        applyListing(); // what was typed before the fix is a step of its own
    const int first = d.fix->firstLine - 1;
    const int last = d.fix->lastLine - 1;
    if (first < 0 || last >= m_il->lines() || first > last)
        return;
    QStringList before;
    for (int line = first; line <= last; ++line)
        before << m_il->lineText(line);
    QStringList after = d.fix->listing.split(QLatin1Char('\n'));
    if (after.size() > 1 && after.back().isEmpty())
        after.removeLast();
    // The replaced lines count as typed: they are applied into the fix's own undo step.
    const auto follow = [this] { applyListingAs(editor::Document::ListingStep::InPlace); };
    m_document->undoStack()->push(
        new editor::ListingLinesCommand(m_il, first, before, after, follow, d.fix->label));
}

void MainWindow::changeEvent(QEvent *event) {
    if (event->type() == QEvent::LanguageChange && m_toolBar)
        retranslate();
    QMainWindow::changeEvent(event);
}

void MainWindow::childEvent(QChildEvent *event) {
    // Qt makes a tab bar for docks tabbed together when it lays them out, eliding the titles
    // to the dock's width: with the project, the cross reference, the terminals and the
    // simulation beside the ladder at 1366x768 every tab read "P...", "Si...". Whole titles
    // and scroll arrows tell each apart; polished is after Qt's own settings.
    if (event->polished())
        if (auto *tabs = qobject_cast<QTabBar *>(event->child())) {
            tabs->setElideMode(Qt::ElideNone);
            tabs->setUsesScrollButtons(true);
        }
    QMainWindow::childEvent(event);
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
    retranslateSimulation();
    retranslatePanels();
    if (m_tabs->count() == 2) {
        m_tabs->setTabText(0, tr("Ladder"));
        m_tabs->setTabText(1, tr("Instruction List"));
    }
    // The findings again, now in this language; the list as typed (errors or forms of its own)
    // stays, and its own findings are read again from it.
    const bool typed = !m_listingErrors.empty();
    m_editingListing = typed;
    m_document->recheck();
    m_editingListing = false;
    if (typed)
        applyListing();
    statusBar()->clearMessage(); // a message of the old language would stay in it
    updateStatus();
    updateMonitorLabel();
    updateTitle();
}

void MainWindow::closeEvent(QCloseEvent *event) {
    if (!maybeSave()) {
        event->ignore();
        return;
    }
    QSettings settings;
    settings.setValue(QStringLiteral("window/geometry"), saveGeometry());
    settings.setValue(QStringLiteral("window/state"), saveState(kDockLayoutVersion));
    if (m_sideBySide)
        settings.setValue(QStringLiteral("view/split"), m_split->saveState());
    m_recovery->remove();
    event->accept();
}

} // namespace rung::app
