// The watch list writes and forces devices through its MonitorSource: the context actions of
// a bit, a value typed into the value column of a word, a double-click on a bit, and the
// reasons it gives for a text that is no value or a command the source refused. A fake source
// stands in for the simulator or a PLC and records what it was asked.

#include "fake_monitor_source.h"
#include "tests/eventually.h"
#include "watch_rows.h"

#include "editor/document.h"
#include "editor/watch_list_view.h"
#include "model/target/address.h"

#include <QAction>
#include <QLineEdit>
#include <QSignalSpy>
#include <QTest>

#include <gtest/gtest.h>

using namespace rung;
using Kind = model::DeviceCommand::Kind;
constexpr int kValue = editor::WatchListView::ValueColumn;

namespace {

struct WatchCommands : ::testing::Test {
    const model::Target &target = model::Target::get(model::Family::Vigor);
    editor::Document document;
    std::unique_ptr<editor::WatchListView> view;
    test::FakeMonitorSource source;

    void SetUp() override {
        document.reset(target, QStringLiteral("VB"));
        document.setWatchLists(
            {{QStringLiteral("W"),
              {QStringLiteral("X0"), QStringLiteral("D5"), QStringLiteral("T3")}}},
            QStringLiteral("watch"));
        view = std::make_unique<editor::WatchListView>(&document);
        view->setMonitorSource(&source);
    }
    QModelIndex row(int k, int column = editor::WatchListView::DeviceColumn) {
        return test::watchIndex(view.get(), 0, k, column);
    }
    QString shown(int k, int column) { return test::watchText(view.get(), 0, k, column); }
    // Typed into the value column, as the cell editor commits it.
    bool type(int k, const QString &value) {
        return view->model()->setData(row(k, kValue), value, Qt::EditRole);
    }
    model::Address at(const char *device) {
        return std::get<model::Address>(model::parseAddress(target, QString::fromLatin1(device)));
    }
    QAction *action(const QList<QAction *> &actions, const char *text) {
        for (QAction *a : actions)
            if (a->text() == QLatin1String(text))
                return a;
        return nullptr;
    }
};

TEST_F(WatchCommands, ABitIsSetForcedAndReleasedFromItsContextActions) {
    QObject owner;
    const QList<QAction *> actions = view->deviceActions(row(0), &owner);
    QStringList texts;
    for (QAction *a : actions)
        texts << a->text();
    EXPECT_EQ(texts, (QStringList{QStringLiteral("Set ON"), QStringLiteral("Set OFF"),
                                  QStringLiteral("Force ON"), QStringLiteral("Force OFF"),
                                  QStringLiteral("Release")}));
    for (const char *text : {"Force ON", "Force OFF", "Release", "Set ON"})
        action(actions, text)->trigger();
    ASSERT_EQ(source.commands.size(), 4u);
    EXPECT_EQ(source.commands[0].kind, Kind::Force);
    EXPECT_EQ(source.commands[0].value, 1);
    EXPECT_EQ(source.commands[1].kind, Kind::Force);
    EXPECT_EQ(source.commands[1].value, 0);
    EXPECT_EQ(source.commands[2].kind, Kind::Release);
    EXPECT_EQ(source.commands[3].kind, Kind::WriteBit);
    EXPECT_EQ(source.commands[3].value, 1);
    for (const auto &c : source.commands)
        EXPECT_EQ(c.address, at("X0"));
    // A list's own row, and a view without a source, offer nothing.
    EXPECT_TRUE(view->deviceActions(view->model()->index(0, 0), &owner).isEmpty());
    view->setMonitorSource(nullptr);
    EXPECT_TRUE(view->deviceActions(row(0), &owner).isEmpty());
}

// A source that cannot force (an online PLC whose protocol has no force command): the force
// entries are greyed and say why; setting the bit stays.
TEST_F(WatchCommands, ForcesAreGreyedWithTheReasonWhereTheSourceCannotForce) {
    source.refusal = QStringLiteral("This PLC cannot force bits");
    QObject owner;
    const QList<QAction *> actions = view->deviceActions(row(0), &owner);
    for (const char *text : {"Force ON", "Force OFF", "Release"}) {
        ASSERT_NE(action(actions, text), nullptr) << text;
        EXPECT_FALSE(action(actions, text)->isEnabled()) << text;
        EXPECT_EQ(action(actions, text)->toolTip(), source.refusal) << text;
    }
    EXPECT_TRUE(action(actions, "Set ON")->isEnabled());
    EXPECT_TRUE(action(actions, "Set OFF")->isEnabled());
}

TEST_F(WatchCommands, AWordOffersToWriteAValueAndTheValueColumnWritesIt) {
    QObject owner;
    const QList<QAction *> actions = view->deviceActions(row(1), &owner);
    ASSERT_EQ(actions.size(), 1);
    EXPECT_EQ(actions[0]->text(), QStringLiteral("Write Value..."));

    // Typed into the value column, as the cell editor commits it.
    EXPECT_TRUE(type(1, QStringLiteral("1234")));
    ASSERT_EQ(source.commands.size(), 1u);
    EXPECT_EQ(source.commands[0].kind, Kind::WriteWord);
    EXPECT_EQ(source.commands[0].address, at("D5"));
    EXPECT_EQ(source.commands[0].value, 1234);
    EXPECT_TRUE(view->writeValue(row(1), QStringLiteral(" -7 ")));
    EXPECT_EQ(source.commands.back().value, -7);
    EXPECT_TRUE(view->writeValue(row(1), QStringLiteral("0x1F")));
    EXPECT_EQ(source.commands.back().value, 31);
    // A timer's current value is the engine's: refused with the reason, nothing offered.
    const std::size_t before = source.commands.size();
    QSignalSpy messages(view.get(), &editor::WatchListView::message);
    EXPECT_FALSE(view->writeValue(row(2), QStringLiteral("25")));
    EXPECT_EQ(source.commands.size(), before);
    ASSERT_EQ(messages.size(), 1);
    EXPECT_EQ(messages[0][0].toString(),
              QStringLiteral("T3 is a timer or counter: its current value follows the program "
                             "and cannot be written here"));
    EXPECT_TRUE(view->deviceActions(row(2), &owner).isEmpty());
    // A bit takes ON/OFF or 1/0.
    EXPECT_TRUE(view->writeValue(row(0), QStringLiteral("on")));
    EXPECT_EQ(source.commands.back().kind, Kind::WriteBit);
    EXPECT_EQ(source.commands.back().value, 1);
    EXPECT_TRUE(view->writeValue(row(0), QStringLiteral("0")));
    EXPECT_EQ(source.commands.back().value, 0);
}

TEST_F(WatchCommands, TextThatIsNoValueIsRefusedWithTheReason) {
    QSignalSpy messages(view.get(), &editor::WatchListView::message);
    EXPECT_FALSE(view->writeValue(row(1), QStringLiteral("12a")));
    EXPECT_FALSE(view->writeValue(row(0), QStringLiteral("maybe")));
    EXPECT_TRUE(source.commands.empty());
    ASSERT_EQ(messages.size(), 2);
    EXPECT_EQ(messages[0][0].toString(),
              QStringLiteral("\"12a\" is no value for D5: type a whole number (0x before a "
                             "hexadecimal one)"));
    EXPECT_EQ(messages[1][0].toString(),
              QStringLiteral("\"maybe\" is no value for X0: type ON or OFF (1 or 0)"));
    // A refused edit does not stay in the column: it shows the source's value again.
    auto snapshot = source.blank(target);
    snapshot->words[static_cast<std::size_t>(snapshot->layout->word(at("D5")))] = 42;
    source.publish(snapshot);
    EXPECT_FALSE(type(1, QStringLiteral("junk")));
    EXPECT_EQ(shown(1, kValue), QStringLiteral("42"));
}

TEST_F(WatchCommands, ADoubleClickFlipsABitAndARefusedCommandIsSaid) {
    auto snapshot = source.blank(target);
    const model::BitRef x0 = snapshot->layout->bit(at("X0"));
    snapshot->words[static_cast<std::size_t>(x0.word)] |= static_cast<std::int32_t>(x0.mask);
    source.publish(snapshot);
    QSignalSpy messages(view.get(), &editor::WatchListView::message);
    source.failWith = QStringLiteral("X0 cannot be written");
    emit view->doubleClicked(row(0, kValue));
    ASSERT_EQ(source.commands.size(), 1u);
    EXPECT_EQ(source.commands[0].kind, Kind::WriteBit);
    EXPECT_EQ(source.commands[0].value, 0); // it was ON
    ASSERT_TRUE(messages.size() == 1 || messages.wait(2000));
    EXPECT_EQ(messages.back()[0].toString(), QStringLiteral("X0 cannot be written"));
}

TEST_F(WatchCommands, TheValueEditorOpensOnTheNumberAndSnapshotsDoNotOverwriteWhatIsTyped) {
    view->show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(view.get()));
    auto snapshot = source.blank(target);
    const auto d5 = static_cast<std::size_t>(snapshot->layout->word(at("D5")));
    snapshot->words[d5] = 12;
    source.publish(snapshot);
    EXPECT_TRUE(test::eventually([&] { return shown(1, kValue) == QStringLiteral("12"); }))
        << shown(1, kValue).toStdString();
    QObject owner;
    const QList<QAction *> actions = view->deviceActions(row(1), &owner);
    ASSERT_EQ(actions.size(), 1);
    actions[0]->trigger(); // Write Value...
    auto *editor = view->viewport()->findChild<QLineEdit *>();
    ASSERT_NE(editor, nullptr);
    EXPECT_EQ(editor->text(), QStringLiteral("12"));
    editor->setText(QStringLiteral("30"));
    // The program changes D5 meanwhile: the editor keeps what the user typed. X0 changes too:
    // once its row shows it, the view has had the snapshot.
    auto later = source.blank(target);
    later->words[d5] = 13;
    const model::BitRef x0 = later->layout->bit(at("X0"));
    later->words[static_cast<std::size_t>(x0.word)] |= static_cast<std::int32_t>(x0.mask);
    source.publish(later);
    ASSERT_TRUE(test::eventually([&] { return shown(0, kValue) == QStringLiteral("ON"); }))
        << shown(0, kValue).toStdString();
    EXPECT_EQ(editor->text(), QStringLiteral("30"));
    QTest::keyClick(editor, Qt::Key_Return);
    // The delegate commits queued.
    ASSERT_TRUE(test::eventually([&] { return !source.commands.empty(); }));
    ASSERT_EQ(source.commands.size(), 1u);
    EXPECT_EQ(source.commands[0].kind, Kind::WriteWord);
    EXPECT_EQ(source.commands[0].address, at("D5"));
    EXPECT_EQ(source.commands[0].value, 30);
    // Closed, the column follows the snapshots again.
    source.publish(later);
    EXPECT_TRUE(test::eventually([&] { return shown(1, kValue) == QStringLiteral("13"); }))
        << shown(1, kValue).toStdString();
}

} // namespace
