#include "compare_window.h"

#include "dialogs.h"
#include "file_dialogs.h"

#include "editor/compare_view.h"

#include "model/ladder/ladder_text.h"
#include "model/project/file_read.h"

#include <QAction>
#include <QDialogButtonBox>
#include <QDir>
#include <QFileInfo>
#include <QHeaderView>
#include <QLabel>
#include <QPlainTextEdit>
#include <QPrintDialog>
#include <QPrinter>
#include <QPushButton>
#include <QTabWidget>
#include <QTableWidget>
#include <QVBoxLayout>

namespace rung::app {

namespace {

constexpr qint64 kMaxTextBytes = 64 * 1024 * 1024;

using Kind = model::ListingRow::Kind;

} // namespace

std::optional<model::Project> loadForComparison(const QString &path, const model::Target &target,
                                                QString *error) {
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (suffix == QLatin1String(model::kProjectExtension)) {
        model::ProjectError e;
        auto project = model::loadProject(path, &e);
        if (!project) {
            *error = e.message;
            return std::nullopt;
        }
        if (project->target != &target) {
            *error = CompareWindow::tr("%1 is a program for %2; the open program is for %3: only "
                                       "programs of one PLC are compared")
                         .arg(QDir::toNativeSeparators(path), project->target->displayName,
                              target.displayName);
            return std::nullopt;
        }
        return project;
    }
    QByteArray bytes;
    QString ioError;
    if (const model::ReadStatus status = model::readAtMost(path, kMaxTextBytes, &bytes, &ioError);
        status != model::ReadStatus::Ok) {
        *error = model::readFailure(status, path, kMaxTextBytes, ioError);
        return std::nullopt;
    }
    const QString text = QString::fromUtf8(bytes);
    model::Project p;
    p.target = &target;
    p.model = target.defaultModel().name;
    p.program.target = &target;
    auto failAt = [&](const model::ParseError &e) {
        *error = CompareWindow::tr("%1, line %2, column %3: %4; a file that does not read whole is "
                                   "not compared")
                     .arg(QDir::toNativeSeparators(path))
                     .arg(e.line)
                     .arg(e.column)
                     .arg(e.message);
        return std::nullopt;
    };
    if (suffix == QLatin1String("ladder")) {
        const model::LadderTextResult ladder = model::parseLadderText(target, text);
        if (!ladder.ok())
            return failAt(ladder.errors.front());
        p.program = ladder.ladder;
        return p;
    }
    const model::ParseResult parsed = model::parseInstructionList(target, text);
    if (!parsed.ok())
        return failAt(parsed.errors.front());
    const model::ToLadderResult ladder = model::listToLadder(parsed.list);
    if (!ladder.ok()) {
        *error = QStringLiteral("%1: %2").arg(QDir::toNativeSeparators(path),
                                              ladder.problems.front().message);
        return std::nullopt;
    }
    p.program = ladder.ladder;
    model::addInstructionComments(parsed.list, &p.program);
    return p;
}

void CompareWindow::compareWithFile(QWidget *parent, const model::Project &open,
                                    const QString &openName, const QString &projectPath) {
    const QString path = askOpenFile(
        parent, tr("Compare With"), projectPath,
        tr("Rung Studio projects (*.rung);;Instruction lists (*.il *.txt);;Ladder texts "
           "(*.ladder)"));
    if (path.isEmpty())
        return;
    QString error;
    const auto other = loadForComparison(path, *open.target, &error);
    if (!other) {
        messageBox(QMessageBox::Critical, parent, tr("Cannot compare"), error);
        return;
    }
    CompareWindow window(*other, QFileInfo(path).fileName(), open, openName, parent);
    window.exec();
}

CompareWindow::CompareWindow(const model::Project &a, const QString &nameA, const model::Project &b,
                             const QString &nameB, QWidget *parent)
    : QDialog(parent)
    , m_a(a)
    , m_b(b)
    , m_nameA(nameA)
    , m_nameB(nameB) {
    setWindowTitle(tr("Compare: %1 and %2").arg(nameA, nameB));
    m_comparison = model::compareProjects(a, b);
    auto *layout = new QVBoxLayout(this);
    auto *sides = new QLabel(tr("A (left): %1        B (right): %2").arg(nameA, nameB));
    sides->setWordWrap(true);
    layout->addWidget(sides);
    m_summary = new QLabel;
    m_summary->setWordWrap(true);
    layout->addWidget(m_summary);
    m_tabs = new QTabWidget;
    m_view = new editor::CompareView;
    m_view->setComparison(a, b, m_comparison);
    m_tabs->addTab(m_view, tr("Ladder"));
    m_list = new QTableWidget(0, 3);
    m_list->setHorizontalHeaderLabels(
        {tr("Change"), tr("A: %1").arg(nameA), tr("B: %1").arg(nameB)});
    m_list->horizontalHeader()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    m_list->horizontalHeader()->setSectionResizeMode(1, QHeaderView::Stretch);
    m_list->horizontalHeader()->setSectionResizeMode(2, QHeaderView::Stretch);
    m_list->verticalHeader()->hide();
    m_list->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_list->setSelectionBehavior(QAbstractItemView::SelectRows);
    QFont mono = m_list->font();
    mono.setFamily(QStringLiteral("monospace"));
    mono.setStyleHint(QFont::Monospace);
    m_list->setFont(mono);
    m_tabs->addTab(m_list, tr("Instruction List"));
    m_report = new QPlainTextEdit;
    m_report->setReadOnly(true);
    m_report->setFont(mono);
    m_report->setPlainText(model::comparisonText(m_comparison, nameA, nameB));
    m_tabs->addTab(m_report, tr("Report"));
    layout->addWidget(m_tabs, 1);
    fillListing();

    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close);
    QPushButton *previous =
        buttons->addButton(tr("&Previous Change"), QDialogButtonBox::ActionRole);
    QPushButton *next = buttons->addButton(tr("&Next Change"), QDialogButtonBox::ActionRole);
    QPushButton *print = buttons->addButton(tr("P&rint..."), QDialogButtonBox::ActionRole);
    previous->setToolTip(tr("Previous change (Alt+Up)"));
    next->setToolTip(tr("Next change (Alt+Down)"));
    connect(previous, &QPushButton::clicked, this, [this] { nextChange(true); });
    connect(next, &QPushButton::clicked, this, [this] { nextChange(false); });
    connect(print, &QPushButton::clicked, this, &CompareWindow::print);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(buttons);
    // The keys of WinMerge and Meld, wherever the focus is in the window.
    auto *down = new QAction(this);
    down->setShortcut(QKeySequence(Qt::ALT | Qt::Key_Down));
    down->setShortcutContext(Qt::WindowShortcut);
    connect(down, &QAction::triggered, this, [this] { nextChange(false); });
    auto *up = new QAction(this);
    up->setShortcut(QKeySequence(Qt::ALT | Qt::Key_Up));
    up->setShortcutContext(Qt::WindowShortcut);
    connect(up, &QAction::triggered, this, [this] { nextChange(true); });
    addActions({down, up});
    connect(m_view, &editor::CompareView::currentChanged, this, &CompareWindow::showCurrent);
    connect(m_list, &QTableWidget::currentCellChanged, this, [this](int row) {
        for (std::size_t d = 0; d < m_listRowOf.size(); ++d)
            if (m_listRowOf[d] <= row &&
                (d + 1 == m_listRowOf.size() || row < m_listRowOf[d + 1])) {
                if (m_view->current() != static_cast<int>(d))
                    m_view->setCurrent(static_cast<int>(d));
                return;
            }
    });
    updateSummary();
    showCurrent(m_view->current());
    resize(1300, 700);
    fitTitle(this);
}

void CompareWindow::updateSummary() {
    const int changes = m_view->changeCount();
    QString text = changes == 0 && m_comparison.equal()
                       ? tr("The programs are the same.")
                       : tr("%n rung(s) differ.", nullptr, changes);
    const int others =
        static_cast<int>(m_comparison.symbols.size() + m_comparison.setValues.size() +
                         m_comparison.watchLists.size() + m_comparison.pending.size()) +
        (m_comparison.modelA != m_comparison.modelB ? 1 : 0);
    if (others > 0)
        text += QLatin1Char(' ') +
                tr("%n difference(s) besides the rungs (symbols, set values, watch lists): see "
                   "the Report.",
                   nullptr, others);
    text += QLatin1Char(' ') + tr("Alt+Down: next change, Alt+Up: previous.");
    m_summary->setText(text);
}

void CompareWindow::fillListing() {
    const std::vector<model::ListingRow> rows =
        model::comparisonListing(m_comparison, m_a.program, m_b.program);
    m_list->setRowCount(static_cast<int>(rows.size()));
    m_listRowOf.assign(m_comparison.rungs.size(), 0);
    for (int i = 0; i < static_cast<int>(rows.size()); ++i) {
        const model::ListingRow &row = rows[static_cast<std::size_t>(i)];
        const model::RungDifference &d =
            m_comparison.rungs[static_cast<std::size_t>(row.difference)];
        if (row.kind == Kind::Rung) {
            m_listRowOf[static_cast<std::size_t>(row.difference)] = i;
            auto *mark =
                new QTableWidgetItem(editor::CompareView::statusMark(d.status) + QLatin1Char(' ') +
                                     editor::CompareView::statusText(d.status));
            auto *a = new QTableWidgetItem(d.a >= 0 ? tr("rung %1").arg(d.a + 1) : QString());
            auto *b = new QTableWidgetItem(d.b >= 0 ? tr("rung %1").arg(d.b + 1) : QString());
            for (QTableWidgetItem *item : {mark, a, b}) {
                QFont f = item->font();
                f.setBold(true);
                item->setFont(f);
                item->setBackground(m_list->palette().color(QPalette::AlternateBase));
            }
            // A light tint only: the words carry the status (a pattern under text hid it).
            if (d.status != model::RungStatus::Same)
                mark->setBackground(editor::CompareView::statusColor(d.status).lighter(170));
            m_list->setItem(i, 0, mark);
            m_list->setItem(i, 1, a);
            m_list->setItem(i, 2, b);
            continue;
        }
        // The sign in words, so the column reads without the colour.
        const QString sign = row.kind == Kind::Same      ? QString()
                             : row.kind == Kind::Changed ? tr("~ changed")
                             : row.kind == Kind::Added   ? tr("+ only in B")
                                                         : tr("- only in A");
        m_list->setItem(i, 0, new QTableWidgetItem(sign));
        auto *a = new QTableWidgetItem(row.a);
        auto *b = new QTableWidgetItem(row.b);
        if (row.kind != Kind::Same) {
            const QColor tint = editor::CompareView::statusColor(
                                    row.kind == Kind::Added     ? model::RungStatus::Inserted
                                    : row.kind == Kind::Removed ? model::RungStatus::Deleted
                                                                : model::RungStatus::Changed)
                                    .lighter(170);
            for (QTableWidgetItem *item : {a, b})
                if (!item->text().isEmpty())
                    item->setBackground(tint);
        }
        m_list->setItem(i, 1, a);
        m_list->setItem(i, 2, b);
    }
}

void CompareWindow::nextChange(bool backwards) {
    if (!m_view->nextChange(backwards))
        m_summary->setText(backwards ? tr("No change before this one.")
                                     : tr("No change after this one."));
}

void CompareWindow::showCurrent(int difference) {
    if (difference < 0 || static_cast<std::size_t>(difference) >= m_listRowOf.size())
        return;
    const int row = m_listRowOf[static_cast<std::size_t>(difference)];
    if (m_list->currentRow() < row ||
        (static_cast<std::size_t>(difference) + 1 < m_listRowOf.size() &&
         m_list->currentRow() >= m_listRowOf[static_cast<std::size_t>(difference) + 1])) {
        const QSignalBlocker block(m_list);
        m_list->setCurrentCell(row, 0);
    }
    m_list->scrollToItem(m_list->item(row, 0), QAbstractItemView::PositionAtTop);
    updateSummary();
}

void CompareWindow::print() {
    QPrinter printer(QPrinter::HighResolution);
    printer.setPageOrientation(QPageLayout::Landscape);
    QPrintDialog dialog(&printer, this);
    if (dialog.exec() == QDialog::Accepted)
        m_view->print(&printer);
}

} // namespace rung::app
