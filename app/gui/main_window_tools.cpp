#include "main_window.h"

#include "editor/ladder_view.h"

#include "model/convert.h"
#include "model/ladder_text.h"

#include <QApplication>
#include <QClipboard>
#include <QDockWidget>
#include <QFileDialog>
#include <QInputDialog>
#include <QLineEdit>
#include <QMessageBox>
#include <QMimeData>
#include <QSaveFile>
#include <QStatusBar>
#include <QTreeWidget>
#include <QVBoxLayout>

// Clipboard, find and replace, cross reference and the symbol table's CSV: the tools that
// work on the whole program rather than one cell.

namespace rung::app {

namespace {

const char *const kLadderMime = "application/x-rungstudio-ladder";
const char *const kCellsMime = "application/x-rungstudio-cells";

bool sameDevice(const model::Operand &o, const model::Address &a) {
    return o.kind == model::Operand::Kind::Device && o.address == a;
}

// CSV field with quotes where needed (RFC 4180).
QString csvField(const QString &s) {
    if (!s.contains(QLatin1Char(',')) && !s.contains(QLatin1Char('"')) &&
        !s.contains(QLatin1Char('\n')))
        return s;
    QString q = s;
    q.replace(QLatin1String("\""), QLatin1String("\"\""));
    return QLatin1Char('"') + q + QLatin1Char('"');
}

QStringList csvFields(const QString &line) {
    QStringList out;
    QString field;
    bool quoted = false;
    for (qsizetype i = 0; i < line.size(); ++i) {
        const QChar c = line[i];
        if (quoted) {
            if (c == QLatin1Char('"') && i + 1 < line.size() && line[i + 1] == QLatin1Char('"')) {
                field += c;
                ++i;
            } else if (c == QLatin1Char('"')) {
                quoted = false;
            } else {
                field += c;
            }
        } else if (c == QLatin1Char('"')) {
            quoted = true;
        } else if (c == QLatin1Char(',') || c == QLatin1Char(';')) {
            out << field;
            field.clear();
        } else {
            field += c;
        }
    }
    out << field;
    return out;
}

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

void MainWindow::replaceDevice() {
    const model::Target &t = m_document->target();
    bool ok = false;
    const QString from = QInputDialog::getText(
        this, tr("Replace Device"), tr("Replace the device:"), QLineEdit::Normal, QString(), &ok);
    if (!ok || from.trimmed().isEmpty())
        return;
    const QString to = QInputDialog::getText(this, tr("Replace Device"), tr("with:"),
                                             QLineEdit::Normal, QString(), &ok);
    if (!ok)
        return;
    QString error;
    const int count = replaceDeviceEverywhere(from, to, &error);
    if (count < 0)
        QMessageBox::warning(this, tr("Replace Device"), error);
    else
        statusBar()->showMessage(tr("%n place(s) changed", nullptr, count), 5000);
    Q_UNUSED(t);
}

int MainWindow::replaceDeviceEverywhere(const QString &fromText, const QString &toText,
                                        QString *error) {
    const model::Target &t = m_document->target();
    auto a = model::parseAddress(t, fromText, m_document->modelVariant());
    auto b = model::parseAddress(t, toText, m_document->modelVariant());
    if (auto *e = std::get_if<model::AddressError>(&a)) {
        *error = e->message;
        return -1;
    }
    if (auto *e = std::get_if<model::AddressError>(&b)) {
        *error = e->message;
        return -1;
    }
    const model::Address from = std::get<model::Address>(a);
    const model::Address to = std::get<model::Address>(b);
    std::vector<model::Rung> rungs = m_document->ladder().rungs;
    int count = 0;
    for (model::Rung &r : rungs) {
        for (model::Cell &c : r.cells)
            for (model::Operand &o : c.contact.operands)
                if (sameDevice(o, from)) {
                    o.address = to;
                    ++count;
                }
        for (auto &out : r.outputs)
            if (out)
                for (model::Operand &o : out->operands)
                    if (sameDevice(o, from)) {
                        o.address = to;
                        ++count;
                    }
    }
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
    auto *panel = new QWidget;
    auto *layout = new QVBoxLayout(panel);
    m_crossDevice = new QLineEdit;
    m_crossDevice->setPlaceholderText(tr("Device, e.g. X0"));
    m_crossTree = new QTreeWidget;
    m_crossTree->setHeaderLabels({tr("Rung"), tr("Step"), tr("Use"), tr("Instruction")});
    m_crossTree->setRootIsDecorated(false);
    layout->addWidget(m_crossDevice);
    layout->addWidget(m_crossTree, 1);
    dock->setWidget(panel);
    addDockWidget(Qt::LeftDockWidgetArea, dock);
    tabifyDockWidget(findChild<QDockWidget *>(QStringLiteral("projectDock")), dock);
    findChild<QDockWidget *>(QStringLiteral("projectDock"))->raise();
    connect(m_crossDevice, &QLineEdit::textChanged, this, &MainWindow::refreshCrossReference);
    connect(m_crossTree, &QTreeWidget::itemActivated, this, [this](QTreeWidgetItem *item) {
        m_ladder->setCursor({item->data(0, Qt::UserRole).toInt(), 0, 0});
        m_ladder->setFocus();
    });
}

void MainWindow::refreshCrossReference() {
    if (!m_crossTree)
        return;
    m_crossTree->clear();
    const model::Target &t = m_document->target();
    auto parsed = model::parseAddress(t, m_crossDevice->text());
    if (!std::holds_alternative<model::Address>(parsed))
        return;
    const model::Address device = std::get<model::Address>(parsed);
    const auto &listing = m_document->listing();
    for (std::size_t r = 0; r + 1 < listing.rungFirst.size(); ++r) {
        for (int i = listing.rungFirst[r]; i < listing.rungFirst[r + 1]; ++i) {
            const model::Instruction &ins = listing.list.instructions[static_cast<std::size_t>(i)];
            bool uses = false;
            for (const model::Operand &o : ins.operands)
                uses = uses || sameDevice(o, device);
            if (!uses)
                continue;
            const model::Op op = ins.op();
            const bool contact =
                op == model::Op::Load || op == model::Op::And || op == model::Op::Or;
            auto *item = new QTreeWidgetItem(m_crossTree);
            item->setText(0, QString::number(r + 1));
            item->setText(1, QStringLiteral("%1").arg(ins.step, 4, 10, QLatin1Char('0')));
            item->setText(2, contact ? tr("contact") : tr("coil / box"));
            item->setText(3, model::printInstruction(t, ins));
            item->setData(0, Qt::UserRole, static_cast<int>(r));
        }
    }
}

void MainWindow::exportSymbols() {
    const QString path = QFileDialog::getSaveFileName(this, tr("Export Symbols"), QString(),
                                                      tr("CSV files (*.csv)"));
    if (path.isEmpty())
        return;
    QString text = QStringLiteral("device,name,comment\n");
    for (const model::Symbol &s : m_document->project().symbols)
        text += QStringLiteral("%1,%2,%3\n")
                    .arg(csvField(model::formatAddress(m_document->target(), s.address)),
                         csvField(s.name), csvField(s.comment));
    QSaveFile file(path);
    const QByteArray bytes = text.toUtf8();
    if (!file.open(QIODevice::WriteOnly) || file.write(bytes) != bytes.size() || !file.commit())
        QMessageBox::critical(this, tr("Cannot export"),
                              tr("%1: %2").arg(path, file.errorString()));
}

bool MainWindow::importSymbols(const QString &path, QString *error) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        *error = tr("%1: %2").arg(path, file.errorString());
        return false;
    }
    std::vector<model::Symbol> symbols;
    int lineNumber = 0;
    for (const QString &line : QString::fromUtf8(file.readAll()).split(QLatin1Char('\n'))) {
        ++lineNumber;
        const QString trimmed = line.trimmed();
        if (trimmed.isEmpty() ||
            (lineNumber == 1 && trimmed.startsWith(QLatin1String("device"), Qt::CaseInsensitive)))
            continue;
        const QStringList fields = csvFields(trimmed);
        auto a =
            model::parseAddress(m_document->target(), fields.value(0), m_document->modelVariant());
        if (auto *e = std::get_if<model::AddressError>(&a)) {
            *error = tr("%1, line %2: %3").arg(path).arg(lineNumber).arg(e->message);
            return false;
        }
        symbols.push_back({std::get<model::Address>(a), fields.value(1), fields.value(2)});
    }
    m_document->setSymbols(symbols);
    return true;
}

} // namespace rung::app
