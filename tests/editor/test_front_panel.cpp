// Issue 30: the PLC's front panel in the IDE, drawn from a real simulation (SimulatorSession)
// and worked with the mouse and the keyboard as a user would.

#include "app/gui/front_panel_controller.h"
#include "app/gui/simulation_controller.h"
#include "editor/front_panel.h"
#include "monitor_fixture.h"
#include "tests/editor/window_fixture.h"
#include "tests/targets.h"

#include <QApplication>
#include <QDockWidget>

#include <QDial>
#include <QJsonObject>
#include <QLabel>
#include <QSpinBox>
#include <QTest>
#include <QToolButton>

using namespace rung;
using namespace rung::test;

namespace {

struct PanelFixture : MonitorFixture {
    editor::FrontPanel panel;
    void start(const model::Target &target, const QString &modelName, const char *listing) {
        MonitorFixture::start(target, modelName, listing);
        panel.setPlc(&document.target(), modelName);
        panel.setMonitorSource(session.get());
        panel.resize(600, 500);
        panel.show();
    }
    std::int32_t value(const char *device) const { return session->snapshot()->value(at(device)); }
    bool bit(const char *device) const { return session->snapshot()->bit(at(device)); }
};

} // namespace

// The Vigor M/VB/VH communication manual's display stub (B-3): "MOV K3 D9080 Set the display
// screen to display mode 3 (displays a 4-digits numeric value)", D9081 naming the register
// shown; the program moves 1234 into that register and the panel shows it.
TEST(FrontPanelView, VigorDisplayShowsTheRegisterTheProgramNamesInD9081) {
    PanelFixture f;
    f.start(rung::testing::vigor(), QStringLiteral("VB"),
            "LD M9002\nMOV K3 D9080\nMOV K10 D9081\nLD M9000\nMOV K1234 D10\nEND\n");
    f.scan();
    EXPECT_EQ(f.panel.view().digitsText, QStringLiteral("1234"));
    EXPECT_EQ(f.panel.display()->text(), QStringLiteral("1234"));
    EXPECT_TRUE(f.panel.display()->isVisible());
    EXPECT_TRUE(f.panel.hint().isEmpty());
    EXPECT_EQ(f.panel.lamp(QStringLiteral("RUN"))->isLit(), true);
    EXPECT_EQ(f.panel.lamp(QStringLiteral("ERROR"))->isLit(), false);
    // The display's size is what its digits need: nothing clipped.
    EXPECT_GE(f.panel.display()->width(), f.panel.display()->sizeHint().width());
}

// "VRRD K1 D0 Read the value of VR1, and store it to D0": the number typed into VR1's box is
// what VRRD reads, and mode 3 shows it; the knob follows.
TEST(FrontPanelView, VigorVrKnobIsWrittenAndReadBackByVrrd) {
    PanelFixture f;
    f.start(rung::testing::vigor(), QStringLiteral("VB"),
            "LD M9002\nMOV K3 D9080\nMOV K1 D9081\nLD M9000\nVRRD K1 D1\nEND\n");
    f.scan();
    QSpinBox *number = f.panel.knobNumber(QStringLiteral("VR1"));
    QDial *dial = f.panel.knob(QStringLiteral("VR1"));
    ASSERT_NE(number, nullptr);
    ASSERT_NE(dial, nullptr);
    EXPECT_EQ(number->maximum(), 255);
    // Typed as a user types it: select, digits, Enter.
    number->setFocus();
    number->selectAll();
    QTest::keyClicks(number, QStringLiteral("200"));
    QTest::keyClick(number, Qt::Key_Return);
    f.settle();
    f.scan();
    EXPECT_EQ(f.value("D1"), 200);
    EXPECT_EQ(f.panel.view().digitsText, QStringLiteral(" 200"));
    EXPECT_EQ(dial->value(), 200);
    // The knob turned with the keyboard (PageUp steps the dial).
    dial->setFocus();
    QTest::keyClick(dial, Qt::Key_End);
    f.settle();
    f.scan();
    EXPECT_EQ(f.value("D1"), 255);
    EXPECT_EQ(f.panel.display()->text(), QStringLiteral(" 255"));
}

// PL110 manual 2.1.16 / 5.4: the program writes its text into DISP from row 3 (DISP42, the
// manual's own MOVTXT) and enables user page 17 as its start page: the OLED shows it. SWAP (the
// mouse) steps to the next page enabled; "S" (the keyboard) too.
TEST(FrontPanelView, Pl110PageShowsTheProgramsTextAndSwapTurnsThePage) {
    PanelFixture f;
    f.start(rung::testing::pl110(), QStringLiteral("PL110-2A"),
            "LD SM0.1\nSBIT SMW103 0\nLD SM0.1\nMOV 17 SM104\n"
            "LD SM0.0\nMOVTXT DISP42 1 \"TESTO DISPLAY\"\n"
            "LD SM110.0\nOUT Q1\nEND\n");
    f.scan();
    f.scan();
    ASSERT_EQ(f.panel.view().page, 17);
    const QStringList rows = f.panel.display()->text().split(QLatin1Char('\n'));
    ASSERT_EQ(rows.size(), 8);
    EXPECT_EQ(rows[2], QStringLiteral("TESTO DISPLAY        "));
    QToolButton *swap = f.panel.key(QStringLiteral("SWAP"));
    ASSERT_NE(swap, nullptr);
    QTest::mousePress(swap, Qt::LeftButton);
    f.settle();
    f.scan();
    EXPECT_TRUE(f.bit("SM110.0"));
    EXPECT_TRUE(f.bit("Q1")) << "the program sees the key held";
    EXPECT_EQ(f.value("SM105"), 1) << "after page 17 the circle starts again at page 1";
    QTest::mouseRelease(swap, Qt::LeftButton);
    f.settle();
    f.scan();
    EXPECT_FALSE(f.bit("SM110.0"));
    EXPECT_TRUE(f.panel.display()->text().startsWith(QStringLiteral("I   "))) << "page 1: I/O";
    // The keyboard: S is SWAP while the panel has the focus.
    f.panel.setFocus();
    QTest::keyPress(&f.panel, Qt::Key_S);
    f.settle();
    f.scan();
    EXPECT_EQ(f.value("SM105"), 2);
    QTest::keyRelease(&f.panel, Qt::Key_S);
    f.settle();
    f.scan();
    EXPECT_FALSE(f.bit("SM110.0"));
}

// PL110 manual 1.2: "Lampeggio lento - (0,5s on /0,5 s off)" while no ladder program runs (the
// simulation stopped); "Acceso fisso" in RUN.
TEST(FrontPanelView, Pl110RunLampBlinksAtTheTablesRateUntilTheProgramRuns) {
    PanelFixture f;
    f.start(rung::testing::pl110(), QStringLiteral("PL110-2A"), "LD I1\nOUT Q1\nEND\n");
    editor::PanelLamp *run = f.panel.lamp(QStringLiteral("RUN"));
    ASSERT_NE(run, nullptr);
    ASSERT_EQ(f.session->runState(), model::MonitorSource::RunState::Stopped);
    EXPECT_EQ(run->blinkMs(), 500);
    EXPECT_TRUE(eventually([&] { return run->isLit(); }));
    QElapsedTimer clock;
    clock.start();
    EXPECT_TRUE(eventually([&] { return !run->isLit(); }));
    EXPECT_TRUE(eventually([&] { return run->isLit(); }));
    // A whole period passed between two lightings: not a flicker.
    EXPECT_GE(clock.elapsed(), 400);
    f.scan();
    EXPECT_EQ(run->blinkMs(), 0);
    EXPECT_TRUE(run->isLit());
}

// No source, or no panel: a sentence, not an empty dock.
TEST(FrontPanelView, WithoutASimulationTheDockSaysHowToStart) {
    editor::FrontPanel panel;
    panel.setPlc(&rung::testing::cpm1(), QStringLiteral("CPM1-20CDR"));
    panel.show();
    EXPECT_TRUE(panel.hint().contains(QStringLiteral("F10"))) << panel.hint().toStdString();
    ASSERT_NE(panel.knob(QStringLiteral("0")), nullptr);
    EXPECT_FALSE(panel.knob(QStringLiteral("0"))->isEnabled());
}

// Omron CPM1 guide 3.4: the analog setting written as BCD into channel 250.
TEST(FrontPanelView, Cpm1AnalogSettingWritesBcd) {
    PanelFixture f;
    f.start(rung::testing::cpm1(), QStringLiteral("CPM1-20CDR"),
            "LD 253.13\nMOV(21) 250 DM0000\nEND\n");
    f.scan();
    QSpinBox *number = f.panel.knobNumber(QStringLiteral("0"));
    ASSERT_NE(number, nullptr);
    number->setValue(150);
    f.settle();
    f.scan();
    EXPECT_EQ(f.value("DM0000"), 0x0150);
    EXPECT_TRUE(f.panel.lamp(QStringLiteral("POWER"))->isLit());
}

// Omron CPM1 guide 2.1, ERROR/ALARM: "Villog - Nem lényegi hiba, a CPU tovább dolgozik": the
// program's FAL(06) 12 (W353) makes the lamp blink while RUN stays lit; FAL 00 clears it and
// the lamp goes dark ("Nem világít - Normál működés").
TEST(FrontPanelView, Cpm1ErrorAlarmBlinksWhileAFalNumberIsSet) {
    PanelFixture f;
    f.start(rung::testing::cpm1(), QStringLiteral("CPM1-20CDR"),
            "LD 000.00\nFAL(06) 12\nLD 000.01\nFAL(06) 00\nEND\n");
    f.scan();
    editor::PanelLamp *alarm = f.panel.lamp(QStringLiteral("ERROR/ALARM"));
    ASSERT_NE(alarm, nullptr);
    EXPECT_FALSE(alarm->isLit());
    EXPECT_EQ(alarm->blinkMs(), 0);
    f.session->writeBit(f.at("000.00"), true);
    f.settle();
    f.scan();
    EXPECT_EQ(f.value("253") & 0xFF, 0x12);
    EXPECT_EQ(alarm->blinkMs(), 500);
    EXPECT_TRUE(eventually([&] { return alarm->isLit(); }));
    EXPECT_TRUE(eventually([&] { return !alarm->isLit(); }));
    EXPECT_TRUE(eventually([&] { return alarm->isLit(); }));
    EXPECT_TRUE(f.panel.lamp(QStringLiteral("RUN"))->isLit()) << "the CPU goes on";
    EXPECT_FALSE(alarm->toolTip().isEmpty());
    f.session->writeBit(f.at("000.00"), false);
    f.session->writeBit(f.at("000.01"), true);
    f.settle();
    f.scan();
    EXPECT_EQ(alarm->blinkMs(), 0);
    EXPECT_FALSE(alarm->isLit());
}

// Omron CPM1 guide 2.1, ERROR/ALARM: "Villog - Nem lényegi hiba, a CPU tovább dolgozik": a timer
// whose set value in DM 0000 is not BCD (W353 TIM: "ER: SV is not in BCD") is skipped with ER
// 255.03 ON and the program goes on, so the lamp blinks and RUN stays lit; the error is the
// simulation's, reported by its source, not a FAL number.
TEST(FrontPanelView, Cpm1ErrorAlarmBlinksOnAnInstructionErrorTheCpuGoesOnAfter) {
    PanelFixture f;
    f.start(rung::testing::cpm1(), QStringLiteral("CPM1-20CDR"),
            "LD 253.13\nTIM 000 DM0000\nEND\n");
    f.scan();
    editor::PanelLamp *alarm = f.panel.lamp(QStringLiteral("ERROR/ALARM"));
    ASSERT_NE(alarm, nullptr);
    EXPECT_FALSE(alarm->isLit()) << "DM 0000 holds 0000, a BCD set value";
    EXPECT_EQ(alarm->blinkMs(), 0);
    f.session->writeWord(f.at("DM0000"), 0x00AB);
    f.settle();
    f.scan();
    ASSERT_TRUE(eventually([&] { return !f.session->errorText().isEmpty(); }));
    EXPECT_TRUE(f.session->errorText().contains(QStringLiteral("BCD")))
        << f.session->errorText().toStdString();
    EXPECT_TRUE(eventually([&] { return alarm->blinkMs() == 500; }));
    EXPECT_TRUE(eventually([&] { return alarm->isLit(); }));
    EXPECT_TRUE(eventually([&] { return !alarm->isLit(); }));
    EXPECT_TRUE(f.panel.lamp(QStringLiteral("RUN"))->isLit()) << "the CPU goes on";
}

// VPC user's manual, II: "LEDs to show which inputs/outputs are driven ON (VPC2416 and higher)":
// the panel has a lamp for each, lit with its point.
TEST(FrontPanelView, VpcLedsFollowTheInputsAndOutputs) {
    PanelFixture f;
    f.start(rung::testing::vpc(), QStringLiteral("VPC2416"), "LD i03\nOUT o05\nEND\n");
    f.scan();
    editor::PanelLamp *input = f.panel.lamp(QStringLiteral("i03"));
    editor::PanelLamp *output = f.panel.lamp(QStringLiteral("o05"));
    ASSERT_NE(input, nullptr);
    ASSERT_NE(output, nullptr);
    EXPECT_NE(f.panel.lamp(QStringLiteral("i23")), nullptr);
    EXPECT_EQ(f.panel.lamp(QStringLiteral("i24")), nullptr);
    EXPECT_FALSE(input->isLit());
    f.session->writeBit(f.at("i03"), true);
    f.settle();
    f.scan();
    f.scan(); // VPC coils take effect from the next scan
    EXPECT_TRUE(input->isLit());
    EXPECT_TRUE(output->isLit());
    EXPECT_FALSE(f.panel.lamp(QStringLiteral("o04"))->isLit());
}

// The window: View > Front Panel, fed by the simulation as the other monitoring docks are (F10
// shows it); showSource points it at any source of any PLC (a network station's) and
// showSimulation back.
struct FrontPanelDock : test::WindowFixture {};

TEST_F(FrontPanelDock, FollowsTheSimulationAndAnySourceItIsPointedAt) {
    FrontPanelDock &f = *this;
    f.load("LD M9002\nMOV K3 D9080\nMOV K0 D9081\nLD M9000\nMOV K42 D0\nEND\n");
    auto *dock = f.window.findChild<QDockWidget *>(QStringLiteral("frontPanelDock"));
    ASSERT_NE(dock, nullptr);
    EXPECT_EQ(dock->windowTitle(), QStringLiteral("Front Panel"));
    editor::FrontPanel *panel = f.window.frontPanel()->panel();
    EXPECT_EQ(panel->monitorSource(), nullptr);
    f.window.show();
    QApplication::setActiveWindow(&f.window);
    ASSERT_TRUE(QTest::qWaitForWindowActive(&f.window));
    f.view->setFocus();
    QTest::keyClick(f.view, Qt::Key_F10);
    ASSERT_NE(f.window.simulation()->session(), nullptr);
    EXPECT_EQ(panel->monitorSource(), f.window.simulation()->session());
    EXPECT_FALSE(dock->isHidden()) << "the first simulation opens it";
    EXPECT_TRUE(eventually([&] { return panel->view().digitsText == QStringLiteral("  42"); }))
        << panel->view().digitsText.toStdString();
    // A station of another PLC: its table and model.
    PanelFixture station;
    station.start(rung::testing::pl110(), QStringLiteral("PL110-2A"), "LD I1\nOUT Q1\nEND\n");
    f.window.frontPanel()->showSource(station.session.get(), rung::testing::pl110(),
                                      QStringLiteral("PL110-2A"));
    EXPECT_EQ(panel->monitorSource(), station.session.get());
    EXPECT_NE(panel->key(QStringLiteral("SWAP")), nullptr);
    f.window.frontPanel()->showSimulation();
    EXPECT_EQ(panel->monitorSource(), f.window.simulation()->session());
    EXPECT_EQ(panel->key(QStringLiteral("SWAP")), nullptr);
    EXPECT_NE(panel->knob(QStringLiteral("VR1")), nullptr);
}

// PL110 manual 5.4, page 18: "SetPAR1 [Modifiable, Par = VW0, Min = #0, Max = #1400]",
// "FormatPAR1 [16 bit signed, Tot7, Dec1, Spaces]", "PosPAR1 [Row4, Column10, Free]" -- the
// program's words for it, and the keys of 5.2 worked with the mouse and the keyboard: SET edits
// the field (in reverse), UP changes the value, SET (Return) stores it into V0.
TEST(FrontPanelView, Pl110KeysEditAFieldAndSetStoresTheValue) {
    PanelFixture f;
    f.start(rung::testing::pl110(), QStringLiteral("PL110-2A"),
            "LD SM0.1\nSBIT SMW103 1\nLD SM0.1\nMOV 18 SM104\n"
            "LD SM0.1\nMOV 2 SM118\nLD SM0.1\nMOV 1 SM119\nLD SM0.1\nMOV 1400 SM127\n"
            "LD SM0.1\nMOV 7 SM129\nLD SM0.1\nMOV 1 SM130\nLD SM0.1\nMOV 4 SM132\n"
            "LD SM0.1\nMOV 10 SM133\nLD SM0.1\nMOV 250 V0\nEND\n");
    f.scan();
    f.scan();
    ASSERT_EQ(f.panel.view().page, 18);
    EXPECT_EQ(f.panel.display()->text().split(QLatin1Char('\n')).value(3),
              QStringLiteral("             25.0    "));
    QToolButton *set = f.panel.key(QStringLiteral("SET"));
    ASSERT_NE(set, nullptr);
    QTest::mouseClick(set, Qt::LeftButton);
    ASSERT_EQ(f.panel.terminal().mode, model::TerminalState::Mode::Field);
    ASSERT_EQ(f.panel.view().fields.size(), 1u);
    EXPECT_TRUE(f.panel.view().fields[0].editing) << "shown in reverse";
    f.panel.setFocus();
    QTest::keyClick(&f.panel, Qt::Key_Up);
    QTest::keyClick(&f.panel, Qt::Key_Up);
    EXPECT_EQ(f.panel.display()->text().split(QLatin1Char('\n')).value(3),
              QStringLiteral("             25.2    "));
    f.scan();
    EXPECT_EQ(f.value("V0"), 250) << "not stored before SET";
    QTest::keyClick(&f.panel, Qt::Key_Return);
    f.settle();
    f.scan();
    EXPECT_EQ(f.value("V0"), 252);
    EXPECT_EQ(f.panel.terminal().mode, model::TerminalState::Mode::Pages);
    EXPECT_FALSE(f.panel.view().fields[0].editing);
}

// 5.5: page 253 "A questa pagina si accede tenendo premuto per circa 2 secondi il tasto SET";
// the number entered goes to SM109 (2.1.2), which the program reads.
TEST(FrontPanelView, Pl110SetHeldOpensThePasswordPageAndSetEntersIt) {
    PanelFixture f;
    f.start(rung::testing::pl110(), QStringLiteral("PL110-2A"), "LD SM0.0\nMOV SM109 V5\nEND\n");
    f.scan();
    QToolButton *set = f.panel.key(QStringLiteral("SET"));
    ASSERT_NE(set, nullptr);
    QTest::mousePress(set, Qt::LeftButton);
    ASSERT_TRUE(eventually(
        [&] { return f.panel.terminal().mode == model::TerminalState::Mode::Password; }, 10000));
    QTest::mouseRelease(set, Qt::LeftButton);
    EXPECT_EQ(f.panel.view().page, 253);
    EXPECT_TRUE(f.panel.display()->text().contains(QStringLiteral("*** PASSWORD ***")));
    f.panel.setFocus();
    QTest::keyClick(&f.panel, Qt::Key_Up); // 1000
    QTest::keyClick(&f.panel, Qt::Key_S);  // the next digit
    QTest::keyClick(&f.panel, Qt::Key_Up); // 1100
    EXPECT_TRUE(f.panel.display()->text().contains(QStringLiteral("1100")));
    f.scan();
    EXPECT_EQ(f.value("SM105"), 1) << "SWAP chose the digit: the page did not turn";
    QTest::keyClick(&f.panel, Qt::Key_Return);
    f.settle();
    f.scan();
    EXPECT_EQ(f.value("SM109"), 1100);
    EXPECT_EQ(f.value("V5"), 1100);
    EXPECT_EQ(f.panel.view().page, 1);
}

// 5.3, page 5 "DISPLAY SETUP": the standby's brightness (SM100) and delay (SM101, "default 2")
// set with the keys as a user page's fields are: SET edits the brightness, SET stores it and
// edits the delay, UP three times, SET stores 5 minutes into SM101, which the program reads.
TEST(FrontPanelView, Pl110DisplaySetupDelayIsChangedWithTheKeys) {
    PanelFixture f;
    f.start(rung::testing::pl110(), QStringLiteral("PL110-2A"),
            "LD SM0.1\nMOV 5 SM104\nLD SM0.0\nMOV SM101 V1\nEND\n");
    f.scan();
    f.scan();
    ASSERT_EQ(f.panel.view().page, 5);
    QStringList rows = f.panel.display()->text().split(QLatin1Char('\n'));
    EXPECT_EQ(rows.value(0), QStringLiteral("*** DISPLAY SETUP ***"));
    EXPECT_EQ(rows.value(3), QStringLiteral("                OFF %"));
    EXPECT_EQ(rows.value(6), QStringLiteral("                2 min"));
    // A click on the display gives the panel the keyboard: the arrows are UP / DOWN there (the
    // scroll area around the parts does not take them to scroll).
    QTest::mouseClick(f.panel.display(), Qt::LeftButton);
    ASSERT_EQ(f.panel.focusWidget(), &f.panel);
    QTest::keyClick(&f.panel, Qt::Key_Return); // the brightness
    ASSERT_EQ(f.panel.terminal().mode, model::TerminalState::Mode::Field);
    QTest::keyClick(&f.panel, Qt::Key_Return); // stored as it was; the delay
    ASSERT_EQ(f.panel.terminal().mode, model::TerminalState::Mode::Field);
    for (int k = 0; k < 3; ++k)
        QTest::keyClick(&f.panel, Qt::Key_Up);
    rows = f.panel.display()->text().split(QLatin1Char('\n'));
    EXPECT_EQ(rows.value(6), QStringLiteral("                5 min"));
    f.scan();
    EXPECT_EQ(f.value("SM101"), 2) << "not stored before SET";
    QTest::keyClick(&f.panel, Qt::Key_Return);
    f.settle();
    f.scan();
    EXPECT_EQ(f.value("SM101"), 5);
    EXPECT_EQ(f.value("V1"), 5) << "the program reads it";
    EXPECT_EQ(f.value("SM100"), 0);
    EXPECT_EQ(f.panel.terminal().mode, model::TerminalState::Mode::Pages);
}

// 5.3, page 3: the slave number (SMW4, 1.6.4) "può essere modificato solo previa immissione
// della password di sistema 1357": SET does nothing until the password page (SET held, 5.5)
// has entered 1357; then UP and SET store it.
TEST(FrontPanelView, Pl110SlaveAddressIsRefusedWithoutTheSystemPasswordAndSetWithIt) {
    PanelFixture f;
    f.start(rung::testing::pl110(), QStringLiteral("PL110-2A"),
            "LD SM0.1\nMOV 3 SM104\nLD SM0.1\nMOV 7 SM4\nEND\n");
    f.scan();
    f.scan();
    ASSERT_EQ(f.panel.view().page, 3);
    EXPECT_EQ(f.panel.display()->text().split(QLatin1Char('\n')).value(7),
              QStringLiteral("SLAVE ADDRESS:      7"));
    // The caption: the page's number, and below it what the page's values are.
    const auto *caption = f.panel.findChild<QLabel *>(QStringLiteral("frontPanelCaption"));
    ASSERT_NE(caption, nullptr);
    EXPECT_TRUE(caption->text().startsWith(QStringLiteral("Page 3 (SM105)\n")))
        << caption->text().toStdString();
    EXPECT_TRUE(caption->text().contains(QStringLiteral("1357")));
    f.panel.setFocus();
    QTest::keyClick(&f.panel, Qt::Key_Return);
    EXPECT_EQ(f.panel.terminal().mode, model::TerminalState::Mode::Pages) << "refused";
    QTest::keyClick(&f.panel, Qt::Key_Up);
    f.scan();
    EXPECT_EQ(f.value("SM4"), 7);
    // The password page: SET held.
    QToolButton *set = f.panel.key(QStringLiteral("SET"));
    ASSERT_NE(set, nullptr);
    QTest::mousePress(set, Qt::LeftButton);
    ASSERT_TRUE(eventually(
        [&] { return f.panel.terminal().mode == model::TerminalState::Mode::Password; }, 10000));
    QTest::mouseRelease(set, Qt::LeftButton);
    f.panel.setFocus();
    for (const int digit : {1, 3, 5, 7}) {
        for (int k = 0; k < digit; ++k)
            QTest::keyClick(&f.panel, Qt::Key_Up);
        QTest::keyClick(&f.panel, Qt::Key_S); // the next digit
    }
    EXPECT_TRUE(f.panel.display()->text().contains(QStringLiteral("1357")));
    QTest::keyClick(&f.panel, Qt::Key_Return);
    f.settle();
    f.scan();
    ASSERT_EQ(f.value("SM109"), 1357);
    ASSERT_EQ(f.panel.view().page, 3);
    QTest::keyClick(&f.panel, Qt::Key_Return);
    ASSERT_EQ(f.panel.terminal().mode, model::TerminalState::Mode::Field) << "accepted";
    QTest::keyClick(&f.panel, Qt::Key_Up);
    QTest::keyClick(&f.panel, Qt::Key_Return);
    f.settle();
    f.scan();
    EXPECT_EQ(f.value("SM4"), 8);
    EXPECT_EQ(f.panel.display()->text().split(QLatin1Char('\n')).value(7),
              QStringLiteral("SLAVE ADDRESS:      8"));
}

// PL110 manual 5.3, page 3: "il nome dell'applicazione ladder caricata, i protocolli associati
// alle porte seriali": the IDE's Front Panel shows the project's name and the protocol its port
// settings give each port (Tools > Communication Ports: EXP1 a MODBUS master), and follows them
// when they change.
TEST_F(FrontPanelDock, Pl110SystemInfoShowsTheProjectsNameAndItsPortsProtocols) {
    FrontPanelDock &f = *this;
    f.window.newProject(rung::testing::pl110(), QStringLiteral("PL110-2A"));
    f.load("LD SM0.1\nMOV 3 SM104\nEND\n");
    f.window.document()->setPath(QStringLiteral("/plant/pump_station.rung"));
    QJsonObject exp1;
    exp1.insert(QStringLiteral("application"), QStringLiteral("modbus-master"));
    QJsonObject ports;
    ports.insert(QStringLiteral("EXP1"), exp1);
    f.window.document()->setPorts(ports, QStringLiteral("ports"));
    editor::FrontPanel *panel = f.window.frontPanel()->panel();
    f.window.show();
    QApplication::setActiveWindow(&f.window);
    ASSERT_TRUE(QTest::qWaitForWindowActive(&f.window));
    f.view->setFocus();
    QTest::keyClick(f.view, Qt::Key_F10);
    ASSERT_NE(f.window.simulation()->session(), nullptr);
    ASSERT_TRUE(eventually([&] { return panel->view().page == 3; }));
    const auto row = [&](int k) {
        return panel->display()->text().split(QLatin1Char('\n')).value(k);
    };
    EXPECT_EQ(row(3), QStringLiteral("pump_station         "));
    EXPECT_EQ(row(4), QStringLiteral("COM1     MODBUS SLAVE"));
    EXPECT_EQ(row(5), QStringLiteral("EXP1    MODBUS MASTER"));
    const auto *caption = panel->findChild<QLabel *>(QStringLiteral("frontPanelCaption"));
    ASSERT_NE(caption, nullptr);
    EXPECT_TRUE(caption->text().contains(QStringLiteral("\"pump_station\"")))
        << caption->text().toStdString();
    // The settings changed: the page follows.
    ports.remove(QStringLiteral("EXP1"));
    f.window.document()->setPorts(ports, QStringLiteral("ports"));
    EXPECT_TRUE(eventually([&] { return row(5) == QStringLiteral("EXP1     MODBUS SLAVE"); }))
        << row(5).toStdString();
}
