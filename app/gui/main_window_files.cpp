#include "main_window.h"

#include "editor/il_editor.h"
#include "editor/ladder_painter.h"
#include "editor/ladder_view.h"

#include "model/project/file_read.h"
#include "model/project/project.h"

#include <QComboBox>
#include <QCoreApplication>
#include <QDate>
#include <QDialog>
#include <QDialogButtonBox>
#include <QDir>
#include <QDirIterator>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QImage>
#include <QLocale>
#include <QLockFile>
#include <QMenu>
#include <QMessageBox>
#include <QPainter>
#include <QPrintPreviewDialog>
#include <QPrinter>
#include <QSaveFile>
#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>
#include <QSvgGenerator>

namespace rung::app {

namespace {

constexpr int kMaxRecent = 8;

// Paints every rung, one below the other, starting at `top`; a new page when needed.
// With `paint` false it only lays the rungs out on pages (to count them for the header).
template <typename NewPage>
void paintProgram(QPainter &p, const editor::Document &document, const editor::LadderMetrics &m,
                  bool namesFirst, double pageHeight, double top, NewPage newPage,
                  bool paint = true) {
    const model::Project &project = document.project();
    editor::LadderPainter painter(project, m);
    painter.setNamesFirst(namesFirst); // as the view shows it
    const model::ToListingResult &listing = document.listing();
    double y = top;
    for (int i = 0; i < static_cast<int>(project.program.rungs.size()); ++i) {
        const double h = m.rungHeight(project.program.rungs[static_cast<std::size_t>(i)]);
        if (pageHeight > 0 && y + h > pageHeight && y > top) {
            newPage();
            y = top;
        }
        if (!paint) {
            y += h;
            continue;
        }
        editor::RungDecorations d; // step addresses, as on screen
        const auto first =
            static_cast<std::size_t>(i) < listing.rungFirst.size()
                ? static_cast<std::size_t>(listing.rungFirst[static_cast<std::size_t>(i)])
                : listing.list.instructions.size();
        if (first < listing.list.instructions.size())
            d.firstStep = listing.list.instructions[first].step;
        painter.paintRung(p, QPointF(0, y), i, d);
        y += h;
    }
}

editor::LadderMetrics exportMetrics(const model::Project &project) {
    editor::LadderMetrics m;
    int widest = std::max(1, project.target->limits.contactsPerRow);
    for (const model::Rung &r : project.program.rungs)
        widest = std::max(widest, r.columns);
    m.gridColumns = widest;
    m.foldColumns = std::max(0, project.target->limits.contactsPerRow); // as on screen
    return m;
}

double programHeight(const model::Project &project, const editor::LadderMetrics &m) {
    double h = 0;
    for (const model::Rung &r : project.program.rungs)
        h += m.rungHeight(r);
    return h;
}

} // namespace

namespace {

QString &recoveryDirectoryOverride() {
    static QString directory;
    return directory;
}

QString recoveryDirectory() {
    const QString dir = recoveryDirectoryOverride().isEmpty()
                            ? QStandardPaths::writableLocation(QStandardPaths::AppDataLocation)
                            : recoveryDirectoryOverride();
    QDir().mkpath(dir);
    return dir;
}

// Beside each recovery file: the lock its instance holds while it runs, and the path of the
// file the recovered program came from (Save goes back there).
QString lockPath(const QString &base) {
    return base + QStringLiteral(".lock");
}
QString originPath(const QString &base) {
    return base + QStringLiteral(".path");
}

// A readable title from an example's file name: "traffic-light" -> "Traffic light",
// "difu-difd" -> "DIFU / DIFD"; the target's mnemonics are written as its manuals write them.
QString exampleTitle(const model::Target *target, const QString &baseName) {
    QStringList words = baseName.split(QLatin1Char('-'), Qt::SkipEmptyParts);
    if (words.isEmpty())
        return baseName;
    int mnemonics = 0;
    for (QString &w : words)
        if (target && target->findInstruction(w.toUpper())) {
            w = w.toUpper();
            ++mnemonics;
        }
    if (mnemonics == words.size() && words.size() > 1)
        return words.join(QStringLiteral(" / "));
    words.front()[0] = words.front()[0].toUpper();
    return words.join(QLatin1Char(' '));
}

} // namespace

void MainWindow::setRecoveryDirectory(const QString &directory) {
    recoveryDirectoryOverride() = directory;
}

void MainWindow::claimRecoveryFile() {
    // Process ids repeat (containers start every program with a low one): a name whose lock is
    // taken, or whose recovery file waits to be offered, belongs to another instance. A
    // directory where no lock can be made ends the search after a few tries.
    static int windows = 0;
    for (int tries = 0; tries < 64; ++tries) {
        m_recoveryBase = QStringLiteral("%1/recovery-%2-%3")
                             .arg(recoveryDirectory())
                             .arg(QCoreApplication::applicationPid())
                             .arg(++windows);
        m_recoveryLock = std::make_unique<QLockFile>(lockPath(m_recoveryBase));
        m_recoveryLock->setStaleLockTime(0); // stale only when its process is gone
        if (!QFile::exists(m_recoveryBase + QStringLiteral(".rung")) && m_recoveryLock->tryLock(0))
            return;
    }
}

QString MainWindow::recoveryPath() const {
    return m_recoveryBase + QStringLiteral(".rung");
}

void MainWindow::removeRecovery() {
    QFile::remove(recoveryPath());
    QFile::remove(originPath(m_recoveryBase));
}

void MainWindow::writeRecovery() {
    if (!m_document->isModified())
        return;
    model::ProjectError error;
    model::saveProject(m_document->project(), recoveryPath(), &error);
    QSaveFile origin(originPath(m_recoveryBase));
    if (origin.open(QIODevice::WriteOnly)) {
        origin.write(m_document->path().toUtf8());
        origin.commit();
    }
}

bool MainWindow::offerRecovery(bool ask) {
    const QFileInfoList files =
        QDir(recoveryDirectory())
            .entryInfoList({QStringLiteral("recovery*.rung")}, QDir::Files, QDir::Time);
    for (const QFileInfo &file : files) {
        const QString base = file.absoluteFilePath().chopped(5); // without ".rung"
        if (base == m_recoveryBase)
            continue;
        // A lock that can be taken belongs to no running instance: its work is orphaned.
        QLockFile owner(lockPath(base));
        owner.setStaleLockTime(0);
        if (!owner.tryLock(0))
            continue;
        QString origin;
        QFile originFile(originPath(base));
        if (originFile.open(QIODevice::ReadOnly))
            origin = QString::fromUtf8(originFile.readAll()).trimmed();
        originFile.close();
        const QString question =
            origin.isEmpty()
                ? tr("Rung Studio was not closed properly last time. Recover the unsaved "
                     "program?")
                : tr("Rung Studio was not closed properly last time. Recover the unsaved "
                     "changes to %1?")
                      .arg(QDir::toNativeSeparators(origin));
        const bool wanted =
            !ask || QMessageBox::question(this, tr("Recover"), question) == QMessageBox::Yes;
        model::ProjectError error;
        const auto project = wanted ? model::loadProject(file.absoluteFilePath(), &error)
                                    : std::optional<model::Project>();
        QFile::remove(file.absoluteFilePath());
        QFile::remove(originPath(base));
        if (!project)
            continue;
        showProject(*project, origin);
        m_document->markUnsaved(); // no file has this work yet: closing asks to save it
        writeRecovery();           // now this instance's to keep
        return true;
    }
    return false;
}

void MainWindow::start(const QString &file, const QString &targetId, bool askToRecover) {
    // Recovery comes first, or a start with a file (as scripts/start.sh does) would never
    // offer it, and the next normal close would delete the orphan with its work.
    if (!offerRecovery(askToRecover) && !file.isEmpty())
        openFile(file, targetId);
}

void MainWindow::showProject(const model::Project &project, const QString &path) {
    // The editor gets the target's lexer before the text arrives, so the text is styled
    // once, as it is shown; Document::setProject emits programChanged, which refreshes.
    m_il->setTarget(*project.target);
    m_il->dropHistory();
    m_listingErrors.clear();
    m_pendingSymbols.clear(); // half-typed rows belong to the program that goes
    m_document->setProject(project, path);
}

void MainWindow::newProject(const model::Target &target, const QString &modelName) {
    m_il->setTarget(target);
    m_il->dropHistory();
    m_listingErrors.clear();
    m_pendingSymbols.clear(); // half-typed rows belong to the program that goes
    m_document->reset(target, modelName);
}

bool MainWindow::openFile(const QString &path, const QString &targetId, bool quiet) {
    auto fail = [&](const QString &message) {
        if (!quiet)
            QMessageBox::critical(this, tr("Cannot open the file"), message);
        statusBar()->showMessage(message, 10000);
        return false;
    };
    const QString suffix = QFileInfo(path).suffix().toLower();
    model::Project project;
    if (suffix == QLatin1String(model::kProjectExtension)) {
        model::ProjectError error;
        auto loaded = model::loadProject(path, &error);
        if (!loaded)
            return fail(error.message);
        project = *loaded;
    } else {
        // The target: as asked, else as the listing's first line names it, else the current.
        QByteArray bytes;
        QString ioError;
        switch (model::readAtMost(path, kMaxTextFileBytes, &bytes, &ioError)) {
        case model::ReadStatus::CannotOpen:
            return fail(tr("%1: %2").arg(path, ioError));
        case model::ReadStatus::TooLarge:
            return fail(tr("%1 is larger than 64 MB").arg(path));
        case model::ReadStatus::Ok:
            break;
        }
        const QString text = QString::fromUtf8(bytes);
        const QString id =
            targetId.isEmpty() ? model::listingTarget(text, m_document->target().id) : targetId;
        const model::Target *target = model::Target::byId(id.toLower());
        if (!target)
            return fail(tr("Unknown target %1").arg(id));
        const model::ParseResult parsed = model::parseInstructionList(*target, text);
        const model::ToLadderResult ladder =
            parsed.ok() ? model::listToLadder(parsed.list) : model::ToLadderResult{};
        if (!parsed.ok() || !ladder.ok()) {
            // A listing with errors opens as text, as typed, its errors marked in the list and
            // the problems: the user fixes it here and the ladder follows.
            newProject(*target, target->defaultModel().name);
            m_il->setText(text);
            applyListing();
            m_errorsMessage = tr("%1 has errors; the ladder follows once they are fixed")
                                  .arg(QFileInfo(path).fileName());
            statusBar()->showMessage(m_errorsMessage, 10000);
            return true;
        }
        project.target = target;
        project.model = target->defaultModel().name;
        project.program = ladder.ladder;
    }
    showProject(project, suffix == QLatin1String(model::kProjectExtension) ? path : QString());
    if (suffix == QLatin1String(model::kProjectExtension))
        addRecent(path);
    return true;
}

bool MainWindow::saveTo(const QString &path) {
    model::ProjectError error;
    if (!model::saveProject(m_document->project(), path, &error)) {
        QMessageBox::critical(this, tr("Cannot save"), error.message);
        return false;
    }
    m_document->setPath(path);
    m_document->markSaved();
    removeRecovery();
    addRecent(path);
    refreshSymbols();
    statusBar()->showMessage(tr("Saved %1").arg(path), 3000);
    return true;
}

bool MainWindow::maybeSave() {
    if (!m_document->isModified())
        return true;
    const auto answer =
        QMessageBox::warning(this, tr("Unsaved changes"), tr("Save the changes to the program?"),
                             QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
    if (answer == QMessageBox::Save)
        return fileSave();
    return answer == QMessageBox::Discard;
}

void MainWindow::fileNew() {
    if (!maybeSave())
        return;
    QDialog dialog(this);
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
    family->setCurrentIndex(1);
    fillModels();
    form->addRow(tr("PLC family:"), family);
    form->addRow(tr("Model:"), modelBox);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
    connect(buttons, &QDialogButtonBox::accepted, &dialog, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
    form->addRow(buttons);
    if (dialog.exec() != QDialog::Accepted)
        return;
    newProject(*model::Target::byId(family->currentData().toString()), modelBox->currentText());
}

void MainWindow::fileOpen() {
    if (!maybeSave())
        return;
    const QString path = QFileDialog::getOpenFileName(
        this, tr("Open"), QString(),
        tr("Rung Studio projects (*.rung);;Instruction lists (*.il *.txt)"));
    if (!path.isEmpty())
        openFile(path);
}

bool MainWindow::fileSave() {
    if (m_document->path().isEmpty())
        return fileSaveAs();
    return saveTo(m_document->path());
}

bool MainWindow::fileSaveAs() {
    QString path = QFileDialog::getSaveFileName(this, tr("Save As"), m_document->path(),
                                                tr("Rung Studio projects (*.rung)"));
    if (path.isEmpty())
        return false;
    if (!path.endsWith(QLatin1String(".rung")))
        path += QLatin1String(".rung");
    return saveTo(path);
}

void MainWindow::importListing() {
    if (!maybeSave())
        return;
    const QString path =
        QFileDialog::getOpenFileName(this, tr("Import Instruction List"), QString(),
                                     tr("Instruction lists (*.il *.txt);;All files (*)"));
    // Read for the PLC the list names on its first line, else for the project's.
    if (!path.isEmpty())
        openFile(path);
}

void MainWindow::exportListing() {
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Export Instruction List"), QString(), tr("Instruction lists (*.il *.txt)"));
    if (path.isEmpty())
        return;
    QSaveFile file(path);
    const QByteArray bytes = m_document->listingText().toUtf8();
    if (!file.open(QIODevice::WriteOnly) || file.write(bytes) != bytes.size() || !file.commit())
        QMessageBox::critical(this, tr("Cannot export"),
                              tr("%1: %2").arg(path, file.errorString()));
}

void MainWindow::exportImage(const QString &format) {
    const QString path = QFileDialog::getSaveFileName(this, tr("Export Ladder"), QString(),
                                                      QStringLiteral("*.%1").arg(format));
    if (path.isEmpty())
        return;
    QString error;
    if (!exportLadder(path.endsWith(QLatin1Char('.') + format, Qt::CaseInsensitive)
                          ? path
                          : path + QLatin1Char('.') + format,
                      &error))
        QMessageBox::critical(this, tr("Cannot export"), error);
}

bool MainWindow::exportLadder(const QString &path, QString *error) {
    const QString format = QFileInfo(path).suffix().toLower();
    const model::Project &project = m_document->project();
    const editor::LadderMetrics m = exportMetrics(project);
    const QSize size(static_cast<int>(m.width()), static_cast<int>(programHeight(project, m)) + 20);
    auto fail = [&] {
        if (error)
            *error = tr("%1 could not be written").arg(QDir::toNativeSeparators(path));
        return false;
    };
    if (format == QLatin1String("png")) {
        QImage image(size, QImage::Format_ARGB32);
        image.fill(Qt::white);
        QPainter p(&image);
        paintProgram(p, *m_document, m, m_ladder->namesFirst(), 0, 10, [] {});
        p.end();
        return image.save(path) || fail();
    }
    if (format == QLatin1String("svg")) {
        QFile probe(path); // QSvgGenerator does not say when it cannot write
        if (!probe.open(QIODevice::WriteOnly))
            return fail();
        probe.close();
        QSvgGenerator svg;
        svg.setFileName(path);
        svg.setSize(size);
        svg.setViewBox(QRect(QPoint(0, 0), size));
        svg.setTitle(QFileInfo(m_document->path()).baseName());
        QPainter p(&svg);
        paintProgram(p, *m_document, m, m_ladder->namesFirst(), 0, 10, [] {});
        return true;
    }
    if (format == QLatin1String("pdf")) {
        // A PDF is the printout: pages with the header, rung numbers and comments.
        QPrinter printer(QPrinter::HighResolution);
        printer.setOutputFormat(QPrinter::PdfFormat);
        printer.setOutputFileName(path);
        printer.setPageSize(QPageSize(QPageSize::A4));
        printer.setPageOrientation(QPageLayout::Landscape);
        printer.setPageMargins(QMarginsF(12, 10, 12, 10), QPageLayout::Millimeter);
        printer.setDocName(QFileInfo(m_document->path()).baseName());
        return printLadder(&printer) || fail();
    }
    if (error)
        *error = tr("%1: the ladder can be exported as PDF, SVG or PNG").arg(path);
    return false;
}

bool MainWindow::printLadder(QPrinter *printer) {
    const model::Project &project = m_document->project();
    const editor::LadderMetrics m = exportMetrics(project);
    QPainter p;
    if (!p.begin(printer))
        return false;
    // The ladder fills the page's width between the margins; the page header is drawn in the
    // same units, so it scales with it.
    const QRect page = printer->pageLayout().paintRectPixels(printer->resolution());
    const double scale = page.width() / m.width();
    p.scale(scale, scale);
    const double pageHeight = page.height() / scale;
    constexpr double kTop = 40; // below the header and its rule
    int pages = 1;
    paintProgram(
        p, *m_document, m, m_ladder->namesFirst(), pageHeight, kTop, [&] { ++pages; }, false);
    const QString projectName =
        m_document->path().isEmpty() ? tr("Untitled") : QFileInfo(m_document->path()).fileName();
    const QString target =
        tr("%1 %2").arg(project.target->displayName, m_document->modelVariant()->name);
    const QString date = QLocale().toString(QDate::currentDate(), QLocale::ShortFormat);
    int pageNumber = 1;
    QFont headerFont(QStringLiteral("DejaVu Sans"));
    headerFont.setPixelSize(13); // in the drawing's units, like the ladder's own text
    QFont bold = headerFont;
    bold.setBold(true);
    auto drawHeader = [&] {
        // Project on the left, PLC in the middle, date and page on the right, a rule below.
        const QRectF line(0, 0, m.width(), 24);
        p.setPen(Qt::black);
        p.setFont(bold);
        p.drawText(line, Qt::AlignLeft | Qt::AlignVCenter, projectName);
        p.setFont(headerFont);
        p.drawText(line, Qt::AlignHCenter | Qt::AlignVCenter, target);
        p.drawText(line, Qt::AlignRight | Qt::AlignVCenter,
                   tr("%1    page %2 of %3").arg(date).arg(pageNumber).arg(pages));
        p.setPen(QPen(Qt::darkGray, 1));
        p.drawLine(QPointF(0, 28), QPointF(m.width(), 28));
    };
    drawHeader();
    paintProgram(p, *m_document, m, m_ladder->namesFirst(), pageHeight, kTop, [&] {
        printer->newPage();
        ++pageNumber;
        drawHeader();
    });
    return p.end();
}

void MainWindow::printPreview() {
    QPrinter printer(QPrinter::HighResolution);
    printer.setPageOrientation(QPageLayout::Landscape);
    printer.setPageMargins(QMarginsF(12, 10, 12, 10), QPageLayout::Millimeter);
    QPrintPreviewDialog dialog(&printer, this);
    connect(&dialog, &QPrintPreviewDialog::paintRequested, this,
            [this](QPrinter *pr) { printLadder(pr); });
    dialog.exec();
}

void MainWindow::addRecent(const QString &path) {
    QSettings settings;
    QStringList recent = settings.value(QStringLiteral("files/recent")).toStringList();
    recent.removeAll(path);
    recent.prepend(path);
    while (recent.size() > kMaxRecent)
        recent.removeLast();
    settings.setValue(QStringLiteral("files/recent"), recent);
    rebuildRecentMenu();
}

void MainWindow::rebuildRecentMenu() {
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

void MainWindow::rebuildExamplesMenu() {
    // The manuals' examples, one submenu per target, from the resources.
    m_examplesMenu->clear();
    QDirIterator it(QStringLiteral(":/examples"), {QStringLiteral("*.rung")}, QDir::Files,
                    QDirIterator::Subdirectories);
    std::map<QString, QStringList> byTarget;
    while (it.hasNext()) {
        const QString path = it.next();
        byTarget[QFileInfo(path).dir().dirName()] << path;
    }
    for (auto &[target, paths] : byTarget) {
        const model::Target *t = model::Target::byId(target);
        QMenu *sub = m_examplesMenu->addMenu(t ? t->displayName : target);
        paths.sort();
        for (const QString &path : paths)
            sub->addAction(exampleTitle(t, QFileInfo(path).baseName()), this, [this, path] {
                if (!maybeSave())
                    return;
                // Examples open as untitled copies: saving asks where.
                model::ProjectError error;
                auto project = model::loadProject(path, &error);
                if (!project) {
                    QMessageBox::critical(this, tr("Cannot open the example"), error.message);
                    return;
                }
                showProject(*project, QString());
            });
    }
    m_examplesMenu->setEnabled(!byTarget.empty());
}

} // namespace rung::app
