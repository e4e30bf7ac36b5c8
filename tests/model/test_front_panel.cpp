// Issue 30: the PLC's front panel as table data (Target::panel) and what it shows for a snapshot
// (model::panelView), with the manuals' examples.

#include "model/image/panel_view.h"
#include "model/target/address.h"
#include "tests/targets.h"

#include <gtest/gtest.h>

#include <QJsonObject>

#include <algorithm>
#include <map>

using namespace rung;
using rung::model::MonitorSource;

namespace {

// A memory image of one target whose words the test sets by their names.
struct PanelImage {
    explicit PanelImage(const model::Target &t)
        : target(t) {
        snapshot.layout = std::make_shared<model::MemoryLayout>(t);
        snapshot.words.assign(static_cast<std::size_t>(snapshot.layout->wordCount()), 0);
    }
    model::Address at(const char *name) const {
        const auto parsed = model::parseAddress(target, QString::fromLatin1(name));
        return std::get<model::Address>(parsed);
    }
    void set(const char *name, std::int32_t value) {
        const model::Address a = at(name);
        if (a.bit >= 0 || target.area(a.area).kind == model::AreaKind::Bit) {
            const model::BitRef r = snapshot.layout->bit(a);
            auto &w = snapshot.words[static_cast<std::size_t>(r.word)];
            w = value ? (w | static_cast<std::int32_t>(r.mask))
                      : (w & ~static_cast<std::int32_t>(r.mask));
            return;
        }
        snapshot.words[static_cast<std::size_t>(snapshot.layout->word(a))] = value;
    }
    // Text into a byte area from `first`, one character a word, as MOVTXT's
    // UN_CARATTERE_PER_WORD stores it (PL110 manual 4.2.10).
    void text(const char *area, int first, const char *text) {
        for (int k = 0; text[k]; ++k)
            set(QStringLiteral("%1%2").arg(QLatin1String(area)).arg(first + k).toLatin1(), text[k]);
    }
    void set(const QByteArray &name, std::int32_t value) { set(name.constData(), value); }
    model::PanelView view(MonitorSource::RunState state = MonitorSource::RunState::Running,
                          const char *modelName = nullptr, qint64 nowMs = 0,
                          bool fault = false) const {
        const model::ModelVariant *m =
            modelName ? target.model(QString::fromLatin1(modelName)) : nullptr;
        return model::panelView(target, m, {&snapshot, state, fault, nowMs});
    }
    const model::Target &target;
    model::Snapshot snapshot;
};

const model::PanelLampView *lamp(const model::PanelView &v, const char *label) {
    for (const model::PanelLampView &l : v.lamps)
        if (l.label == QLatin1String(label))
            return &l;
    return nullptr;
}

} // namespace

// Vigor M/VB/VH communication manual, B-3 (Computer Link example): "MOV K3 D9080 Set the display
// screen to display mode 3 (displays a 4-digits numeric value), and show the value of D1 onto
// the screen. MOV K1 D9081".
TEST(FrontPanel, VigorModeThreeShowsTheRegisterD9081Names) {
    PanelImage image(rung::testing::vigor());
    image.set("D9080", 3);
    image.set("D9081", 1);
    image.set("D1", 123);
    model::PanelView v = image.view();
    EXPECT_EQ(v.display, model::DisplayKind::Digits);
    EXPECT_EQ(v.mode, 3);
    EXPECT_EQ(v.digitsText, QStringLiteral(" 123"));
    EXPECT_TRUE(v.fits);
    EXPECT_TRUE(v.note.isEmpty());
    // What an online source is to poll for the panel: the mode, the register's number and the
    // register it names.
    for (const char *device : {"D9080", "D9081", "D1", "VR1", "VR2"})
        EXPECT_NE(std::find(v.devices.begin(), v.devices.end(), image.at(device)), v.devices.end())
            << device;
    image.set("D1", 9999);
    EXPECT_EQ(image.view().digitsText, QStringLiteral("9999"));
    // Beyond four digits the manual does not say what the PLC shows: the value, plainly.
    image.set("D1", 12345);
    v = image.view();
    EXPECT_FALSE(v.fits);
    EXPECT_EQ(v.digitsText, QStringLiteral("12345"));
}

// B-3-4 (CPU Link example): "MOV K4 D9080 Set the display screen to display mode 4 (displays two
// 2-digits numeric values) Show the value of D10 on the right side of the screen, and show the
// value of D11 on the left side of the screen. MOV K10 D9081".
TEST(FrontPanel, VigorModeFourShowsTwoValuesTheNamedOneOnTheRight) {
    PanelImage image(rung::testing::vigor());
    image.set("D9080", 4);
    image.set("D9081", 10);
    image.set("D10", 7);
    image.set("D11", 42);
    const model::PanelView v = image.view();
    EXPECT_EQ(v.digitsText, QStringLiteral("42 7"));
    EXPECT_TRUE(v.fits);
}

// A mode the manual does not describe (0 at power-on) shows nothing and says so.
TEST(FrontPanel, VigorUndescribedModeIsSaidNotInvented) {
    PanelImage image(rung::testing::vigor());
    const model::PanelView v = image.view();
    EXPECT_TRUE(v.digitsText.isEmpty());
    EXPECT_TRUE(v.note.contains(QStringLiteral("Display mode 0"))) << v.note.toStdString();
    EXPECT_TRUE(v.note.contains(QStringLiteral("mode 3"))) << v.note.toStdString();
}

// "VRRD K1 D0 Read the value of VR1": the knobs VR1 and VR2, 0..255, write their VR word.
TEST(FrontPanel, VigorKnobsAreTheVariableResistors) {
    PanelImage image(rung::testing::vigor());
    image.set("VR1", 200);
    const model::PanelView v = image.view();
    ASSERT_EQ(v.knobs.size(), 2u);
    EXPECT_EQ(v.knobs[0].label, QStringLiteral("VR1"));
    EXPECT_EQ(v.knobs[0].value, 200);
    EXPECT_EQ(v.knobs[0].highest, 255);
    EXPECT_EQ(v.knobs[0].address, image.at("VR1"));
    EXPECT_EQ(model::panelKnobWord(v.knobs[1], 300), 255);
    ASSERT_NE(lamp(v, "RUN"), nullptr);
    EXPECT_TRUE(lamp(v, "RUN")->lit);
    EXPECT_FALSE(lamp(v, "ERROR")->lit);
    const model::PanelView fault =
        image.view(MonitorSource::RunState::Paused, nullptr, 0, /*fault=*/true);
    EXPECT_FALSE(lamp(fault, "RUN")->lit);
    EXPECT_TRUE(lamp(fault, "ERROR")->lit);
}

// PL110 manual 1.2: "Led verde RUN: Acceso fisso -> il PLC è in RUN ... Lampeggio lento -
// (0,5s on /0,5 s off) il PL110 è usato come modulo di IN/OUT senza l'applicativo ladder".
TEST(FrontPanel, Pl110RunLampBlinksSlowlyWhenNoLadderRuns) {
    PanelImage image(rung::testing::pl110());
    const auto run = [&](MonitorSource::RunState state, qint64 ms) {
        const model::PanelView v = image.view(state, nullptr, ms);
        return *lamp(v, "RUN");
    };
    using R = MonitorSource::RunState;
    EXPECT_TRUE(run(R::Running, 0).lit);
    EXPECT_EQ(run(R::Running, 0).blinkMs, 0);
    EXPECT_EQ(run(R::Stopped, 0).blinkMs, 500);
    EXPECT_TRUE(run(R::Stopped, 0).lit);
    EXPECT_TRUE(run(R::Stopped, 499).lit);
    EXPECT_FALSE(run(R::Stopped, 500).lit);
    EXPECT_FALSE(run(R::Stopped, 999).lit);
    EXPECT_TRUE(run(R::Stopped, 1000).lit);
    EXPECT_FALSE(run(R::Offline, 0).lit);
}

// "Led gialli COM1 ed EXP1: Acceso - alla trasmissione di ogni pacchetto di dati": lit while the
// port's transmitting marker is.
TEST(FrontPanel, Pl110PortLampsFollowTheTransmittingMarkers) {
    PanelImage image(rung::testing::pl110());
    image.set("SM0.7", 1);
    const model::PanelView v = image.view();
    EXPECT_FALSE(lamp(v, "COM1")->lit);
    EXPECT_TRUE(lamp(v, "EXP1")->lit);
    EXPECT_FALSE(lamp(v, "COM2")->lit);
}

// 2.1.16: "Per scrivere "TESTO DISPLAY" nella riga 3 del display per esempio ... MOVTXT
// (DISP42, 1 Char per word) "TESTO DISPLAY"": on a user page (SM105 17..32) the rows are DISP.
TEST(FrontPanel, Pl110UserPageShowsTheDisplayCharacters) {
    PanelImage image(rung::testing::pl110());
    image.set("SM105", 17);
    image.text("DISP", 0, "PAGINA UTENTE N1");
    image.text("DISP", 42, "TESTO DISPLAY");
    const model::PanelView v = image.view(MonitorSource::RunState::Running, "PL110-2A");
    ASSERT_EQ(v.display, model::DisplayKind::Text);
    ASSERT_EQ(v.lines.size(), 8);
    for (const QString &line : v.lines)
        EXPECT_EQ(line.size(), 21);
    EXPECT_EQ(v.page, 17);
    EXPECT_EQ(v.lines[0], QStringLiteral("PAGINA UTENTE N1     "));
    EXPECT_EQ(v.lines[1].trimmed(), QString());
    EXPECT_EQ(v.lines[2], QStringLiteral("TESTO DISPLAY        "));
}

// 5.4: "IMPOSTA AI1 COME PRIMO CAMPO IN VISUALIZZAZIONE, 16 BIT CON SEGNO, 7 CIFRE TOTALI
// 1 DECIMALE, VISUALIZZA IN RIGA 4 COLONNA 10" -- SM118 1 (Visualizzato), SM119 3 (area AI in
// SM107's list), SM120 / SM121 the number 1, SM128 0 (16 bit con segno), SM129 7, SM130 1,
// SM131 0 (spazi), SM132 4, SM133 10.
TEST(FrontPanel, Pl110FieldIsFormattedWhereThePageSays) {
    PanelImage image(rung::testing::pl110());
    image.set("SM105", 17);
    const std::pair<const char *, int> field[] = {
        {"SM118", 1}, {"SM119", 3}, {"SM120", 0}, {"SM121", 1}, {"SM128", 0},
        {"SM129", 7}, {"SM130", 1}, {"SM131", 0}, {"SM132", 4}, {"SM133", 10}};
    for (const auto &[name, value] : field)
        image.set(name, value);
    image.set("AI1", 250);
    model::PanelView v = image.view(MonitorSource::RunState::Running, "PL110-2A");
    EXPECT_EQ(v.lines[3], QStringLiteral("             25.0    "));
    ASSERT_EQ(v.fields.size(), 1u);
    EXPECT_EQ(v.fields[0].row, 3);
    EXPECT_EQ(v.fields[0].column, 9);
    EXPECT_EQ(v.fields[0].length, 8);
    EXPECT_FALSE(v.fields[0].editable);
    image.set("SM118", 0); // "0 - Disabilitato"
    EXPECT_TRUE(image.view(MonitorSource::RunState::Running, "PL110-2A").fields.empty());
}

TEST(FrontPanel, Pl110FieldFormats) {
    EXPECT_EQ(model::formatPanelField(250, 7, 1, false), QStringLiteral("    25.0"));
    EXPECT_EQ(model::formatPanelField(250, 7, 1, true), QStringLiteral("000025.0"));
    EXPECT_EQ(model::formatPanelField(-5, 4, 0, false), QStringLiteral("  -5"));
    EXPECT_EQ(model::formatPanelField(-5, 4, 0, true), QStringLiteral("-005"));
    EXPECT_EQ(model::formatPanelField(5, 3, 2, false), QStringLiteral("0.05"));
    EXPECT_EQ(model::formatPanelField(123456, 3, 0, false), QStringLiteral("123456"));
}

// 5.3: page 1 "viene visualizzato lo stato degli ingressi e uscite digitali ... con un
// quadratino pieno"; page 2 the analog inputs.
TEST(FrontPanel, Pl110SystemPagesShowTheTerminals) {
    PanelImage image(rung::testing::pl110());
    image.set("SM105", 1);
    image.set("I2", 1);
    image.set("Q8", 1);
    model::PanelView v = image.view(MonitorSource::RunState::Running, "PL110-2A");
    EXPECT_EQ(v.lines[0].trimmed(),
              QStringLiteral("I   \u25a1\u25a0\u25a1\u25a1\u25a1\u25a1\u25a1\u25a1"));
    EXPECT_EQ(v.lines[1].trimmed(),
              QStringLiteral("Q   \u25a1\u25a1\u25a1\u25a1\u25a1\u25a1\u25a1\u25a0"));
    image.set("SM105", 2);
    image.set("AI3", 1023);
    v = image.view(MonitorSource::RunState::Running, "PL110-2A");
    EXPECT_EQ(v.lines[2].trimmed(), QStringLiteral("AI3     1023"));
}

// 5.3, page 3: "la versione del programma di BOOT e del Firmware ... ed il numero dello slave";
// 1.6.4: "INDIRIZZO MODULO = OFFSET INDIRIZZO (SMW4)". The simulator has no version: a dash,
// no number, and the note says so.
TEST(FrontPanel, Pl110SystemInfoShowsTheSlaveAddressAndNoInventedVersion) {
    PanelImage image(rung::testing::pl110());
    image.set("SM105", 3);
    image.set("SM4", 17);
    const model::PanelView v = image.view(MonitorSource::RunState::Running, "PL110-2A");
    ASSERT_EQ(v.lines.size(), 8);
    EXPECT_EQ(v.lines[0].trimmed(), QStringLiteral("SYSTEM INFO"));
    EXPECT_EQ(v.lines[1], QStringLiteral("BOOT                \u2014"));
    EXPECT_EQ(v.lines[2], QStringLiteral("FIRMWARE            \u2014"));
    EXPECT_EQ(v.lines[7], QStringLiteral("SLAVE ADDRESS:     17"));
    ASSERT_EQ(v.fields.size(), 1u);
    EXPECT_EQ(v.fields[0].row, 7);
    EXPECT_EQ(v.fields[0].column, 18);
    ASSERT_EQ(v.fields.size(), 1u);
    EXPECT_TRUE(v.fields[0].editable);
    EXPECT_FALSE(v.fields[0].editing);
    EXPECT_NE(std::find(v.devices.begin(), v.devices.end(), image.at("SM4")), v.devices.end());
    EXPECT_TRUE(v.note.contains(QStringLiteral("1357"))) << v.note.toStdString();
}

// 5.3, page 3: "il nome dell'applicazione ladder caricata, i protocolli associati alle porte
// seriali": the project's name on row 4 and each port's protocol as its settings give it (the
// project's "ports": EXP1 a MODBUS master, COM1 and COM2 unnamed, their first application).
TEST(FrontPanel, Pl110SystemInfoShowsTheApplicationAndThePortsProtocols) {
    const model::Target &t = rung::testing::pl110();
    PanelImage image(t);
    image.set("SM105", 3);
    image.set("SM4", 1);
    const model::ModelVariant *m = t.model(QStringLiteral("PL110-2A"));
    QJsonObject exp1;
    exp1.insert(QStringLiteral("application"), QStringLiteral("modbus-master"));
    QJsonObject ports;
    ports.insert(QStringLiteral("EXP1"), exp1);
    const model::PanelContext context = model::panelContext(t, m, QStringLiteral("pump"), ports);
    model::PanelInput in{&image.snapshot, MonitorSource::RunState::Running};
    in.context = &context;
    const model::PanelView v = model::panelView(t, m, in);
    ASSERT_EQ(v.lines.size(), 8);
    EXPECT_EQ(v.lines[0], QStringLiteral("SYSTEM INFO          "));
    EXPECT_EQ(v.lines[1], QStringLiteral("BOOT                \u2014"));
    EXPECT_EQ(v.lines[2], QStringLiteral("FIRMWARE            \u2014"));
    EXPECT_EQ(v.lines[3], QStringLiteral("pump                 "));
    EXPECT_EQ(v.lines[4], QStringLiteral("COM1     MODBUS SLAVE"));
    EXPECT_EQ(v.lines[5], QStringLiteral("EXP1    MODBUS MASTER"));
    EXPECT_EQ(v.lines[6], QStringLiteral("COM2     MODBUS SLAVE"));
    EXPECT_EQ(v.lines[7], QStringLiteral("SLAVE ADDRESS:      1"));
    EXPECT_TRUE(v.note.contains(QStringLiteral("\"pump\""))) << v.note.toStdString();
}

// A name longer than the display's 21 columns is cut at the row's end, as the display would;
// the page's note gives it whole. The NAIS master's row.
TEST(FrontPanel, Pl110SystemInfoCutsALongNameAtTheRowsEnd) {
    const model::Target &t = rung::testing::pl110();
    PanelImage image(t);
    image.set("SM105", 3);
    const model::ModelVariant *m = t.model(QStringLiteral("PL110-2A"));
    const QString name = QStringLiteral("water_treatment_plant_line_2");
    std::map<QString, const model::PortApplication *> chosen;
    chosen[QStringLiteral("COM1")] = t.port(QStringLiteral("COM1"))->application(u"nais-master");
    const model::PanelContext context = model::panelContext(t, m, name, chosen);
    model::PanelInput in{&image.snapshot, MonitorSource::RunState::Running};
    in.context = &context;
    const model::PanelView v = model::panelView(t, m, in);
    EXPECT_EQ(v.lines[3], QStringLiteral("water_treatment_plant"));
    EXPECT_EQ(v.lines[4], QStringLiteral("COM1      NAIS MASTER"));
    EXPECT_EQ(v.lines[5], QStringLiteral("EXP1     MODBUS SLAVE"));
    EXPECT_TRUE(v.note.contains(name)) << v.note.toStdString();
}

// Without a context (nothing says which program the PLC holds nor how its ports are set) the
// page shows a dash where each would stand, and its note says so.
TEST(FrontPanel, Pl110SystemInfoWithoutContextSaysWhatItDoesNotKnow) {
    PanelImage image(rung::testing::pl110());
    image.set("SM105", 3);
    const model::PanelView v = image.view(MonitorSource::RunState::Running, "PL110-2A");
    EXPECT_EQ(v.lines[3], QStringLiteral("                    \u2014"));
    EXPECT_EQ(v.lines[4], QStringLiteral("COM1                \u2014"));
    EXPECT_EQ(v.lines[5], QStringLiteral("EXP1                \u2014"));
    EXPECT_EQ(v.lines[6], QStringLiteral("COM2                \u2014"));
    EXPECT_TRUE(v.note.contains(QStringLiteral("not known"))) << v.note.toStdString();
}

// Settings that do not read (an application the port does not have): that port's protocol is
// not known, the others are.
TEST(FrontPanel, Pl110SystemInfoPortWhoseSettingsDoNotReadIsNotKnown) {
    const model::Target &t = rung::testing::pl110();
    PanelImage image(t);
    image.set("SM105", 3);
    const model::ModelVariant *m = t.model(QStringLiteral("PL110-2A"));
    QJsonObject com2;
    com2.insert(QStringLiteral("application"), QStringLiteral("modbus-master"));
    QJsonObject ports;
    ports.insert(QStringLiteral("COM2"), com2);
    const model::PanelContext context = model::panelContext(t, m, QStringLiteral("p"), ports);
    model::PanelInput in{&image.snapshot, MonitorSource::RunState::Running};
    in.context = &context;
    const model::PanelView v = model::panelView(t, m, in);
    EXPECT_EQ(v.lines[4], QStringLiteral("COM1     MODBUS SLAVE"));
    EXPECT_EQ(v.lines[6], QStringLiteral("COM2                \u2014"));
}

// 5.3, page 4: "data ed ora dell'orologio interno", SM9..SM15 (2.1.2), which the simulator keeps
// as the program writes them: shown plainly, and the note says the clock does not count.
TEST(FrontPanel, Pl110DateAndTimeShowTheClockWordsPlainly) {
    PanelImage image(rung::testing::pl110());
    image.set("SM105", 4);
    image.set("SM9", 0);
    image.set("SM10", 5);
    image.set("SM11", 7);
    image.set("SM12", 9);
    image.set("SM13", 3);
    image.set("SM14", 26);
    image.set("SM15", 0); // "0=Domenica"
    const model::PanelView v = image.view(MonitorSource::RunState::Running, "PL110-2A");
    EXPECT_EQ(v.lines[0].trimmed(), QStringLiteral("DATE & TIME"));
    EXPECT_EQ(v.lines[2], QStringLiteral("DATE         09/03/26"));
    EXPECT_EQ(v.lines[4], QStringLiteral("TIME         07:05:00"));
    EXPECT_EQ(v.lines[6], QStringLiteral("DAY OF WEEK         0"));
    EXPECT_TRUE(v.note.contains(QStringLiteral("does not count"))) << v.note.toStdString();
}

// 5.3, page 5 as the manual's figure draws it: "*** DISPLAY SETUP ***", "STANDBY BRIGHTNESS",
// "OFF %", "STANDBY DELAY", "2 min" (2.1.2: SM100 "default 0=OFF", SM101 "default 2").
TEST(FrontPanel, Pl110DisplaySetupAsTheManualDrawsIt) {
    PanelImage image(rung::testing::pl110());
    image.set("SM105", 5);
    image.set("SM101", 2);
    model::PanelView v = image.view(MonitorSource::RunState::Running, "PL110-2A");
    EXPECT_EQ(v.lines[0], QStringLiteral("*** DISPLAY SETUP ***"));
    EXPECT_EQ(v.lines[2].trimmed(), QStringLiteral("STANDBY BRIGHTNESS"));
    EXPECT_EQ(v.lines[3], QStringLiteral("                OFF %"));
    EXPECT_EQ(v.lines[5].trimmed(), QStringLiteral("STANDBY DELAY"));
    EXPECT_EQ(v.lines[6], QStringLiteral("                2 min"));
    EXPECT_TRUE(v.note.isEmpty());
    image.set("SM100", 40);
    image.set("SM101", 15);
    v = image.view(MonitorSource::RunState::Running, "PL110-2A");
    EXPECT_EQ(v.lines[3], QStringLiteral("                 40 %"));
    EXPECT_EQ(v.lines[6], QStringLiteral("               15 min"));
}

// 1.2: "Terminale con display OLED e tasti. (solo modello PL110-2A)": the PL110-1A has the
// lamps only.
TEST(FrontPanel, Pl110TerminalOnlyOnThe2A) {
    PanelImage image(rung::testing::pl110());
    const model::PanelView one = image.view(MonitorSource::RunState::Running, "PL110-1A");
    EXPECT_EQ(one.display, model::DisplayKind::None);
    EXPECT_TRUE(one.keys.empty());
    EXPECT_EQ(one.lamps.size(), 4u);
    image.set("SM110.3", 1);
    const model::PanelView two = image.view(MonitorSource::RunState::Running, "PL110-2A");
    ASSERT_EQ(two.keys.size(), 4u);
    EXPECT_EQ(two.keys[0].label, QStringLiteral("SWAP"));
    EXPECT_EQ(two.keys[3].label, QStringLiteral("SET"));
    EXPECT_TRUE(two.keys[3].pressed);
    EXPECT_FALSE(two.keys[0].pressed);
}

// Omron CPM1 guide 3.4: "Mindkét potenciométer a hozzájuk tartozó csatornán BCD 0000 - 0200
// között állítja az adott csatorna értékét"; 2.1: the POWER, RUN, ERROR/ALARM and COMM lamps.
TEST(FrontPanel, Cpm1AnalogSettingsAreBcdAndItsLampsAreTheGuides) {
    PanelImage image(rung::testing::cpm1());
    image.set("250", 0x0150);
    const model::PanelView v = image.view();
    ASSERT_EQ(v.knobs.size(), 2u);
    EXPECT_EQ(v.knobs[0].value, 150);
    EXPECT_EQ(model::panelKnobWord(v.knobs[0], 150), 0x0150);
    EXPECT_EQ(model::panelKnobWord(v.knobs[1], 250), 0x0200);
    QStringList labels;
    for (const model::PanelLampView &l : v.lamps)
        labels << l.label;
    EXPECT_EQ(labels, (QStringList{"POWER", "RUN", "ERROR/ALARM", "COMM"}));
    EXPECT_TRUE(lamp(v, "POWER")->lit);
    const model::PanelView off = image.view(MonitorSource::RunState::Offline);
    EXPECT_FALSE(lamp(off, "POWER")->lit);
    EXPECT_EQ(v.display, model::DisplayKind::None);
}

// Omron CPM1 guide 2.1, ERROR/ALARM (piros): "Világít - Lényegi hiba, a CPU leállt", "Villog -
// Nem lényegi hiba, a CPU tovább dolgozik", "Nem világít - Normál működés". A non-fatal error is
// a FAL number in 253.00..253.07 (W353 FAL(06)) or an error the source reports while the program
// runs on (the simulator skips the instruction and goes on); one it reports while the program
// does not run stopped the CPU. The guide gives no blink rate: 0.5 s.
TEST(FrontPanel, Cpm1ErrorAlarmBlinksOnANonFatalErrorAndIsLitOnAFatalOne) {
    PanelImage image(rung::testing::cpm1());
    using R = MonitorSource::RunState;
    const auto alarm = [&](qint64 ms, bool fault = false, R state = R::Running) {
        return *lamp(image.view(state, nullptr, ms, fault), "ERROR/ALARM");
    };
    image.set("253", 0x2000); // 253.13, always ON: no error
    EXPECT_FALSE(alarm(0).lit);
    EXPECT_EQ(alarm(0).blinkMs, 0) << "normal operation: dark";
    image.set("253", 0x2012); // FAL 12
    EXPECT_EQ(alarm(0).blinkMs, 500);
    EXPECT_TRUE(alarm(0).lit);
    EXPECT_TRUE(alarm(499).lit);
    EXPECT_FALSE(alarm(500).lit);
    EXPECT_TRUE(alarm(1000).lit);
    EXPECT_TRUE(lamp(image.view(R::Running, nullptr, 500), "RUN")->lit) << "the CPU goes on";
    // An error the source reports while the program runs on (paused: a PLC in RUN frozen in
    // time): blinking, RUN lit, with or without a FAL number.
    image.set("253", 0);
    for (const R state : {R::Running, R::Paused, R::Stepping}) {
        EXPECT_EQ(alarm(0, true, state).blinkMs, 500);
        EXPECT_TRUE(alarm(0, true, state).lit);
        EXPECT_FALSE(alarm(500, true, state).lit);
        EXPECT_TRUE(lamp(image.view(state, nullptr, 500, true), "RUN")->lit) << "the CPU goes on";
    }
    // An error the source reports while the program does not run stopped the CPU: lit, steady,
    // whatever FAL number is there; RUN dark.
    EXPECT_TRUE(alarm(500, true, R::Stopped).lit);
    EXPECT_EQ(alarm(500, true, R::Stopped).blinkMs, 0);
    image.set("253", 0x0012);
    EXPECT_TRUE(alarm(500, true, R::Stopped).lit);
    EXPECT_EQ(alarm(500, true, R::Stopped).blinkMs, 0);
    EXPECT_FALSE(lamp(image.view(R::Stopped, nullptr, 0, true), "RUN")->lit);
    image.set("253", 0);
    EXPECT_FALSE(alarm(0, false, R::Stopped).lit) << "stopped without an error: dark";
    // Without power nothing is lit.
    EXPECT_FALSE(lamp(image.view(R::Offline, nullptr, 0), "ERROR/ALARM")->lit);
}

// A family whose manual does not tell the two kinds apart (FrontPanel::errorsGoOn false, the
// Vigor's ERROR "lit when a program error stopped the PLC"): any error the source reports is
// shown as one that stopped it, RUN dark, whatever the run state.
TEST(FrontPanel, WithoutErrorsThatGoOnAnyErrorDarkensRun) {
    PanelImage image(rung::testing::vigor());
    EXPECT_FALSE(rung::testing::vigor().panel.errorsGoOn);
    EXPECT_TRUE(rung::testing::cpm1().panel.errorsGoOn);
    const model::PanelView v = image.view(MonitorSource::RunState::Running, nullptr, 0, true);
    EXPECT_FALSE(lamp(v, "RUN")->lit);
    EXPECT_TRUE(lamp(v, "ERROR")->lit);
    EXPECT_EQ(lamp(v, "ERROR")->blinkMs, 0);
}

// Omron CPM1 guide 2.1, COMM (narancssárga): "Világít - A PLC kommunikál", "Nem világít - A PLC
// éppen nem kommunikál". Lit for 0.2 s of the PLC's clock after a byte on its port (the hold is
// ours: the guide gives none); dark when nothing is known of its ports.
TEST(FrontPanel, Cpm1CommIsLitWhileItsPortCarriedAByteWithinTheHold) {
    PanelImage image(rung::testing::cpm1());
    using R = MonitorSource::RunState;
    const auto comm = [&](qint64 timeMs, qint64 communicatedUs, R state = R::Running) {
        image.snapshot.statistics.timeMs = timeMs;
        image.snapshot.communicatedUs = communicatedUs;
        return *lamp(image.view(state), "COMM");
    };
    EXPECT_FALSE(comm(1000, -1).lit) << "no port, or no byte yet";
    EXPECT_TRUE(comm(1000, 1000000).lit) << "a byte at the end of this scan";
    EXPECT_TRUE(comm(1000, 1010000).lit) << "a reply still leaving after the scan";
    EXPECT_TRUE(comm(1000, 800001).lit);
    EXPECT_FALSE(comm(1000, 800000).lit) << "0.2 s after the last byte: dark";
    EXPECT_FALSE(comm(5000, 1000000).lit);
    EXPECT_EQ(comm(1000, 1000000).blinkMs, 0);
    EXPECT_TRUE(comm(1000, 1000000, R::Paused).lit) << "frozen as the last scan left it";
    EXPECT_FALSE(comm(1000, 1000000, R::Offline).lit) << "no power";
    EXPECT_NE(QString::fromLatin1(lamp(image.view(), "COMM")->meaning).indexOf(u"peripheral"), -1);
    EXPECT_EQ(QString::fromLatin1(lamp(image.view(), "COMM")->meaning).indexOf(u"no port"), -1);
}

// VPC user's manual, II Technical specifications, Indication: "LEDs to show which
// inputs/outputs are driven ON (VPC2416 and higher)": a lamp a point on those models, none on
// the smaller ones; no colour is given, so none is invented.
TEST(FrontPanel, VpcInputAndOutputLedsOnVpc2416AndHigher) {
    PanelImage image(rung::testing::vpc());
    image.set("i01", 1);
    image.set("o15", 1);
    const model::PanelView v = image.view(MonitorSource::RunState::Running, "VPC2416");
    ASSERT_EQ(v.lamps.size(), 24u + 16u);
    EXPECT_EQ(v.lamps.front().label, QStringLiteral("i00"));
    EXPECT_EQ(v.lamps.back().label, QStringLiteral("o15"));
    EXPECT_EQ(v.lamps.front().colour, model::LampColour::Unstated);
    EXPECT_FALSE(lamp(v, "i00")->lit);
    EXPECT_TRUE(lamp(v, "i01")->lit);
    EXPECT_TRUE(lamp(v, "o15")->lit);
    EXPECT_FALSE(lamp(v, "o14")->lit);
    EXPECT_EQ(image.view(MonitorSource::RunState::Running, "VPC4030A84").lamps.size(), 40u + 30u);
    for (const char *smaller : {"VPC106", "VPC108A4", "VPC1410", "VPC1812"})
        EXPECT_TRUE(image.view(MonitorSource::RunState::Running, smaller).lamps.empty()) << smaller;
}

// VPC user's manual, V.a: "The upper part of the display is for the outputs, shown by 16 per
// line. The lower part of the display is for the inputs ... A filled field represents the state
// ON".
TEST(FrontPanel, VpcLcdShowsOutputsThenInputsSixteenALine) {
    PanelImage image(rung::testing::vpc());
    image.set("o00", 1);
    image.set("i01", 1);
    const model::PanelView v = image.view(MonitorSource::RunState::Running, "VPC2416");
    ASSERT_EQ(v.display, model::DisplayKind::IoLines);
    ASSERT_GE(v.lines.size(), 2);
    EXPECT_EQ(v.lineLabels.first(), QStringLiteral("o00"));
    EXPECT_TRUE(v.lines.first().startsWith(QStringLiteral("\u25a0\u25a1")));
    const qsizetype firstInputs = v.lineLabels.indexOf(QStringLiteral("i00"));
    ASSERT_GT(firstInputs, 0);
    EXPECT_TRUE(v.lines[firstInputs].startsWith(QStringLiteral("\u25a1\u25a0")));
    for (const QString &line : v.lines)
        EXPECT_LE(line.size(), 16);
}

TEST(FrontPanel, EveryFamilyHasAPanel) {
    for (const model::Family f : model::Target::families())
        EXPECT_TRUE(model::hasFrontPanel(model::Target::get(f), nullptr));
}

// ---- The PL110-2A's keys editing the fields, the password page, the standby (issue 30) -----

namespace {

using Role = model::PanelKeyRole;
using Mode = model::TerminalState::Mode;

// 5.4's page 18: "SetPAR1 [Modifiable, Par = VW0, Min = #0, Max = #1400]", "FormatPAR1 [16 bit
// signed, Tot7, Dec1, Spaces]", "PosPAR1 [Row4, Column10, Free]": field `k` (0-based) as its
// words from SM118 + 17 k hold it, the limits constants (area 0).
void editableField(PanelImage &image, int k, const char *variable, int areaCode, int number,
                   int row, int lowest, int highest, int access = 0) {
    const int first = 118 + 17 * k;
    const auto sm = [&](int offset, std::int32_t value) {
        image.set(QStringLiteral("SM%1").arg(first + offset).toLatin1(), value);
    };
    sm(0, 2); // Modifica
    sm(1, areaCode);
    sm(2, 0);
    sm(3, number);
    sm(4, 0);
    sm(5, 0);
    sm(6, lowest);
    sm(7, 0);
    sm(8, 0);
    sm(9, highest);
    sm(10, 0); // 16 bit signed
    sm(11, 7);
    sm(12, 1);
    sm(13, 0);
    sm(14, row);
    sm(15, 10);
    sm(16, access);
    (void)variable;
}

struct Terminal {
    PanelImage image{rung::testing::pl110()};
    model::TerminalState state;
    qint64 wallMs = 0;
    std::vector<model::TerminalWrite> press(Role role, qint64 holdMs = 0) {
        auto writes = model::terminalKey(image.target, image.snapshot, state, role, true, wallMs);
        wallMs += holdMs;
        model::terminalTick(image.target, image.snapshot, state, wallMs);
        auto more = model::terminalKey(image.target, image.snapshot, state, role, false, wallMs);
        writes.insert(writes.end(), more.begin(), more.end());
        return writes;
    }
    model::PanelView view() {
        model::terminalTick(image.target, image.snapshot, state, wallMs);
        model::PanelInput in{&image.snapshot, MonitorSource::RunState::Running, false, 0};
        in.terminal = &state;
        return model::panelView(image.target, image.target.model(QStringLiteral("PL110-2A")), in);
    }
    model::Address at(const char *name) const { return image.at(name); }
};

} // namespace

// 5.2: "Il tasto SET permette di abilitare la modifica ai campi numerici ... il campo numerico
// viene visualizzato in reverse"; UP / DOWN "incrementerà di una sola unità oppure di un valore
// 1*10^n" once SWAP has switched "alla modifica a cifre"; the value stays within SetPAR's
// Min / Max and SET stores it.
TEST(FrontPanelKeys, Pl110SetEditsAFieldUpDownChangeItSetStoresIt) {
    Terminal t;
    t.image.set("SM105", 18);
    editableField(t.image, 0, "V0", 1, 0, 4, 0, 1400);
    t.image.set("V0", 250);
    EXPECT_EQ(t.view().lines[3], QStringLiteral("             25.0    "));
    EXPECT_TRUE(t.press(Role::Set).empty());
    EXPECT_EQ(t.state.mode, Mode::Field);
    EXPECT_EQ(t.state.value, 250);
    EXPECT_TRUE(t.press(Role::Up).empty()); // nothing is stored before SET
    model::PanelView v = t.view();
    EXPECT_EQ(v.lines[3], QStringLiteral("             25.1    "));
    ASSERT_EQ(v.fields.size(), 1u);
    EXPECT_TRUE(v.fields[0].editing);
    EXPECT_EQ(v.fields[0].cursor, -1);
    t.press(Role::Swap); // digit by digit: the units (the tenths here) first
    t.press(Role::Swap); // then the next digit to the left
    t.press(Role::Up);
    EXPECT_EQ(t.state.value, 261);
    v = t.view();
    EXPECT_EQ(v.lines[3], QStringLiteral("             26.1    "));
    EXPECT_EQ(v.fields[0].cursor, 5); // "   26.1": the 6
    t.press(Role::Swap);
    t.press(Role::Swap);
    t.press(Role::Up); // + 1000
    EXPECT_EQ(t.state.value, 1261);
    t.press(Role::Up); // not beyond Max = #1400
    EXPECT_EQ(t.state.value, 1400);
    // SWAP's bit does not reach the engine while a value is entered (it would step the page).
    EXPECT_FALSE(model::terminalPassesKey(t.state, Role::Swap));
    EXPECT_TRUE(model::terminalPassesKey(t.state, Role::Up));
    const auto writes = t.press(Role::Set);
    // 2.1.2 SM107 / SM108: "se tramite il terminale si modifica la variabile VW30, si avrà ...
    // SM107 = 1 e SM108 = 30": the note of the variable stored, V (area 1) number 0.
    ASSERT_EQ(writes.size(), 3u);
    EXPECT_EQ(writes[0], (model::TerminalWrite{t.at("V0"), 1400}));
    EXPECT_EQ(writes[1], (model::TerminalWrite{t.at("SM107"), 1}));
    EXPECT_EQ(writes[2], (model::TerminalWrite{t.at("SM108"), 0}));
    EXPECT_EQ(t.state.mode, Mode::Pages); // the page's only field: back to the page
    EXPECT_TRUE(model::terminalPassesKey(t.state, Role::Swap));
}

// "Se in una pagina ci sono più campi abilitati alla modifica, con la pressione del tasto SET si
// passa alla modifica da un campo all'altro": each SET stores the field and edits the next; a
// field only shown (state 1) is passed over.
TEST(FrontPanelKeys, Pl110SetGoesFromFieldToFieldStoringEach) {
    Terminal t;
    t.image.set("SM105", 18);
    editableField(t.image, 0, "V0", 1, 0, 4, 0, 1400);
    editableField(t.image, 1, "AI1", 3, 1, 6, 0, 1000);
    t.image.set("SM135", 1); // field 2 only shown
    editableField(t.image, 2, "V2", 1, 2, 8, 200, 999);
    t.image.set("V2", 300);
    t.press(Role::Set);
    EXPECT_EQ(t.state.field, 0);
    t.press(Role::Down); // 0 is Min: stays
    auto writes = t.press(Role::Set);
    ASSERT_EQ(writes.size(), 3u);
    EXPECT_EQ(writes[0], (model::TerminalWrite{t.at("V0"), 0}));
    EXPECT_EQ(t.state.field, 2);
    EXPECT_EQ(t.state.value, 300);
    t.press(Role::Down);
    writes = t.press(Role::Set);
    ASSERT_EQ(writes.size(), 3u);
    EXPECT_EQ(writes[0], (model::TerminalWrite{t.at("V2"), 299}));
    EXPECT_EQ(writes[1], (model::TerminalWrite{t.at("SM107"), 1}));
    EXPECT_EQ(writes[2], (model::TerminalWrite{t.at("SM108"), 2}));
    EXPECT_EQ(t.state.mode, Mode::Pages);
}

// A page changed by the program (SM106 -> SM105) ends the editing; the value entered is not
// stored.
TEST(FrontPanelKeys, Pl110APageChangeLeavesTheFieldUnstored) {
    Terminal t;
    t.image.set("SM105", 18);
    editableField(t.image, 0, "V0", 1, 0, 4, 0, 1400);
    t.press(Role::Set);
    t.press(Role::Up);
    t.image.set("SM105", 17);
    t.view();
    EXPECT_EQ(t.state.mode, Mode::Pages);
    t.image.set("SM105", 18);
    EXPECT_TRUE(t.press(Role::Up).empty());
}

// 5.5, page 253: "A questa pagina si accede tenendo premuto per circa 2 secondi il tasto SET.
// Tramite le frecce e il tasto swap inserire la password per l'accesso alla modifica dei campi
// parametro"; 2.1.2 SM109 and SM134 / SM185: a field "protetto da password" is edited "solamente
// dopo aver inserito la password utente 1234".
TEST(FrontPanelKeys, Pl110SetHeldOpensThePasswordPageThatUnlocksProtectedFields) {
    Terminal t;
    t.image.set("SM105", 18);
    editableField(t.image, 0, "V0", 1, 0, 4, 0, 1400, 1);
    t.press(Role::Set);
    EXPECT_EQ(t.state.mode, Mode::Pages) << "protected, no password yet";
    // Held for less than 2 s: a press; for 2 s: the password page, and its release stores
    // nothing.
    EXPECT_TRUE(t.press(Role::Set, 1999).empty());
    EXPECT_EQ(t.state.mode, Mode::Pages);
    EXPECT_TRUE(t.press(Role::Set, 2000).empty());
    ASSERT_EQ(t.state.mode, Mode::Password);
    model::PanelView v = t.view();
    EXPECT_EQ(v.page, 253);
    EXPECT_EQ(v.lines[1].trimmed(), QStringLiteral("*** PASSWORD ***"));
    EXPECT_EQ(v.lines[4].trimmed(), QStringLiteral("0000"));
    ASSERT_EQ(v.fields.size(), 1u);
    EXPECT_EQ(v.fields[0].cursor, 0); // the first digit
    // 1, 2, 3, 4 digit by digit; DOWN turns a digit round (0 -> 9).
    t.press(Role::Up);
    t.press(Role::Swap);
    t.press(Role::Up);
    t.press(Role::Up);
    t.press(Role::Swap);
    t.press(Role::Down);
    t.press(Role::Down);
    t.press(Role::Down);
    t.press(Role::Down);
    t.press(Role::Down);
    t.press(Role::Down);
    t.press(Role::Down); // 0 -> 9 -> ... -> 3
    t.press(Role::Swap);
    for (int k = 0; k < 4; ++k)
        t.press(Role::Up);
    EXPECT_EQ(t.view().lines[4].trimmed(), QStringLiteral("1234"));
    const auto writes = t.press(Role::Set);
    ASSERT_EQ(writes.size(), 1u);
    EXPECT_EQ(writes[0], (model::TerminalWrite{t.at("SM109"), 1234}));
    EXPECT_EQ(t.state.mode, Mode::Pages);
    t.image.set("SM109", 1234); // as the source stores it
    EXPECT_EQ(t.view().page, 18);
    t.press(Role::Set);
    EXPECT_EQ(t.state.mode, Mode::Field) << "unlocked by the user password";
}

// 2.1.2 SM100 / SM101: "la modalità standby, se abilitata, si attiva dopo il tempo in minuti
// specificato da SMW101 dall'ultima pressione di un pulsante"; "bastera la pressione di uno dei
// pulsanti del terminale per riportare il display alla massima luminosità"; "Il cambio pagina da
// programma, tramite scrittura di SMW106, equivale alla pressione di un tasto"; "Impostando
// questa word a 0, si disabilita la modalità standby".
TEST(FrontPanelKeys, Pl110StandbyDimsAfterTheDelayAndAKeyOrAPageWakesIt) {
    Terminal t;
    t.image.set("SM105", 1);
    t.image.set("SM100", 30);
    t.image.set("SM101", 2);
    t.image.snapshot.statistics.timeMs = 119999;
    EXPECT_EQ(t.view().brightness, 100);
    t.image.snapshot.statistics.timeMs = 120000;
    EXPECT_EQ(t.view().brightness, 30);
    t.press(Role::Up);
    EXPECT_EQ(t.view().brightness, 100);
    t.image.snapshot.statistics.timeMs = 240000;
    EXPECT_EQ(t.view().brightness, 30);
    t.image.set("SM105", 2); // the program changed the page
    EXPECT_EQ(t.view().brightness, 100);
    t.image.set("SM101", 0);
    t.image.snapshot.statistics.timeMs = 10000000;
    EXPECT_EQ(t.view().brightness, 100);
}

// 5.3, page 3: the slave number "può essere modificato solo previa immissione della password di
// sistema 1357" (2.1.2 SM109: "per impostare il parametro SLAVE ADDRESS da terminale, è
// necessario immettere la password di sistema 1357"): the user password does not do.
TEST(FrontPanelKeys, Pl110SlaveAddressOnlyAfterTheSystemPassword) {
    Terminal t;
    t.image.set("SM105", 3);
    t.image.set("SM4", 1);
    EXPECT_TRUE(t.press(Role::Set).empty());
    EXPECT_EQ(t.state.mode, Mode::Pages) << "no password";
    t.image.set("SM109", 1234);
    EXPECT_TRUE(t.press(Role::Set).empty());
    EXPECT_EQ(t.state.mode, Mode::Pages) << "the user password";
    t.image.set("SM109", 1357);
    t.press(Role::Set);
    ASSERT_EQ(t.state.mode, Mode::Field);
    t.press(Role::Up);
    t.press(Role::Up);
    model::PanelView v = t.view();
    EXPECT_EQ(v.lines[7], QStringLiteral("SLAVE ADDRESS:      3"));
    ASSERT_EQ(v.fields.size(), 1u);
    EXPECT_TRUE(v.fields[0].editing);
    const auto writes = t.press(Role::Set);
    // Stored as a user field's variable, with the note (SM is area 2 of SM107's list).
    ASSERT_EQ(writes.size(), 3u);
    EXPECT_EQ(writes[0], (model::TerminalWrite{t.at("SM4"), 3}));
    EXPECT_EQ(writes[1], (model::TerminalWrite{t.at("SM107"), 2}));
    EXPECT_EQ(writes[2], (model::TerminalWrite{t.at("SM108"), 4}));
    EXPECT_EQ(t.state.mode, Mode::Pages);
}

// 5.3, page 5: "è possibile visualizzare ed impostare" the standby's brightness (SM100, in %)
// and delay (SM101, minutes): SET edits the first, stores it and edits the second.
TEST(FrontPanelKeys, Pl110DisplaySetupIsSetWithTheKeys) {
    Terminal t;
    t.image.set("SM105", 5);
    t.image.set("SM100", 99);
    t.image.set("SM101", 2);
    t.press(Role::Set);
    ASSERT_EQ(t.state.mode, Mode::Field);
    t.press(Role::Up);
    t.press(Role::Up); // not beyond 100 %
    EXPECT_EQ(t.view().lines[3], QStringLiteral("                100 %"));
    auto writes = t.press(Role::Set);
    ASSERT_FALSE(writes.empty());
    EXPECT_EQ(writes[0], (model::TerminalWrite{t.at("SM100"), 100}));
    ASSERT_EQ(t.state.mode, Mode::Field);
    t.press(Role::Swap); // the units
    t.press(Role::Swap); // the tens
    t.press(Role::Up);
    EXPECT_EQ(t.view().lines[6], QStringLiteral("               12 min"));
    writes = t.press(Role::Set);
    ASSERT_FALSE(writes.empty());
    EXPECT_EQ(writes[0], (model::TerminalWrite{t.at("SM101"), 12}));
    EXPECT_EQ(t.state.mode, Mode::Pages);
}

// 5.3, page 4: "è possibile visualizzare e modificare data ed ora": the day first, within 1..31.
TEST(FrontPanelKeys, Pl110TheClockIsSetWithTheKeys) {
    Terminal t;
    t.image.set("SM105", 4);
    t.image.set("SM12", 31);
    t.press(Role::Set);
    ASSERT_EQ(t.state.mode, Mode::Field);
    t.press(Role::Up); // not beyond 31
    t.press(Role::Down);
    const auto writes = t.press(Role::Set);
    ASSERT_FALSE(writes.empty());
    EXPECT_EQ(writes[0], (model::TerminalWrite{t.at("SM12"), 30}));
    EXPECT_EQ(t.state.mode, Mode::Field) << "then the month";
}
