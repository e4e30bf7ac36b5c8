#include "model/comm/port_config.h"
#include "model/listing/il.h"
#include "model/target/address.h"
#include "model/target/target.h"
#include "tests/targets.h"

#include <gtest/gtest.h>

#include <cstring>
#include <set>

// Readable failure output: gtest would print a QString as an array of UTF-16 units.
static void PrintTo(const QString &s, std::ostream *os) {
    *os << '"' << s.toStdString() << '"';
}

using namespace rung::model;

namespace {

using rung::testing::cpm1;
using rung::testing::pl110;
using rung::testing::vigor;
using rung::testing::vpc;

const Area &areaOf(const Target &t, const char *device) {
    const auto r = parseAddress(t, QString::fromLatin1(device));
    if (!std::holds_alternative<Address>(r)) {
        ADD_FAILURE() << device << ": " << std::get<AddressError>(r).message.toStdString();
        static const Area none;
        return none;
    }
    return t.area(std::get<Address>(r).area);
}

const InstructionSpec &spec(const Target &t, const char *mnemonic) {
    const InstructionSpec *s = t.findInstruction(QString::fromLatin1(mnemonic));
    if (!s) {
        ADD_FAILURE() << t.id.toStdString() << " has no " << mnemonic;
        static const InstructionSpec none;
        return none;
    }
    return *s;
}

QString canonical(const Target &t, Op op, ContactMode mode = ContactMode::Normal,
                  CompareOp compare = CompareOp::None, bool negated = false) {
    const InstructionSpec *s = t.findInstruction(op, mode, compare, negated);
    return s ? s->mnemonic : QStringLiteral("(none)");
}

} // namespace

// Table integrity ---------------------------------------------------------------------------

TEST(Targets, AreaKeysAreUniqueAndRangesOrdered) {
    for (Family f : Target::families()) {
        const Target &t = Target::get(f);
        std::set<QString> keys;
        for (const Area &a : t.areas) {
            SCOPED_TRACE((t.id + QLatin1Char(' ') + a.key).toStdString());
            EXPECT_TRUE(keys.insert(a.key).second);
            EXPECT_LE(a.first, a.last);
            EXPECT_NE(a.description, nullptr);
            EXPECT_TRUE(a.wordBits == 8 || a.wordBits == 16 || a.wordBits == 32);
        }
    }
}

TEST(Targets, AreasSharingAPrefixDoNotOverlap) {
    for (Family f : Target::families()) {
        const Target &t = Target::get(f);
        for (std::size_t i = 0; i < t.areas.size(); ++i)
            for (std::size_t j = i + 1; j < t.areas.size(); ++j) {
                const Area &a = t.areas[i];
                const Area &b = t.areas[j];
                if (a.prefix.compare(b.prefix, Qt::CaseInsensitive) != 0)
                    continue;
                SCOPED_TRACE(
                    (t.id + QLatin1Char(' ') + a.key + QLatin1Char('/') + b.key).toStdString());
                EXPECT_TRUE(a.last < b.first || b.last < a.first);
            }
    }
}

TEST(Targets, EveryInstructionHasASummaryAndAMnemonic) {
    for (Family f : Target::families()) {
        const Target &t = Target::get(f);
        EXPECT_FALSE(t.instructions.empty());
        for (const InstructionSpec &s : t.instructions) {
            SCOPED_TRACE((t.id + QLatin1Char(' ') + s.mnemonic).toStdString());
            EXPECT_FALSE(s.mnemonic.isEmpty());
            ASSERT_NE(s.summary, nullptr);
            EXPECT_GT(std::strlen(s.summary), 5u);
            EXPECT_GE(s.steps, 1);
            EXPECT_GE(s.inputs, 1);
        }
    }
}

TEST(Targets, EveryMnemonicAndAliasIsFoundBySpelling) {
    for (Family f : Target::families()) {
        const Target &t = Target::get(f);
        for (const InstructionSpec &s : t.instructions) {
            QStringList names = s.aliases;
            names.prepend(s.mnemonic);
            for (const QString &n : names) {
                SCOPED_TRACE((t.id + QLatin1Char(' ') + n).toStdString());
                const InstructionSpec *found = t.findInstruction(n);
                ASSERT_NE(found, nullptr);
                // Infix variants (VPC compares/transfers) share the plain form's spelling.
                EXPECT_TRUE(found->mnemonic == s.mnemonic || found->aliases.contains(n) ||
                            s.aliases.contains(found->mnemonic));
            }
        }
    }
}

TEST(Targets, NoTwoInstructionsAreTheSameOperation) {
    for (Family f : Target::families()) {
        const Target &t = Target::get(f);
        for (std::size_t i = 0; i < t.instructions.size(); ++i)
            for (std::size_t j = i + 1; j < t.instructions.size(); ++j) {
                const InstructionSpec &a = t.instructions[i];
                const InstructionSpec &b = t.instructions[j];
                SCOPED_TRACE((t.id + QLatin1Char(' ') + a.mnemonic).toStdString());
                EXPECT_FALSE(a.mnemonic == b.mnemonic && a.op == b.op && a.mode == b.mode &&
                             a.compare == b.compare && a.negated == b.negated &&
                             a.transfer == b.transfer);
            }
    }
}

TEST(Targets, SystemDevicesParseIntoSystemAreasOfTheirTarget) {
    for (Family f : Target::families()) {
        const Target &t = Target::get(f);
        EXPECT_FALSE(t.systemDevices.empty());
        for (const SystemDevice &d : t.systemDevices) {
            SCOPED_TRACE((t.id + QLatin1Char(' ') + d.device).toStdString());
            EXPECT_NE(d.description, nullptr);
            const auto r = parseAddress(t, d.device);
            ASSERT_TRUE(std::holds_alternative<Address>(r));
            EXPECT_TRUE(t.area(std::get<Address>(r).area).system);
            EXPECT_EQ(formatAddress(t, std::get<Address>(r)), d.device);
        }
    }
}

TEST(Targets, ModelOverridesNameExistingAreas) {
    for (Family f : Target::families()) {
        const Target &t = Target::get(f);
        for (const ModelVariant &m : t.models)
            for (const ModelVariant::Override &o : m.overrides) {
                bool found = false;
                for (const Area &a : t.areas)
                    found = found || a.key == o.area;
                EXPECT_TRUE(found) << m.name.toStdString() << " " << o.area.toStdString();
            }
        EXPECT_EQ(&t.defaultModel(), &t.models.back());
    }
}

// Devices -----------------------------------------------------------------------------------

TEST(Targets, TimersAndCountersShareABankOnVpcAndCpm1Only) {
    EXPECT_GE(areaOf(vpc(), "t00").bank, 0);
    EXPECT_EQ(areaOf(vpc(), "t00").bank, areaOf(vpc(), "c00").bank);
    EXPECT_GE(areaOf(cpm1(), "TIM 000").bank, 0);
    EXPECT_EQ(areaOf(cpm1(), "TIM 000").bank, areaOf(cpm1(), "CNT 000").bank);
    EXPECT_EQ(areaOf(vigor(), "T0").bank, -1);
    EXPECT_EQ(areaOf(vigor(), "C0").bank, -1);
    EXPECT_EQ(areaOf(pl110(), "T1").bank, -1);
    EXPECT_NE(areaOf(vpc(), "p00").bank, areaOf(vpc(), "t00").bank);
}

TEST(Targets, VpcRetainsTimersCountersRegistersAndR72ToR87) {
    for (const char *d : {"t00", "t31", "c00", "c31", "p00", "p75", "r72", "r87"})
        EXPECT_TRUE(areaOf(vpc(), d).retentive) << d;
    for (const char *d : {"r00", "r71", "r88", "p76", "p77", "i00", "o00"})
        EXPECT_FALSE(areaOf(vpc(), d).retentive) << d;
}

TEST(Targets, VpcInputsAndAnalogInputsAreNeverDestinations) {
    for (const char *d : {"i00", "i39", "a00", "a07", "p77", "r90", "r95"})
        EXPECT_FALSE(areaOf(vpc(), d).writable) << d;
    // Coils may target o00..o29 and r00..r89 (VPC user's manual, III): r88 stops, r89 signals
    // an alarm.
    for (const char *d : {"o00", "r00", "r87", "r88", "r89", "p00", "p76", "d00"})
        EXPECT_TRUE(areaOf(vpc(), d).writable) << d;
    EXPECT_TRUE(areaOf(vpc(), "i00").physical);
    EXPECT_TRUE(areaOf(vpc(), "a00").physical);
    EXPECT_FALSE(areaOf(vpc(), "r00").physical);
}

TEST(Targets, VpcSystemRelaysHaveTheirRoles) {
    EXPECT_EQ(vpc().systemDevice(SystemRole::AlwaysOn)->device, QStringLiteral("r88"));
    EXPECT_EQ(vpc().systemDevice(SystemRole::Error)->device, QStringLiteral("r89"));
    EXPECT_EQ(vpc().systemDevice(SystemRole::Connected)->device, QStringLiteral("r90"));
    EXPECT_EQ(vpc().systemDevice(SystemRole::ScanToggle)->device, QStringLiteral("r92"));
    EXPECT_EQ(vpc().systemDevice(SystemRole::Clock10ms)->device, QStringLiteral("r93"));
    EXPECT_EQ(vpc().systemDevice(SystemRole::Clock100ms)->device, QStringLiteral("r94"));
    EXPECT_EQ(vpc().systemDevice(SystemRole::Clock1s)->device, QStringLiteral("r95"));
    EXPECT_TRUE(areaOf(vpc(), "r88").system);
    EXPECT_FALSE(areaOf(vpc(), "r87").system);
}

TEST(Targets, VigorDevicesAreOctalWhereTheManualSaysAndLatchedAbove) {
    EXPECT_EQ(areaOf(vigor(), "X0").numbering, Numbering::Octal);
    EXPECT_EQ(areaOf(vigor(), "Y0").numbering, Numbering::Octal);
    EXPECT_EQ(areaOf(vigor(), "M0").numbering, Numbering::Decimal);
    EXPECT_FALSE(areaOf(vigor(), "X0").writable);
    EXPECT_TRUE(areaOf(vigor(), "X0").physical);
    EXPECT_TRUE(areaOf(vigor(), "Y0").physical);
    EXPECT_TRUE(areaOf(vigor(), "M9000").system);
    EXPECT_TRUE(areaOf(vigor(), "D9000").system);
    EXPECT_FALSE(areaOf(vigor(), "M499").retentive);
    EXPECT_TRUE(areaOf(vigor(), "M500").retentive);
    EXPECT_TRUE(areaOf(vigor(), "S500").retentive);
    EXPECT_TRUE(areaOf(vigor(), "D200").retentive);
    EXPECT_TRUE(areaOf(vigor(), "C100").retentive);
    EXPECT_EQ(areaOf(vigor(), "C199").wordBits, 16);
    EXPECT_EQ(areaOf(vigor(), "C200").wordBits, 32);
    EXPECT_EQ(areaOf(vigor(), "C255").wordBits, 32);
    EXPECT_EQ(areaOf(vigor(), "T0").kind, AreaKind::Timer);
    EXPECT_EQ(areaOf(vigor(), "C0").kind, AreaKind::Counter);
}

TEST(Targets, VigorSpecialRelaysFromTheSeed) {
    EXPECT_EQ(vigor().systemDevice(SystemRole::AlwaysOn)->device, QStringLiteral("M9000"));
    EXPECT_EQ(vigor().systemDevice(SystemRole::FirstScan)->device, QStringLiteral("M9002"));
    bool mbus = false;
    for (const SystemDevice &d : vigor().systemDevices)
        mbus = mbus || d.device == QLatin1String("M9199");
    EXPECT_TRUE(mbus);
    EXPECT_NE(vigor().systemDevice(SystemRole::ScanTimeCurrent), nullptr);
}

TEST(Targets, Cpm1AreasFollowTheChannelMap) {
    EXPECT_FALSE(areaOf(cpm1(), "000.00").writable);
    EXPECT_TRUE(areaOf(cpm1(), "000.00").physical);
    EXPECT_TRUE(areaOf(cpm1(), "010.00").writable);
    EXPECT_TRUE(areaOf(cpm1(), "010.00").physical);
    EXPECT_FALSE(areaOf(cpm1(), "200.00").physical);
    EXPECT_TRUE(areaOf(cpm1(), "253.13").system);
    EXPECT_TRUE(areaOf(cpm1(), "HR00.00").retentive);
    EXPECT_FALSE(areaOf(cpm1(), "200.00").retentive);
    EXPECT_FALSE(areaOf(cpm1(), "TIM 000").retentive); // reset on power loss (Omron CPM1 guide)
    EXPECT_TRUE(areaOf(cpm1(), "DM 0000").writable);
    EXPECT_FALSE(areaOf(cpm1(), "DM 6144").writable);
    EXPECT_EQ(areaOf(cpm1(), "010.00").numbering, Numbering::ChannelBit);
}

TEST(Targets, Cpm1SpecialBitsHaveTheirRoles) {
    EXPECT_EQ(cpm1().systemDevice(SystemRole::AlwaysOn)->device, QStringLiteral("253.13"));
    EXPECT_EQ(cpm1().systemDevice(SystemRole::FirstScan)->device, QStringLiteral("253.15"));
    EXPECT_EQ(cpm1().systemDevice(SystemRole::Clock100ms)->device, QStringLiteral("255.00"));
    EXPECT_EQ(cpm1().systemDevice(SystemRole::Clock1s)->device, QStringLiteral("255.02"));
    EXPECT_EQ(cpm1().systemDevice(SystemRole::Clock1min)->device, QStringLiteral("254.00"));
}

TEST(Targets, Pl110AreasAreOneBasedAndVAndSmAreRetained) {
    EXPECT_EQ(areaOf(pl110(), "I1").first, 1);
    EXPECT_EQ(areaOf(pl110(), "Q1").first, 1);
    EXPECT_FALSE(areaOf(pl110(), "I1").writable);
    EXPECT_TRUE(areaOf(pl110(), "I1").physical);
    EXPECT_FALSE(areaOf(pl110(), "AI1").writable);
    EXPECT_TRUE(areaOf(pl110(), "V0").retentive);
    EXPECT_TRUE(areaOf(pl110(), "SM0").retentive);
    EXPECT_FALSE(areaOf(pl110(), "M1").retentive);
    EXPECT_EQ(areaOf(pl110(), "V0").numbering, Numbering::ChannelBit);
    EXPECT_EQ(areaOf(pl110(), "V0").last, 349); // 350 words
    EXPECT_EQ(areaOf(pl110(), "B1").last, 32);
    EXPECT_EQ(areaOf(pl110(), "M1").last, 128); // 8 words
    EXPECT_EQ(areaOf(pl110(), "C1").last, 16);
    EXPECT_EQ(areaOf(pl110(), "DISP0").last, 167); // 8 rows x 21 characters
}

TEST(Targets, Pl110StatusBitsHaveTheirRoles) {
    EXPECT_EQ(pl110().systemDevice(SystemRole::Run)->device, QStringLiteral("SM0.0"));
    EXPECT_EQ(pl110().systemDevice(SystemRole::FirstScan)->device, QStringLiteral("SM0.1"));
    EXPECT_EQ(pl110().systemDevice(SystemRole::Clock1min)->device, QStringLiteral("SM0.2"));
    EXPECT_EQ(pl110().systemDevice(SystemRole::Clock1s)->device, QStringLiteral("SM0.3"));
    EXPECT_EQ(pl110().systemDevice(SystemRole::ScanToggle)->device, QStringLiteral("SM0.4"));
    EXPECT_EQ(pl110().systemDevice(SystemRole::ScanTimeCurrent)->device, QStringLiteral("SM6"));
    EXPECT_EQ(pl110().systemDevice(SystemRole::ScanTimeMin)->device, QStringLiteral("SM7"));
    EXPECT_EQ(pl110().systemDevice(SystemRole::ScanTimeMax)->device, QStringLiteral("SM8"));
}

// Models and limits -------------------------------------------------------------------------

TEST(Targets, ModelsAreTheManualsModels) {
    QStringList names;
    for (const ModelVariant &m : vpc().models)
        names << m.name;
    EXPECT_EQ(names, (QStringList{"VPC106", "VPC108A4", "VPC1410", "VPC1812", "VPC2416", "VPC3224L",
                                  "VPC3224A63", "VPC4030", "VPC4030A84"}));
    names.clear();
    for (const ModelVariant &m : vigor().models)
        names << m.name;
    EXPECT_EQ(names, (QStringList{"M", "VB", "VH"}));
    names.clear();
    for (const ModelVariant &m : pl110().models)
        names << m.name;
    EXPECT_EQ(names, (QStringList{"PL110-1A", "PL110-2A"}));
    EXPECT_NE(cpm1().model(QStringLiteral("cpm1-20cdr")), nullptr); // case-insensitive
    EXPECT_EQ(vpc().model(QStringLiteral("VPC9999")), nullptr);
}

TEST(Targets, VpcModelRangesComeFromItsName) {
    const Target &t = vpc();
    auto range = [&](const char *model, const char *device) {
        const auto a = parseAddress(t, QString::fromLatin1(device));
        return t.range(std::get<Address>(a).area, t.model(QString::fromLatin1(model)));
    };
    EXPECT_EQ(range("VPC3224A63", "i00"), (std::pair{0, 31}));
    EXPECT_EQ(range("VPC3224A63", "o00"), (std::pair{0, 23}));
    EXPECT_EQ(range("VPC3224A63", "a00"), (std::pair{0, 5}));
    EXPECT_EQ(range("VPC3224A63", "d00"), (std::pair{0, 2}));
    EXPECT_EQ(range("VPC106", "a00"), std::nullopt);
    EXPECT_EQ(range("VPC4030A84", "a00"), (std::pair{0, 7}));
    EXPECT_EQ(range("VPC4030A84", "d00"), (std::pair{0, 3}));
    EXPECT_EQ(range("VPC106", "r00"), (std::pair{0, 71})); // not narrowed
}

TEST(Targets, LimitsPerFamily) {
    EXPECT_EQ(vigor().limits.contactsPerRow, 11);
    EXPECT_EQ(vigor().limits.maxBlocksInRow, 8);
    EXPECT_EQ(vigor().limits.stackDepth, 8);
    EXPECT_TRUE(vigor().limits.allowsStack);
    EXPECT_FALSE(vpc().limits.allowsStack);
    EXPECT_FALSE(cpm1().limits.allowsStack);
    EXPECT_FALSE(pl110().limits.allowsStack);
    EXPECT_TRUE(vpc().limits.duplicateCoilIsError);
    EXPECT_TRUE(cpm1().limits.duplicateCoilIsError);
    EXPECT_FALSE(vigor().limits.duplicateCoilIsError);
    EXPECT_EQ(vpc().limits.programSteps, 2048);
    EXPECT_EQ(cpm1().limits.programSteps, 2048);
    EXPECT_EQ(cpm1().limits.jumpLabels, 50);
    EXPECT_EQ(cpm1().limits.maxBlocksInRow, 0); // AND LD / OR LD: no limit
    EXPECT_GT(pl110().limits.programSteps, 0);
}

TEST(Targets, DefaultTimerBases) {
    EXPECT_EQ(vpc().defaultTimerBaseMs, 10.0);    // 00.00..99.99 s
    EXPECT_EQ(vigor().defaultTimerBaseMs, 100.0); // K10 = 1 s
    EXPECT_EQ(cpm1().defaultTimerBaseMs, 100.0);  // TIM 0.1 s
    EXPECT_EQ(pl110().defaultTimerBaseMs, 100.0);
}

TEST(Targets, DefaultTargetIsOneOfTheFamilies) {
    const Target &d = Target::defaultTarget();
    EXPECT_EQ(&d, &vigor()); // the new-project dialog and an empty document start here
    EXPECT_EQ(Target::byId(d.id), &d);
}

TEST(Targets, ScanTimeWordsCountInTheirTablesUnit) {
    EXPECT_EQ(SystemDevice{}.unitUs, 1000); // 1 ms unless the table says otherwise
    for (const Target *t : {&vigor(), &pl110()}) {
        const SystemDevice *d = t->systemDevice(SystemRole::ScanTimeCurrent);
        ASSERT_NE(d, nullptr) << t->id.toStdString();
        EXPECT_EQ(d->unitUs, 100) << t->id.toStdString(); // 0.1 ms: Vigor D9010, PL110 SM6
    }
}

// Semantics and constant rules: what family.h and the Family switches used to say ----------

TEST(Semantics, VpcParallelPortsAreTwelveBitsOfP76AndP77) {
    // VPC user's manual, III: p76 appears binary on o00..o11 (o11 = MSB); i00..i11 read into
    // p77.
    const ParallelPort &out = vpc().semantics.parallelOut;
    const ParallelPort &in = vpc().semantics.parallelIn;
    EXPECT_EQ(out.word, QStringLiteral("p76"));
    EXPECT_EQ(out.firstBit, QStringLiteral("o00"));
    EXPECT_EQ(out.bits, 12);
    EXPECT_EQ(in.word, QStringLiteral("p77"));
    EXPECT_EQ(in.firstBit, QStringLiteral("i00"));
    EXPECT_EQ(in.bits, 12);
    // Written with the target's own rules: the port words are registers, the bits I/O.
    EXPECT_EQ(areaOf(vpc(), "p76").kind, AreaKind::Word);
    EXPECT_EQ(areaOf(vpc(), "p77").kind, AreaKind::Word);
    EXPECT_FALSE(areaOf(vpc(), "p77").writable); // read-only, the inputs drive it
    EXPECT_EQ(areaOf(vpc(), "o00").key, QStringLiteral("o"));
    EXPECT_EQ(areaOf(vpc(), "i00").key, QStringLiteral("i"));
    EXPECT_EQ(areaOf(vpc(), "o11").key, QStringLiteral("o")); // the last bit exists too
    for (const Target *t : {&vigor(), &cpm1(), &pl110()}) {
        EXPECT_TRUE(t->semantics.parallelOut.word.isEmpty()) << t->id.toStdString();
        EXPECT_TRUE(t->semantics.parallelIn.word.isEmpty()) << t->id.toStdString();
    }
}

TEST(Semantics, OnlyVpcDefersBitWrites) {
    EXPECT_TRUE(vpc().semantics.deferredBitWrites);
    for (const Target *t : {&vigor(), &cpm1(), &pl110()})
        EXPECT_FALSE(t->semantics.deferredBitWrites) << t->id.toStdString();
}

TEST(Semantics, DownCountingTimersAndCountersPerFamily) {
    // VPC TIM00..15 / CNT00..15 count down, 16..31 up; every CPM1 TIM / CNT counts down.
    EXPECT_EQ(vpc().semantics.downTimersBelow, 16);
    EXPECT_EQ(vpc().semantics.downCountersBelow, 16);
    const int cpm1Last = areaOf(cpm1(), "TIM127").last;
    EXPECT_GT(cpm1().semantics.downTimersBelow, cpm1Last);
    EXPECT_GT(cpm1().semantics.downCountersBelow, cpm1Last);
    for (const Target *t : {&vigor(), &pl110()}) {
        EXPECT_EQ(t->semantics.downTimersBelow, 0) << t->id.toStdString();
        EXPECT_EQ(t->semantics.downCountersBelow, 0) << t->id.toStdString();
    }
}

TEST(Semantics, Cpm1TimhCarriesItsOwnTimeBase) {
    EXPECT_EQ(spec(cpm1(), "TIMH(15)").timerBaseMs, 10.0); // 0.01 s
    EXPECT_EQ(&spec(cpm1(), "TIMH"), &spec(cpm1(), "TIMH(15)"));
    EXPECT_EQ(spec(cpm1(), "TIM").timerBaseMs, 0.0); // the target's 0.1 s
    for (const Target *t : {&vpc(), &vigor(), &pl110()})
        for (const InstructionSpec &s : t->instructions)
            EXPECT_EQ(s.timerBaseMs, 0.0) << t->id.toStdString() << " " << s.mnemonic.toStdString();
}

TEST(Semantics, Pl110TimersCountInTheirWordAndCountersSaturate) {
    const Semantics &s = pl110().semantics;
    EXPECT_TRUE(s.timerCountsInWord);
    for (const char *timer : {"TON", "TOFF", "TONR"}) // PL110 manual 4.2.4: the time base
        EXPECT_EQ(spec(pl110(), timer).operands.at(2).allowedValues,
                  (std::vector<int>{10, 100, 1000}))
            << timer;
    EXPECT_TRUE(s.upDownCountersSaturate); // MUP / MDOWN
    EXPECT_EQ(pl110().limits.timerMax, 32767);
    EXPECT_EQ(pl110().limits.counterMin, -32768); // PL110 manual 4.2.5
    EXPECT_EQ(pl110().limits.counterMax, 32767);
    for (const Target *t : {&vpc(), &vigor(), &cpm1(), &pl110()})
        EXPECT_EQ(t->limits.scanTimeMax, 32767) << t->id.toStdString(); // one 16-bit word
    for (const Target *t : {&vpc(), &vigor(), &cpm1()}) {
        EXPECT_FALSE(t->semantics.timerCountsInWord) << t->id.toStdString();
        EXPECT_FALSE(t->semantics.upDownCountersSaturate) << t->id.toStdString(); // CNTR wraps
    }
}

TEST(Semantics, ConstantNotationPerFamily) {
    EXPECT_TRUE(vigor().constants.prefixed);
    EXPECT_FALSE(vigor().constants.plain);
    EXPECT_TRUE(cpm1().constants.bcd);
    EXPECT_TRUE(cpm1().constants.bcdSetValues);
    EXPECT_FALSE(cpm1().constants.plain);
    EXPECT_TRUE(vpc().constants.plain);
    EXPECT_FALSE(vpc().constants.hashPlain);
    EXPECT_TRUE(pl110().constants.plain);
    EXPECT_TRUE(pl110().constants.hashPlain);
    EXPECT_TRUE(pl110().constants.wordsInConstantSlots);
    for (const Target *t : {&vpc(), &vigor(), &pl110()})
        EXPECT_FALSE(t->constants.bcdSetValues) << t->id.toStdString();
}

TEST(Semantics, ConstantRulesAreReadFromTheTableNotTheFamily) {
    // A table with K/H and plain numbers both: the parser follows the rules, whatever the
    // family field says, so a fifth PLC needs only its table.
    Target t = vpc();
    t.constants.prefixed = true;
    const auto k = parseConstant(t, u"K10");
    ASSERT_TRUE(std::holds_alternative<Constant>(k));
    EXPECT_EQ(std::get<Constant>(k).value, 10);
    const auto plain = parseConstant(t, u"10");
    ASSERT_TRUE(std::holds_alternative<Constant>(plain));
    EXPECT_EQ(std::get<Constant>(plain).style, Constant::Style::Plain);
    t.constants.plain = false;
    EXPECT_TRUE(std::holds_alternative<AddressError>(parseConstant(t, u"10")));
    EXPECT_EQ(formatConstant(t, Constant{7, Constant::Style::Plain}), QStringLiteral("K7"));
    t.constants.hashPlain = true;
    t.constants.plain = true;
    const auto hash = parseConstant(t, u"#5");
    ASSERT_TRUE(std::holds_alternative<Constant>(hash));
    EXPECT_EQ(std::get<Constant>(hash).style, Constant::Style::Plain);
}

// Instructions ------------------------------------------------------------------------------

TEST(Instructions, VpcNegatedContactsHaveStarAliases) {
    EXPECT_EQ(&spec(vpc(), "LD*"), &spec(vpc(), "LD NOT"));
    EXPECT_EQ(&spec(vpc(), "AND*"), &spec(vpc(), "AND NOT"));
    EXPECT_EQ(&spec(vpc(), "OR*"), &spec(vpc(), "OR NOT"));
    EXPECT_EQ(&spec(vpc(), "OUT*"), &spec(vpc(), "OUT NOT"));
    EXPECT_EQ(&spec(vpc(), "ld   not"), &spec(vpc(), "LD NOT"));
    EXPECT_EQ(spec(vpc(), "LD NOT").mode, ContactMode::Negated);
    EXPECT_EQ(spec(vpc(), "OUT NOT").op, Op::Out);
    EXPECT_TRUE(spec(vpc(), "OUT NOT").negated);
    EXPECT_EQ(vpc().findInstruction(QStringLiteral("LDI")), nullptr);
}

TEST(Instructions, VpcTimersAndCountersFuseTheirNumber) {
    EXPECT_TRUE(spec(vpc(), "TIM").fusedOperand);
    EXPECT_TRUE(spec(vpc(), "CNT").fusedOperand);
    EXPECT_EQ(spec(vpc(), "CNT").inputs, 2);
    EXPECT_EQ(spec(vpc(), "TIM").inputs, 1);
    EXPECT_EQ(spec(vpc(), "LR").op, Op::Keep);
    EXPECT_EQ(spec(vpc(), "LR").inputs, 2);
    EXPECT_EQ(spec(vpc(), "AND LD").op, Op::AndBlock);
    EXPECT_EQ(spec(vpc(), "OR LD").op, Op::OrBlock);
    EXPECT_EQ(spec(vpc(), "JPE").op, Op::JumpEnd);
    EXPECT_EQ(spec(vpc(), "ILC").op, Op::InterlockClear);
}

TEST(Instructions, VpcComparesAndTransfersExistForEveryForm) {
    for (Op op : {Op::Load, Op::And, Op::Or})
        for (CompareOp c : {CompareOp::Eq, CompareOp::Lt, CompareOp::Gt})
            for (ContactMode m : {ContactMode::Normal, ContactMode::Negated}) {
                const InstructionSpec *s = vpc().findInstruction(op, m, c);
                ASSERT_NE(s, nullptr);
                EXPECT_EQ(s->operands.size(), 2u);
            }
    int transfers = 0;
    for (const InstructionSpec &s : vpc().instructions)
        if (s.op == Op::Transfer) {
            ++transfers;
            EXPECT_TRUE(s.mnemonic == QLatin1String(s.negated ? "OUT NOT" : "OUT"));
        }
    EXPECT_EQ(transfers, 6); // , + - times OUT / OUT NOT
}

TEST(Instructions, Cpm1FunctionCodesAreAccepted) {
    EXPECT_EQ(&spec(cpm1(), "KEEP(11)"), &spec(cpm1(), "KEEP"));
    EXPECT_EQ(&spec(cpm1(), "keep(11)"), &spec(cpm1(), "KEEP"));
    EXPECT_EQ(cpm1().findInstruction(QStringLiteral("KEEP(12)")), nullptr);
    EXPECT_EQ(spec(cpm1(), "KEEP").functionCode, 11);
    EXPECT_EQ(spec(cpm1(), "KEEP").inputs, 2);
    EXPECT_EQ(spec(cpm1(), "DIFU(13)").op, Op::PulseRise);
    EXPECT_EQ(spec(cpm1(), "DIFD(14)").op, Op::PulseFall);
    EXPECT_EQ(spec(cpm1(), "TIMH(15)").op, Op::Timer);
    EXPECT_EQ(spec(cpm1(), "CNTR(12)").op, Op::UpDownCounter);
    EXPECT_EQ(spec(cpm1(), "CNTR").inputs, 3);
    EXPECT_EQ(spec(cpm1(), "CNT").inputs, 2);
    EXPECT_EQ(spec(cpm1(), "JMP(04)").operands.front().kind, OperandKind::Label);
    EXPECT_EQ(spec(cpm1(), "JME(05)").op, Op::JumpEnd);
    EXPECT_EQ(&spec(cpm1(), "END(01)"), &spec(cpm1(), "END"));
    EXPECT_EQ(spec(cpm1(), "NOP(00)").op, Op::Nop);
    EXPECT_EQ(spec(cpm1(), "AND LD").op, Op::AndBlock);
    EXPECT_EQ(spec(cpm1(), "OR LD").op, Op::OrBlock);
    EXPECT_EQ(spec(cpm1(), "RESET").op, Op::Reset);
}

TEST(Instructions, VigorFxMnemonics) {
    EXPECT_EQ(spec(vigor(), "LDI").mode, ContactMode::Negated);
    EXPECT_EQ(spec(vigor(), "ANI").op, Op::And);
    EXPECT_EQ(spec(vigor(), "ORF").mode, ContactMode::Falling);
    EXPECT_EQ(spec(vigor(), "LDP").mode, ContactMode::Rising);
    EXPECT_EQ(spec(vigor(), "MPS").op, Op::Push);
    EXPECT_EQ(spec(vigor(), "MRD").op, Op::ReadStack);
    EXPECT_EQ(spec(vigor(), "MPP").op, Op::Pop);
    EXPECT_EQ(spec(vigor(), "INV").op, Op::Invert);
    EXPECT_EQ(spec(vigor(), "PLS").op, Op::PulseRise);
    EXPECT_EQ(spec(vigor(), "PLF").op, Op::PulseFall);
    EXPECT_EQ(spec(vigor(), "STL").op, Op::StepLadder);
    EXPECT_EQ(spec(vigor(), "RET").op, Op::Return);
    // TMR T0 K10 (PLC concepts (WPLSoft family) 1.5.1)
    EXPECT_EQ(spec(vigor(), "TMR").operands.size(), 2u);
    EXPECT_EQ(spec(vigor(), "CNT").inputs, 1);
    EXPECT_EQ(spec(vigor(), "LD=").compare, CompareOp::Eq);
    EXPECT_EQ(spec(vigor(), "AND<>").compare, CompareOp::Ne);
    EXPECT_EQ(spec(vigor(), "OR>=").op, Op::Or);
    EXPECT_EQ(vigor().findInstruction(QStringLiteral("LD NOT")), nullptr);
}

TEST(Instructions, VigorApplicationInstructionsTheSimulatorNeeds) {
    const std::pair<const char *, ApplyFunction> needed[] = {
        {"MOV", ApplyFunction::Mov},        {"CMP", ApplyFunction::Compare},
        {"ZRST", ApplyFunction::ZoneReset}, {"ADD", ApplyFunction::Add},
        {"SUB", ApplyFunction::Sub},        {"MUL", ApplyFunction::Mul},
        {"DIV", ApplyFunction::Div},        {"INC", ApplyFunction::Inc},
        {"DEC", ApplyFunction::Dec}};
    for (const auto &[name, function] : needed) {
        EXPECT_EQ(spec(vigor(), name).op, Op::Apply) << name;
        EXPECT_EQ(spec(vigor(), name).function, function) << name;
    }
    EXPECT_EQ(spec(vigor(), "CMP").operands.size(), 3u);
    // The communication instructions and the ones their programs build frames with
    // (docs/network.md); REF alone is not simulated.
    const std::pair<const char *, ApplyFunction> communication[] = {
        {"SWAP", ApplyFunction::Swap},       {"ASCI", ApplyFunction::ToAscii},
        {"HEX", ApplyFunction::FromAscii},   {"RS", ApplyFunction::SerialData},
        {"LINK", ApplyFunction::EasyLink},   {"MBUS", ApplyFunction::ModbusMaster},
        {"VRRD", ApplyFunction::ReadVolume}, {"SMOV", ApplyFunction::ShiftDigits},
        {"FROM", ApplyFunction::ModuleRead}, {"TO", ApplyFunction::ModuleWrite},
        {"TOP", ApplyFunction::ModuleWrite}, {"ALTP", ApplyFunction::Toggle},
        {"REF", ApplyFunction::NotSimulated}};
    for (const auto &[name, function] : communication)
        EXPECT_EQ(spec(vigor(), name).function, function) << name;
    EXPECT_TRUE(spec(vigor(), "LINK").oncePerProgram);
    EXPECT_TRUE(spec(vigor(), "MBUS").oncePerProgram);
    EXPECT_FALSE(spec(vigor(), "RS").oncePerProgram);
}

TEST(Instructions, Pl110ListingElements) {
    EXPECT_EQ(&spec(pl110(), "LD NOT"), &spec(pl110(), "LDN"));
    EXPECT_EQ(spec(pl110(), "ANDN").mode, ContactMode::Negated);
    EXPECT_EQ(spec(pl110(), "ORN").op, Op::Or);
    EXPECT_EQ(spec(pl110(), "ANB").op, Op::AndBlock);
    EXPECT_EQ(spec(pl110(), "ORB").op, Op::OrBlock);
    EXPECT_EQ(spec(pl110(), "NOT").op, Op::Invert);
    EXPECT_EQ(spec(pl110(), "P").op, Op::Invert);
    EXPECT_EQ(spec(pl110(), "P").mode, ContactMode::Rising);
    EXPECT_EQ(spec(pl110(), "N").mode, ContactMode::Falling);
    EXPECT_EQ(spec(pl110(), "LDII").op, Op::Load);
    EXPECT_EQ(spec(pl110(), "LD>=").compare, CompareOp::Ge);
    EXPECT_EQ(&spec(pl110(), "LDIF>="), &spec(pl110(), "LD>="));
    EXPECT_EQ(spec(pl110(), "AND<>").compare, CompareOp::Ne);
    EXPECT_EQ(&spec(pl110(), "QI"), &spec(pl110(), "OUTQI"));
    EXPECT_EQ(spec(pl110(), "OUTB").function, ApplyFunction::Toggle);
    EXPECT_EQ(spec(pl110(), "SBIT").function, ApplyFunction::SetBit);
    EXPECT_EQ(spec(pl110(), "RBIT").function, ApplyFunction::ResetBit);
    EXPECT_EQ(spec(pl110(), "TON").timerMode, TimerMode::OnDelay);
    EXPECT_EQ(spec(pl110(), "TOFF").timerMode, TimerMode::OffDelay);
    EXPECT_EQ(spec(pl110(), "TONR").timerMode, TimerMode::Accumulating);
    EXPECT_EQ(spec(pl110(), "MUP").op, Op::UpDownCounter);
    EXPECT_EQ(spec(pl110(), "MUP").inputs, 3);
    EXPECT_EQ(spec(pl110(), "MUP").counterMode, CounterMode::Up);
    EXPECT_EQ(spec(pl110(), "MDOWN").counterMode, CounterMode::Down);
    EXPECT_EQ(spec(pl110(), "MDOWN").inputs, 3);
    EXPECT_EQ(spec(pl110(), "FM").function, ApplyFunction::Math);
    EXPECT_EQ(spec(pl110(), "FM").operands.size(), 4u); // FM S1 OP S2 D
    EXPECT_EQ(spec(pl110(), "MOV").function, ApplyFunction::Mov);
    EXPECT_EQ(spec(pl110(), "BLKMOV").function, ApplyFunction::BlockMove);
    EXPECT_EQ(spec(pl110(), "MOVIND").function, ApplyFunction::IndirectMove);
    for (const char *box : {"PID", "POS", "GENSET", "StartPID", "RANGE"})
        EXPECT_EQ(spec(pl110(), box).function, ApplyFunction::NotSimulated) << box;
    // PL110 manual 4.2.19, 4.2.21: SEND names its port, COM drives COM1 and EXP EXP1.
    EXPECT_EQ(spec(pl110(), "SEND").function, ApplyFunction::FreePortSend);
    EXPECT_EQ(spec(pl110(), "SEND").portOperand, 0);
    EXPECT_EQ(spec(pl110(), "COM").function, ApplyFunction::MasterQuery);
    EXPECT_STREQ(spec(pl110(), "COM").port, "COM1");
    EXPECT_STREQ(spec(pl110(), "EXP").port, "EXP1");
    EXPECT_EQ(spec(pl110(), "EXP").operands.size(), 7u);
}

TEST(Instructions, CanonicalSpecForAnOperation) {
    EXPECT_EQ(canonical(vpc(), Op::Load, ContactMode::Negated), QStringLiteral("LD NOT"));
    EXPECT_EQ(canonical(vpc(), Op::Out, ContactMode::Normal, CompareOp::None, true),
              QStringLiteral("OUT NOT"));
    EXPECT_EQ(vpc().findInstruction(Op::Out, ContactMode::Normal, CompareOp::None, true)->transfer,
              TransferOp::None);
    EXPECT_EQ(vpc().findInstruction(Op::Load, ContactMode::Normal, CompareOp::Lt)->compare,
              CompareOp::Lt);
    EXPECT_EQ(canonical(vpc(), Op::Keep), QStringLiteral("LR"));
    EXPECT_EQ(canonical(vpc(), Op::Push), QStringLiteral("(none)"));
    EXPECT_EQ(canonical(vigor(), Op::Load, ContactMode::Rising), QStringLiteral("LDP"));
    EXPECT_EQ(canonical(vigor(), Op::Or, ContactMode::Negated), QStringLiteral("ORI"));
    EXPECT_EQ(canonical(vigor(), Op::And, ContactMode::Normal, CompareOp::Le),
              QStringLiteral("AND<="));
    EXPECT_EQ(canonical(vigor(), Op::Invert), QStringLiteral("INV"));
    EXPECT_EQ(canonical(vigor(), Op::Timer), QStringLiteral("TMR"));
    EXPECT_EQ(canonical(cpm1(), Op::Keep), QStringLiteral("KEEP(11)"));
    EXPECT_EQ(canonical(cpm1(), Op::AndBlock), QStringLiteral("AND LD"));
    EXPECT_EQ(canonical(cpm1(), Op::Timer), QStringLiteral("TIM"));
    EXPECT_EQ(canonical(cpm1(), Op::End), QStringLiteral("END(01)"));
    EXPECT_EQ(canonical(pl110(), Op::Load), QStringLiteral("LD"));
    EXPECT_EQ(canonical(pl110(), Op::Load, ContactMode::Negated), QStringLiteral("LDN"));
    EXPECT_EQ(canonical(pl110(), Op::Invert), QStringLiteral("NOT"));
    EXPECT_EQ(canonical(pl110(), Op::Invert, ContactMode::Rising), QStringLiteral("P"));
    EXPECT_EQ(canonical(pl110(), Op::Out), QStringLiteral("OUT"));
    EXPECT_EQ(canonical(pl110(), Op::Timer), QStringLiteral("TON"));
    EXPECT_EQ(canonical(pl110(), Op::UpDownCounter), QStringLiteral("MUP"));
    // Edge contacts on a device exist only on Vigor.
    EXPECT_EQ(canonical(pl110(), Op::Load, ContactMode::Rising), QStringLiteral("(none)"));
    EXPECT_EQ(canonical(vpc(), Op::Load, ContactMode::Rising), QStringLiteral("(none)"));
}

TEST(Instructions, OnlyVigorHasTheBranchStack) {
    for (Family f : Target::families()) {
        const Target &t = Target::get(f);
        const bool has = t.findInstruction(Op::Push) != nullptr;
        EXPECT_EQ(has, t.limits.allowsStack) << t.id.toStdString();
    }
}

TEST(Instructions, EveryFamilyEndsWithEnd) {
    for (Family f : Target::families())
        EXPECT_NE(Target::get(f).findInstruction(Op::End), nullptr);
}

TEST(Instructions, IndexOfFindsTheSpecAndRejectsForeignPointers) {
    const InstructionSpec &s = spec(vigor(), "MOV");
    EXPECT_EQ(&vigor().instructions[static_cast<std::size_t>(vigor().indexOf(&s))], &s);
    EXPECT_EQ(vpc().indexOf(&s), -1);
    EXPECT_EQ(vpc().indexOf(nullptr), -1);
}

// The PL110 listing of docs/targets.md, read through the IL parser: the operand signatures
// in the table accept every form the document shows.
TEST(Instructions, Pl110DocumentedListingParses) {
    const char *text = "LD I1\nANDN M2\nLD>= V1 V2\nORB\nP\nOUT Q1\n"
                       "LDII I3\nOUTQI Q2\n"
                       "LD SM0.4\nOUTB B1\n"
                       "LD I2\nSBIT V3 5\nLD I2\nRBIT V3.5\n"
                       "LD I4\nTON T1 50 100\nLD I4\nTONR T2 VW1 10\n"
                       "LD I5\nLD I6\nLD I7\nMUP C1 10\n"
                       "LD SM0.0\nFM V1 << 2 V4\n"
                       "LD SM0.0\nBLKMOV 0 V10 5\n"
                       "LD SM0.0\nPID 1 V1 V2\n"
                       "LD I1\nNOT\nOUT M1\nEND\n";
    const ParseResult r = parseInstructionList(pl110(), QString::fromLatin1(text));
    for (const ParseError &e : r.errors)
        ADD_FAILURE() << e.line << ":" << e.column << " " << e.message.toStdString();
    ASSERT_EQ(r.list.instructions.size(), 32u);
    EXPECT_EQ(r.list.instructions[4].spec->mnemonic, QStringLiteral("P"));
    EXPECT_EQ(r.list.instructions[15].spec->mnemonic, QStringLiteral("TON"));
    EXPECT_EQ(r.list.instructions[15].operands.size(), 3u);
    EXPECT_EQ(r.list.instructions[21].spec->mnemonic, QStringLiteral("MUP"));
}

// The CPM1's peripheral port (Omron CPM1 guide 2.1, item 9 "Perifériacsatlakozó", used for
// "Monitorozás (PLC-PC on-line kapcsolat)") runs Host Link with the standard settings of
// Omron's public Host Link documentation (W353, PC Setup of the peripheral port): 9600 bps, 7
// data bits, even parity, 2 stop bits, unit 0; 1200..19200 bps, units 00..31.
TEST(Ports, Cpm1PeripheralPortAnswersHostLinkAtTheStandardSettings) {
    const Target &t = cpm1();
    ASSERT_EQ(t.ports.size(), 1u);
    const PortSpec *port = t.port(u"peripheral");
    ASSERT_NE(port, nullptr);
    EXPECT_EQ(port->name, QStringLiteral("PERIPHERAL"));
    EXPECT_TRUE(port->models.isEmpty()) << "every CPU unit has it";
    ASSERT_EQ(port->applications.size(), 1u);
    const PortApplication &a = port->applications.front();
    EXPECT_STREQ(a.id, "host-link");
    EXPECT_EQ(a.answers, ProtocolId::HostLink);
    EXPECT_NE(findProtocolMap(t, *a.answers), nullptr);
    EXPECT_EQ(a.bauds, (std::vector<int>{9600, 1200, 2400, 4800, 19200}));
    EXPECT_STREQ(a.frame, "7E2");
    EXPECT_FALSE(a.fixedFrame);
    EXPECT_EQ(a.stationMin, 0);
    EXPECT_EQ(a.stationMax, 31);
    EXPECT_EQ(a.station, 0);
    EXPECT_FALSE(a.master);
    EXPECT_TRUE(a.published);
    // Host Link numbers its units from 0: unit 0 answers (MODBUS's 0 is the broadcast).
    EXPECT_TRUE(answersAt(a, 0));
    EXPECT_TRUE(answersAt(a, 31));
    PortApplication modbus;
    modbus.answers = ProtocolId::Modbus;
    EXPECT_FALSE(answersAt(modbus, 0));
    EXPECT_TRUE(answersAt(modbus, 1));
    EXPECT_FALSE(answersAt(PortApplication{}, 1));
    // A network file's or project's settings are read against the table: the defaults, and
    // what is out of its ranges is refused with where and why.
    PortConfig config;
    QString error;
    ASSERT_TRUE(readPortConfig(t, &t.defaultModel(), QStringLiteral("PERIPHERAL"),
                               {{QJsonObject{}, QStringLiteral("stations[0].ports.PERIPHERAL")}},
                               &config, &error))
        << error.toStdString();
    EXPECT_EQ(config.application, &a);
    EXPECT_EQ(config.station, 0);
    EXPECT_EQ(config.line.baud, 9600);
    EXPECT_EQ(frameFormatText(config.line), QStringLiteral("7E2"));
    EXPECT_FALSE(readPortConfig(t, &t.defaultModel(), QStringLiteral("PERIPHERAL"),
                                {{QJsonObject{{QStringLiteral("station"), 32}},
                                  QStringLiteral("stations[0].ports.PERIPHERAL")}},
                                &config, &error));
    EXPECT_TRUE(error.contains(QStringLiteral("stations[0].ports.PERIPHERAL.station")))
        << error.toStdString();
    EXPECT_FALSE(readPortConfig(t, &t.defaultModel(), QStringLiteral("PERIPHERAL"),
                                {{QJsonObject{{QStringLiteral("baud"), 38400}},
                                  QStringLiteral("stations[0].ports.PERIPHERAL")}},
                                &config, &error));
}
