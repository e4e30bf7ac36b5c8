#include "main_window.h"

#include "layout_controller.h"

#include "dialogs.h"
#include "file_controller.h"
#include "network_port_dialog.h"
#include "symbol_table.h"

#include "editor/cross_reference_view.h"
#include "editor/il_editor.h"
#include "editor/ladder_view.h"

#include "model/comm/port_spec.h"
#include "model/convert/convert.h"
#include "model/ladder/ladder_text.h"
#include "model/ladder/replace_device.h"
#include "model/target/target.h"

#include <QApplication>
#include <QClipboard>
#include <QDockWidget>
#include <QLineEdit>
#include <QMessageBox>
#include <QMimeData>
#include <QStatusBar>
#include <QVBoxLayout>

// Clipboard, find and replace, cross reference: the tools that work on the whole program
// rather than one cell.

namespace rung::app {

namespace {

const char *const kLadderMime = "application/x-rungstudio-ladder";
const char *const kCellsMime = "application/x-rungstudio-cells";

} // namespace

void MainWindow::copyRung(bool cut) {
    if (m_ladder->selectedCells().valid()) {
        // A run of cells: the exact drawing for Rung Studio, the same as text for others.
        model::LadderProgram piece;
        piece.target = &m_document->target();
        piece.rungs = {m_ladder->copyCells()};
        auto *mime = new QMimeData;
        const QString text = model::printLadderText(piece);
        mime->setText(text);
        mime->setData(QString::fromLatin1(kCellsMime), text.toUtf8());
        QApplication::clipboard()->setMimeData(mime);
        if (cut)
            m_ladder->clearCells();
        return;
    }
    const auto [rung, count] = m_ladder->selectedRungs();
    const auto &rungs = m_document->ladder().rungs;
    if (rung < 0 || count <= 0 || rung + count > static_cast<int>(rungs.size()))
        return;
    model::LadderProgram one;
    one.target = &m_document->target();
    one.rungs.assign(rungs.begin() + rung, rungs.begin() + rung + count);
    auto *mime = new QMimeData;
    // Other programs get the listing; Rung Studio gets the exact drawing.
    const model::ToListingResult il = model::ladderToList(one);
    mime->setText(il.ok() ? model::printInstructionList(il.list) : model::printLadderText(one));
    mime->setData(QString::fromLatin1(kLadderMime), model::printLadderText(one).toUtf8());
    QApplication::clipboard()->setMimeData(mime);
    if (cut) {
        m_ladder->clearSelection();
        m_document->replaceRungs(rung, count, {}, tr("Cut rungs"));
    }
}

void MainWindow::pasteRungs() {
    const QMimeData *mime = QApplication::clipboard()->mimeData();
    if (!mime)
        return;
    const model::Target &t = m_document->target();
    if (mime->hasFormat(QString::fromLatin1(kCellsMime))) {
        const model::LadderTextResult r = model::parseLadderText(
            t, QString::fromUtf8(mime->data(QString::fromLatin1(kCellsMime))));
        if (r.ok() && !r.ladder.rungs.empty())
            m_ladder->pasteCells(r.ladder.rungs.front());
        else if (!r.ok())
            statusBar()->showMessage(tr("Cannot paste the cells: %1").arg(r.errors.front().message),
                                     5000);
        return;
    }
    std::vector<model::Rung> rungs;
    QString problem;
    if (mime->hasFormat(QString::fromLatin1(kLadderMime))) {
        const model::LadderTextResult r = model::parseLadderText(
            t, QString::fromUtf8(mime->data(QString::fromLatin1(kLadderMime))));
        if (r.ok())
            rungs = r.ladder.rungs;
        else
            problem = r.errors.front().message;
    } else {
        // Listing text from another program or another project.
        const model::ParseResult parsed =
            model::parseInstructionList(t, mime->text(), m_document->modelVariant());
        if (!parsed.ok()) {
            problem = tr("Line %1: %2")
                          .arg(parsed.errors.front().line)
                          .arg(parsed.errors.front().message);
        } else {
            const model::ToLadderResult ladder = model::listToLadder(parsed.list);
            if (ladder.ok())
                rungs = ladder.ladder.rungs;
            else
                problem = ladder.problems.front().message;
        }
    }
    if (rungs.empty()) {
        statusBar()->showMessage(problem.isEmpty() ? tr("The clipboard holds no rungs")
                                                   : tr("Cannot paste: %1").arg(problem),
                                 6000);
        return;
    }
    m_document->replaceRungs(m_ladder->cursor().rung, 0, rungs,
                             rungs.size() == 1
                                 ? tr("Paste rung")
                                 : tr("Paste %n rungs", nullptr, static_cast<int>(rungs.size())));
}

void MainWindow::findDeviceDialog() {
    bool ok = false;
    const QString start =
        m_ladder->deviceAtCursor().isEmpty() ? m_findText : m_ladder->deviceAtCursor();
    const QString text = askText(this, tr("Find Device"), tr("Device:"), start, &ok);
    if (ok && !text.trimmed().isEmpty())
        findDevice(text, false);
}

bool MainWindow::findDevice(const QString &text, bool backwards) {
    if (text.trimmed().isEmpty()) {
        findDeviceDialog();
        return false;
    }
    auto parsed =
        model::parseAddress(m_document->target(), text.trimmed(), m_document->modelVariant());
    if (auto *e = std::get_if<model::AddressError>(&parsed)) {
        statusBar()->showMessage(e->message, 5000);
        return false;
    }
    m_findText = text.trimmed();
    m_layout->showPage(m_ladder);
    m_ladder->setFocus();
    return m_ladder->findDevice(std::get<model::Address>(parsed), backwards);
}

void MainWindow::replaceDevice() {
    bool ok = false;
    // The device under the cursor, of the list when it has the focus, else of the ladder.
    const QString current = m_il->hasFocus() ? m_il->deviceAtCaret() : m_ladder->deviceAtCursor();
    const QString from =
        askText(this, tr("Replace Device"), tr("Replace the device:"), current, &ok);
    if (!ok || from.trimmed().isEmpty())
        return;
    const QString to = askText(this, tr("Replace Device"), tr("with:"), QString(), &ok);
    if (!ok)
        return;
    QString error;
    const int count = replaceDeviceEverywhere(from, to, &error);
    if (count < 0)
        messageBox(QMessageBox::Warning, this, tr("Replace Device"), error);
    else
        statusBar()->showMessage(tr("%n place(s) changed", nullptr, count), 5000);
}

int MainWindow::replaceDeviceEverywhere(const QString &fromText, const QString &toText,
                                        QString *error) {
    const model::Target &t = m_document->target();
    auto a = model::parseAddress(t, fromText, m_document->modelVariant());
    auto b = model::parseAddress(t, toText, m_document->modelVariant());
    for (const auto *parsed : {&a, &b})
        if (const auto *e = std::get_if<model::AddressError>(parsed)) {
            *error = e->message;
            return -1;
        }
    const model::Address from = std::get<model::Address>(a);
    const model::Address to = std::get<model::Address>(b);
    std::vector<model::Rung> rungs = m_document->ladder().rungs;
    const int count = model::replaceDevice(rungs, t, from, to, error);
    if (count > 0)
        m_document->replaceRungs(
            0, static_cast<int>(rungs.size()), rungs,
            tr("Replace %1 with %2")
                .arg(model::formatAddress(t, from), model::formatAddress(t, to)));
    return count;
}

void MainWindow::buildCrossReference() {
    auto *dock = new QDockWidget(tr("Cross Reference"), this);
    dock->setObjectName(QStringLiteral("crossReferenceDock"));
    m_crossReference = new editor::CrossReferenceView(m_document);
    m_crossDevice = m_crossReference->filter();
    dock->setWidget(m_crossReference);
    addDockWidget(Qt::LeftDockWidgetArea, dock); // a tab beside the project (dock_layout.h)
    connect(dock, &QDockWidget::visibilityChanged, m_crossReference,
            &editor::CrossReferenceView::setOnScreen);
    connect(m_crossReference, &editor::CrossReferenceView::rungActivated, this, [this](int rung) {
        m_ladder->setCursor({rung, 0, 0});
        m_ladder->setFocus();
    });
}

void MainWindow::exportSymbols() {
    // A row that is no symbol yet (a device this PLC does not have) cannot go into a file
    // that imports again: say which, and let the user choose, before asking for a name.
    if (const auto &pending = m_symbols->pending(); !pending.empty()) {
        QStringList rows;
        for (const model::PendingSymbol &p : pending)
            rows << (p.device.isEmpty() ? tr("(no device) %1").arg(p.name)
                                        : QStringLiteral("%1 %2").arg(p.device, p.name));
        if (messageBox(QMessageBox::Question, this, tr("Export Symbols"),
                       tr("%n row(s) of the symbol table name no device of this PLC and are "
                          "left out of the file: %1. Export the other symbols?",
                          nullptr, static_cast<int>(pending.size()))
                           .arg(rows.join(QStringLiteral(", ")))) != QMessageBox::Yes)
            return;
    }
    const QString path = m_files->askSavePath(tr("Export Symbols"), tr("CSV files (*.csv)"),
                                              {QStringLiteral("csv")});
    QString error;
    if (!path.isEmpty() && !m_symbols->exportCsv(path, &error))
        messageBox(QMessageBox::Critical, this, tr("Cannot export"), error);
}

void MainWindow::editCommunicationPorts() {
    const model::Project &project = m_document->project();
    const model::Target &target = m_document->target();
    if (std::none_of(target.ports.begin(), target.ports.end(),
                     [&project](const model::PortSpec &p) { return p.on(project.model); })) {
        messageBox(
            QMessageBox::Information, this, tr("Communication Ports"),
            tr("The %1 has no port settings a program or a network uses.").arg(target.displayName));
        return;
    }
    // The port dialog checks every setting against the target's table (model::readPortConfig),
    // as the project's reader and a network do.
    const std::optional<QJsonObject> ports =
        editProjectPorts(this, target, project.model, project.ports);
    if (!ports)
        return;
    const bool same = *ports == project.ports;
    m_document->setPorts(*ports, tr("Communication Ports"));
    statusBar()->showMessage(same ? tr("The communication ports are as they were")
                                  : tr("Communication ports set: File > Save keeps them in the "
                                       "project"),
                             8000);
}

} // namespace rung::app
