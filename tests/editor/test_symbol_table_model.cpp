// The symbol table's model alone, without its view: its rows (the symbols, the rows typed that
// are no symbol yet, a free row), each column, an edit as one undo step of the document, the
// mark and reason of a row that is no symbol yet, and the model's signals as Qt's model tester
// checks them.

#include "editor/document.h"
#include "editor/symbol_table_model.h"

#include "tests/editor/model_tester.h"

#include <QSignalSpy>
#include <QUndoStack>

#include <gtest/gtest.h>

using namespace rung;
using editor::SymbolTableModel;

namespace {

struct SymbolTableModelTest : ::testing::Test {
    SymbolTableModelTest() { document.reset(vigor, QStringLiteral("VB")); }

    model::Address device(const char *text) const {
        return std::get<model::Address>(model::parseAddress(vigor, QString::fromLatin1(text)));
    }
    QString whyNot(const char *text) const {
        const auto parsed =
            model::parseAddress(vigor, QString::fromLatin1(text), document.modelVariant());
        const auto *error = std::get_if<model::AddressError>(&parsed);
        return error ? error->message : QString();
    }
    QString cell(int row, int column, int role = Qt::DisplayRole) const {
        return symbols.index(row, column).data(role).toString();
    }
    bool pending(int row) const {
        return symbols.index(row, 0).data(SymbolTableModel::PendingRole).toBool();
    }
    bool type(int row, int column, const QString &text) {
        return symbols.setData(symbols.index(row, column), text);
    }
    int steps() { return document.undoStack()->count(); }

    const model::Target &vigor = model::Target::get(model::Family::Vigor);
    editor::Document document;
    SymbolTableModel symbols{&document};
};

} // namespace

TEST_F(SymbolTableModelTest, TheRowsAreTheSymbolsThenTheRowsTypedThenAFreeRow) {
    document.setSymbols({{device("X0"), QStringLiteral("Start"), QStringLiteral("green, big")},
                         {device("Y0"), QStringLiteral("Pump"), QString()}});
    symbols.setPending({{QStringLiteral("X9"), QStringLiteral("Spare"), QStringLiteral("later")},
                        {QString(), QStringLiteral("Lamp"), QString()}});
    ASSERT_EQ(symbols.rowCount(), 5);
    ASSERT_EQ(symbols.columnCount(), 3);
    EXPECT_EQ(symbols.headerData(SymbolTableModel::DeviceColumn, Qt::Horizontal).toString(),
              QStringLiteral("Device"));
    EXPECT_EQ(symbols.headerData(SymbolTableModel::NameColumn, Qt::Horizontal).toString(),
              QStringLiteral("Name"));
    EXPECT_EQ(symbols.headerData(SymbolTableModel::CommentColumn, Qt::Horizontal).toString(),
              QStringLiteral("Comment"));
    const QStringList expected[5] = {
        {QStringLiteral("X0"), QStringLiteral("Start"), QStringLiteral("green, big")},
        {QStringLiteral("Y0"), QStringLiteral("Pump"), QString()},
        {QStringLiteral("X9"), QStringLiteral("Spare"), QStringLiteral("later")},
        {QString(), QStringLiteral("Lamp"), QString()},
        {QString(), QString(), QString()}};
    for (int r = 0; r < 5; ++r)
        for (int c = 0; c < 3; ++c) {
            EXPECT_EQ(cell(r, c), expected[r][c]) << r << "," << c;
            EXPECT_EQ(cell(r, c, Qt::EditRole), expected[r][c]) << r << "," << c;
            EXPECT_TRUE(symbols.flags(symbols.index(r, c)) & Qt::ItemIsEditable);
        }
    // The symbols and the free row are not marked, the rows typed are, and say why.
    EXPECT_FALSE(pending(0));
    EXPECT_FALSE(pending(1));
    EXPECT_TRUE(pending(2));
    EXPECT_TRUE(pending(3));
    EXPECT_FALSE(pending(4));
    EXPECT_TRUE(symbols.index(2, 2).data(SymbolTableModel::PendingRole).toBool()); // each cell
    ASSERT_FALSE(whyNot("X9").isEmpty());
    EXPECT_EQ(cell(2, 0, Qt::ToolTipRole), whyNot("X9"));
    EXPECT_EQ(cell(3, 0, Qt::ToolTipRole),
              QStringLiteral("No device yet: the row becomes a symbol when it names one"));
    EXPECT_TRUE(cell(0, 0, Qt::ToolTipRole).isEmpty());
    EXPECT_TRUE(cell(4, 0, Qt::ToolTipRole).isEmpty());
}

TEST_F(SymbolTableModelTest, AnEditOfACellIsOneUndoStepOfTheDocumentAndUndoShowsItBack) {
    document.setSymbols({{device("X0"), QStringLiteral("Start"), QString()}});
    const int before = steps();
    QSignalSpy changed(&symbols, &QAbstractItemModel::dataChanged);
    ASSERT_TRUE(type(0, SymbolTableModel::NameColumn, QStringLiteral("Begin")));
    EXPECT_EQ(steps(), before + 1);
    EXPECT_EQ(document.undoStack()->undoText(), QStringLiteral("Edit symbols"));
    ASSERT_EQ(document.project().symbols.size(), 1u);
    EXPECT_EQ(document.project().symbols[0].name, QStringLiteral("Begin"));
    EXPECT_EQ(cell(0, 1), QStringLiteral("Begin"));
    ASSERT_FALSE(changed.isEmpty());
    EXPECT_EQ(changed.last().at(0).toModelIndex().row(), 0);
    EXPECT_EQ(symbols.rowCount(), 2); // no row came or went

    changed.clear();
    document.undoStack()->undo();
    EXPECT_EQ(document.project().symbols[0].name, QStringLiteral("Start"));
    EXPECT_EQ(cell(0, 1), QStringLiteral("Start"));
    EXPECT_EQ(changed.size(), 1);
    document.undoStack()->redo();
    EXPECT_EQ(cell(0, 1), QStringLiteral("Begin"));

    // The same text again is no change: no undo step.
    ASSERT_TRUE(type(0, SymbolTableModel::NameColumn, QStringLiteral("Begin")));
    EXPECT_EQ(steps(), before + 1);
    // A header, a role other than the edit, a cell outside the table: no edit.
    EXPECT_FALSE(symbols.setData(symbols.index(0, 1), QStringLiteral("x"), Qt::ToolTipRole));
    EXPECT_FALSE(symbols.setData(symbols.index(5, 1), QStringLiteral("x")));
    EXPECT_EQ(steps(), before + 1);
}

TEST_F(SymbolTableModelTest, ARowTypedStaysMarkedUntilItsDeviceIsOneAndThenIsASymbol) {
    const int before = steps();
    QSignalSpy messages(&symbols, &SymbolTableModel::message);
    QSignalSpy pendingChanged(&symbols, &SymbolTableModel::pendingChanged);
    QSignalSpy inserted(&symbols, &QAbstractItemModel::rowsInserted);
    ASSERT_EQ(symbols.rowCount(), 1); // the free row
    // A name before the device: a row typed, a new free row after it, no undo step.
    ASSERT_TRUE(type(0, SymbolTableModel::NameColumn, QStringLiteral("Start")));
    EXPECT_EQ(steps(), before);
    ASSERT_EQ(symbols.rowCount(), 2);
    ASSERT_EQ(inserted.size(), 1);
    EXPECT_EQ(inserted[0].at(1).toInt(), 1); // after the row being typed: it keeps its place
    EXPECT_EQ(cell(0, 1), QStringLiteral("Start"));
    EXPECT_TRUE(pending(0));
    EXPECT_FALSE(pending(1));
    EXPECT_EQ(pendingChanged.size(), 1);
    EXPECT_TRUE(messages.isEmpty()); // nothing wrong with a device not typed yet
    ASSERT_EQ(symbols.pending().size(), 1u);
    EXPECT_EQ(symbols.pending()[0],
              (model::PendingSymbol{QString(), QStringLiteral("Start"), QString()}));

    // A device the target does not have: still no symbol, and the message says why.
    ASSERT_TRUE(type(0, SymbolTableModel::DeviceColumn, QStringLiteral(" X9 ")));
    EXPECT_EQ(steps(), before);
    ASSERT_EQ(messages.size(), 1);
    EXPECT_EQ(messages[0].at(0).toString(), whyNot("X9"));
    EXPECT_TRUE(pending(0));
    EXPECT_EQ(cell(0, 0), QStringLiteral("X9")); // as typed, without the spaces
    EXPECT_EQ(cell(0, 0, Qt::ToolTipRole), whyNot("X9"));
    EXPECT_EQ(pendingChanged.size(), 2);

    // Corrected: a symbol, one undo step, the mark gone.
    ASSERT_TRUE(type(0, SymbolTableModel::DeviceColumn, QStringLiteral("X7")));
    EXPECT_EQ(steps(), before + 1);
    ASSERT_EQ(document.project().symbols.size(), 1u);
    EXPECT_EQ(document.project().symbols[0],
              (model::Symbol{device("X7"), QStringLiteral("Start"), QString()}));
    EXPECT_FALSE(pending(0));
    EXPECT_TRUE(cell(0, 0, Qt::ToolTipRole).isEmpty());
    EXPECT_TRUE(symbols.pending().empty());
    EXPECT_EQ(pendingChanged.size(), 3);
    EXPECT_EQ(symbols.rowCount(), 2);

    // A symbol given a device the target lacks leaves the symbols (an undo step) and waits.
    ASSERT_TRUE(type(0, SymbolTableModel::DeviceColumn, QStringLiteral("X8")));
    EXPECT_EQ(steps(), before + 2);
    EXPECT_TRUE(document.project().symbols.empty());
    EXPECT_TRUE(pending(0));
    EXPECT_EQ(cell(0, 1), QStringLiteral("Start"));
}

TEST_F(SymbolTableModelTest, ARowClearedOfEverythingGoes) {
    ASSERT_TRUE(type(0, SymbolTableModel::CommentColumn, QStringLiteral("spare")));
    ASSERT_EQ(symbols.rowCount(), 2);
    QSignalSpy removed(&symbols, &QAbstractItemModel::rowsRemoved);
    QSignalSpy pendingChanged(&symbols, &SymbolTableModel::pendingChanged);
    ASSERT_TRUE(type(0, SymbolTableModel::CommentColumn, QString()));
    EXPECT_EQ(symbols.rowCount(), 1);
    EXPECT_EQ(removed.size(), 1);
    EXPECT_TRUE(symbols.pending().empty());
    EXPECT_EQ(pendingChanged.size(), 1);
    EXPECT_FALSE(pending(0));
}

TEST_F(SymbolTableModelTest, ADeviceOfThePlcReadAsARowTypedSaysHowItBecomesASymbol) {
    // A project file may hold one (written by hand, or by another version).
    symbols.setPending({{QStringLiteral("X1"), QStringLiteral("Stop"), QString()}});
    EXPECT_TRUE(pending(0));
    EXPECT_EQ(cell(0, 0, Qt::ToolTipRole),
              QStringLiteral("No symbol yet: edit the row to make it one"));
    ASSERT_TRUE(type(0, SymbolTableModel::CommentColumn, QStringLiteral("red")));
    ASSERT_EQ(document.project().symbols.size(), 1u);
    EXPECT_EQ(document.project().symbols[0],
              (model::Symbol{device("X1"), QStringLiteral("Stop"), QStringLiteral("red")}));
}

TEST_F(SymbolTableModelTest, ItFollowsTheDocumentsUndoRedoAndAnotherProject) {
    symbols.setPending({{QStringLiteral("X9"), QStringLiteral("Spare"), QString()}});
    QSignalSpy inserted(&symbols, &QAbstractItemModel::rowsInserted);
    QSignalSpy removed(&symbols, &QAbstractItemModel::rowsRemoved);
    document.setSymbols({{device("X0"), QStringLiteral("Start"), QString()},
                         {device("Y0"), QStringLiteral("Pump"), QString()}}); // an import, say
    ASSERT_EQ(symbols.rowCount(), 4);
    EXPECT_EQ(inserted.size(), 1);
    EXPECT_EQ(cell(0, 0), QStringLiteral("X0"));
    EXPECT_EQ(cell(1, 0), QStringLiteral("Y0"));
    EXPECT_EQ(cell(2, 0), QStringLiteral("X9"));
    EXPECT_TRUE(pending(2));
    document.undoStack()->undo();
    ASSERT_EQ(symbols.rowCount(), 2);
    EXPECT_EQ(removed.size(), 1);
    EXPECT_EQ(cell(0, 0), QStringLiteral("X9"));
    EXPECT_TRUE(pending(0));
    document.undoStack()->redo();
    EXPECT_EQ(symbols.rowCount(), 4);

    // Another project with its own rows typed: the model shows those.
    model::Project other = document.project();
    other.symbols = {{device("M0"), QStringLiteral("Run"), QString()}};
    symbols.setPending({});
    document.setProject(other, QString());
    ASSERT_EQ(symbols.rowCount(), 2);
    EXPECT_EQ(cell(0, 0), QStringLiteral("M0"));
    EXPECT_EQ(cell(0, 1), QStringLiteral("Run"));
    EXPECT_FALSE(pending(1));
}

TEST_F(SymbolTableModelTest, QtsModelTesterFindsNothingThroughEditsUndoAndAnotherProject) {
    test::CheckedModel checked(&symbols);
    ASSERT_TRUE(type(0, SymbolTableModel::NameColumn, QStringLiteral("Start")));
    ASSERT_TRUE(type(0, SymbolTableModel::DeviceColumn, QStringLiteral("X9")));
    ASSERT_TRUE(type(1, SymbolTableModel::DeviceColumn, QStringLiteral("Y0")));
    ASSERT_TRUE(type(0, SymbolTableModel::DeviceColumn, QStringLiteral("X0")));
    ASSERT_TRUE(type(2, SymbolTableModel::CommentColumn, QStringLiteral("spare")));
    ASSERT_TRUE(type(2, SymbolTableModel::CommentColumn, QString()));
    document.setSymbols({{device("M0"), QStringLiteral("Run"), QString()},
                         {device("M1"), QStringLiteral("Fault"), QString()},
                         {device("M2"), QString(), QString()}});
    document.undoStack()->undo();
    document.undoStack()->undo();
    document.undoStack()->redo();
    symbols.setPending({{QStringLiteral("X9"), QString(), QString()}});
    symbols.retranslate();
    document.reset(vigor, QStringLiteral("VB"));
    symbols.setPending({});
    EXPECT_EQ(symbols.rowCount(), 1);
    EXPECT_TRUE(checked.findings().isEmpty()) << checked.findings().join(u'\n').toStdString();
}
