// PLCopen files other tools wrote (tests/data/plcopen/foreign, README there: OpenPLC Editor's
// and Beremiz's own examples, verbatim), imported as a user would: first the variables without
// a device and the devices proposed, then with those proposals as the mapping file. Each
// result is asserted whole: the listing, every element not imported with its line, the notes.

#include "model/convert/convert.h"
#include "model/exchange/plcopen.h"

#include "tests/model/plcopen_test_util.h"
#include "tests/targets.h"

#include <gtest/gtest.h>

using namespace rung::model;
using rung::testing::cpm1;
using rung::testing::issues;
using rung::testing::listing;
using rung::testing::pl110;
using rung::testing::readTestFile;
using rung::testing::vigor;

namespace {

QByteArray foreignFile(const char *name) {
    const QByteArray xml =
        readTestFile(QStringLiteral(RUNG_TEST_DATA_DIR "/plcopen/foreign/") + QLatin1String(name));
    EXPECT_FALSE(xml.isEmpty()) << name;
    return xml;
}

// The devices proposed, as the mapping file the tool prints and the import dialog fills.
DeviceMapping proposals(const PlcopenImport &r) {
    DeviceMapping m;
    for (const UnmappedVariable &u : r.unmapped)
        m.devices[u.name] = u.proposed;
    return m;
}

// Imported twice, as a user does: the first time lists only variables without a device (what
// waits for them is not listed besides); the second takes the proposals.
PlcopenImport importWithProposals(const QByteArray &xml, const Target &t, const char *unmapped) {
    const PlcopenImport first = importPlcopen(xml, t, nullptr);
    EXPECT_TRUE(first.project);
    EXPECT_EQ(issues(first), unmapped) << t.id.toStdString();
    return importPlcopen(xml, t, nullptr, proposals(first));
}

const char *const kBlinkComment =
    "This example cascades two timers (TON and TOF) to generate a square wave. The width of the "
    "wave is determined by the size of the PT variable on both timers.";

} // namespace

// OpenPLC Editor's Blink: a TON and a TOF in cascade, each with EN (the rail, and the TON's
// ENO), a negated contact, a coil from the TOF's Q, the rail closed on the TOF's ENO, a comment
// in CDATA, variables without an address and no executionOrderId on most elements.
TEST(PlcopenForeign, OpenPlcBlinkOnTheVigorAndTheCpm1TakesTheTonAndListsTheTof) {
    const QByteArray xml = foreignFile("openplc-blink.xml");
    PlcopenImport r = importWithProposals(xml, vigor(),
                                          "28: unmapped TON0 -> T0\n"
                                          "33: unmapped TOF0 -> T1\n"
                                          "23: unmapped blink_led -> M0\n");
    ASSERT_TRUE(r.project);
    EXPECT_EQ(listing(*r.project), QStringLiteral("LDI M0\nTMR T0 K5\nEND\n"));
    // Neither PLC has an off-delay timer: the TOF is listed, and the coil its Q drives.
    EXPECT_EQ(issues(r), "226: block TOF: Vigor has no TOF timer that times 500 ms on T1\n"
                         "290: coil blink_led: its power comes from block TOF (line 226), which "
                         "is not imported\n");
    EXPECT_EQ(r.project->program.rungs.front().comment, QLatin1String(kBlinkComment));
    EXPECT_TRUE(r.notes.isEmpty());

    r = importWithProposals(xml, cpm1(),
                            "28: unmapped TON0 -> TIM 000\n"
                            "33: unmapped TOF0 -> TIM 001\n"
                            "23: unmapped blink_led -> 200.00\n");
    ASSERT_TRUE(r.project);
    EXPECT_EQ(listing(*r.project), QStringLiteral("LD NOT 200.00\nTIM 000 #0005\nEND(01)\n"));
    EXPECT_EQ(issues(r), "226: block TOF: CPM1 has no TOF timer that times 500 ms on TIM 001\n"
                         "290: coil blink_led: its power comes from block TOF (line 226), which "
                         "is not imported\n");
}

// The PL110 has TOFF (PL110 manual 4.2.4): all of Blink is imported.
TEST(PlcopenForeign, OpenPlcBlinkOnThePl110ImportsWhole) {
    const PlcopenImport r = importWithProposals(foreignFile("openplc-blink.xml"), pl110(),
                                                "28: unmapped TON0 -> T1\n"
                                                "33: unmapped TOF0 -> T2\n"
                                                "23: unmapped blink_led -> M1\n");
    ASSERT_TRUE(r.complete()) << issues(r);
    EXPECT_EQ(listing(*r.project), QStringLiteral("LDN M1\nTON T1 5 100\n"
                                                  "LD T1\nTOFF T2 5 100\n"
                                                  "LD T2\nOUT M1\nEND\n"));
    // The variables' names are the devices' symbols.
    ASSERT_EQ(r.project->symbols.size(), 3u);
    EXPECT_EQ(r.project->symbols[0].name, QStringLiteral("blink_led"));
}

// OpenPLC Editor's Arduino 7 segments: the Blink timers, and a CTU whose CU is marked
// edge="rising", R from a contact of its own Q's coil, PV a literal, CV to an external
// variable no configuration declares.
TEST(PlcopenForeign, OpenPlc7SegmentsCounterIsEachTargetsCounter) {
    const QByteArray xml = foreignFile("openplc-7-segments.xml");
    PlcopenImport r = importWithProposals(xml, vigor(),
                                          "28: unmapped TON0 -> T0\n"
                                          "33: unmapped TOF0 -> T1\n"
                                          "47: unmapped CTU0 -> C0\n"
                                          "23: unmapped square_wave -> M0\n"
                                          "52: unmapped ctu_reset -> M1\n"
                                          "40: unmapped current_count -> D0\n");
    ASSERT_TRUE(r.project);
    EXPECT_EQ(listing(*r.project), QStringLiteral("LDI M0\nTMR T0 K2\n"
                                                  "LD M0\nCNT C0 K10\nLD M1\nRST C0\n"
                                                  "LD C0\nOUT M1\n"
                                                  "LD M9000\nMOV C0 D0\nEND\n"));
    EXPECT_EQ(issues(r), "249: block TOF: Vigor has no TOF timer that times 200 ms on T1\n"
                         "313: coil square_wave: its power comes from block TOF (line 249), "
                         "which is not imported\n");
    EXPECT_EQ(r.notes, QStringList{QStringLiteral(
                           "CTU (CTU0) is imported as Vigor's CNT: Vigor's CNT stops counting at "
                           "its set value, where CV counts on past PV (Q is the same); its reset "
                           "is an RST, which acts where it stands in the program, not when the "
                           "counter runs as R does")});

    // The CPM1's CNT counts down (Omron CPM1 guide, CNT): the bit is CTU's, CV is not. Its
    // timers and counters share one bank: the counter proposed is not a timer's number.
    r = importWithProposals(xml, cpm1(),
                            "28: unmapped TON0 -> TIM 000\n"
                            "33: unmapped TOF0 -> TIM 001\n"
                            "47: unmapped CTU0 -> CNT 002\n"
                            "23: unmapped square_wave -> 200.00\n"
                            "52: unmapped ctu_reset -> 200.01\n"
                            "40: unmapped current_count -> DM 0000\n");
    ASSERT_TRUE(r.project);
    EXPECT_EQ(listing(*r.project), QStringLiteral("LD NOT 200.00\nTIM 000 #0002\n"
                                                  "LD 200.00\nLD 200.01\nCNT 002 #0010\n"
                                                  "LD CNT 002\nOUT 200.01\nEND(01)\n"));
    EXPECT_EQ(issues(r), "249: block TOF: CPM1 has no TOF timer that times 200 ms on TIM 001\n"
                         "313: coil square_wave: its power comes from block TOF (line 249), "
                         "which is not imported\n"
                         "441: outVariable current_count: CTU0.CV is not imported: CNT 002 "
                         "counts the other way, its present value is not CV\n");
    EXPECT_EQ(r.notes, QStringList{QStringLiteral(
                           "CTU (CTU0) is imported as CPM1's CNT, which counts the other way: its "
                           "bit is CTU's Q once R has been ON, and its present value is not CV")});
    const ToListingResult listed = ladderToList(r.project->program);
    EXPECT_TRUE(listed.ok());

    r = importWithProposals(xml, pl110(),
                            "28: unmapped TON0 -> T1\n"
                            "33: unmapped TOF0 -> T2\n"
                            "47: unmapped CTU0 -> C1\n"
                            "23: unmapped square_wave -> M1\n"
                            "52: unmapped ctu_reset -> M2\n"
                            "40: unmapped current_count -> V0\n");
    ASSERT_TRUE(r.complete()) << issues(r);
    // MUP's DOWN never ON: the RUN bit negated; CV moved every scan under the RUN bit.
    EXPECT_EQ(listing(*r.project), QStringLiteral("LDN M1\nTON T1 2 100\n"
                                                  "LD T1\nTOFF T2 2 100\n"
                                                  "LD T2\nOUT M1\n"
                                                  "LD M1\nLDN SM0.0\nLD M2\nMUP C1 10\n"
                                                  "LD C1\nOUT M2\n"
                                                  "LD SM0.0\nMOV C1 V0\nEND\n"));
    EXPECT_EQ(r.notes.size(), 1);
}

// Beremiz's First Steps: the program is FBD, beside a function and function blocks in ST,
// FBD, SFC, IL and LD. Nothing is a ladder program: every POU and the program's body are
// listed with their lines, and nothing is written.
TEST(PlcopenForeign, BeremizFirstStepsListsEveryPouAndBody) {
    const QByteArray xml = foreignFile("beremiz-first-steps.xml");
    for (const Target *t : {&vigor(), &cpm1()}) {
        const PlcopenImport r = importPlcopen(xml, *t, nullptr);
        EXPECT_FALSE(r.project);
        const QString plc = t->displayName;
        const std::string others =
            QStringLiteral("runs one ladder, with no user functions or function blocks\n")
                .prepend(plc + QLatin1Char(' '))
                .toStdString();
        EXPECT_EQ(issues(r), "20: pou AverageVal: a function is not imported: " + others +
                                 "72: pou plc_prg: the program has no ladder (LD) body\n"
                                 "142: body FBD: a body in FBD is not imported: only ladder (LD) "
                                 "is\n"
                                 "451: pou CounterST: a functionBlock is not imported: " +
                                 others +
                                 "494: pou CounterFBD: a functionBlock is not imported: " + others +
                                 "657: pou CounterSFC: a functionBlock is not imported: " + others +
                                 "910: pou CounterIL: a functionBlock is not imported: " + others +
                                 "963: pou CounterLD: a functionBlock is not imported: " + others)
            << t->id.toStdString();
    }
}

// Every file validates against the schema: they are PLCopen TC6 XML 2.01 as the tools wrote
// them, not edited for the tests.
TEST(PlcopenForeign, TheFilesAreValidPlcopen) {
    QStringList files;
    for (const char *name :
         {"openplc-blink.xml", "openplc-7-segments.xml", "beremiz-first-steps.xml"})
        files << QStringLiteral(RUNG_TEST_DATA_DIR "/plcopen/foreign/") + QLatin1String(name);
    EXPECT_EQ(rung::testing::schemaErrors(files), "");
}
