// The watch lists' model alone, without a view: the rows are the document's lists and their
// devices, each column's text in each format, a value set in the value column is written
// through the source, a snapshot changes only the value and force cells (no reset, no rows),
// and an edit, its undo and its redo insert and remove the rows that changed. Qt's own model
// tester watches it through edits and reports nothing.

#include "fake_monitor_source.h"

#include "editor/device_mime.h"
#include "editor/document.h"
#include "editor/watch_list_model.h"
#include "model/target/address.h"

#include <QAbstractItemModelTester>
#include <QLoggingCategory>
#include <QPersistentModelIndex>
#include <QSignalSpy>
#include <QUndoStack>

#include <gtest/gtest.h>

using namespace rung;
using Model = editor::WatchListModel;
using model::ValueFormat;
using Kind = model::DeviceCommand::Kind;

namespace {

struct WatchListModelTest : ::testing::Test {
    const model::Target &target = model::Target::get(model::Family::Vigor);
    editor::Document document;
    std::unique_ptr<Model> model;
    test::FakeMonitorSource source;

    void SetUp() override {
        document.reset(target, QStringLiteral("VB"));
        document.setWatchLists(
            {{QStringLiteral("Lamps"), {QStringLiteral("X0"), QStringLiteral("D5")}, {}},
             {QStringLiteral("Timers"), {QStringLiteral("T3"), QStringLiteral("Q9")}, {}}},
            QStringLiteral("watch"));
        model = std::make_unique<Model>(&document);
    }
    QModelIndex list(int i) const { return model->index(i, 0); }
    QModelIndex row(int i, int k, int column = Model::DeviceColumn) const {
        return model->index(k, column, list(i));
    }
    QString text(int i, int k, int column, int role = Qt::DisplayRole) const {
        return row(i, k, column).data(role).toString();
    }
    model::Address at(const char *device) const {
        return std::get<model::Address>(model::parseAddress(target, QString::fromLatin1(device)));
    }
    void publish(const std::function<void(model::Snapshot &)> &fill) {
        ASSERT_TRUE(source.publishFilled(target, fill));
    }
    void setWord(model::Snapshot &s, const char *device, std::int32_t value) const {
        s.words[static_cast<std::size_t>(s.layout->word(at(device)))] = value;
    }
    void setBit(model::Snapshot &s, const char *device, bool forced) const {
        const model::BitRef r = s.layout->bit(at(device));
        s.words[static_cast<std::size_t>(r.word)] |= static_cast<std::int32_t>(r.mask);
        if (forced)
            s.forceMask[static_cast<std::size_t>(r.word)] |= r.mask;
    }
    QStringList devices(int i) const {
        QStringList out;
        for (int k = 0; k < model->rowCount(list(i)); ++k)
            out << text(i, k, Model::DeviceColumn);
        return out;
    }
};

// Qt's model tester reports through the "qt.modeltest" category; in its Warning mode a finding
// is a warning there, collected here while the tester watches.
QStringList *g_modelTesterFindings = nullptr;

void collectModelTesterFinding(QtMsgType, const QMessageLogContext &context, const QString &text) {
    if (g_modelTesterFindings && context.category &&
        QByteArray(context.category).startsWith("qt.modeltest"))
        *g_modelTesterFindings << text;
}

} // namespace

TEST_F(WatchListModelTest, TheRowsAreTheListsAndTheirDevices) {
    ASSERT_EQ(model->rowCount(), 2);
    EXPECT_EQ(model->columnCount(), 5);
    EXPECT_EQ(list(0).data().toString(), QStringLiteral("Lamps"));
    EXPECT_EQ(list(1).data().toString(), QStringLiteral("Timers"));
    EXPECT_EQ(list(1).data(Qt::AccessibleTextRole).toString(), QStringLiteral("Watch list Timers"));
    EXPECT_EQ(devices(0), (QStringList{QStringLiteral("X0"), QStringLiteral("D5")}));
    EXPECT_EQ(devices(1), (QStringList{QStringLiteral("T3"), QStringLiteral("Q9")}));
    EXPECT_EQ(row(1, 0).parent(), list(1));
    EXPECT_FALSE(list(1).parent().isValid());
    EXPECT_EQ(model->rowCount(row(0, 0)), 0);
    EXPECT_FALSE(model->isDevice(list(0)));
    EXPECT_TRUE(model->isDevice(row(0, 1, Model::ValueColumn)));
    EXPECT_EQ(model->listOf(row(1, 1)), 1);
    EXPECT_EQ(model->device(row(1, 0)), QStringLiteral("T3"));
    EXPECT_EQ(model->address(row(0, 1)), at("D5"));
    EXPECT_TRUE(model->isBit(row(0, 0)));
    EXPECT_FALSE(model->isBit(row(0, 1)));
    EXPECT_TRUE(model->isElement(row(1, 0)));
    EXPECT_FALSE(model->isElement(row(0, 1)));

    // Headers, with what a double-click does where it does something.
    EXPECT_EQ(model->headerData(Model::DeviceColumn, Qt::Horizontal).toString(),
              QStringLiteral("Device"));
    EXPECT_EQ(model->headerData(Model::ForceColumn, Qt::Horizontal).toString(),
              QStringLiteral("Forced"));
    EXPECT_EQ(model->headerData(Model::FormatColumn, Qt::Horizontal, Qt::ToolTipRole).toString(),
              QStringLiteral("Double-click: show the word in decimal, signed, hexadecimal, "
                             "binary or BCD"));
    EXPECT_FALSE(model->headerData(Model::DeviceColumn, Qt::Horizontal, Qt::ToolTipRole).isValid());

    // Without a source: the device, its symbol and format; no value, except that a name the
    // target has no device for says so.
    document.setSymbols(
        {model::Symbol{at("X0"), QStringLiteral("Start"), QStringLiteral("green button")}});
    EXPECT_EQ(text(0, 0, Model::SymbolColumn), QStringLiteral("Start"));
    EXPECT_EQ(text(0, 0, Model::SymbolColumn, Qt::ToolTipRole), QStringLiteral("green button"));
    EXPECT_EQ(text(0, 1, Model::SymbolColumn), QString());
    EXPECT_EQ(text(0, 0, Model::FormatColumn), QString()); // a bit has none
    EXPECT_EQ(text(0, 1, Model::FormatColumn), QStringLiteral("Decimal"));
    EXPECT_EQ(text(0, 1, Model::ValueColumn), QString());
    EXPECT_EQ(text(1, 1, Model::ValueColumn), QStringLiteral("not a device"));
    EXPECT_FALSE(model->address(row(1, 1)));
    // Rows drag out; the value column takes a value only while a source can write it.
    EXPECT_TRUE(model->flags(row(0, 1)).testFlag(Qt::ItemIsDragEnabled));
    EXPECT_FALSE(model->flags(list(0)).testFlag(Qt::ItemIsDragEnabled));
    EXPECT_FALSE(model->flags(row(0, 1, Model::ValueColumn)).testFlag(Qt::ItemIsEditable));
    model->setMonitorSource(&source);
    EXPECT_TRUE(model->flags(row(0, 1, Model::ValueColumn)).testFlag(Qt::ItemIsEditable));
    EXPECT_TRUE(model->flags(row(0, 0, Model::ValueColumn)).testFlag(Qt::ItemIsEditable));
    EXPECT_FALSE(model->flags(row(1, 0, Model::ValueColumn)).testFlag(Qt::ItemIsEditable));
    EXPECT_FALSE(model->flags(row(0, 1, Model::DeviceColumn)).testFlag(Qt::ItemIsEditable));
}

TEST_F(WatchListModelTest, EachColumnShowsTheSnapshotInTheRowsFormat) {
    model->setMonitorSource(&source);
    std::vector<model::Address> watched{at("X0"), at("D5"), at("T3")};
    std::sort(watched.begin(), watched.end());
    EXPECT_EQ(source.watched(), watched);
    publish([&](model::Snapshot &s) {
        setBit(s, "X0", true);
        setWord(s, "D5", -5);
        setWord(s, "T3", 12);
        s.words[static_cast<std::size_t>(s.layout->setValueWord(at("T3")))] = 50;
    });
    EXPECT_EQ(text(0, 0, Model::ValueColumn), QStringLiteral("ON (forced)"));
    EXPECT_EQ(text(0, 0, Model::ValueColumn, Qt::EditRole), QStringLiteral("ON"));
    EXPECT_EQ(text(0, 0, Model::ForceColumn), QStringLiteral("ON"));
    EXPECT_EQ(text(0, 0, Model::ForceColumn, Qt::AccessibleTextRole), QStringLiteral("Forced ON"));
    EXPECT_TRUE(row(0, 0, Model::ValueColumn).data(Model::ForcedRole).toBool());
    EXPECT_FALSE(row(0, 1, Model::ValueColumn).data(Model::ForcedRole).toBool());
    EXPECT_EQ(text(0, 1, Model::ForceColumn), QString());
    EXPECT_EQ(text(0, 1, Model::ForceColumn, Qt::AccessibleTextRole), QStringLiteral("Not forced"));
    EXPECT_EQ(text(1, 0, Model::ValueColumn), QStringLiteral("12 of 50, OFF"));

    const std::pair<ValueFormat, const char *> expected[] = {
        {ValueFormat::Decimal, "65531"},        {ValueFormat::Signed, "-5"},
        {ValueFormat::Hex, "0xFFFB"},           {ValueFormat::Binary, "1111 1111 1111 1011"},
        {ValueFormat::Bcd, "0xFFFB (not BCD)"},
    };
    for (const auto &[format, value] : expected) {
        model->setFormat(row(0, 1), format);
        EXPECT_EQ(model->format(row(0, 1)), format);
        EXPECT_EQ(text(0, 1, Model::ValueColumn), QString::fromLatin1(value));
        // The editor opens on the value alone, in the row's format.
        EXPECT_EQ(text(0, 1, Model::ValueColumn, Qt::EditRole), QString::fromLatin1(value));
        EXPECT_EQ(text(0, 1, Model::FormatColumn), model::valueFormatName(format));
    }
    EXPECT_EQ(document.undoStack()->undoText(), QStringLiteral("Show D5 as BCD"));
    model->setFormat(row(1, 0), ValueFormat::Hex);
    EXPECT_EQ(text(1, 0, Model::ValueColumn), QStringLiteral("0x000C of 0x0032, OFF"));
    EXPECT_EQ(text(1, 0, Model::ValueColumn, Qt::EditRole), QStringLiteral("0x000C"));

    // A snapshot of another target is not ours: no values.
    test::FakeMonitorSource other;
    model->setMonitorSource(&other);
    EXPECT_TRUE(source.watched().empty());
    other.publish(other.blank(model::Target::get(model::Family::Cpm1)));
    EXPECT_EQ(text(0, 1, Model::ValueColumn), QString());
    EXPECT_EQ(text(0, 0, Model::ForceColumn, Qt::AccessibleTextRole), QString());
}

// A CPM1 shows its channels as BCD digits until the user picks another format.
TEST_F(WatchListModelTest, ACpm1ChannelIsBcdUntilChosenOtherwise) {
    const model::Target &cpm1 = model::Target::get(model::Family::Cpm1);
    document.reset(cpm1, cpm1.defaultModel().name);
    EXPECT_EQ(model->rowCount(), 0);
    ASSERT_TRUE(model->addDevices({QStringLiteral("DM 0000")}));
    EXPECT_EQ(list(0).data().toString(), QStringLiteral("Watch 1"));
    EXPECT_EQ(model->format(row(0, 0)), ValueFormat::Bcd);
    model->setFormat(row(0, 0), ValueFormat::Decimal);
    EXPECT_EQ(model->format(row(0, 0)), ValueFormat::Decimal);
    EXPECT_EQ(document.project().watchLists[0].format(QStringLiteral("DM 0000")),
              ValueFormat::Decimal);
}

TEST_F(WatchListModelTest, AValueSetInTheValueColumnIsWrittenThroughTheSource) {
    QSignalSpy messages(model.get(), &Model::message);
    // No source: nothing to write to.
    EXPECT_FALSE(model->setData(row(0, 1, Model::ValueColumn), QStringLiteral("7")));
    model->setMonitorSource(&source);
    publish([&](model::Snapshot &s) { setWord(s, "D5", 42); });
    QSignalSpy changed(model.get(), &QAbstractItemModel::dataChanged);
    EXPECT_TRUE(model->setData(row(0, 1, Model::ValueColumn), QStringLiteral(" 1234 ")));
    ASSERT_EQ(source.commands.size(), 1u);
    EXPECT_EQ(source.commands[0].kind, Kind::WriteWord);
    EXPECT_EQ(source.commands[0].address, at("D5"));
    EXPECT_EQ(source.commands[0].value, 1234);
    // The cell shows what the source holds, not the text set, until a snapshot has it.
    EXPECT_EQ(text(0, 1, Model::ValueColumn), QStringLiteral("42"));
    ASSERT_EQ(changed.size(), 1);
    EXPECT_EQ(changed[0][0].value<QModelIndex>(), row(0, 1, Model::ValueColumn));
    // A bit takes ON/OFF or 1/0.
    EXPECT_TRUE(model->setData(row(0, 0, Model::ValueColumn), QStringLiteral("off")));
    EXPECT_EQ(source.commands.back().kind, Kind::WriteBit);
    EXPECT_EQ(source.commands.back().address, at("X0"));
    EXPECT_EQ(source.commands.back().value, 0);
    EXPECT_TRUE(model->flipBit(row(0, 0)));
    EXPECT_EQ(source.commands.back().value, 1); // it was OFF
    // Only the value column, and only the edit role, write.
    EXPECT_FALSE(model->setData(row(0, 1, Model::DeviceColumn), QStringLiteral("D6")));
    EXPECT_FALSE(
        model->setData(row(0, 1, Model::ValueColumn), QStringLiteral("7"), Qt::DisplayRole));
    EXPECT_FALSE(model->setData(list(0), QStringLiteral("7")));
    EXPECT_EQ(source.commands.size(), 3u);
    EXPECT_TRUE(messages.isEmpty());
    // What cannot be written is refused, with the reason.
    EXPECT_FALSE(model->setData(row(0, 1, Model::ValueColumn), QStringLiteral("12a")));
    EXPECT_FALSE(model->setData(row(1, 0, Model::ValueColumn), QStringLiteral("25")));
    EXPECT_FALSE(model->checkWritable(row(1, 0)));
    EXPECT_FALSE(model->flipBit(row(0, 1))); // a word does not flip
    EXPECT_EQ(source.commands.size(), 3u);
    ASSERT_EQ(messages.size(), 3);
    EXPECT_EQ(messages[0][0].toString(),
              QStringLiteral("\"12a\" is no value for D5: type a whole number (0x before a "
                             "hexadecimal one)"));
    EXPECT_EQ(messages[1][0].toString(),
              QStringLiteral("T3 is a timer or counter: its current value follows the program "
                             "and cannot be written here"));
    EXPECT_EQ(messages[2][0].toString(), messages[1][0].toString());
    EXPECT_TRUE(model->checkWritable(row(0, 1)));
    // A command the source refuses later is said too.
    source.failWith = QStringLiteral("D5 cannot be written");
    EXPECT_TRUE(model->setData(row(0, 1, Model::ValueColumn), QStringLiteral("1")));
    ASSERT_TRUE(messages.size() == 4 || messages.wait(2000));
    EXPECT_EQ(messages.back()[0].toString(), QStringLiteral("D5 cannot be written"));
}

// A watch of 500 devices at the source's rate: every snapshot changes the value and force
// cells, nothing else; no reset, no rows.
TEST_F(WatchListModelTest, ASnapshotChangesOnlyTheValueAndForceColumns) {
    ASSERT_TRUE(model->addDevices({QStringLiteral("D0..D499")}, 1));
    ASSERT_EQ(model->rowCount(list(1)), 2 + 500);
    model->setMonitorSource(&source);
    QSignalSpy reset(model.get(), &QAbstractItemModel::modelReset);
    QSignalSpy inserted(model.get(), &QAbstractItemModel::rowsInserted);
    QSignalSpy removed(model.get(), &QAbstractItemModel::rowsRemoved);
    QSignalSpy layout(model.get(), &QAbstractItemModel::layoutChanged);
    QSignalSpy changed(model.get(), &QAbstractItemModel::dataChanged);
    for (int n = 1; n <= 3; ++n)
        publish([&](model::Snapshot &s) {
            setWord(s, "D499", n);
            setBit(s, "X0", n % 2 == 1);
        });
    EXPECT_EQ(text(1, 2 + 499, Model::ValueColumn), QStringLiteral("3"));
    EXPECT_EQ(text(0, 0, Model::ForceColumn), QStringLiteral("ON"));
    EXPECT_EQ(reset.size(), 0);
    EXPECT_EQ(inserted.size(), 0);
    EXPECT_EQ(removed.size(), 0);
    EXPECT_EQ(layout.size(), 0);
    // Each snapshot: one range of each list's value cells and one of its force cells.
    ASSERT_EQ(changed.size(), 3 * 2 * 2);
    std::set<int> columns;
    for (const QList<QVariant> &signal : changed) {
        const auto from = signal[0].value<QModelIndex>();
        const auto to = signal[1].value<QModelIndex>();
        EXPECT_EQ(from.column(), to.column());
        EXPECT_EQ(from.parent(), to.parent());
        EXPECT_EQ(from.row(), 0);
        EXPECT_EQ(to.row(), model->rowCount(to.parent()) - 1);
        columns.insert(from.column());
    }
    EXPECT_EQ(columns, (std::set<int>{Model::ValueColumn, Model::ForceColumn}));
}

TEST_F(WatchListModelTest, AnAddItsUndoAndItsRedoInsertAndRemoveTheRows) {
    QSignalSpy reset(model.get(), &QAbstractItemModel::modelReset);
    QSignalSpy inserted(model.get(), &QAbstractItemModel::rowsInserted);
    QSignalSpy removed(model.get(), &QAbstractItemModel::rowsRemoved);
    const QPersistentModelIndex d5 = row(0, 1);
    ASSERT_TRUE(model->addDevices({QStringLiteral("Y0"), QStringLiteral("D10..D12")}, 0));
    EXPECT_EQ(document.undoStack()->undoText(), QStringLiteral("Add Y0..D12 to the watch list"));
    EXPECT_EQ(devices(0), (QStringList{"X0", "D5", "Y0", "D10", "D11", "D12"}));
    ASSERT_EQ(inserted.size(), 1);
    EXPECT_EQ(inserted[0][0].value<QModelIndex>(), list(0));
    EXPECT_EQ(inserted[0][1].toInt(), 2);
    EXPECT_EQ(inserted[0][2].toInt(), 5);

    document.undoStack()->undo();
    EXPECT_EQ(devices(0), (QStringList{"X0", "D5"}));
    ASSERT_EQ(removed.size(), 1);
    EXPECT_EQ(removed[0][1].toInt(), 2);
    EXPECT_EQ(removed[0][2].toInt(), 5);
    document.undoStack()->redo();
    EXPECT_EQ(devices(0).size(), 6);
    EXPECT_EQ(inserted.size(), 2);

    // Rows apart removed at once: each run its own signal; the rows between stay the same
    // rows (a view keeps their selection).
    const QPersistentModelIndex y0 = row(0, 2);
    model->removeDevices({row(0, 1, Model::ValueColumn), row(0, 1), row(0, 3), row(0, 4)});
    EXPECT_EQ(document.undoStack()->undoText(),
              QStringLiteral("Remove D5, D10, D11 from the watch list"));
    EXPECT_EQ(devices(0), (QStringList{"X0", "Y0", "D12"}));
    EXPECT_EQ(removed.size(), 3);
    EXPECT_FALSE(d5.isValid());
    ASSERT_TRUE(y0.isValid());
    EXPECT_EQ(model->device(y0), QStringLiteral("Y0"));
    document.undoStack()->undo();
    EXPECT_EQ(devices(0), (QStringList{"X0", "D5", "Y0", "D10", "D11", "D12"}));
    EXPECT_EQ(model->device(y0), QStringLiteral("Y0"));
    EXPECT_EQ(y0.row(), 2);

    // A list of its own comes and goes as one row, with its devices.
    std::vector<model::WatchList> lists = document.project().watchLists;
    lists.insert(lists.begin() + 1, {QStringLiteral("Tank"), {QStringLiteral("M1")}, {}});
    const int before = static_cast<int>(inserted.size());
    document.setWatchLists(lists, QStringLiteral("add a list"));
    ASSERT_EQ(model->rowCount(), 3);
    EXPECT_EQ(list(1).data().toString(), QStringLiteral("Tank"));
    EXPECT_EQ(devices(1), QStringList{QStringLiteral("M1")});
    ASSERT_EQ(inserted.size(), before + 1);
    EXPECT_FALSE(inserted.back()[0].value<QModelIndex>().isValid());
    document.undoStack()->undo();
    EXPECT_EQ(model->rowCount(), 2);
    EXPECT_EQ(devices(1), (QStringList{"T3", "Q9"}));
    EXPECT_EQ(reset.size(), 0);

    // Another family: every address means something else, the model starts again.
    document.reset(model::Target::get(model::Family::Cpm1),
                   model::Target::get(model::Family::Cpm1).defaultModel().name);
    EXPECT_EQ(reset.size(), 1);
    EXPECT_EQ(model->rowCount(), 0);
}

TEST_F(WatchListModelTest, DevicesDragOutInTheTablesOrderAndDropIntoAList) {
    const QModelIndexList rows{row(1, 0, Model::ValueColumn), row(0, 1), row(1, 0), list(0)};
    std::unique_ptr<QMimeData> out(model->mimeData(rows));
    ASSERT_NE(out, nullptr);
    EXPECT_EQ(editor::devicesFromMime(out.get()), (QStringList{"D5", "T3"}));
    EXPECT_EQ(model->mimeData({list(0)}), nullptr);
    EXPECT_TRUE(model->mimeTypes().contains(editor::deviceMimeType()));

    std::unique_ptr<QMimeData> in(editor::deviceMimeData({"M5", "D0..D1"}));
    EXPECT_TRUE(model->canDropMimeData(in.get(), Qt::CopyAction, -1, -1, list(1)));
    EXPECT_FALSE(model->canDropMimeData(in.get(), Qt::MoveAction, -1, -1, list(1)));
    QMimeData empty;
    EXPECT_FALSE(model->canDropMimeData(&empty, Qt::CopyAction, -1, -1, list(1)));
    // On a device row: into its list.
    EXPECT_TRUE(model->dropMimeData(in.get(), Qt::CopyAction, -1, -1, row(1, 1)));
    EXPECT_EQ(devices(1), (QStringList{"T3", "Q9", "M5", "D0", "D1"}));
    EXPECT_EQ(devices(0), (QStringList{"X0", "D5"}));
    QSignalSpy messages(model.get(), &Model::message);
    QMimeData wrong;
    wrong.setText(QStringLiteral("M5, Q7"));
    EXPECT_FALSE(model->dropMimeData(&wrong, Qt::CopyAction, -1, -1, list(0)));
    EXPECT_EQ(devices(0), (QStringList{"X0", "D5"}));
    ASSERT_EQ(messages.size(), 1);
    EXPECT_TRUE(messages[0][0].toString().startsWith(QStringLiteral("Not added to the watch list")))
        << messages[0][0].toString().toStdString();
}

TEST_F(WatchListModelTest, QtsModelTesterFindsNothingThroughEdits) {
    QStringList findings;
    g_modelTesterFindings = &findings;
    const QtMessageHandler previous = qInstallMessageHandler(collectModelTesterFinding);
    {
        QAbstractItemModelTester tester(model.get(),
                                        QAbstractItemModelTester::FailureReportingMode::Warning);
        model->setMonitorSource(&source);
        ASSERT_TRUE(model->addDevices({QStringLiteral("D0..D3"), QStringLiteral("M1")}, 1));
        publish([&](model::Snapshot &s) {
            setWord(s, "D2", 9);
            setBit(s, "X0", true);
        });
        model->setFormat(row(1, 3), ValueFormat::Hex);
        model->removeDevices({row(1, 0), row(1, 4), row(1, 6)});
        document.undoStack()->undo();
        document.undoStack()->redo();
        document.setSymbols({model::Symbol{at("D5"), QStringLiteral("Level"), {}}});
        std::vector<model::WatchList> lists = document.project().watchLists;
        std::swap(lists[0], lists[1]);
        lists.push_back({QStringLiteral("Empty"), {}, {}});
        document.setWatchLists(lists, QStringLiteral("reorder"));
        document.undoStack()->undo();
        model->retranslate();
        model->setMonitorSource(nullptr);
        document.reset(model::Target::get(model::Family::Cpm1),
                       model::Target::get(model::Family::Cpm1).defaultModel().name);
        ASSERT_TRUE(model->addDevices({QStringLiteral("DM 0000")}));
    }
    qInstallMessageHandler(previous);
    g_modelTesterFindings = nullptr;
    EXPECT_TRUE(findings.isEmpty()) << findings.join(QLatin1Char('\n')).toStdString();
}
