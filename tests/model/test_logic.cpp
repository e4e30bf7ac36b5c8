// The combinational evaluators (tests/model/logic_oracle.h) that the conversion property tests rely
// on: each is checked here against logic written out by hand.

#include "logic_oracle.h"
#include "model/convert/convert.h"
#include "model/ladder/ladder_text.h"
#include "model/ladder/reverse_current.h"
#include "tests/targets.h"

#include <gtest/gtest.h>

#include <QFile>

#include <map>

using namespace rung::model;

namespace {

using rung::testing::vigor;

Address addr(const char *name) {
    return std::get<Address>(parseAddress(vigor(), QString::fromLatin1(name)));
}

InstructionList vigorProgram(const char *text) {
    ParseResult r = parseInstructionList(vigor(), QString::fromLatin1(text));
    EXPECT_TRUE(r.ok()) << text;
    return r.list;
}

// Inputs named in `names` take the bits of `k` in order; everything else reads 0.
struct Inputs {
    std::map<Address, bool> values;
    Inputs(std::initializer_list<const char *> names, unsigned k) {
        int i = 0;
        for (const char *n : names)
            values[addr(n)] = ((k >> i++) & 1u) != 0;
    }
    bool operator()(const char *n) const { return values.at(addr(n)); }
    BitReader reader() const {
        return [this](const Address &a) {
            const auto it = values.find(a);
            return it != values.end() && it->second;
        };
    }
};

bool out(const OutputImage &image, const char *name) {
    const auto it = image.find(addr(name));
    EXPECT_NE(it, image.end()) << name << " never written";
    return it != image.end() && it->second;
}

LadderProgram ladderFile(const char *name) {
    QFile f(QStringLiteral(RUNG_TEST_DATA_DIR "/ladder/%1").arg(QString::fromLatin1(name)));
    EXPECT_TRUE(f.open(QIODevice::ReadOnly)) << name;
    LadderTextResult r = parseLadderText(vigor(), QString::fromUtf8(f.readAll()));
    EXPECT_TRUE(r.ok());
    return r.ladder;
}

} // namespace

TEST(Logic, ExecutionOrderExampleComputesTheBlocksOfTheManual) {
    // PLC concepts (WPLSoft family) 1.5.1, verbatim.
    const InstructionList list =
        vigorProgram("LD X0\nOR M0\nAND X1\nLD X3\nAND M1\nORB\nLD Y1\nAND X4\n"
                     "LD T0\nAND M3\nORB\nANB\nOUT Y1\nTMR T0 K10\n");
    const LadderProgram ladder = listToLadder(list).ladder;
    const auto names = {"X0", "M0", "X1", "X3", "M1", "Y1", "X4", "T0", "M3"};
    for (unsigned k = 0; k < 512; ++k) {
        const Inputs in(names, k);
        const bool expected = (((in("X0") || in("M0")) && in("X1")) || (in("X3") && in("M1"))) &&
                              ((in("Y1") && in("X4")) || (in("T0") && in("M3")));
        const OutputImage a = evaluateList(list, in.reader());
        EXPECT_EQ(out(a, "Y1"), expected) << k;
        EXPECT_EQ(out(a, "T0"), expected) << k; // the timer's enable input
        EXPECT_EQ(evaluateLadder(ladder, in.reader()), a) << k;
    }
}

TEST(Logic, LaterWritesWinStopFirstAndStartFirst) {
    const InstructionList stopFirst = vigorProgram("LD X0\nSET Y0\nLD X1\nRST Y0\n");
    const InstructionList startFirst = vigorProgram("LD X1\nRST Y0\nLD X0\nSET Y0\n");
    const Inputs both({"X0", "X1"}, 3);
    EXPECT_FALSE(out(evaluateList(stopFirst, both.reader()), "Y0"));
    EXPECT_TRUE(out(evaluateList(startFirst, both.reader()), "Y0"));
    // Neither condition: SET/RST leave the output unwritten.
    const Inputs none({"X0", "X1"}, 0);
    EXPECT_TRUE(evaluateList(stopFirst, none.reader()).empty());
}

TEST(Logic, LaterContactsSeeEarlierOutputsOfTheSamePass) {
    // Y0 written by rung 1 is read by rung 2 in the same scan.
    const InstructionList list = vigorProgram("LD X0\nOUT Y0\nLD Y0\nOUT Y1\n");
    const LadderProgram ladder = listToLadder(list).ladder;
    for (unsigned k = 0; k < 2; ++k) {
        const Inputs in({"X0"}, k);
        const OutputImage a = evaluateList(list, in.reader());
        EXPECT_EQ(out(a, "Y1"), k == 1);
        EXPECT_EQ(evaluateLadder(ladder, in.reader()), a);
    }
}

TEST(Logic, StackBranchesEachSeeTheSavedCondition) {
    const InstructionList list =
        vigorProgram("LD X0\nMPS\nAND X1\nOUT Y0\nMRD\nANI X2\nOUT Y1\nMPP\nOUT Y2\n");
    const LadderProgram ladder = listToLadder(list).ladder;
    for (unsigned k = 0; k < 8; ++k) {
        const Inputs in({"X0", "X1", "X2"}, k);
        const OutputImage a = evaluateList(list, in.reader());
        EXPECT_EQ(out(a, "Y0"), in("X0") && in("X1")) << k;
        EXPECT_EQ(out(a, "Y1"), in("X0") && !in("X2")) << k;
        EXPECT_EQ(out(a, "Y2"), in("X0")) << k;
        EXPECT_EQ(evaluateLadder(ladder, in.reader()), a) << k;
    }
}

TEST(Logic, PowerNeverFlowsRightToLeftThroughABridge) {
    const LadderProgram bridge = ladderFile("bridge.ladder");
    const auto names = {"X0", "X1", "X2", "X3", "X4"};
    for (unsigned k = 0; k < 32; ++k) {
        const Inputs in(names, k);
        // Only the left-to-right paths: X0-X1, X0-X2-X4, X3-X4. The reverse path X3-X2-X1
        // would cross X2 backwards.
        const bool expected =
            (in("X0") && in("X1")) || (in("X0") && in("X2") && in("X4")) || (in("X3") && in("X4"));
        EXPECT_EQ(out(evaluateLadder(bridge, in.reader()), "Y0"), expected) << k;
    }
    // The standard correction keeps exactly that meaning.
    const auto found = findReverseCurrent(bridge.rungs[0]);
    ASSERT_EQ(found.size(), 1u);
    LadderProgram corrected = bridge;
    corrected.rungs = {found[0].corrected};
    const InstructionList list = ladderToList(corrected).list;
    for (unsigned k = 0; k < 32; ++k) {
        const Inputs in(names, k);
        EXPECT_EQ(evaluateLadder(corrected, in.reader()), evaluateLadder(bridge, in.reader()));
        EXPECT_EQ(evaluateList(list, in.reader()), evaluateLadder(bridge, in.reader()));
    }
}

// INV inverts the block so far: in the ladder it conducts exactly when no power reaches it,
// and an INV after another INV sees the first one's result.
TEST(LadderEvaluator, AnInverterConductsWhenNoPowerReachesIt) {
    const InstructionList list =
        vigorProgram("LD X0\nAND X1\nINV\nOUT Y0\nLD X0\nINV\nAND X2\nINV\nOUT Y1\nEND\n");
    const ToLadderResult ladder = listToLadder(list);
    ASSERT_TRUE(ladder.ok());
    for (unsigned k = 0; k < 8; ++k) {
        const Inputs in({"X0", "X1", "X2"}, k);
        const OutputImage fromLadder = evaluateLadder(ladder.ladder, in.reader());
        const OutputImage fromList = evaluateList(list, in.reader());
        EXPECT_EQ(out(fromLadder, "Y0"), !(in("X0") && in("X1"))) << k;
        EXPECT_EQ(out(fromLadder, "Y1"), !(!in("X0") && in("X2"))) << k;
        EXPECT_EQ(fromLadder, fromList) << k;
    }
}

// PL110's P and N are power-flow elements like NOT; the ladder text keeps them apart.
TEST(LadderText, PowerFlowElementsKeepWhichTheyAre) {
    const Target &pl110 = Target::get(Family::Pl110);
    ParseResult parsed =
        parseInstructionList(pl110, QStringLiteral("LD I1\nP\nOUT M1\nLD I1\nN\nOUT M2\nLD "
                                                   "I1\nNOT\nOUT M3\nEND\n"));
    ASSERT_TRUE(parsed.ok());
    const ToLadderResult ladder = listToLadder(parsed.list);
    ASSERT_TRUE(ladder.ok());
    const QString text = printLadderText(ladder.ladder);
    EXPECT_TRUE(text.contains(QStringLiteral("[~P"))) << text.toStdString();
    EXPECT_TRUE(text.contains(QStringLiteral("[~N"))) << text.toStdString();
    const LadderTextResult back = parseLadderText(pl110, text);
    ASSERT_TRUE(back.ok()) << text.toStdString();
    const ToListingResult list = ladderToList(back.ladder);
    ASSERT_TRUE(list.ok());
    EXPECT_EQ(printInstructionList(list.list), printInstructionList(parsed.list));
    QString error;
    EXPECT_FALSE(contactFromText(pl110, QStringLiteral("~Q"), &error).has_value());
    const std::optional<Contact> n = contactFromText(pl110, QStringLiteral("~N"), &error);
    ASSERT_TRUE(n.has_value()) << error.toStdString();
    EXPECT_TRUE(n->invert);
    EXPECT_EQ(n->mode, ContactMode::Falling);
    EXPECT_EQ(contactToText(pl110, *n), QStringLiteral("~N"));
}
