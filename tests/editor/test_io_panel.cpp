// The inputs and outputs panel: the model's terminals from the target table, inputs as
// switches or push buttons (mouse and Space), outputs as lamps that follow the program on a
// real simulation, analog values written as the table says (the CPM1's pots in BCD).

#include "fake_monitor_source.h"
#include "monitor_fixture.h"

#include "editor/io_panel.h"
#include "editor/terminal_widgets.h"

#include <QApplication>
#include <QMenu>
#include <QSignalSpy>
#include <QSlider>
#include <QSpinBox>
#include <QTest>
#include <QTimer>

#include <gtest/gtest.h>

using namespace rung;
using Kind = model::DeviceCommand::Kind;

namespace {

model::Address at(const model::Target &t, const char *device) {
    return std::get<model::Address>(model::parseAddress(t, QString::fromLatin1(device)));
}

} // namespace

TEST(IoPanel, ShowsTheModelsTerminalsAsTheStripGroupsThem) {
    editor::Document document;
    document.reset(model::Target::get(model::Family::Vigor), QStringLiteral("VB"));
    editor::IoPanel panel(&document);
    // X0..X7, X10..X17 (octal), Y likewise.
    EXPECT_NE(panel.input(QStringLiteral("X0")), nullptr);
    EXPECT_NE(panel.input(QStringLiteral("X7")), nullptr);
    EXPECT_NE(panel.input(QStringLiteral("X10")), nullptr);
    EXPECT_NE(panel.input(QStringLiteral("X17")), nullptr);
    EXPECT_EQ(panel.input(QStringLiteral("X20")), nullptr);
    EXPECT_NE(panel.lamp(QStringLiteral("Y17")), nullptr);
    // Without a source the inputs cannot be worked; the lamps are off.
    EXPECT_FALSE(panel.input(QStringLiteral("X0"))->isEnabled());
    // A program that uses an input beyond the strip (an expansion) gets it too.
    std::vector<model::Diagnostic> errors;
    ASSERT_TRUE(document.setListing(QStringLiteral("LD X20\nOUT Y21\nEND\n"), &errors));
    EXPECT_NE(panel.input(QStringLiteral("X20")), nullptr);
    EXPECT_NE(panel.lamp(QStringLiteral("Y21")), nullptr);

    editor::Document cpm1;
    cpm1.reset(model::Target::get(model::Family::Cpm1), QStringLiteral("CPM1-20CDR"));
    editor::IoPanel cpm1Panel(&cpm1);
    // Omron CPM1 guide: 12 inputs on channel 000, 8 outputs on 010, the pots on 250 and 251.
    EXPECT_NE(cpm1Panel.input(QStringLiteral("000.11")), nullptr);
    EXPECT_EQ(cpm1Panel.input(QStringLiteral("000.12")), nullptr);
    EXPECT_NE(cpm1Panel.lamp(QStringLiteral("010.07")), nullptr);
    EXPECT_EQ(cpm1Panel.lamp(QStringLiteral("010.08")), nullptr);
    ASSERT_NE(cpm1Panel.analog(QStringLiteral("250")), nullptr);
    EXPECT_EQ(cpm1Panel.analog(QStringLiteral("250"))->slider()->maximum(), 200);

    editor::Document vpc;
    vpc.reset(model::Target::get(model::Family::Vpc), QStringLiteral("VPC108A4"));
    editor::IoPanel vpcPanel(&vpc);
    EXPECT_NE(vpcPanel.input(QStringLiteral("i09")), nullptr);
    EXPECT_EQ(vpcPanel.input(QStringLiteral("i10")), nullptr);
    EXPECT_NE(vpcPanel.analog(QStringLiteral("a03")), nullptr);
    EXPECT_EQ(vpcPanel.analog(QStringLiteral("a04")), nullptr);

    editor::Document pl110;
    pl110.reset(model::Target::get(model::Family::Pl110), QStringLiteral("PL110-2A"));
    editor::IoPanel pl110Panel(&pl110);
    EXPECT_NE(pl110Panel.input(QStringLiteral("I8")), nullptr);
    EXPECT_NE(pl110Panel.analog(QStringLiteral("AI4")), nullptr);
    EXPECT_EQ(pl110Panel.analog(QStringLiteral("AI4"))->slider()->maximum(), 1023);
}

TEST(IoPanel, APushButtonIsOnWhileHeldByMouseOrSpace) {
    const model::Target &t = model::Target::get(model::Family::Vigor);
    editor::Document document;
    document.reset(t, QStringLiteral("VB"));
    editor::IoPanel panel(&document);
    test::FakeMonitorSource source;
    panel.setMonitorSource(&source);
    panel.setAllPushButtons(true);
    editor::InputTerminal *x3 = panel.input(QStringLiteral("X3"));
    ASSERT_NE(x3, nullptr);
    ASSERT_TRUE(x3->isEnabled());
    QTest::mousePress(x3, Qt::LeftButton);
    ASSERT_EQ(source.commands.size(), 1u);
    EXPECT_EQ(source.commands[0].kind, Kind::WriteBit);
    EXPECT_EQ(source.commands[0].address, at(t, "X3"));
    EXPECT_EQ(source.commands[0].value, 1);
    QTest::mouseRelease(x3, Qt::LeftButton);
    ASSERT_EQ(source.commands.size(), 2u);
    EXPECT_EQ(source.commands[1].value, 0);
    // Space on the focused button: pressed while the key is down, released with it.
    QTest::keyPress(x3, Qt::Key_Space);
    ASSERT_EQ(source.commands.size(), 3u);
    EXPECT_EQ(source.commands[2].value, 1);
    QTest::keyRelease(x3, Qt::Key_Space);
    ASSERT_EQ(source.commands.size(), 4u);
    EXPECT_EQ(source.commands[3].value, 0);
}

// An input's context menu greys its forces and says why where the source cannot force (an
// online PLC whose protocol has no force command).
TEST(IoPanel, AnInputsForcesAreGreyedWithTheReasonWhereTheSourceCannotForce) {
    const model::Target &t = model::Target::get(model::Family::Vigor);
    editor::Document document;
    document.reset(t, QStringLiteral("VB"));
    editor::IoPanel panel(&document);
    test::FakeMonitorSource source;
    source.refusal = QStringLiteral("This PLC cannot force bits");
    panel.setMonitorSource(&source);
    panel.show();
    editor::InputTerminal *x0 = panel.input(QStringLiteral("X0"));
    ASSERT_TRUE(x0);
    QStringList seen; // "text|enabled|tooltip" of each entry of the open menu
    QTimer::singleShot(0, [&seen] {
        auto *menu = qobject_cast<QMenu *>(QApplication::activePopupWidget());
        if (!menu)
            return;
        for (QAction *a : menu->actions())
            if (!a->isSeparator())
                seen << QStringLiteral("%1|%2|%3")
                            .arg(a->text(), a->isEnabled() ? "on" : "off", a->toolTip());
        menu->close();
    });
    emit x0->customContextMenuRequested(QPoint(2, 2));
    ASSERT_FALSE(seen.isEmpty()) << "no menu opened";
    for (const char *force : {"Force ON", "Force OFF", "Release"})
        EXPECT_TRUE(
            seen.contains(QStringLiteral("%1|off|%2").arg(QLatin1String(force), source.refusal)))
            << force << ": " << seen.join(QLatin1Char(' ')).toStdString();
    EXPECT_TRUE(source.commands.empty());
}

TEST(IoPanel, ASwitchTogglesFromTheStateTheImageShows) {
    const model::Target &t = model::Target::get(model::Family::Vigor);
    editor::Document document;
    document.reset(t, QStringLiteral("VB"));
    editor::IoPanel panel(&document);
    test::FakeMonitorSource source;
    panel.setMonitorSource(&source);
    editor::InputTerminal *x0 = panel.input(QStringLiteral("X0"));
    ASSERT_EQ(x0->mode(), editor::InputTerminal::Mode::Switch);
    QTest::mouseClick(x0, Qt::LeftButton);
    ASSERT_EQ(source.commands.size(), 1u);
    EXPECT_EQ(source.commands[0].value, 1); // it was OFF
    // The image says X0 is ON (and forced): the switch shows it, and a click turns it OFF.
    auto snapshot = source.blank(t);
    const model::BitRef r = snapshot->layout->bit(at(t, "X0"));
    snapshot->words[static_cast<std::size_t>(r.word)] |= static_cast<std::int32_t>(r.mask);
    snapshot->forceMask[static_cast<std::size_t>(r.word)] |= r.mask;
    QSignalSpy changed(&source, &model::MonitorSource::snapshotChanged);
    source.publish(snapshot);
    ASSERT_TRUE(changed.wait(5000));
    EXPECT_TRUE(x0->isOn());
    EXPECT_TRUE(x0->isForced());
    QTest::mouseClick(x0, Qt::LeftButton);
    ASSERT_EQ(source.commands.size(), 2u);
    EXPECT_EQ(source.commands[1].value, 0);
    // A press and release without a click's toggle: a switch writes nothing until clicked.
    panel.setAllPushButtons(false);
    QTest::mousePress(x0, Qt::LeftButton);
    EXPECT_EQ(source.commands.size(), 2u);
    QTest::mouseRelease(x0, Qt::LeftButton);
    EXPECT_EQ(source.commands.size(), 3u);
}

TEST(IoPanel, TheLampFollowsTheOutputOfARealSimulation) {
    // The latch of PLC concepts (WPLSoft family) 1.9: START X1 sets Y1, STOP X2 resets it; X1
    // as a push button.
    test::MonitorFixture f;
    f.start(model::Target::get(model::Family::Vigor), QStringLiteral("VB"),
            "LD X1\nLD Y1\nANI X2\nORB\nOUT Y1\nEND\n");
    editor::IoPanel panel(&f.document);
    panel.setMonitorSource(f.session.get());
    panel.setAllPushButtons(true);
    editor::InputTerminal *start = panel.input(QStringLiteral("X1"));
    editor::InputTerminal *stop = panel.input(QStringLiteral("X2"));
    editor::Lamp *lamp = panel.lamp(QStringLiteral("Y1"));
    ASSERT_TRUE(start && stop && lamp);
    f.scan();
    EXPECT_FALSE(lamp->isOn());
    QTest::mousePress(start, Qt::LeftButton); // held
    f.scan();
    ASSERT_TRUE(test::eventually([&] { return lamp->isOn() && start->isOn(); }));
    QTest::mouseRelease(start, Qt::LeftButton); // released: the latch holds
    f.scan();
    ASSERT_TRUE(test::eventually([&] { return !start->isOn(); }));
    EXPECT_TRUE(lamp->isOn());
    QTest::keyPress(stop, Qt::Key_Space);
    f.scan();
    ASSERT_TRUE(test::eventually([&] { return !lamp->isOn(); }));
    QTest::keyRelease(stop, Qt::Key_Space);
    f.scan();
    EXPECT_FALSE(lamp->isOn());
}

TEST(IoPanel, AnalogValuesAreWrittenAsTheTableSays) {
    // CPM1 pots: 0..200 into channels 250/251 as BCD (Omron CPM1 guide 3.4).
    const model::Target &t = model::Target::get(model::Family::Cpm1);
    editor::Document document;
    document.reset(t, QStringLiteral("CPM1-20CDR"));
    editor::IoPanel panel(&document);
    test::FakeMonitorSource source;
    panel.setMonitorSource(&source);
    editor::AnalogTerminal *pot = panel.analog(QStringLiteral("250"));
    ASSERT_NE(pot, nullptr);
    pot->slider()->setValue(150);
    ASSERT_FALSE(source.commands.empty());
    EXPECT_EQ(source.commands.back().kind, Kind::WriteWord);
    EXPECT_EQ(source.commands.back().address, at(t, "250"));
    EXPECT_EQ(source.commands.back().value, 0x150);
    EXPECT_EQ(pot->spinBox()->value(), 150);
    // The image's BCD word is shown as its number.
    auto snapshot = source.blank(t);
    snapshot->words[static_cast<std::size_t>(snapshot->layout->word(at(t, "250")))] = 0x123;
    QSignalSpy changed(&source, &model::MonitorSource::snapshotChanged);
    source.publish(snapshot);
    ASSERT_TRUE(changed.wait(5000));
    EXPECT_EQ(pot->spinBox()->value(), 123);
    EXPECT_EQ(pot->slider()->value(), 123);
    EXPECT_EQ(pot->unreadable(), QString());
    // A nibble above 9 is no BCD digit: the word is shown as it is, not clamped to 1294, and
    // the slider stays at the last number.
    snapshot = source.blank(t);
    snapshot->words[static_cast<std::size_t>(snapshot->layout->word(at(t, "250")))] = 0x12A4;
    source.publish(snapshot);
    ASSERT_TRUE(changed.wait(5000));
    EXPECT_EQ(pot->unreadable(), QStringLiteral("0x12A4 (not BCD)"));
    EXPECT_EQ(pot->spinBox()->value(), 123);
    snapshot = source.blank(t);
    snapshot->words[static_cast<std::size_t>(snapshot->layout->word(at(t, "250")))] = 0x99;
    source.publish(snapshot);
    ASSERT_TRUE(changed.wait(5000));
    EXPECT_EQ(pot->unreadable(), QString());
    EXPECT_EQ(pot->spinBox()->value(), 99);
}

TEST(IoPanel, AnAnalogInputDrivesTheProgramOnARealSimulation) {
    // VPC a00 as a timer's set value source, VPC user's manual, VII: "OUT t00,a00"; the slider
    // writes a00.
    test::MonitorFixture f;
    f.start(model::Target::get(model::Family::Vpc), QStringLiteral("VPC108A4"),
            "LD r88\nOUT p00,a00\nEND\n");
    editor::IoPanel panel(&f.document);
    panel.setMonitorSource(f.session.get());
    editor::AnalogTerminal *a00 = panel.analog(QStringLiteral("a00"));
    ASSERT_NE(a00, nullptr);
    a00->spinBox()->setValue(1234);
    f.scan();
    ASSERT_TRUE(
        test::eventually([&] { return f.session->snapshot()->value(f.at("p00")) == 1234; }));
}
