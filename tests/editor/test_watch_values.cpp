// The watch list's live value column, fed by a MonitorSource. A fake source stands in for
// the simulator or a PLC: the view must not care which it is.

#include "fake_monitor_source.h"
#include "watch_rows.h"

#include "app/gui/language.h"
#include "editor/document.h"
#include "editor/watch_list_view.h"
#include "model/target/address.h"

#include <QCoreApplication>
#include <QSignalSpy>

#include <gtest/gtest.h>

using namespace rung;
constexpr int kValueColumn = editor::WatchListView::ValueColumn;

namespace {

model::Address at(const model::Target &target, const char *device) {
    return std::get<model::Address>(model::parseAddress(target, QString::fromLatin1(device)));
}

} // namespace

TEST(WatchValues, TheValueColumnShowsEachSnapshotAndTheSourceLearnsWhatIsWatched) {
    const model::Target &target = model::Target::get(model::Family::Vigor);
    editor::Document document;
    document.reset(target, QStringLiteral("VB"));
    document.setWatchLists(
        {{QStringLiteral("W"), {QStringLiteral("X0"), QStringLiteral("D5"), QStringLiteral("T3")}}},
        QStringLiteral("watch"));
    editor::WatchListView view(&document);
    test::FakeMonitorSource source;
    // Device, symbol, value, format, forced: the value column is empty without a source.
    EXPECT_EQ(view.model()->columnCount(), 5);
    EXPECT_TRUE(test::watchText(&view, 0, 1, kValueColumn).isEmpty());
    view.setMonitorSource(&source);
    EXPECT_EQ(view.model()->columnCount(), 5);
    std::vector<model::Address> expected{at(target, "X0"), at(target, "D5"), at(target, "T3")};
    std::sort(expected.begin(), expected.end());
    EXPECT_EQ(source.watched(), expected);

    auto snapshot = source.blank(target);
    const model::MemoryLayout &layout = *snapshot->layout;
    const model::BitRef x0 = layout.bit(at(target, "X0"));
    snapshot->words[static_cast<std::size_t>(x0.word)] |= static_cast<std::int32_t>(x0.mask);
    snapshot->forceMask[static_cast<std::size_t>(x0.word)] |= x0.mask;
    snapshot->words[static_cast<std::size_t>(layout.word(at(target, "D5")))] = 1234;
    snapshot->words[static_cast<std::size_t>(layout.word(at(target, "T3")))] = 12;
    snapshot->words[static_cast<std::size_t>(layout.setValueWord(at(target, "T3")))] = 50;
    QSignalSpy changed(&source, &model::MonitorSource::snapshotChanged);
    source.publish(snapshot);
    ASSERT_TRUE(changed.wait(5000));
    const auto value = [&view](int row) { return test::watchText(&view, 0, row, kValueColumn); };
    ASSERT_EQ(test::watchRows(&view, 0), 3);
    EXPECT_EQ(value(0), QStringLiteral("ON (forced)"));
    EXPECT_EQ(value(1), QStringLiteral("1234"));
    EXPECT_EQ(value(2), QStringLiteral("12 of 50, OFF"));

    // Online, the PLC answered for T3's present value but nobody could read its set value
    // (a Vigor K preset lives in the program): not "of 0".
    auto online = std::make_shared<model::Snapshot>(*snapshot);
    auto read = std::make_shared<std::vector<bool>>(online->words.size(), true);
    (*read)[static_cast<std::size_t>(layout.setValueWord(at(target, "T3")))] = false;
    online->words[static_cast<std::size_t>(layout.setValueWord(at(target, "T3")))] = 0;
    online->wordsRead = read;
    source.publish(online);
    ASSERT_TRUE(changed.wait(5000));
    EXPECT_EQ(value(2), QStringLiteral("12 of ?, OFF"));
    EXPECT_EQ(value(1), QStringLiteral("1234"));

    // A device added to the list is watched and shown at once.
    view.setCurrentIndex(view.model()->index(0, 0));
    view.addDevice(QStringLiteral("Y1"));
    EXPECT_EQ(source.watched().size(), 4u);
    ASSERT_EQ(test::watchRows(&view, 0), 4);
    EXPECT_EQ(value(3), QStringLiteral("OFF"));

    view.setMonitorSource(nullptr);
    EXPECT_TRUE(value(0).isEmpty());
    EXPECT_TRUE(source.watched().empty());
}

TEST(WatchValues, AViewThatGoesAwayStopsBeingWatched) {
    const model::Target &target = model::Target::get(model::Family::Vigor);
    editor::Document document;
    document.reset(target, QStringLiteral("VB"));
    document.setWatchLists({{QStringLiteral("W"), {QStringLiteral("M7")}}},
                           QStringLiteral("watch"));
    test::FakeMonitorSource source;
    {
        editor::WatchListView view(&document);
        view.setMonitorSource(&source);
        EXPECT_EQ(source.watched(), std::vector<model::Address>{at(target, "M7")});
    }
    EXPECT_TRUE(source.watched().empty());
}

TEST(WatchValues, CommandsCarryAnIdAndTheirAnswerArrivesLater) {
    const model::Target &target = model::Target::get(model::Family::Vigor);
    test::FakeMonitorSource source;
    QSignalSpy finished(&source, &model::MonitorSource::commandFinished);
    const auto first = source.writeWord(at(target, "D5"), 7);
    source.failWith = QStringLiteral("the PLC refused");
    const auto second = source.force(at(target, "X0"), true);
    EXPECT_NE(first, second);
    EXPECT_EQ(finished.count(), 0); // answered through the event loop, not inside the call
    ASSERT_TRUE(finished.wait(5000));
    while (finished.count() < 2 && finished.wait(5000)) {
    }
    ASSERT_EQ(finished.count(), 2);
    EXPECT_EQ(finished.at(0).at(0).value<model::MonitorSource::CommandId>(), first);
    EXPECT_TRUE(finished.at(0).at(1).toBool());
    EXPECT_EQ(finished.at(1).at(0).value<model::MonitorSource::CommandId>(), second);
    EXPECT_FALSE(finished.at(1).at(1).toBool());
    EXPECT_EQ(finished.at(1).at(2).toString(), QStringLiteral("the PLC refused"));
    ASSERT_EQ(source.commands.size(), 2u);
    EXPECT_EQ(source.commands[0].kind, model::DeviceCommand::Kind::WriteWord);
    EXPECT_EQ(source.commands[0].value, 7);
}

// A language switched while the program runs reaches the watch list at once: its headers and
// the values' words ("ON", "forced").
TEST(WatchValues, HeadersAndValuesFollowALanguageSwitch) {
    const model::Target &target = model::Target::get(model::Family::Vigor);
    editor::Document document;
    document.reset(target, QStringLiteral("VB"));
    document.setWatchLists({{QStringLiteral("W"), {QStringLiteral("X0")}}},
                           QStringLiteral("watch"));
    editor::WatchListView view(&document);
    test::FakeMonitorSource source;
    view.setMonitorSource(&source);
    auto snapshot = source.blank(target);
    const model::BitRef x0 = snapshot->layout->bit(at(target, "X0"));
    snapshot->words[static_cast<std::size_t>(x0.word)] |= static_cast<std::int32_t>(x0.mask);
    QSignalSpy changed(&source, &model::MonitorSource::snapshotChanged);
    source.publish(snapshot);
    ASSERT_TRUE(changed.wait(5000));
    const auto header = [&view](int column) {
        return view.model()->headerData(column, Qt::Horizontal).toString();
    };
    ASSERT_EQ(header(kValueColumn), QStringLiteral("Value"));
    ASSERT_EQ(test::watchText(&view, 0, 0, kValueColumn), QStringLiteral("ON"));

    ASSERT_TRUE(app::setLanguage(QStringLiteral("hu"), false));
    QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
    const auto hu = [](const char *text) {
        return QCoreApplication::translate("rung::editor::WatchListModel", text);
    };
    ASSERT_NE(hu("Value"), QStringLiteral("Value")); // the catalogue is there
    EXPECT_EQ(header(0), hu("Device"));
    EXPECT_EQ(header(kValueColumn), hu("Value"));
    EXPECT_EQ(test::watchText(&view, 0, 0, kValueColumn), hu("ON"));
    app::setLanguage(QStringLiteral("en"), false);
    QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
    EXPECT_EQ(header(kValueColumn), QStringLiteral("Value"));
}
