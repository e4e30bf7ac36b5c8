// PL110 table facts of issue 14 (PL110 manual): the MODBUS map as chapter 3.2 prints it (T1..T48
// only, inputs R/W as bits and R as words, special-marker bits to SM129.15), the double
// words VD / SMD (2.1.1), the trimmers TR as a preset source (4.2.4, 4.2.5) and the timers
// T49..T64 that SM0.13 enables (2.1.2).

#include "model/checks/checks.h"
#include "model/listing/il.h"
#include "model/target/address.h"
#include "model/target/protocol_map.h"
#include "tests/targets.h"

#include <gtest/gtest.h>

using namespace rung::model;

namespace {

using rung::testing::pl110;

Address at(const char *text) {
    const auto a = parseAddress(pl110(), QString::fromLatin1(text));
    EXPECT_TRUE(std::holds_alternative<Address>(a)) << text;
    return std::holds_alternative<Address>(a) ? std::get<Address>(a) : Address{};
}

QString addressError(const char *text) {
    const auto a = parseAddress(pl110(), QString::fromLatin1(text));
    return std::holds_alternative<AddressError>(a) ? std::get<AddressError>(a).message : QString();
}

std::vector<Diagnostic> check(const char *text) {
    const ParseResult r = parseInstructionList(pl110(), QString::fromLatin1(text));
    EXPECT_TRUE(r.ok()) << (r.ok() ? "" : r.errors.front().message.toStdString());
    return checkList(r.list);
}

int count(const std::vector<Diagnostic> &found, const char *code) {
    return static_cast<int>(std::count_if(found.begin(), found.end(), [&](const Diagnostic &d) {
        return d.code == QLatin1String(code);
    }));
}

const ProtocolMap &modbus() {
    return *findProtocolMap(pl110(), ProtocolId::Modbus);
}

} // namespace

// 3.2: "4800 Contatto n.a. timer T1 ... 4847 Contatto n.a. timer T48", words 300..302 and
// 12000..12047 / 13000..13047: the manual gives T49..T64 no MODBUS address.
TEST(Pl110Modbus, TimersEndAtT48AsTheManualsMapDoes) {
    const ProtocolMap &m = modbus();
    EXPECT_EQ(toProtocol(pl110(), m, at("T48"), DevicePart::Bit)->unit, 4847);
    EXPECT_FALSE(toProtocol(pl110(), m, at("T49"), DevicePart::Bit));
    EXPECT_FALSE(toProtocol(pl110(), m, at("T64"), DevicePart::Value));
    EXPECT_FALSE(toProtocol(pl110(), m, at("PT49"), DevicePart::Value));
    EXPECT_EQ(toProtocol(pl110(), m, at("PT48"), DevicePart::Value)->unit, 13047);
    EXPECT_FALSE(fromProtocol(pl110(), m, ProtocolSpace::Coils, 4848));
    EXPECT_FALSE(fromProtocol(pl110(), m, ProtocolSpace::HoldingRegisters, 303, 0));
    EXPECT_FALSE(fromProtocol(pl110(), m, ProtocolSpace::HoldingRegisters, 12048));
    // The counters follow at 5600 as before.
    EXPECT_EQ(fromProtocol(pl110(), m, ProtocolSpace::Coils, 5600)->index, 1);
}

// 3.2: bits 1600..1855 "Contatto n.a. ingresso digitale I1..I256  R/W", words 100..115 "R";
// timer and counter contacts and the analog inputs are R; SM bits end at 18079 (SM129.15).
TEST(Pl110Modbus, AccessIsTheManualsReadWriteColumn) {
    const ProtocolMap &m = modbus();
    const auto inputBit = fromProtocol(pl110(), m, ProtocolSpace::Coils, 1600);
    ASSERT_TRUE(inputBit);
    EXPECT_FALSE(inputBit->readOnly);
    EXPECT_FALSE(pl110().area(inputBit->area).writable); // the program still cannot write I
    const auto inputWord = fromProtocol(pl110(), m, ProtocolSpace::HoldingRegisters, 100, 0);
    ASSERT_TRUE(inputWord);
    EXPECT_TRUE(inputWord->readOnly);
    EXPECT_TRUE(fromProtocol(pl110(), m, ProtocolSpace::Coils, 4800)->readOnly);
    EXPECT_TRUE(fromProtocol(pl110(), m, ProtocolSpace::Coils, 5615)->readOnly);
    EXPECT_TRUE(fromProtocol(pl110(), m, ProtocolSpace::HoldingRegisters, 300, 3)->readOnly);
    EXPECT_TRUE(fromProtocol(pl110(), m, ProtocolSpace::HoldingRegisters, 19000)->readOnly);
    EXPECT_FALSE(fromProtocol(pl110(), m, ProtocolSpace::HoldingRegisters, 19400)->readOnly);
    EXPECT_FALSE(fromProtocol(pl110(), m, ProtocolSpace::Coils, 2400)->readOnly);
    EXPECT_FALSE(fromProtocol(pl110(), m, ProtocolSpace::HoldingRegisters, 12000)->readOnly);
    EXPECT_EQ(toProtocol(pl110(), m, at("SM129.15"), DevicePart::Bit)->unit, 18079);
    EXPECT_FALSE(toProtocol(pl110(), m, at("SM130.0"), DevicePart::Bit));
    EXPECT_EQ(toProtocol(pl110(), m, at("SM130"), DevicePart::Value)->unit, 1130);
}

TEST(Pl110DoubleWords, VdAndSmdAreDoubleWordsNumberedByWord) {
    const Address vd = at("VD8");
    EXPECT_EQ(pl110().area(vd.area).key, QStringLiteral("VD"));
    EXPECT_EQ(pl110().area(vd.area).wordBits, 32);
    EXPECT_EQ(formatAddress(pl110(), at("smd20")), QStringLiteral("SMD20"));
    EXPECT_EQ(formatAddress(pl110(), at("V8")), QStringLiteral("V8")); // V stays the word
    // The last double word is VD348 (V348 : V349).
    EXPECT_TRUE(addressError("VD349").contains(QLatin1String("VD0..VD348")))
        << addressError("VD349").toStdString();
    EXPECT_FALSE(addressError("VD2.1").isEmpty()); // a double word has no bit form
    // A 32-bit constant fits a double word, not a word.
    EXPECT_TRUE(parseInstructionList(pl110(), QStringLiteral("LD I1\nMOV 100000 VD0\nEND")).ok());
    EXPECT_FALSE(parseInstructionList(pl110(), QStringLiteral("LD I1\nMOV 100000 V0\nEND")).ok());
}

TEST(Pl110DoubleWords, BlockMovesCountWordsAndRefuseThem) {
    const std::vector<Diagnostic> found = check("LD I1\nBLKMOV VD0 V10 2\nLD I1\nMOVIND 5 VD0 V1\n"
                                                "LD I1\nBLKMOV V0 V10 2\nEND");
    EXPECT_EQ(count(found, "OP005"), 2);
}

// 4.2.4 / 4.2.5: PT and PV come "da una variabile dell'area VW, SMW, AI e TR".
TEST(Pl110Presets, PresetsComeFromVSmAiTrOrAConstant) {
    EXPECT_EQ(count(check("LD I1\nTON T1 TR1 100\nLD I2\nTON T2 AI1\nLD I3\nTOFF T3 V5\n"
                          "LD I4\nTONR T4 SMW30\nLD I1\nLD I2\nLD I3\nMUP C1 TR2\nEND"),
                    "OP005"),
              0);
    const std::vector<Diagnostic> found = check("LD I1\nTON T1 C1 100\nLD I1\nLD I2\nLD I3\n"
                                                "MUP C2 T5\nEND");
    ASSERT_EQ(count(found, "OP005"), 2);
    bool named = false;
    for (const Diagnostic &d : found)
        named = named || d.message.contains(QLatin1String("from V, SM, AI, TR, not C1"));
    EXPECT_TRUE(named);
}

TEST(Pl110Trimmers, TrIsAReadOnlyWordArea) {
    const Address tr = at("TR1");
    EXPECT_FALSE(pl110().area(tr.area).writable);
    EXPECT_TRUE(addressError("TR5").contains(QLatin1String("TR1..TR4")));
    EXPECT_EQ(count(check("LD I1\nMOV 5 TR1\nEND"), "OP002"), 1);
    EXPECT_EQ(count(check("LD I1\nMOV TR1 V0\nEND"), "OP002"), 0);
}

TEST(Pl110Sm013, TimersFrom49AreTheirOwnAreaGatedBySm013) {
    const Area &t49 = pl110().area(at("T49").area);
    ASSERT_NE(t49.enabledBy, nullptr);
    EXPECT_EQ(QString::fromLatin1(t49.enabledBy), QStringLiteral("SM0.13"));
    EXPECT_TRUE(t49.enabledWhenOn);
    const Area &c = pl110().area(at("C1").area);
    ASSERT_NE(c.enabledBy, nullptr);
    EXPECT_FALSE(c.enabledWhenOn);
    EXPECT_EQ(pl110().area(at("T48").area).enabledBy, nullptr);
    // T49's preset is PT49, as T1's is PT1.
    EXPECT_STREQ(pl110().area(at("PT49").area).presetsOf, "T49");
}

// OP006 (2.1.2): T49..T64 run only with SM0.13 ON, C1..C16 only with it OFF.
TEST(Pl110Sm013, ATimerThatNothingSwitchesOnIsAWarning) {
    std::vector<Diagnostic> found = check("LD I1\nTON T49 5\nEND");
    ASSERT_EQ(count(found, "OP006"), 1);
    for (const Diagnostic &d : found)
        if (d.code == QLatin1String("OP006")) {
            EXPECT_EQ(d.severity, Severity::Warning);
            EXPECT_EQ(d.location.line, 2);
            EXPECT_EQ(d.message, QStringLiteral("T49 runs only while SM0.13 is ON, and no "
                                                "instruction sets SM0.13"));
        }
    EXPECT_EQ(count(check("LD I2\nOUT SM0.13\nLD I1\nTON T49 5\nEND"), "OP006"), 0);
    EXPECT_EQ(count(check("LD I2\nSBIT SM0 13\nLD I1\nTON T64 5\nEND"), "OP006"), 0);
    EXPECT_EQ(count(check("LD I1\nTON T48 5\nEND"), "OP006"), 0);
}

TEST(Pl110Sm013, ACounterBesideAWriteOfSm013IsAWarning) {
    std::vector<Diagnostic> found = check("LD I2\nSBIT SM0 13\nLD I1\nLD I2\nLD I3\nMUP C1 5\nEND");
    ASSERT_EQ(count(found, "OP006"), 1);
    for (const Diagnostic &d : found)
        if (d.code == QLatin1String("OP006")) {
            EXPECT_EQ(d.location.line, 6);
            EXPECT_TRUE(
                d.message.contains(QLatin1String("C1 stops while SM0.13 is ON, and line 2")))
                << d.message.toStdString();
            ASSERT_EQ(d.related.size(), 1u);
            EXPECT_EQ(d.related[0].line, 2);
        }
    EXPECT_EQ(count(check("LD I1\nLD I2\nLD I3\nMUP C1 5\nLD I1\nTON T1 5\nEND"), "OP006"), 0);
}

// Issue 14, PL110 manual 2.1.2; issue 30: the display's pages (SM102..SM106), the terminal's
// keys (SM110) and the user pages' fields (SM118..SM185) are simulated now (the front panel
// shows them), and so are the standby (SM100, SM101) and the password (SM109), which the front
// panel's keys model, and the note of the last variable stored from the keys (SM107, SM108);
// what is still plain memory -- here the protocol's line setting SM71 -- is named at each use
// (SIM101), and nothing of the rest of SM.
TEST(Pl110Checks, DisplayKeyAndPortMarkersWarn) {
    const char *program = "LD SM0.1\n"      // 1 first scan: no warning
                          "SBIT SM103.0\n"  // 2 user page 17 enabled (5.4): simulated
                          "LD= SMW105 17\n" // 3 the page shown: simulated
                          "MOV 17 SM106\n"  // 4 the page request: simulated
                          "LD SM110.1\n"    // 5 the UP key: simulated
                          "OUT M1\n"        // 6
                          "LD SM0.0\n"      // 7
                          "MOV V0 SMD120\n" // 8 parameter 1's number: simulated
                          "LD SM0.0\n"      // 9
                          "MOV 3 SM37\n"    // 10 TEST inputs: simulated
                          "LD SM0.0\n"      // 11
                          "MOV SM111 V1\n"  // 12 not in the manual's table
                          "LD SM0.1\n"      // 13
                          "MOV SM71 V2\n"   // 14 the line setting: plain memory
                          "LD SM0.1\n"      // 15
                          "MOV 50 SM100\n"  // 16 the standby brightness: the front panel's
                          "LD SM0.0\n"      // 17
                          "MOV SM109 V3\n"  // 18 the password: the front panel's
                          "END\n";
    const std::vector<Diagnostic> found = check(program);
    std::vector<std::pair<int, QString>> warned;
    for (const Diagnostic &d : found)
        if (d.code == QLatin1String("SIM101")) {
            EXPECT_EQ(d.severity, Severity::Warning);
            warned.emplace_back(d.location.line, d.message);
        }
    ASSERT_EQ(warned.size(), 1u);
    EXPECT_EQ(warned[0].first, 14);
    EXPECT_TRUE(warned[0].second.startsWith(QLatin1String("SM71 is not simulated: the "
                                                          "protocol's baud rate")))
        << warned[0].second.toStdString();
    EXPECT_EQ(count(found, "SIM100"), 0);
    // With the source at hand the column is the device's, for the editor's marker.
    const QString text = QString::fromLatin1(program);
    CheckOptions options;
    options.source = &text;
    const std::vector<Diagnostic> placed =
        checkList(parseInstructionList(pl110(), text).list, options);
    const auto sm71 = std::find_if(placed.begin(), placed.end(), [](const Diagnostic &d) {
        return d.code == QLatin1String("SIM101") && d.location.line == 14;
    });
    ASSERT_NE(sm71, placed.end());
    EXPECT_EQ(sm71->location.column, 5);
}

// Issue 14, PL110 manual 2.1.2: every special-marker word behind hardware the simulator does not
// have is named at `check` time, first and last word of each range: the timed interrupts'
// intervals SM16 / SM17 ("Intervallo dell'interrupt a tempo n° 1"), the clock SM9..SM15, the
// encoders SM20..SM31 and SM2, the protocol address SM4 / SM5, filters and analog
// configuration SM38..SM69, the protocols' line settings SM71 / SM72, SM81 / SM82 and COM2's
// slave markers SM90..SM97; SM32..SM36, which 4.2.19 names for free-port against the table. What
// the simulator models (SM0, SM6..SM8 scan time, SM37 TEST inputs, the COM / EXP and free-port
// markers SM70, SM73..SM80, SM83..SM89, SM98, SM99) and the faults SM1 (no fault in a
// simulation) stay quiet.
TEST(Pl110Checks, HardwareAndInterruptMarkersWarnWhereTheyAreUsed) {
    const std::pair<const char *, const char *> warned[] = {
        {"SM16", "the timed interrupts"},
        {"SM17", "the timed interrupts"},
        {"SM18", "ramp"},
        {"SM2", "encoders' load bits"},
        {"SM4", "protocol address"},
        {"SM5", "rotary switch"},
        {"SM9", "real-time clock"},
        {"SM15", "real-time clock"},
        {"SM20", "encoders"},
        {"SM31", "encoders"},
        {"SM38", "input filters"},
        {"SM69", "analog settings"},
        {"SM71", "baud rate and format"},
        {"SM82", "baud rate and format"},
        {"SM90", "COM2 runs the MODBUS slave only"},
        {"SM97", "COM2 runs the MODBUS slave only"},
        {"SM32", "4.2.19 names SM32..SM34 for free-port"},
        {"SM36", "SM78 / SM88 / SM98"},
    };
    for (const auto &[device, phrase] : warned) {
        const QString text = QStringLiteral("LD SM0.0\nMOV 10 %1\nEND").arg(QLatin1String(device));
        const ParseResult r = parseInstructionList(pl110(), text);
        ASSERT_TRUE(r.ok()) << device;
        std::vector<Diagnostic> found;
        for (const Diagnostic &d : checkList(r.list))
            if (d.code == QLatin1String("SIM101"))
                found.push_back(d);
        ASSERT_EQ(found.size(), 1u) << device;
        EXPECT_EQ(found[0].location.line, 2) << device;
        EXPECT_EQ(found[0].severity, Severity::Warning);
        EXPECT_TRUE(found[0].message.startsWith(QLatin1String(device) +
                                                QLatin1String(" is not simulated: ")))
            << found[0].message.toStdString();
        EXPECT_TRUE(found[0].message.contains(QLatin1String(phrase)))
            << device << ": " << found[0].message.toStdString();
    }
    // A bit of an interval word and the double word over the encoder count warn as well.
    EXPECT_EQ(count(check("LD SM17.3\nOUT Q1\nEND"), "SIM101"), 1);
    EXPECT_EQ(count(check("LD SM0.0\nMOV SMD22 VD0\nEND"), "SIM101"), 1);
    for (const char *quiet : {"SM1", "SM3", "SM6", "SM8", "SM19", "SM37", "SM70", "SM73", "SM79",
                              "SM80", "SM88", "SM98", "SM99"}) {
        const QString text = QStringLiteral("LD SM0.0\nMOV %1 V0\nEND").arg(QLatin1String(quiet));
        EXPECT_EQ(count(checkList(parseInstructionList(pl110(), text).list), "SIM101"), 0) << quiet;
    }
}

// Issue 14: what the PL110 simulator does not model among the instructions (PID, POS, RANGE
// scaling) is named by `check` at each use (SIM100), the instruction's own mnemonic in the
// message, not only when simulating.
TEST(Pl110Checks, EveryInstructionNotSimulatedWarnsAtCheckTime) {
    // SEND, COM and EXP are simulated (docs/network.md), and the display fields' SetPAR,
    // FormatPAR and PosPAR (issue 30).
    QStringList expected = {"RANGE", "TunePOS",   "POS",    "StartPID",
                            "PID",   "SetOutPID", "GENSET", "CONV"};
    QStringList seen;
    for (const InstructionSpec &spec : pl110().instructions) {
        if (spec.function != ApplyFunction::NotSimulated)
            continue;
        seen << spec.mnemonic;
        // MOVTXT takes a text (4.2.10): D, characters per word, "TEXT".
        const QString operands =
            spec.operands.size() == 3 && spec.operands[2].kind == OperandKind::Text
                ? QStringLiteral("V1 1 \"A\"")
                : QStringLiteral("V1 V2");
        const QString text =
            QStringLiteral("LD I1\n%1 %2\nLD I2\nOUT Q1\nEND").arg(spec.mnemonic, operands);
        const ParseResult r = parseInstructionList(pl110(), text);
        ASSERT_TRUE(r.ok()) << spec.mnemonic.toStdString();
        std::vector<Diagnostic> found;
        for (const Diagnostic &d : checkList(r.list))
            if (d.code == QLatin1String("SIM100"))
                found.push_back(d);
        ASSERT_EQ(found.size(), 1u) << spec.mnemonic.toStdString();
        EXPECT_EQ(found[0].severity, Severity::Warning);
        EXPECT_EQ(found[0].location.line, 2);
        EXPECT_EQ(found[0].message,
                  spec.mnemonic +
                      QLatin1String(" is not simulated: it does nothing in the simulator"));
    }
    seen.sort();
    expected.sort();
    EXPECT_EQ(seen, expected);
}
