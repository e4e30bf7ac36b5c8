// The CPM1's application instructions as the listing, the checks and the converter know them
// (issue 14): the function codes of Omron's CPM1 programming manual W353, the "@" forms, the
// LR link relays and the guide's "TC" bank (Omron CPM1 guide 3.5 Memóriatérkép), and the
// operand rules `check` gives where the simulator would refuse.

#include "model/checks/checks.h"
#include "model/convert/convert.h"
#include "model/ladder/ladder_text.h"
#include "model/listing/il.h"
#include "model/listing/structure.h"
#include "model/target/word_text.h"
#include "tests/targets.h"

#include <gtest/gtest.h>

using namespace rung::model;

namespace {

using rung::testing::cpm1;

QString text(const char *semicolonSeparated) {
    return QString::fromLatin1(semicolonSeparated).replace(QLatin1Char(';'), QLatin1Char('\n'));
}

ParseResult parseCpm1(const char *listing) {
    return parseInstructionList(cpm1(), text(listing));
}

std::vector<Diagnostic> check(const char *listing) {
    const ParseResult parsed = parseCpm1(listing);
    EXPECT_TRUE(parsed.ok()) << (parsed.errors.empty() ? ""
                                                       : parsed.errors[0].message.toStdString());
    return checkList(parsed.list);
}

const Diagnostic *find(const std::vector<Diagnostic> &ds, const char *code) {
    for (const Diagnostic &d : ds)
        if (d.code == QLatin1String(code))
            return &d;
    return nullptr;
}

QString all(const std::vector<Diagnostic> &ds) {
    QString s;
    for (const Diagnostic &d : ds)
        s += QStringLiteral("%1 %2: %3\n").arg(d.code).arg(d.location.line).arg(d.message);
    return s;
}

} // namespace

// W353's function codes, each one also accepted bare and, where W353 has it, with "@".
TEST(Cpm1Instructions, FunctionCodesAsW353GivesThem) {
    const std::pair<const char *, int> codes[] = {
        {"STEP", 8},  {"SNXT", 9}, {"SFT", 10},  {"WSFT", 16}, {"CMP", 20},  {"MOV", 21},
        {"MVN", 22},  {"BIN", 23}, {"BCD", 24},  {"COM", 29},  {"ADD", 30},  {"SUB", 31},
        {"MUL", 32},  {"DIV", 33}, {"ANDW", 34}, {"ORW", 35},  {"XORW", 36}, {"INC", 38},
        {"DEC", 39},  {"STC", 40}, {"CLC", 41},  {"ADB", 50},  {"SBB", 51},  {"MOVB", 82},
        {"MOVD", 83}, {"SBS", 91}, {"SBN", 92},  {"RET", 93}};
    for (const auto &[name, code] : codes) {
        const InstructionSpec *bare = cpm1().findInstruction(QString::fromLatin1(name));
        ASSERT_NE(bare, nullptr) << name;
        EXPECT_EQ(bare->functionCode, code) << name;
        EXPECT_FALSE(bare->differentiated) << name;
        EXPECT_EQ(
            bare->mnemonic,
            QStringLiteral("%1(%2)").arg(QLatin1String(name)).arg(code, 2, 10, QLatin1Char('0')));
        EXPECT_EQ(cpm1().findInstruction(bare->mnemonic), bare);
        // A wrong code is no such instruction ("MOV(22)" is not MOV).
        EXPECT_EQ(
            cpm1().findInstruction(QStringLiteral("%1(%2)").arg(QLatin1String(name)).arg(code + 1)),
            nullptr)
            << name;
    }
}

TEST(Cpm1Instructions, DifferentiatedFormsExistWhereW353HasThem) {
    for (const char *name :
         {"MOV", "MVN", "MOVB", "MOVD", "WSFT", "BIN", "BCD", "COM", "ANDW", "ORW", "XORW",
          "INC", "DEC", "ADD",  "SUB",  "MUL",  "DIV", "ADB", "SBB", "STC",  "CLC", "SBS"}) {
        const InstructionSpec *at =
            cpm1().findInstruction(QStringLiteral("@") + QLatin1String(name));
        ASSERT_NE(at, nullptr) << name;
        EXPECT_TRUE(at->differentiated) << name;
        EXPECT_TRUE(at->mnemonic.startsWith(QLatin1Char('@'))) << name;
        EXPECT_EQ(at->function, cpm1().findInstruction(QLatin1String(name))->function) << name;
    }
    // No "@" form: CMP, SFT (driven by its shift pulse), the step and subroutine markers.
    for (const char *name : {"CMP", "SFT", "STEP", "SNXT", "SBN", "RET", "KEEP", "TIM"})
        EXPECT_EQ(cpm1().findInstruction(QStringLiteral("@") + QLatin1String(name)), nullptr)
            << name;
}

TEST(Cpm1Instructions, ListingRoundTripsEveryNewForm) {
    const char *listing = "LD 000.00;@MOV(21) #0012 DM 0000;LD 000.01;MVN(22) 200 HR00;"
                          "LD 253.13;MOVB(82) 200 #1203 201;MOVD(83) 200 #0210 202;"
                          "CMP(20) DM 0000 #0100;CLC(41);ADD(30) LR00 #6103 DM 0100;"
                          "SUB(31) DM 0100 #0001 DM 0101;MUL(32) DM 0100 #0002 DM 0102;"
                          "DIV(33) DM 0102 #0003 DM 0104;ADB(50) 200 #00FF 203;"
                          "SBB(51) 200 #0001 204;@INC(38) HR01;DEC(39) HR02;STC(40);"
                          "LD 000.02;LD 000.03;LD 000.04;SFT(10) 210 211;"
                          "LD 000.05;WSFT(16) DM 0010 DM 0012;LD 000.06;SBS(91) 05;"
                          "LD 000.07;SNXT(09) LR00.00;STEP(08) LR00.00;LD 000.08;OUT 010.00;"
                          "LD 000.09;SNXT(09) LR00.01;STEP(08);SBN(92) 05;LD 253.13;"
                          "OUT 010.01;RET(93);END(01)";
    const ParseResult p = parseCpm1(listing);
    ASSERT_TRUE(p.ok()) << p.errors.front().line << ": " << p.errors.front().message.toStdString();
    const QString printed = printInstructionList(p.list);
    EXPECT_TRUE(printed.contains(QStringLiteral("@MOV(21) #0012 DM 0000")))
        << printed.toStdString();
    EXPECT_TRUE(printed.contains(QStringLiteral("SBS(91) 05"))) << printed.toStdString();
    EXPECT_TRUE(printed.contains(QStringLiteral("STEP(08) LR00.00\n"))) << printed.toStdString();
    EXPECT_TRUE(printed.contains(QStringLiteral("STEP(08)\n"))) << printed.toStdString();
    const ParseResult again = parseInstructionList(cpm1(), printed);
    ASSERT_TRUE(again.ok());
    ASSERT_EQ(again.list.instructions.size(), p.list.instructions.size());
    for (std::size_t k = 0; k < p.list.instructions.size(); ++k)
        EXPECT_TRUE(again.list.instructions[k].sameAs(p.list.instructions[k])) << k;
    EXPECT_TRUE(check(listing).empty()) << all(check(listing)).toStdString();
}

// Omron CPM1 guide 3.5: "Időrelék/számlálók TC - terület TC000-TC127": TC names the bank, so
// TC 005 is the counter CNT 005 when the program counts with it, the timer TIM 005 when it
// times.
TEST(Cpm1Instructions, TcNamesTheTimerOrTheCounterTheProgramDefines) {
    const ParseResult p = parseCpm1("LD 000.00;LD 000.01;CNT 005 #0003;LD TC 005;OUT 010.00;"
                                    "LD 000.02;TIM 006 #0010;LD TC006;OUT 010.01;"
                                    "LD 253.13;MOV(21) TC 005 DM 0000;END(01)");
    ASSERT_TRUE(p.ok()) << p.errors.front().message.toStdString();
    const QString printed = printInstructionList(p.list);
    EXPECT_TRUE(printed.contains(QStringLiteral("LD CNT 005"))) << printed.toStdString();
    EXPECT_TRUE(printed.contains(QStringLiteral("LD TIM 006"))) << printed.toStdString();
    EXPECT_TRUE(printed.contains(QStringLiteral("MOV(21) CNT 005 DM 0000")))
        << printed.toStdString();
    // No bank conflict (OP003): TC 005 is the counter, not a second use as a timer.
    const ParseResult again = parseInstructionList(cpm1(), printed);
    ASSERT_TRUE(again.ok());
    EXPECT_TRUE(checkList(again.list).empty()) << all(checkList(again.list)).toStdString();
    EXPECT_FALSE(parseCpm1("LD TC 128;OUT 010.00;END(01)").ok()); // beyond TC000..TC127
}

// W353 / Omron CPM1 guide: LR 00..15, bits LR 00.00..LR 15.15; the guide writes bits as
// LR0005 too.
TEST(Cpm1Instructions, LinkRelaysAreChannelsWithBits) {
    const ParseResult p =
        parseCpm1("LD LR 00.05;OUT LR1504;LD LR0005;MOV(21) LR 03 DM 0000;END(01)");
    ASSERT_TRUE(p.ok()) << p.errors.front().message.toStdString();
    EXPECT_EQ(printInstructionList(p.list),
              QStringLiteral("LD LR00.05\nOUT LR15.04\nLD LR00.05\nMOV(21) LR03 DM 0000\n"
                             "END(01)\n"));
    const ParseResult beyond = parseCpm1("LD LR16.00;OUT 010.00;END(01)");
    ASSERT_FALSE(beyond.ok());
    EXPECT_TRUE(beyond.errors.front().message.contains(QStringLiteral("LR00..LR15")))
        << beyond.errors.front().message.toStdString();
}

// The operand rules W353 gives, as `check` errors (OP005) with their place; the simulator
// refuses the same (tests/simulator/test_cpm1.cpp).
TEST(Cpm1Instructions, OperandRulesOfW353AreCheckErrors) {
    struct Case {
        const char *listing;
        const char *words; // in the message
    };
    const Case cases[] = {
        // BCD operands: a # constant with a hexadecimal digit is no BCD number.
        {"LD 000.00;ADD(30) DM 0000 #12A4 DM 0001;END(01)", "BCD"},
        {"LD 000.00;BIN(23) #00FF DM 0001;END(01)", "BCD"},
        // MOVB(82) Bi: bits 00..15; MOVD(83) Di: digits 0..3.
        {"LD 000.00;MOVB(82) 200 #0016 201;END(01)", "#DDSS"},
        {"LD 000.00;MOVD(83) 200 #0400 201;END(01)", "#0DNS"},
        // SFT(10) / WSFT(16): E in St's area and not before it; SFT only on channels with bits.
        {"LD 000.00;LD 000.01;LD 000.02;SFT(10) 201 200;END(01)", "not before"},
        {"LD 000.00;WSFT(16) 200 HR01;END(01)", "not before"},
        {"LD 000.00;LD 000.01;LD 000.02;SFT(10) DM 0000 DM 0001;END(01)", "channel with bits"},
        // MUL(32) / DIV(33) write R and R+1 in R's area.
        {"LD 000.00;MUL(32) #0002 #0003 DM 1023;END(01)",
         "DM 1023..DM 1024, but DM 1024 does not exist"},
        // Subroutine numbers 00..49.
        {"LD 000.00;SBS(91) 50;END(01)", "0 to 49"},
    };
    for (const Case &c : cases) {
        const auto found = check(c.listing);
        const Diagnostic *d = find(found, "OP005");
        ASSERT_NE(d, nullptr) << c.listing << "\n" << all(found).toStdString();
        EXPECT_EQ(d->severity, Severity::Error);
        EXPECT_EQ(d->location.line,
                  QString::fromLatin1(c.listing).split(QLatin1Char(';')).size() - 1)
            << c.listing; // the instruction before END(01)
        EXPECT_TRUE(d->message.contains(QLatin1String(c.words))) << d->message.toStdString();
    }
    // Their clean twins.
    for (const char *clean :
         {"LD 000.00;ADD(30) DM 0000 #1294 DM 0001;END(01)",
          "LD 000.00;MOVB(82) 200 #1500 201;END(01)", "LD 000.00;MOVD(83) 200 #0333 201;END(01)",
          "LD 000.00;LD 000.01;LD 000.02;SFT(10) 200 201;END(01)",
          "LD 000.00;WSFT(16) DM 0000 DM 0002;END(01)",
          "LD 000.00;MUL(32) #0002 #0003 DM 1022;END(01)"})
        EXPECT_TRUE(check(clean).empty()) << clean << "\n" << all(check(clean)).toStdString();
}

// The flags are the PLC's: a program reads them, only the instructions write them (OP002).
TEST(Cpm1Instructions, FlagsAreReadOnlySystemBits) {
    EXPECT_TRUE(check("LD 255.04;OUT 010.00;LD 255.06;OUT 010.01;END(01)").empty());
    const auto found = check("LD 000.00;OUT 255.04;END(01)");
    ASSERT_NE(find(found, "OP002"), nullptr) << all(found).toStdString();
}

// W353 "Subroutines" and "Step Instructions": the structure problems, by code (each with a
// clean twin in tests/model/test_checks.cpp's table).
TEST(Cpm1Instructions, SubroutinesPairByNumberAfterTheMainProgram) {
    const ParseResult p = parseCpm1("LD 000.00;SBS(91) 01;LD 000.01;SBS(91) 02;SBN(92) 01;"
                                    "LD 253.13;OUT 010.00;RET(93);SBN(92) 02;RET(93);END(01)");
    ASSERT_TRUE(p.ok());
    const BlockPairs pairs = pairBlocks(p.list);
    EXPECT_TRUE(pairs.problems.empty());
    EXPECT_EQ(pairs.partner[1], 4); // SBS 01 -> SBN 01
    EXPECT_EQ(pairs.partner[3], 8); // SBS 02 -> SBN 02
    EXPECT_EQ(pairs.partner[4], 7); // SBN 01 .. RET
    EXPECT_EQ(pairs.partner[7], 4);
}

TEST(Cpm1Instructions, StructureProblemsAreNamedInTheFamilysWords) {
    const auto missing = check("LD 000.00;SBS(91) 03;END(01)");
    ASSERT_NE(find(missing, "SB001"), nullptr);
    EXPECT_TRUE(find(missing, "SB001")->message.contains(QStringLiteral("SBN(92) 3")))
        << find(missing, "SB001")->message.toStdString();
    const auto open = check("LD 000.00;SBS(91) 03;SBN(92) 03;LD 253.13;OUT 010.00;END(01)");
    ASSERT_NE(find(open, "SB003"), nullptr);
    EXPECT_TRUE(find(open, "SB003")->message.contains(QStringLiteral("RET(93)")));
    const auto inside = check("LD 000.00;SNXT(09) LR00.00;STEP(08) LR00.00;LD 000.01;IL(02);"
                              "LD 000.02;OUT 010.00;ILC(03);STEP(08);END(01)");
    ASSERT_NE(find(inside, "SP003"), nullptr) << all(inside).toStdString();
    EXPECT_EQ(find(inside, "SP003")->location.line, 5);
}

// An SFT(10) is a box with three inputs (data, shift, reset) as CNTR(12) is; SBN(92), RET(93)
// and STEP(08) stand at the rail. The ladder and back give the same listing.
TEST(Cpm1Instructions, LadderAndBackKeepTheBoxes) {
    const ParseResult p =
        parseCpm1("LD 000.00;LD 000.01;LD 000.02;SFT(10) 200 201;LD 000.03;@ADD(30) DM 0000 #0001 "
                  "DM 0000;LD 000.04;SNXT(09) LR00.00;STEP(08) LR00.00;LD 000.05;OUT 010.00;"
                  "STEP(08);LD 000.06;SBS(91) 00;SBN(92) 00;LD 253.13;OUT 010.01;RET(93);END(01)");
    ASSERT_TRUE(p.ok()) << p.errors.front().message.toStdString();
    const ToLadderResult ladder = listToLadder(p.list);
    ASSERT_TRUE(ladder.ok()) << (ladder.problems.empty()
                                     ? ""
                                     : ladder.problems.front().message.toStdString());
    const ToListingResult back = ladderToList(ladder.ladder);
    ASSERT_TRUE(back.ok());
    EXPECT_EQ(printInstructionList(back.list), printInstructionList(p.list));
    // The ladder text (docs/ladder-text.md) reads back the same boxes.
    const QString drawn = printLadderText(ladder.ladder);
    EXPECT_TRUE(drawn.contains(QStringLiteral("SFT(10) 200 201"))) << drawn.toStdString();
    const LadderTextResult reread = parseLadderText(cpm1(), drawn);
    ASSERT_TRUE(reread.ok()) << reread.errors.front().message.toStdString();
    EXPECT_EQ(printInstructionList(ladderToList(reread.ladder).list), printInstructionList(p.list));
}

// W353's examples keep a branch point in a temporary relay: OUT TR 0 ... LD TR 0. Every
// rung that branches may use TR 0 again, so it is no duplicate coil; an output is.
TEST(Cpm1Instructions, TemporaryRelaysMayBeDrivenInEveryRung) {
    const char *listing = "00000 LD 00002;00001 OUT TR 0;00002 CLC(41);"
                          "00003 ADD(30) 200 #6103 DM 0100;00004 AND 25504;"
                          "00005 MOV(21) #0001 DM 0101;00006 LD TR 0;00007 AND NOT 25504;"
                          "00008 MOV(21) #0000 DM 0101;LD 000.03;OUT TR 0;AND 000.04;"
                          "OUT 010.00;LD TR 0;OUT 010.01;END(01)";
    const ParseResult p = parseCpm1(listing);
    ASSERT_TRUE(p.ok()) << p.errors.front().message.toStdString();
    EXPECT_TRUE(printInstructionList(p.list).startsWith(QStringLiteral("LD 000.02\nOUT TR 0\n")));
    EXPECT_TRUE(check(listing).empty()) << all(check(listing)).toStdString();
    EXPECT_NE(find(check("LD 000.00;OUT 010.00;LD 000.01;OUT 010.00;END(01)"), "DC001"), nullptr);
    EXPECT_FALSE(parseCpm1("LD TR 8;OUT 010.00;END(01)").ok()); // TR 0..7
}

// The CPM1's words are BCD digits (its # constants, its timers' values, W353): the watch list
// shows and takes them as #0012; the other families keep numbers.
TEST(Cpm1Instructions, WordsAreShownAndTypedAsTheirDigits) {
    EXPECT_EQ(formatWord(cpm1(), 0x0012), QStringLiteral("#0012"));
    EXPECT_EQ(formatWord(cpm1(), static_cast<std::int16_t>(0x9999)), QStringLiteral("#9999"));
    EXPECT_EQ(parseWordValue(cpm1(), QStringLiteral("#0012")), 0x12);
    EXPECT_EQ(parseWordValue(cpm1(), QStringLiteral("18")), 18);
    EXPECT_EQ(parseWordValue(cpm1(), QStringLiteral("0x1F")), 0x1F);
    EXPECT_FALSE(parseWordValue(cpm1(), QStringLiteral("#12345")));
    EXPECT_FALSE(parseWordValue(cpm1(), QStringLiteral("#")));
    const Target &vigor = Target::get(Family::Vigor);
    EXPECT_EQ(formatWord(vigor, 18), QStringLiteral("18"));
    EXPECT_EQ(formatWord(vigor, -3), QStringLiteral("-3"));
    EXPECT_FALSE(parseWordValue(vigor, QStringLiteral("#0012")));
}
