#include "file_controller.h"

#include "compare_window.h"
#include "dialogs.h"
#include "example_titles.h"
#include "file_dialogs.h"
#include "installed_files.h"
#include "ladder_export.h"
#include "listing_controller.h"
#include "plcopen_exchange.h"
#include "recovery.h"
#include "symbol_table.h"
#include "tests_panel.h"

#include "editor/document.h"
#include "editor/il_editor.h"
#include "editor/ladder_view.h"
#include "editor/tool_icons.h"

#include "model/ladder/ladder_text.h"
#include "model/project/program_file.h"
#include "model/project/project.h"
#include "network/network_file.h"

#include <QComboBox>
#include <QDialog>
#include <QDialogButtonBox>
#include <QDir>
#include <QDirIterator>
#include <QDockWidget>
#include <QFileInfo>
#include <QFontMetrics>
#include <QFormLayout>
#include <QMenu>
#include <QMessageBox>
#include <QPrintPreviewDialog>
#include <QPrinter>
#include <QSettings>
#include <QStatusBar>
#include <QToolBar>

namespace rung::app {

namespace {

constexpr int kMaxRecent = 8;

} // namespace

FileController::FileController(editor::Document *document, editor::LadderView *ladder,
                               editor::IlEditor *il, ListingController *listing,
                               SymbolTable *symbols, QStatusBar *status, QWidget *window,
                               QObject *parent)
    : QObject(parent)
    , m_document(document)
    , m_ladder(ladder)
    , m_il(il)
    , m_listing(listing)
    , m_symbols(symbols)
    , m_status(status)
    , m_window(window)
    , m_recovery(std::make_unique<RecoveryFile>()) {
    m_recoveryTimer.setInterval(60 * 1000);
    connect(&m_recoveryTimer, &QTimer::timeout, this, &FileController::writeRecovery);
    m_recoveryTimer.start();
}

FileController::~FileController() = default;

void FileController::addActions(QMenu *file, QToolBar *bar) {
    QAction *newAction = file->addAction(editor::toolIcon(editor::ToolIcon::NewFile),
                                         tr("&New Project..."), this, &FileController::fileNew);
    newAction->setShortcut(QKeySequence::New);
    QAction *newNetwork = file->addAction(tr("New Net&work"), this, [this] {
        QString error;
        if (m_networkOpener && !m_networkOpener(QString(), &error))
            statusBar()->showMessage(error, 10000);
    });
    newNetwork->setObjectName(QStringLiteral("fileNewNetwork"));
    QAction *open = file->addAction(editor::toolIcon(editor::ToolIcon::OpenFile), tr("&Open..."),
                                    this, &FileController::fileOpen);
    open->setShortcut(QKeySequence::Open);
    m_recentMenu = file->addMenu(tr("Open &Recent"));
    m_examplesMenu = file->addMenu(tr("E&xamples"));
    m_examplesMenu->setObjectName(QStringLiteral("examplesMenu"));
    QAction *save = file->addAction(editor::toolIcon(editor::ToolIcon::SaveFile), tr("&Save"), this,
                                    &FileController::fileSave);
    save->setShortcut(QKeySequence::Save);
    file->addAction(tr("Save &As..."), this, &FileController::fileSaveAs)
        ->setShortcut(QKeySequence::SaveAs);
    file->addAction(tr("Co&mpare With..."), this, [this] {
        CompareWindow::compareWithFile(m_window, projectToKeep(), m_document->name(),
                                       m_document->path());
    });
    file->addSeparator();
    file->addAction(tr("&Import Instruction List..."), this, &FileController::importListing);
    file->addAction(tr("&Export Instruction List..."), this, &FileController::exportListing);
    file->addAction(tr("Import &PLCopen XML..."), this, [this] {
        if (!maybeSave())
            return;
        if (auto imported = importPlcopenFile(m_window, m_document->target(), m_document->path())) {
            showProject(imported->project, QString());
            nameImported(imported->path);
        }
    });
    file->addAction(tr("Expor&t PLCopen XML..."), this, [this] {
        m_listing->flush();
        exportPlcopenFile(
            m_window, projectToKeep(), m_document->name(), m_document->path(),
            m_listing->pendingListing().isEmpty()
                ? QString()
                : tr("The instruction list has "
                     "errors, so the ladder is not the program as typed: fix the list first."));
    });
    QMenu *exportMenu = file->addMenu(tr("Export &Ladder"));
    exportMenu->addAction(tr("As &PDF..."), this, [this] { exportImage(QStringLiteral("pdf")); });
    exportMenu->addAction(tr("As &SVG..."), this, [this] { exportImage(QStringLiteral("svg")); });
    exportMenu->addAction(tr("As P&NG..."), this, [this] { exportImage(QStringLiteral("png")); });
    file->addAction(tr("Print Pre&view..."), this, &FileController::printPreview)
        ->setShortcut(QKeySequence::Print);
    file->addSeparator();
    if (m_window)
        file->addAction(tr("&Quit"), m_window, &QWidget::close)->setShortcut(QKeySequence::Quit);
    bar->addAction(newAction);
    bar->addAction(open);
    bar->addAction(save);
    for (QAction *a : {newAction, open, save})
        a->setToolTip(QStringLiteral("%1 (%2)").arg(
            a->text().remove(QLatin1Char('&')).remove(QStringLiteral("...")),
            a->shortcut().toString(QKeySequence::NativeText)));
    rebuildRecentMenu();
    rebuildExamplesMenu();
}

bool FileController::isModified() const {
    return m_document->isModified() || m_listing->pendingListing() != m_savedPending ||
           m_symbols->pending() != m_savedPendingSymbols;
}

model::Project FileController::projectToKeep() const {
    model::Project project = m_document->project();
    project.pendingListing = m_listing->pendingListing();
    project.pendingSymbols = m_symbols->pending();
    return project;
}

void FileController::closing() {
    m_recovery->remove();
}

QString FileController::recoveryPath() const {
    return m_recovery->path();
}

void FileController::writeRecovery() {
    m_listing->flush(); // what was typed last is work too
    QString error;
    if (isModified() && !m_recovery->write(projectToKeep(), m_document->path(), &error))
        statusBar()->showMessage(error, 10000);
}

bool FileController::offerRecovery(bool ask) {
    QStringList unreadable;
    auto recovered = m_recovery->takeOrphan(
        [this, ask](const QString &origin) {
            const QString question =
                origin.isEmpty()
                    ? tr("Rung Studio was not closed properly last time. Recover the unsaved "
                         "program?")
                    : tr("Rung Studio was not closed properly last time. Recover the unsaved "
                         "changes to %1?")
                          .arg(QDir::toNativeSeparators(origin));
            return !ask || messageBox(QMessageBox::Question, m_window, tr("Recover"), question) ==
                               QMessageBox::Yes;
        },
        &unreadable);
    if (!unreadable.isEmpty()) {
        statusBar()->showMessage(unreadable.join(u' '), 15000);
        if (ask)
            messageBox(QMessageBox::Warning, m_window, tr("Recover"), unreadable.join(u'\n'));
    }
    if (!recovered)
        return false;
    showProject(recovered->project, recovered->origin);
    m_document->markUnsaved(); // no file has this work yet: closing asks to save it
    writeRecovery();           // now this instance's to keep
    return true;
}

void FileController::start(const QString &file, const QString &targetId, bool askToRecover) {
    // Recovery comes first, or a start with a file (as scripts/start.sh does) would never
    // offer it, and the next normal close would delete the orphan with its work.
    if (!offerRecovery(askToRecover) && !file.isEmpty())
        openFile(file, targetId);
}

void FileController::showProject(const model::Project &project, const QString &path) {
    // The editor gets the target's lexer before the text arrives, so the text is styled
    // once, as it is shown; Document::setProject emits programChanged, which refreshes.
    m_il->setTarget(*project.target);
    m_il->dropHistory();
    m_listing->forget();
    m_symbols->setPending(project.pendingSymbols); // the rows typed that are no symbol yet
    m_savedPendingSymbols = project.pendingSymbols;
    m_document->setProject(project, path);
    m_savedPending = project.pendingListing;
    if (!project.pendingListing.isEmpty()) {
        // Saved while the list had errors: it shows as it was typed, errors marked, the
        // ladder showing the last valid program.
        m_il->setText(project.pendingListing);
        m_listing->applyListing();
    }
}

void FileController::newProject(const model::Target &target, const QString &modelName) {
    m_il->setTarget(target);
    m_il->dropHistory();
    m_listing->forget();
    m_symbols->setPending({}); // half-typed rows belong to the program that goes
    m_savedPendingSymbols.clear();
    m_savedPending.clear();
    m_document->reset(target, modelName);
}

bool FileController::openFile(const QString &path, const QString &targetId, bool quiet) {
    auto fail = [&](const QString &message) {
        if (!quiet)
            messageBox(QMessageBox::Critical, m_window, tr("Cannot open the file"), message);
        statusBar()->showMessage(message, 10000);
        return false;
    };
    const QString suffix = QFileInfo(path).suffix().toLower();
    // A network opens in a window of its own (network_window.h), beside this one.
    if (suffix == QLatin1String(network::kNetworkExtension)) {
        QString error;
        if (!m_networkOpener || !m_networkOpener(path, &error))
            return fail(
                error.isEmpty()
                    ? tr("%1: networks cannot be opened here").arg(QDir::toNativeSeparators(path))
                    : error);
        addRecent(path);
        return true;
    }
    // A scenario test opens the program it names, with the scenario chosen in the Tests dock
    // (what a double-click on a .rungtest in a file manager means).
    if (suffix == QLatin1String("rungtest")) {
        QString targetOfTest;
        QString error;
        const QString program = TestsPanel::programOf(path, &targetOfTest, &error);
        if (program.isEmpty())
            return fail(error);
        const auto same = [](const QString &a, const QString &b) {
            return !a.isEmpty() &&
                   QFileInfo(a).canonicalFilePath() == QFileInfo(b).canonicalFilePath();
        };
        if (!same(m_document->path(), program) && !openFile(program, targetOfTest, quiet))
            return false;
        auto *tests = m_window ? m_window->findChild<TestsPanel *>() : nullptr;
        if (auto *dock = m_window ? m_window->findChild<QDockWidget *>(QStringLiteral("testsDock"))
                                  : nullptr) {
            dock->show();
            dock->raise();
        }
        if (tests && !tests->select(path))
            statusBar()->showMessage(
                tr("%1 names %2, but the Tests dock lists the scenarios beside the project")
                    .arg(QDir::toNativeSeparators(path), QDir::toNativeSeparators(program)),
                10000);
        return true;
    }
    // The target: as asked, else as the file names it, else the one the listing's syntax
    // reads (the current first), else the current.
    model::ProgramFileOptions options;
    options.target = targetId;
    options.fallbackTarget = m_document->target().id;
    options.maxBytes = kMaxTextFileBytes;
    QString error;
    std::optional<model::ProgramFile> file =
        model::openProgramFile(path, model::programFileKind(path), options, &error);
    if (!file)
        return fail(error);
    const model::Target &target = *file->target;
    switch (file->kind) {
    case model::ProgramFileKind::Project:
        showProject(file->project, path);
        addRecent(path);
        return true;
    case model::ProgramFileKind::LadderText: {
        // The drawing has no text of its own in the window: one that does not read opens
        // nothing, and says where it stops.
        const model::LadderTextResult ladder = model::parseLadderText(target, file->text);
        if (!ladder.ok()) {
            const model::ParseError &e = ladder.errors.front();
            return fail(tr("%1, line %2, column %3: %4")
                            .arg(QDir::toNativeSeparators(path))
                            .arg(e.line)
                            .arg(e.column)
                            .arg(e.message));
        }
        showImported(target, ladder.ladder, path);
        return true;
    }
    case model::ProgramFileKind::Listing:
        break;
    }
    const model::ParseResult parsed = model::parseInstructionList(target, file->text);
    const model::ToLadderResult ladder =
        parsed.ok() ? model::listToLadder(parsed.list) : model::ToLadderResult{};
    if (!parsed.ok() || !ladder.ok()) {
        // A listing with errors opens as text, as typed, its errors marked in the list and
        // the problems: the user fixes it here and the ladder follows.
        newProject(target, target.defaultModel().name);
        m_il->setText(file->text);
        m_listing->applyListing();
        nameImported(path);
        m_listing->sayErrors(tr("%1 has errors; the ladder follows once they are fixed")
                                 .arg(QFileInfo(path).fileName()));
        return true;
    }
    showImported(target, ladder.ladder, path);
    return true;
}

void FileController::showImported(const model::Target &target, const model::LadderProgram &program,
                                  const QString &path) {
    model::Project project;
    project.target = &target;
    project.model = target.defaultModel().name;
    project.program = program;
    showProject(project, QString());
    nameImported(path);
}

void FileController::nameImported(const QString &path) {
    // A listing or ladder text opens as a new project named after its file; saving it writes
    // a project beside it, not over the text.
    const QFileInfo file(path);
    m_document->setUntitledName(
        file.fileName(),
        file.absoluteDir().filePath(file.completeBaseName() + QLatin1Char('.') +
                                    QString::fromLatin1(model::kProjectExtension)));
}

bool FileController::saveTo(const QString &path) {
    m_listing->flush(); // what was typed last is saved too
    const model::Project project = projectToKeep();
    model::ProjectError error;
    if (!model::saveProject(project, path, &error)) {
        messageBox(QMessageBox::Critical, m_window, tr("Cannot save"), error.message);
        return false;
    }
    m_savedPending = project.pendingListing;
    m_savedPendingSymbols = project.pendingSymbols;
    m_document->setPath(path);
    m_document->markSaved();
    m_recovery->remove();
    addRecent(path);
    emit saved();
    if (project.pendingListing.isEmpty())
        statusBar()->showMessage(tr("Saved %1").arg(path), 3000);
    else
        statusBar()->showMessage(
            tr("Saved %1 with the instruction list as typed; it has errors, so the ladder "
               "holds the last valid program until they are fixed")
                .arg(path),
            10000);
    return true;
}

bool FileController::maybeSave() {
    m_listing->flush();
    if (!isModified())
        return true;
    const auto answer = messageBox(QMessageBox::Warning, m_window, tr("Unsaved changes"),
                                   tr("Save the changes to the program?"),
                                   QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
    if (answer == QMessageBox::Save)
        return fileSave();
    return answer == QMessageBox::Discard;
}

void FileController::fileNew() {
    if (!maybeSave())
        return;
    QDialog dialog(m_window);
    dialog.setWindowTitle(tr("New Project"));
    auto *form = new QFormLayout(&dialog);
    auto *family = new QComboBox;
    auto *modelBox = new QComboBox;
    for (model::Family f : model::Target::families())
        family->addItem(model::Target::get(f).displayName, model::Target::get(f).id);
    auto fillModels = [&] {
        modelBox->clear();
        const model::Target *t = model::Target::byId(family->currentData().toString());
        for (const model::ModelVariant &m : t->models)
            modelBox->addItem(m.name);
        modelBox->setCurrentIndex(modelBox->count() - 1);
    };
    connect(family, &QComboBox::currentIndexChanged, &dialog, fillModels);
    family->setCurrentIndex(family->findData(model::Target::defaultTarget().id));
    fillModels();
    form->addRow(tr("PLC family:"), family);
    form->addRow(tr("Model:"), modelBox);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
    connect(buttons, &QDialogButtonBox::accepted, &dialog, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
    form->addRow(buttons);
    // A dialog only as wide as its two combo boxes cut "Nuovo progetto" to "Nuovo... getto".
    fitTitle(&dialog);
    if (dialog.exec() != QDialog::Accepted)
        return;
    newProject(*model::Target::byId(family->currentData().toString()), modelBox->currentText());
}

void FileController::fileOpen() {
    const QString path = askOpenFile(
        m_window, tr("Open"), m_document->path(),
        tr("Rung Studio projects (*.rung);;Instruction lists (*.il *.txt);;Ladder texts "
           "(*.ladder);;Scenario tests (*.rungtest);;Networks of PLCs (*.rungnet)"));
    if (path.isEmpty())
        return;
    // A network opens beside the program shown, which stays as it is: nothing to save first.
    const bool network = QFileInfo(path).suffix().compare(QLatin1String(network::kNetworkExtension),
                                                          Qt::CaseInsensitive) == 0;
    if (network || maybeSave())
        openFile(path);
}

bool FileController::fileSave() {
    if (m_document->path().isEmpty())
        return fileSaveAs();
    return saveTo(m_document->path());
}

QString FileController::completeSavePath(const QString &chosen, const QStringList &suffixes) {
    if (chosen.isEmpty() || suffixes.isEmpty())
        return chosen;
    if (suffixes.contains(QFileInfo(chosen).suffix(), Qt::CaseInsensitive))
        return chosen;
    const QString path = chosen + QLatin1Char('.') + suffixes.front();
    if (QFileInfo::exists(path) &&
        messageBox(QMessageBox::Question, m_window, tr("Replace File"),
                   tr("%1 already exists. Replace it?").arg(QDir::toNativeSeparators(path))) !=
            QMessageBox::Yes)
        return QString();
    return path;
}

QString FileController::askSavePath(const QString &title, const QString &filter,
                                    const QStringList &suffixes) {
    return completeSavePath(
        askSaveFile(m_window, title, fileDialogFolder(m_document->path()), filter), suffixes);
}

bool FileController::fileSaveAs() {
    const QString path = completeSavePath(askSaveFile(m_window, tr("Save As"),
                                                      m_document->suggestedPath().isEmpty()
                                                          ? fileDialogFolder(QString())
                                                          : m_document->suggestedPath(),
                                                      tr("Rung Studio projects (*.rung)")),
                                          {QString::fromLatin1(model::kProjectExtension)});
    if (path.isEmpty())
        return false;
    return saveTo(path);
}

void FileController::importListing() {
    if (!maybeSave())
        return;
    const QString path = askOpenFile(m_window, tr("Import Instruction List"), m_document->path(),
                                     tr("Instruction lists (*.il *.txt);;All files (*)"));
    // Read for the PLC the list names on its first line, else for the project's.
    if (!path.isEmpty())
        openFile(path);
}

void FileController::exportListing() {
    m_listing->flush();
    // Say what stands in the way before the user picks a file for nothing.
    QString error = ProgramExport(*m_document, m_ladder->namesFirst())
                        .listingBlockers(m_listing->listingErrors());
    if (!error.isEmpty()) {
        messageBox(QMessageBox::Critical, m_window, tr("Cannot export"), error);
        return;
    }
    const QString path =
        askSavePath(tr("Export Instruction List"), tr("Instruction lists (*.il *.txt)"),
                    {QStringLiteral("il"), QStringLiteral("txt")});
    if (!path.isEmpty() && !ProgramExport(*m_document, m_ladder->namesFirst())
                                .listing(path, &error, m_listing->listingErrors()))
        messageBox(QMessageBox::Critical, m_window, tr("Cannot export"), error);
}

void FileController::exportImage(const QString &format) {
    const QString path =
        askSavePath(tr("Export Ladder"), QStringLiteral("*.%1").arg(format), {format});
    if (path.isEmpty())
        return;
    QString error;
    if (!ProgramExport(*m_document, m_ladder->namesFirst()).ladder(path, &error))
        messageBox(QMessageBox::Critical, m_window, tr("Cannot export"), error);
}

void FileController::printPreview() {
    QPrinter printer(QPrinter::HighResolution);
    printer.setPageOrientation(QPageLayout::Landscape);
    printer.setPageMargins(QMarginsF(12, 10, 12, 10), QPageLayout::Millimeter);
    QPrintPreviewDialog dialog(&printer, m_window);
    connect(&dialog, &QPrintPreviewDialog::paintRequested, this,
            [this](QPrinter *pr) { ProgramExport(*m_document, m_ladder->namesFirst()).print(pr); });
    dialog.exec();
}

void FileController::addRecent(const QString &path) {
    QSettings settings;
    QStringList recent = settings.value(QStringLiteral("files/recent")).toStringList();
    recent.removeAll(path);
    recent.prepend(path);
    while (recent.size() > kMaxRecent)
        recent.removeLast();
    settings.setValue(QStringLiteral("files/recent"), recent);
    rebuildRecentMenu();
}

void FileController::rebuildRecentMenu() {
    if (!m_recentMenu) // no menu given yet (addActions): the list is kept all the same
        return;
    m_recentMenu->clear();
    const QStringList recent = QSettings().value(QStringLiteral("files/recent")).toStringList();
    for (const QString &path : recent)
        m_recentMenu
            ->addAction(QFileInfo(path).fileName(), this,
                        [this, path] {
                            if (maybeSave())
                                openFile(path);
                        })
            ->setToolTip(path);
    m_recentMenu->setEnabled(!recent.isEmpty());
}

void FileController::rebuildExamplesMenu() {
    // The manuals' examples, one submenu per target, from the folder installed beside the
    // program (share/rungstudio/examples).
    if (!m_examplesMenu)
        return;
    m_examplesMenu->clear();
    std::map<QString, QStringList> byTarget;
    if (const QString folder = examplesFolder(); !folder.isEmpty()) {
        QDirIterator it(folder, {QStringLiteral("*.rung")}, QDir::Files,
                        QDirIterator::Subdirectories);
        while (it.hasNext()) {
            const QString path = it.next();
            byTarget[QFileInfo(path).dir().dirName()] << path;
        }
    }
    for (auto &[target, paths] : byTarget) {
        const model::Target *t = model::Target::byId(target);
        QMenu *sub = m_examplesMenu->addMenu(t ? t->displayName : target);
        paths.sort();
        for (const QString &path : paths) {
            const QString title = exampleTitle(t, QFileInfo(path).baseName());
            sub->addAction(title, this, [this, path, title] {
                if (!maybeSave())
                    return;
                // Examples open as untitled copies: saving asks where.
                model::ProjectError error;
                auto project = model::loadProject(path, &error);
                if (!project) {
                    messageBox(QMessageBox::Critical, m_window, tr("Cannot open the example"),
                               error.message);
                    return;
                }
                showProject(*project, QString());
                m_document->setUntitledName(
                    title, QDir(fileDialogFolder(QString())).filePath(QFileInfo(path).fileName()));
            });
        }
    }
    // The networks of the manuals' communication chapters, each in a window of its own.
    QStringList networks;
    if (const QString folder = examplesFolder(); !folder.isEmpty()) {
        QDirIterator it(folder, {QStringLiteral("*.") + QLatin1String(network::kNetworkExtension)},
                        QDir::Files, QDirIterator::Subdirectories);
        while (it.hasNext())
            networks << it.next();
    }
    networks.sort();
    if (!networks.isEmpty()) {
        QMenu *sub = m_examplesMenu->addMenu(tr("Networks"));
        sub->setObjectName(QStringLiteral("networkExamplesMenu"));
        for (const QString &path : networks)
            sub->addAction(exampleTitle(nullptr, QFileInfo(path).completeBaseName()), this,
                           [this, path] { openFile(path); });
    }
    m_examplesMenu->setEnabled(!byTarget.empty() || !networks.isEmpty());
}

} // namespace rung::app
