// Golden traces: tests/data/sim/NAME.il (first line "; target: T", second line
// "; simulate: OPTIONS" as the command line takes them) must print exactly NAME.csv.
// The expected traces are derived by hand from the manuals' examples (see each .il).

#include "model/listing/il.h"
#include "model/target/address.h"
#include "simulator/compiler.h"
#include "simulator/engine.h"
#include "simulator/trace.h"

#include <QDir>
#include <QFile>
#include <QProcess>
#include <QRegularExpression>

#include <gtest/gtest.h>

#include <algorithm>

using namespace rung;

namespace {

QString readText(const QString &path) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly | QIODevice::Text))
        return {};
    return QString::fromUtf8(f.readAll());
}

QString dataDir() {
    return QStringLiteral(RUNG_TEST_DATA_DIR "/sim");
}

std::vector<std::string> goldenNames() {
    std::vector<std::string> names;
    for (const QString &csv : QDir(dataDir()).entryList({QStringLiteral("*.csv")}, QDir::Files))
        names.push_back(QFileInfo(csv).completeBaseName().toStdString());
    return names;
}

struct Loaded {
    const model::Target *target = nullptr;
    model::ParseResult parsed;
    simulator::CompileResult compiled;
    QStringList options;
};

Loaded load(const QString &text) {
    Loaded l;
    static const QRegularExpression targetRe(QStringLiteral("^; target: (\\w+)"));
    static const QRegularExpression simRe(QStringLiteral("^; simulate: (.*)$"),
                                          QRegularExpression::MultilineOption);
    const auto t = targetRe.match(text);
    l.target = t.hasMatch() ? model::Target::byId(t.captured(1)) : nullptr;
    if (!l.target)
        return l;
    if (const auto s = simRe.match(text); s.hasMatch())
        l.options = QProcess::splitCommand(s.captured(1));
    l.parsed = model::parseInstructionList(*l.target, text);
    if (l.parsed.ok())
        l.compiled = simulator::compileProgram(l.parsed.list);
    return l;
}

class GoldenTrace : public ::testing::TestWithParam<std::string> {};

} // namespace

TEST_P(GoldenTrace, PrintsTheExpectedTrace) {
    const QString base = dataDir() + QLatin1Char('/') + QString::fromStdString(GetParam());
    const QString expected = readText(base + QStringLiteral(".csv"));
    const Loaded l = load(readText(base + QStringLiteral(".il")));
    ASSERT_NE(l.target, nullptr) << "no '; target:' line";
    ASSERT_TRUE(l.parsed.ok()) << l.parsed.errors.front().line << ": "
                               << l.parsed.errors.front().message.toStdString();
    ASSERT_TRUE(l.compiled.ok()) << l.compiled.diagnostics.front().location.line << ": "
                                 << l.compiled.diagnostics.front().message.toStdString();
    simulator::TraceRequest request;
    QString error;
    ASSERT_TRUE(simulator::parseTraceOptions(*l.target, l.options, &request, &error))
        << error.toStdString();
    QString actual;
    QTextStream out(&actual);
    simulator::runTrace(l.compiled.program, request, out);
    out.flush();
    EXPECT_EQ(actual.toStdString(), expected.toStdString());
}

INSTANTIATE_TEST_SUITE_P(Manuals, GoldenTrace, ::testing::ValuesIn(goldenNames()),
                         [](const ::testing::TestParamInfo<std::string> &info) {
                             return info.param;
                         });

// Every example the issue lists has its trace (a missing or renamed file fails here, not
// silently drops out of the parameterized test). The traffic light has its own test below.
TEST(GoldenTraceSet, CoversEveryFamilyExampleListedInTheIssue) {
    const std::vector<std::string> expected = {
        // Vigor, PLC concepts (WPLSoft family) 1.9
        "vigor_stop_first_latch", "vigor_start_first_latch", "vigor_set_rst_order",
        "vigor_interlock", "vigor_sequential_control", "vigor_oscillator", "vigor_timer_oscillator",
        "vigor_flasher", "vigor_delay_off", "vigor_counting_extension",
        // VPC, VPC user's manual, VII
        "vpc_compare_contacts", "vpc_add_compare", "vpc_set_value_arithmetic",
        "vpc_out_not_transfer", "vpc_transfers", "vpc_analog", "vpc_interlock", "vpc_counter_latch",
        "vpc_timers_down_up", "vpc_add_every_scan", "vpc_add_once_a_second",
        // CPM1, Omron CPM1 guide
        "cpm1_and", "cpm1_or", "cpm1_out_not", "cpm1_and_ld", "cpm1_or_ld", "cpm1_keep",
        "cpm1_difu_difd", "cpm1_jmp_jme", "cpm1_tim_timh", "cpm1_cnt_cntr",
        // CPM1, Omron W353 (issue 14): application instructions, subroutines, steps
        "cpm1_add_carry", "cpm1_sft", "cpm1_cmp_timer", "cpm1_step_snxt", "cpm1_subroutine",
        "cpm1_mov_bcd_set_value",
        // PL110, PL110 manual 4.2
        "pl110_contacts", "pl110_timers", "pl110_counters", "pl110_movind",
        // PL110, PL110 manual 2.1 and 4.2 (issue 14): TONR, presets, SM0.13, trimmers, VD / SMD
        "pl110_tonr_scan_toggle", "pl110_presets", "pl110_sm0_13", "pl110_trimmer_preset",
        "pl110_double_words",
        // Vigor, Vigor M/VB/VH communication manual and PLC concepts (WPLSoft family) (issue
        // 14): digits and index registers, CCD, RS, timer resolutions
        "vigor_digits_index", "vigor_ccd_check_code", "vigor_send_frame",
        "vigor_timer_resolutions"};
    const std::vector<std::string> names = goldenNames();
    for (const std::string &name : expected)
        EXPECT_NE(std::find(names.begin(), names.end(), name), names.end()) << name;
    EXPECT_TRUE(QFile::exists(dataDir() + QStringLiteral("/vigor_traffic_light.il")));
}

TEST(TrafficLight, PhasesLast35_5_25_5Seconds) {
    const Loaded l = load(readText(dataDir() + QStringLiteral("/vigor_traffic_light.il")));
    ASSERT_NE(l.target, nullptr);
    ASSERT_TRUE(l.parsed.ok());
    ASSERT_TRUE(l.compiled.ok());
    const model::Target &t = *l.target;
    auto addr = [&](const char *name) {
        return std::get<model::Address>(model::parseAddress(t, QString::fromLatin1(name)));
    };
    const model::Address red = addr("Y0"), yellow = addr("Y1"), green = addr("Y2");
    simulator::Engine engine(l.compiled.program);
    engine.setPeriodMs(100);
    qint64 yellowOn = -1, greenOn = -1, redAgain = -1;
    int blinkOffs = 0;
    bool steadyGreen = true;
    bool lastGreen = false;
    for (int scan = 0; scan < 800; ++scan) {
        const qint64 time = engine.statistics().timeMs;
        engine.scan();
        const bool g = engine.bit(green);
        if (yellowOn < 0 && engine.bit(yellow))
            yellowOn = time;
        if (greenOn < 0 && g)
            greenOn = time;
        if (greenOn >= 0 && redAgain < 0 && engine.bit(red))
            redAgain = time;
        if (time > 40000 && time < 65000 && !g)
            steadyGreen = false;
        if (time >= 65000 && time < 70000 && lastGreen && !g)
            ++blinkOffs;
        lastGreen = g;
    }
    EXPECT_EQ(yellowOn, 35000);
    EXPECT_EQ(greenOn, 40000);
    EXPECT_TRUE(steadyGreen);
    EXPECT_GE(blinkOffs, 4);
    // S0 stands above S3, so the step set at 70 s runs from the next scan on.
    EXPECT_GE(redAgain, 70000);
    EXPECT_LE(redAgain, 70100);
}
