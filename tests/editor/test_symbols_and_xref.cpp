// The symbol table as CSV (export, import, the forms spreadsheets write) and the cross
// reference of every device: grouped by device, filtered by a device or a prefix, and a use
// shows its rung.

#include "app/gui/main_window.h"
#include "app/gui/symbol_table.h"
#include "editor/cross_reference_view.h"
#include "editor/ladder_view.h"
#include "model/target/address.h"

#include <QApplication>
#include <QDockWidget>
#include <QFile>
#include <QFileDialog>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QSet>
#include <QSignalSpy>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QTreeView>
#include <QUndoStack>

#include "tests/editor/window_fixture.h"

#include <gtest/gtest.h>

using namespace rung;

namespace {

model::Address address(const char *text) {
    return std::get<model::Address>(
        model::parseAddress(model::Target::get(model::Family::Vigor), QString::fromLatin1(text)));
}

// The rows as the cross reference's tree shows them.
QSet<QString> devicesListed(editor::CrossReferenceView *view) {
    const QAbstractItemModel *rows = view->tree()->model();
    QSet<QString> names;
    for (int i = 0; i < rows->rowCount(); ++i)
        names << rows->index(i, 0).data().toString().section(QLatin1Char(' '), 0, 0);
    return names;
}

QString text(const QModelIndex &index, int role = Qt::DisplayRole) {
    return index.data(role).toString();
}

// The symbol table's cells, as the view shows them and as a user types them.
QTableView *symbolsTable(app::MainWindow &window) {
    return window.findChild<QTableView *>(QStringLiteral("symbolsTable"));
}
QModelIndex cell(QTableView *table, int row, int column) {
    return table->model()->index(row, column);
}
void type(QTableView *table, int row, int column, const QString &text) {
    ASSERT_TRUE(table->model()->setData(cell(table, row, column), text));
}

struct XrefFixture : test::WindowFixture {
    void SetUp() override {
        WindowFixture::SetUp();
        load("LD X0\nOUT Y0\nLD Y0\nANI X1\nOUT Y1\nLD M0\nTMR T0 K10\nEND\n");
    }
    void filter(const QString &text) {
        window.crossReferenceDevice()->setText(QStringLiteral("#")); // a change either way
        window.crossReferenceDevice()->setText(text);
    }
};

} // namespace

TEST_F(XrefFixture, AnEmptyFilterListsEveryDeviceAPrefixSome) {
    filter(QString());
    editor::CrossReferenceView *xref = window.crossReference();
    EXPECT_EQ(devicesListed(xref),
              (QSet<QString>{QStringLiteral("X0"), QStringLiteral("X1"), QStringLiteral("Y0"),
                             QStringLiteral("Y1"), QStringLiteral("M0"), QStringLiteral("T0")}));
    filter(QStringLiteral("x"));
    EXPECT_EQ(devicesListed(xref), (QSet<QString>{QStringLiteral("X0"), QStringLiteral("X1")}));
    filter(QStringLiteral("T0"));
    const QAbstractItemModel *rows = xref->tree()->model();
    ASSERT_EQ(rows->rowCount(), 1);
    const QModelIndex t0 = rows->index(0, 0);
    ASSERT_EQ(rows->rowCount(t0), 1);
    EXPECT_EQ(text(rows->index(0, 2, t0)), QStringLiteral("box"));
    EXPECT_EQ(text(rows->index(0, 3, t0)), QStringLiteral("TMR T0 K10"));
}

TEST_F(XrefFixture, ADeviceShowsItsNameAndEachUseLeadsToItsRung) {
    window.document()->setSymbols(
        {{address("Y0"), QStringLiteral("Pump"), QStringLiteral("main")}});
    filter(QStringLiteral("Y0"));
    QTreeView *tree = window.crossReference()->tree();
    const QAbstractItemModel *rows = tree->model();
    ASSERT_EQ(rows->rowCount(), 1);
    const QModelIndex y0 = rows->index(0, 0);
    EXPECT_EQ(text(y0), QStringLiteral("Y0  Pump"));
    EXPECT_EQ(text(y0, Qt::ToolTipRole), text(y0)); // whole, when the column cuts a long name
    EXPECT_EQ(text(rows->index(0, 3)), QStringLiteral("main"));
    EXPECT_TRUE(tree->isExpanded(y0));
    ASSERT_EQ(rows->rowCount(y0), 2);
    EXPECT_EQ(text(rows->index(1, 1, y0)), QStringLiteral("0002")); // LD Y0 is step 2
    emit tree->activated(rows->index(1, 0, y0));
    EXPECT_EQ(window.ladderView()->cursor().rung, 1);
}

TEST_F(XrefFixture, ACrossReferenceOffScreenCatchesUpWhenItComesBack) {
    window.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
    auto *dock = window.findChild<QDockWidget *>(QStringLiteral("crossReferenceDock"));
    auto *project = window.findChild<QDockWidget *>(QStringLiteral("projectDock"));
    ASSERT_NE(dock, nullptr);
    ASSERT_NE(project, nullptr);
    QSignalSpy shown(dock, &QDockWidget::visibilityChanged);
    dock->raise();
    if (shown.isEmpty()) {
        ASSERT_TRUE(shown.wait(3000));
    }
    filter(QString());
    std::vector<model::Diagnostic> errors;
    ASSERT_TRUE(window.document()->setListing(QStringLiteral("LD X7\nOUT Y7\nEND\n"), &errors));
    EXPECT_EQ(devicesListed(window.crossReference()), // on screen: it follows at once
              (QSet<QString>{QStringLiteral("X7"), QStringLiteral("Y7")}));

    shown.clear();
    project->raise(); // behind the project dock: edits leave it alone
    if (shown.isEmpty()) {
        ASSERT_TRUE(shown.wait(3000));
    }
    ASSERT_TRUE(window.document()->setListing(QStringLiteral("LD X6\nOUT Y6\nEND\n"), &errors));
    EXPECT_EQ(devicesListed(window.crossReference()),
              (QSet<QString>{QStringLiteral("X7"), QStringLiteral("Y7")}));
    shown.clear();
    dock->raise(); // back: it catches up
    if (shown.isEmpty()) {
        ASSERT_TRUE(shown.wait(3000));
    }
    EXPECT_EQ(devicesListed(window.crossReference()),
              (QSet<QString>{QStringLiteral("X6"), QStringLiteral("Y6")}));
}

TEST(SymbolsTable, ExportAndImportGiveTheSameTableWithCommasQuotesAndLineBreaks) {
    const std::vector<model::Symbol> symbols = {
        {address("X0"), QStringLiteral("Start"), QStringLiteral("green, big; left")},
        {address("Y0"), QStringLiteral("Pump \"A\""), QStringLiteral("line one\nline two")},
        {address("M7"), QStringLiteral("Fault"), QString()}};
    app::MainWindow window;
    window.newProject(model::Target::get(model::Family::Vigor), QStringLiteral("VB"));
    window.document()->setSymbols(symbols);
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("symbols.csv"));
    QString error;
    ASSERT_TRUE(window.symbolTable()->exportCsv(path, &error)) << error.toStdString();

    app::MainWindow other;
    other.newProject(model::Target::get(model::Family::Vigor), QStringLiteral("VB"));
    ASSERT_TRUE(other.symbolTable()->importCsv(path, &error)) << error.toStdString();
    const auto &back = other.document()->project().symbols;
    ASSERT_EQ(back.size(), symbols.size());
    for (std::size_t i = 0; i < symbols.size(); ++i) {
        EXPECT_EQ(back[i].address, symbols[i].address);
        EXPECT_EQ(back[i].name, symbols[i].name);
        EXPECT_EQ(back[i].comment, symbols[i].comment);
    }
    EXPECT_EQ(other.document()->undoStack()->count(), 1); // one step

    EXPECT_FALSE(window.symbolTable()->exportCsv(QStringLiteral("/nonexistent-dir/s.csv"), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("nonexistent-dir"))) << error.toStdString();
}

// The symbol table is edited in place: a row is a symbol once its device is valid; until then
// it stays as typed, and an invalid device says why.
TEST(SymbolsTable, EditedInPlaceKeepsIncompleteRowsAndMarksInvalidDevices) {
    app::MainWindow window;
    const model::Target &vigor = model::Target::get(model::Family::Vigor);
    window.newProject(vigor, QStringLiteral("VB"));
    QTableView *table = symbolsTable(window);
    ASSERT_NE(table, nullptr);
    const QAbstractItemModel *rows = table->model();
    QUndoStack *undo = window.document()->undoStack();
    const int before = undo->count();
    ASSERT_EQ(rows->rowCount(), 1); // the free row
    // A name before the device: no symbol yet, no undo step, and the row stays.
    type(table, 0, 1, QStringLiteral("Start"));
    EXPECT_EQ(undo->count(), before);
    EXPECT_TRUE(window.document()->project().symbols.empty());
    ASSERT_EQ(rows->rowCount(), 2); // the typed row and a new free row
    EXPECT_EQ(text(cell(table, 0, 1)), QStringLiteral("Start"));
    // Its device completes it: one undo step.
    type(table, 0, 0, QStringLiteral("X0"));
    EXPECT_EQ(undo->count(), before + 1);
    EXPECT_EQ(undo->undoText(), QStringLiteral("Edit symbols"));
    ASSERT_EQ(window.document()->project().symbols.size(), 1u);
    EXPECT_EQ(window.document()->project().symbols.front().name, QStringLiteral("Start"));
    // A device the target does not have stays, marked, with the reason as its tooltip.
    ASSERT_EQ(rows->rowCount(), 2);
    type(table, 1, 0, QStringLiteral("X9"));
    EXPECT_EQ(undo->count(), before + 1);
    ASSERT_EQ(rows->rowCount(), 3);
    const auto parsed =
        model::parseAddress(vigor, QStringLiteral("X9"), vigor.model(QStringLiteral("VB")));
    ASSERT_TRUE(std::holds_alternative<model::AddressError>(parsed));
    EXPECT_EQ(text(cell(table, 1, 0)), QStringLiteral("X9"));
    EXPECT_EQ(text(cell(table, 1, 0), Qt::ToolTipRole),
              std::get<model::AddressError>(parsed).message);
    EXPECT_NE(cell(table, 1, 0).data(Qt::BackgroundRole),
              cell(table, 0, 0).data(Qt::BackgroundRole));
    EXPECT_TRUE(cell(table, 1, 0).data(Qt::BackgroundRole).value<QColor>().isValid());
    // Corrected, it becomes a symbol.
    type(table, 1, 0, QStringLiteral("X7"));
    EXPECT_EQ(undo->count(), before + 2);
    EXPECT_EQ(window.document()->project().symbols.size(), 2u);
    EXPECT_EQ(rows->rowCount(), 3);
    // A typed row cleared of everything goes.
    type(table, 2, 1, QStringLiteral("Spare"));
    ASSERT_EQ(rows->rowCount(), 4);
    type(table, 2, 1, QString());
    EXPECT_EQ(rows->rowCount(), 3);
    EXPECT_EQ(undo->count(), before + 2);
}

// A row that is no symbol yet (X9 on a Vigor) is the user's work too: Save keeps it, reopening
// shows it marked as before, and it counts as unsaved until saved.
TEST(SymbolsTable, AnInvalidRowIsSavedAndReopensMarked) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("symbols.rung"));
    app::MainWindow window;
    const model::Target &vigor = model::Target::get(model::Family::Vigor);
    window.newProject(vigor, QStringLiteral("VB"));
    ASSERT_TRUE(window.saveTo(path));
    QTableView *table = symbolsTable(window);
    ASSERT_NE(table, nullptr);
    type(table, 0, 0, QStringLiteral("X9"));
    type(table, 0, 1, QStringLiteral("Spare"));
    type(table, 0, 2, QStringLiteral("wired later"));
    EXPECT_TRUE(window.isModified());
    EXPECT_TRUE(window.isWindowModified());
    ASSERT_TRUE(window.saveTo(path));
    EXPECT_FALSE(window.isModified());
    const auto saved = model::loadProject(path, nullptr);
    ASSERT_TRUE(saved);
    EXPECT_TRUE(saved->symbols.empty());
    ASSERT_EQ(saved->pendingSymbols.size(), 1u);
    EXPECT_EQ(saved->pendingSymbols.front(),
              (model::PendingSymbol{QStringLiteral("X9"), QStringLiteral("Spare"),
                                    QStringLiteral("wired later")}));

    app::MainWindow reopened;
    ASSERT_TRUE(reopened.openFile(path, QString(), true));
    QTableView *back = symbolsTable(reopened);
    ASSERT_NE(back, nullptr);
    ASSERT_EQ(back->model()->rowCount(), 2); // the row and the free row
    EXPECT_EQ(text(cell(back, 0, 0)), QStringLiteral("X9"));
    EXPECT_EQ(text(cell(back, 0, 1)), QStringLiteral("Spare"));
    EXPECT_EQ(text(cell(back, 0, 2)), QStringLiteral("wired later"));
    const auto parsed =
        model::parseAddress(vigor, QStringLiteral("X9"), vigor.model(QStringLiteral("VB")));
    ASSERT_TRUE(std::holds_alternative<model::AddressError>(parsed));
    EXPECT_EQ(text(cell(back, 0, 0), Qt::ToolTipRole),
              std::get<model::AddressError>(parsed).message);
    EXPECT_NE(cell(back, 0, 0).data(Qt::BackgroundRole), cell(back, 1, 0).data(Qt::BackgroundRole));
    EXPECT_FALSE(reopened.isModified());
    // Corrected, it is a symbol, and the next save leaves the key out.
    type(back, 0, 0, QStringLiteral("X7"));
    ASSERT_EQ(reopened.document()->project().symbols.size(), 1u);
    ASSERT_TRUE(reopened.saveTo(path));
    const auto fixed = model::loadProject(path, nullptr);
    ASSERT_TRUE(fixed);
    EXPECT_TRUE(fixed->pendingSymbols.empty());
    EXPECT_EQ(fixed->symbols.front().name, QStringLiteral("Spare"));
}

// Export Symbols cannot write a row that names no device of the PLC (it would not import
// again): it names the row and asks first; No exports nothing.
TEST(SymbolsTable, ExportSaysWhichRowsItLeavesOutAndAsks) {
    app::MainWindow window;
    window.newProject(model::Target::get(model::Family::Vigor), QStringLiteral("VB"));
    QTableView *table = symbolsTable(window);
    ASSERT_NE(table, nullptr);
    type(table, 0, 0, QStringLiteral("X9"));
    type(table, 0, 1, QStringLiteral("Spare"));
    QAction *exportAction = test::editMenuEntry(window, QStringLiteral("Export Symbols (CSV)..."));
    ASSERT_NE(exportAction, nullptr);
    QString asked;
    int fileDialogs = 0;
    // Whatever opens is answered: the question with No, a file dialog (which must not come)
    // with Cancel, so the test cannot hang.
    QTimer answer;
    answer.setInterval(10);
    QObject::connect(&answer, &QTimer::timeout, [&] {
        QWidget *modal = QApplication::activeModalWidget();
        if (auto *box = qobject_cast<QMessageBox *>(modal)) {
            asked = box->text();
            box->button(QMessageBox::No)->click();
        } else if (auto *files = qobject_cast<QFileDialog *>(modal)) {
            ++fileDialogs;
            files->reject();
        }
    });
    answer.start();
    exportAction->trigger();
    answer.stop();
    EXPECT_TRUE(asked.contains(QLatin1String("X9 Spare"))) << asked.toStdString();
    EXPECT_EQ(fileDialogs, 0);
}
