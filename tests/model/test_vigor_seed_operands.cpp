// The Vigor operand rules of the Vigor M/VB/VH communication manual's own tables ("Operand
// Devices" of FNC 80 RS, FNC 89 LINK, FNC 149 MBUS), the REF of PLC concepts (WPLSoft family)
// 1.1 and the Vigor manual's FROM/TO pages: the manuals' example operands pass `check`,
// operands the tables do not mark are OP005 errors on their line.

#include "model/checks/checks.h"
#include "model/listing/il.h"
#include "model/target/address.h"

#include <gtest/gtest.h>

using namespace rung::model;

namespace {

std::vector<Diagnostic> operandErrors(const char *line) {
    const QString text = QStringLiteral("LD X20\n%1\nEND").arg(QLatin1String(line));
    const ParseResult parsed = parseInstructionList(Target::get(Family::Vigor), text);
    EXPECT_TRUE(parsed.ok()) << line;
    std::vector<Diagnostic> found;
    if (!parsed.ok())
        return found;
    for (Diagnostic &d : checkList(parsed.list, {}))
        if (d.severity == Severity::Error)
            found.push_back(std::move(d));
    return found;
}

} // namespace

TEST(VigorOperands, SeedOneOperandTables) {
    // The manuals' own examples.
    for (const char *good :
         {"RS D0 D200 D100 D201", "RS D0 K0 D100 K256", "RS D10 H10 D8000 D3", "LINK D1000 D100",
          "MBUS D1000 D100", "LINK D0 D8188", "FROM K1 K2000 D50 K15", "TO K1 K1000 D0 K15",
          "TO K1 K2 K14 K1", "TO K1 K1 K1M20 K1", "TOP K1 K0 H7096 K1", "REF X0 K8", "REF Y0 K8",
          "REF X4 K4"}) {
        SCOPED_TRACE(good);
        const std::vector<Diagnostic> errors = operandErrors(good);
        EXPECT_TRUE(errors.empty()) << errors.front().message.toStdString();
    }
    struct Bad {
        const char *line;
        const char *says;
    };
    const Bad bad[] = {
        // FNC 80: S and D in the D column; m, n = 0~256.
        {"RS K5 D200 D100 D201", "from D only, not K5"},
        {"RS K4M0 D200 D100 D201", "from D only, not K4M0"},
        {"RS D0 D200 C10 D201", "from D only, not C10"},
        {"RS D0 K257 D100 D201", "from 0 to 256, not 257"},
        {"RS D0 D200 D100 T5", "from a constant or from D, not T5"},
        // FNC 89 / FNC 149: S1 and S2 on D; S2 occupies 4 consecutive registers.
        {"LINK K1000 D100", "from D only, not K1000"},
        {"MBUS D1000 K4M100", "from D only, not K4M100"},
        {"LINK D1000 D8189", "D8192 does not exist"},
        {"MBUS D1000 D8190", "D8192 does not exist"},
        // FROM / TO: n >= 1, the block inside its area.
        {"FROM K1 K2000 D8180 K15", "D8192 does not exist"},
        {"FROM K1 K2000 D50 K0", "at least 1, not 0"},
        {"TO K1 K1000 D8190 K15", "D8192 does not exist"},
        // TOP (Vigor M/VB/VH communication manual, B-4-5) is TO's pulse form: the same rules.
        {"TOP K1 K0 D8190 K15", "D8192 does not exist"},
        {"TOP K1 K0 D0 K0", "at least 1, not 0"},
        // REF: inputs or outputs.
        {"REF M0 K8", "from X, Y only, not M0"},
        {"REF S0 K8", "from X, Y only, not S0"},
    };
    for (const Bad &b : bad) {
        SCOPED_TRACE(b.line);
        const std::vector<Diagnostic> errors = operandErrors(b.line);
        ASSERT_EQ(errors.size(), 1u);
        EXPECT_EQ(errors.front().code, QStringLiteral("OP005"));
        EXPECT_EQ(errors.front().location.line, 2);
        EXPECT_TRUE(errors.front().message.contains(QLatin1String(b.says)))
            << errors.front().message.toStdString();
    }
}

// Issue 14, PLC concepts (WPLSoft family) 1.4 "Every timer has its resolution (unit:
// 1ms/10ms/100ms)": the ranges of docs/targets.md "Timer resolutions" hold on every Vigor model
// the product offers (M, VB, VH): each timer number exists there with its time base and mode,
// and one past the last does not. A model given other ranges would have to say so in the table
// (ModelVariant::overrides).
TEST(VigorTimerRanges, EveryModelHasTheFamilysResolutions) {
    const Target &t = Target::get(Family::Vigor);
    struct Expected {
        const char *device;
        double baseMs;
        TimerMode mode;
    };
    const Expected expected[] = {
        {"T0", 100, TimerMode::OnDelay},        {"T199", 100, TimerMode::OnDelay},
        {"T200", 10, TimerMode::OnDelay},       {"T245", 10, TimerMode::OnDelay},
        {"T246", 1, TimerMode::Accumulating},   {"T249", 1, TimerMode::Accumulating},
        {"T250", 100, TimerMode::Accumulating}, {"T255", 100, TimerMode::Accumulating},
    };
    ASSERT_EQ(t.models.size(), 3u);
    for (const ModelVariant &model : t.models) {
        SCOPED_TRACE(model.name.toStdString());
        for (const Expected &e : expected) {
            const auto parsed = parseAddress(t, QString::fromLatin1(e.device));
            ASSERT_TRUE(std::holds_alternative<Address>(parsed)) << e.device;
            const Address a = std::get<Address>(parsed);
            const auto range = t.range(a.area, &model);
            ASSERT_TRUE(range.has_value()) << e.device;
            EXPECT_TRUE(a.index >= range->first && a.index <= range->second) << e.device;
            const Area &area = t.area(a.area);
            const double base = area.timerBaseMs > 0 ? area.timerBaseMs : t.defaultTimerBaseMs;
            EXPECT_EQ(base, e.baseMs) << e.device;
            EXPECT_EQ(area.timerMode, e.mode) << e.device;
        }
        EXPECT_FALSE(std::holds_alternative<Address>(parseAddress(t, QStringLiteral("T256"))));
    }
}
