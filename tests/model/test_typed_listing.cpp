// The instruction list typed back: the marked lines that stand for what the list cannot say
// put it back (model/convert/typed_listing.h), read here without a display.

#include "model/convert/typed_listing.h"
#include "model/ladder/ladder_text.h"
#include "model/target/address.h"
#include "tests/targets.h"

#include <QFile>

#include <gtest/gtest.h>

using namespace rung::model;
using rung::testing::vigor;

namespace {

Rung bridge() {
    QFile f(QStringLiteral(RUNG_TEST_DATA_DIR "/ladder/bridge.ladder"));
    EXPECT_TRUE(f.open(QIODevice::ReadOnly));
    const LadderTextResult r = parseLadderText(vigor(), QString::fromUtf8(f.readAll()));
    EXPECT_TRUE(r.ok());
    return r.ladder.rungs.at(0);
}

} // namespace

TEST(TypedListing, AMarkedLinePutsItsRungBackWhereItStands) {
    HeldRungs held;
    const Rung drawn = bridge();
    const QString key = holdRung(held, vigor(), 4, drawn);
    EXPECT_TRUE(key.startsWith(QStringLiteral("5:"))) << key.toStdString();
    EXPECT_EQ(placeholderKey(QStringLiteral("; [[%1]] Rung 5 is not in the list").arg(key)), key);
    EXPECT_EQ(placeholderKey(QStringLiteral("; Rung 5")), QString());
    const QString text = QStringLiteral("LD X0\nOUT Y0\n; [[%1]] whatever the language\nLD X1\n"
                                        "OUT Y1\nEND\n")
                             .arg(key);
    const TypedListing typed = readTypedListing(vigor(), nullptr, text, held);
    ASSERT_TRUE(typed.rungs.has_value());
    ASSERT_EQ(typed.rungs->size(), 4u); // X0, the bridge, X1, END
    EXPECT_EQ((*typed.rungs)[1], drawn);
    EXPECT_TRUE(typed.findings.empty());
}

TEST(TypedListing, ALineForARungThisListNeverShowedIsAnErrorNotALostRung) {
    const TypedListing typed = readTypedListing(
        vigor(), nullptr, QStringLiteral("LD X0\n; [[7:abcdef]] pasted\nOUT Y0\nEND\n"), {});
    EXPECT_FALSE(typed.rungs.has_value());
    ASSERT_EQ(typed.findings.size(), 1u);
    EXPECT_EQ(typed.findings[0].code, QStringLiteral("SYN001"));
    EXPECT_EQ(typed.findings[0].location.line, 2);
    EXPECT_EQ(typed.findings[0].message,
              QStringLiteral("This line stood for a rung of another program: delete the line "
                             "or undo the paste"));
}

TEST(TypedListing, AKeptContactGoesBackIntoTheRungBelowItsLine) {
    // X5 stands on no path to an output: the list leaves it out and a marked line keeps it.
    QString error;
    Rung drawn(2, 2);
    drawn.cell(0, 0) = {CellKind::Contact, *contactFromText(vigor(), QStringLiteral("X0"), &error)};
    drawn.cell(0, 1).kind = CellKind::Wire;
    drawn.cell(1, 1) = {CellKind::Contact, *contactFromText(vigor(), QStringLiteral("X5"), &error)};
    Instruction out;
    out.spec = vigor().findInstruction(QStringLiteral("OUT"));
    Operand y0;
    y0.address = std::get<Address>(parseAddress(vigor(), QStringLiteral("Y0")));
    out.operands = {y0};
    drawn.outputs[0] = out;
    LadderProgram program;
    program.target = &vigor();
    program.rungs = {drawn};
    const ToListingResult listing = ladderToList(program);
    ASSERT_EQ(leftOutContacts(drawn, 0, listing), (std::vector<std::pair<int, int>>{{1, 1}}));
    EXPECT_EQ(contactName(vigor(), drawn.cell(1, 1).contact), QStringLiteral("X5"));
    HeldRungs held;
    const QString key = holdRung(held, vigor(), 0, drawn);
    const TypedListing kept = readTypedListing(
        vigor(), nullptr, QStringLiteral("; [[%1@2,2]] X5\nLD X0\nOUT Y0\n").arg(key), held);
    ASSERT_TRUE(kept.rungs.has_value());
    ASSERT_EQ(kept.rungs->size(), 1u);
    EXPECT_EQ((*kept.rungs)[0], drawn);
    // The line deleted, the contact goes.
    const TypedListing dropped =
        readTypedListing(vigor(), nullptr, QStringLiteral("LD X0\nOUT Y0\n"), held);
    ASSERT_TRUE(dropped.rungs.has_value());
    ASSERT_EQ(dropped.rungs->size(), 1u);
    EXPECT_EQ((*dropped.rungs)[0].rows, 1);
}
