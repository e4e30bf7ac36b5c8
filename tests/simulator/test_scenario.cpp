// Scenario tests (docs/scenario-tests.md): the file's statements, the run on virtual time, the
// report of a failure and JUnit XML.

#include "simulator/compiler.h"
#include "simulator/scenario.h"

#include "tests/targets.h"

#include <QXmlStreamReader>

#include <gtest/gtest.h>

using namespace rung;
using namespace rung::simulator;

namespace {

// A loader that hands this listing, whatever the scenario names (the file's own path is kept
// to tell what was asked).
struct ListingLoader {
    const model::Target *target;
    QString listing;
    mutable QString asked;
    ScenarioProgram operator()(const QString &path, const QString &, const QString &) const {
        asked = path;
        ScenarioProgram out;
        const model::ParseResult parsed = model::parseInstructionList(*target, listing);
        EXPECT_TRUE(parsed.ok());
        CompileResult compiled = compileProgram(parsed.list);
        EXPECT_TRUE(compiled.ok());
        out.program = compiled.program;
        return out;
    }
};

// A start/stop latch with an on-delay: Y0 latches on X0, X1 stops it; T0 (K20 = 2 s) runs
// while Y0 is ON and lights Y1.
const QString kLatch = QStringLiteral("LD X0\nOR Y0\nANI X1\nOUT Y0\nLD Y0\nTMR T0 K20\nLD "
                                      "T0\nOUT Y1\nLD X2\nMOV K7 D0\nEND\n");

ScenarioResult run(const QString &scenario, const QString &listing = kLatch,
                   const model::Target &target = rung::testing::vigor()) {
    ListingLoader loader{&target, listing, {}};
    return runScenario(scenario, QStringLiteral("/plant/tests/latch.rungtest"), std::cref(loader));
}

std::string why(const ScenarioResult &r) {
    std::string s;
    for (const ScenarioError &e : r.errors)
        s += std::to_string(e.line) + ": " + e.message.toStdString() + "\n";
    for (const ScenarioFailure &f : r.failures)
        s += std::to_string(f.line) + ": " + f.message.toStdString() + "\n";
    return s;
}

} // namespace

// The statements of the issue, one each, on a program that holds them.
TEST(Scenario, TheIssuesStatementsPass) {
    const ScenarioResult r = run(QStringLiteral("program ../latch.il   # the program\n"
                                                "period 10ms\n"
                                                "at 0s set X0=1\n"
                                                "at 100ms set X0=0\n"
                                                "at 1s expect Y0=1 Y1=0\n"
                                                "at 2.1s expect Y0=1 Y1=1\n"
                                                "at 3s set X1=1\n"
                                                "within 20ms expect Y0=0 Y1=0\n"
                                                "always expect not (Y1 and not Y0)\n"));
    EXPECT_TRUE(r.passed()) << why(r);
    EXPECT_EQ(r.expectations.size(), 4u);
    EXPECT_EQ(r.durationMs, 3010);
    EXPECT_EQ(r.scans, 301u);
}

// A `within` that waited past the next `at` would apply it late without a word: the scenario
// fails there, saying when the run was. An `at T expect` before an `at T set` is as written.
TEST(Scenario, AStatementTheRunHasPassedIsAFailureNotALateChange) {
    const ScenarioResult late =
        run(QStringLiteral("program ../latch.il\n"
                           "at 0s set X0=1\n"
                           "within 3s expect Y1=1\n" // met in the scan at 2 s
                           "at 1s set X1=1\n"));
    ASSERT_EQ(late.failures.size(), 1u) << why(late);
    EXPECT_EQ(late.failures[0].line, 4);
    EXPECT_EQ(late.failures[0].message.toStdString(),
              QStringLiteral("at 1s set X1=1: the run was already at 2.01s (the statement before "
                             "waited until then), so it applied then, not at 1s")
                  .toStdString());
    const ScenarioResult asWritten = run(QStringLiteral("program ../latch.il\n"
                                                        "at 0s set X0=1\n"
                                                        "at 1s expect Y0=1\n"
                                                        "at 1s set X1=1\n"
                                                        "at 1s expect Y0=1\n"
                                                        "at 1.02s expect Y0=0\n"));
    EXPECT_TRUE(asWritten.passed()) << why(asWritten);
}

TEST(Scenario, TheProgramIsFoundBesideTheScenario) {
    ListingLoader loader{&rung::testing::vigor(), kLatch, {}};
    runScenario(QStringLiteral("program ../latch.il\nat 0s expect Y0=0\n"),
                QStringLiteral("/plant/tests/latch.rungtest"), std::cref(loader));
    EXPECT_EQ(loader.asked, QStringLiteral("/plant/latch.il"));
}

// A failure names the line, the time, what was expected and the values seen.
TEST(Scenario, AFailedExpectationSaysWhenWhatAndWhatWasSeen) {
    const ScenarioResult r = run(QStringLiteral("program latch.il\n"
                                                "at 0s set X0=1\n"
                                                "at 1.5s expect Y0=1 Y1=1   # too early\n"
                                                "at 3s set X1=1\n"
                                                "within 2scan expect Y0=1\n"
                                                "always expect Y1=0\n"));
    ASSERT_TRUE(r.ran) << why(r);
    ASSERT_EQ(r.failures.size(), 3u) << why(r);
    EXPECT_EQ(r.failures[0].line, 3);
    EXPECT_EQ(r.failures[0].timeMs, 1500);
    EXPECT_EQ(r.failures[0].message, QStringLiteral("at 1.5s: expected Y0=1 Y1=1, seen Y0=1 Y1=0"));
    EXPECT_EQ(r.failures[1].line, 5);
    EXPECT_EQ(r.failures[1].message,
              QStringLiteral("within 2scan of 3s (until 3.02s): expected Y0=1, seen Y0=0"));
    EXPECT_EQ(r.failures[2].line, 6);
    // T0 is done at 2 s: Y1 is ON from the scan that starts at 2 s until X1 stops it at 3 s:
    // 100 of the 303 scans run.
    EXPECT_EQ(r.failures[2].timeMs, 2000);
    EXPECT_TRUE(r.failures[2].message.startsWith(
        QStringLiteral("at 2s: expected always Y1=0, seen Y1=1 (failed in 100 of 303 scans)")))
        << r.failures[2].message.toStdString();
    EXPECT_EQ(r.failures[2].devices.size(), 1u);
}

// Words, set values, current values, forcing and hexadecimal words.
TEST(Scenario, WordsTimersAndForcing) {
    const ScenarioResult r = run(QStringLiteral("program latch.il\n"
                                                "at 0s set X0=1 X2=1\n"
                                                "at 0s expect sv:T0=20 D0=7 D0>6 D0<>8\n"
                                                "at 300ms expect cv:T0=3 Y1=OFF\n"
                                                "at 2.1s expect Y1=ON\n"
                                                "at 2.5s set X2=0 D0=0x10\n"
                                                "at 2.5s expect D0=16 D0=16#10\n"
                                                "at 3s force Y0=0\n"
                                                "at 3s expect not Y0 and not Y1\n"
                                                "at 4s release all\n"
                                                "at 4s expect Y0\n"));
    EXPECT_TRUE(r.passed()) << why(r);
}

TEST(Scenario, DevicesAsTheTargetWritesThem) {
    const model::Target &cpm1 = rung::testing::cpm1();
    const ScenarioResult r =
        run(QStringLiteral("program count.il --target cpm1\n"
                           "at 0s set DM 0010=#0150\n"
                           "at 0s set 000.01=1\n"
                           "at 0s expect 010.00=1 DM 0010=#0150 DM 0011 = 336\n"
                           "at 1s expect TIM 000 = OFF\n"),
            QStringLiteral("LD 000.01\nOUT 010.00\nLD 253.13\nMOV(21) DM 0010 DM 0011\nEND(01)\n"),
            cpm1);
    EXPECT_TRUE(r.passed()) << why(r);
}

// Lines that do not read, devices the target does not have and times out of order are errors
// with their lines; the scenario does not run.
TEST(Scenario, ErrorsHaveTheirLines) {
    std::vector<ScenarioError> errors;
    parseScenario(QStringLiteral("period fast\nat 1s push X0\nat 2 s expect\nrun 3 weeks\n"),
                  QStringLiteral("x.rungtest"), &errors);
    ASSERT_EQ(errors.size(), 5u);
    EXPECT_EQ(errors[0].line, 1);
    EXPECT_EQ(errors[1].line, 2);
    EXPECT_EQ(errors[2].line, 3);
    EXPECT_EQ(errors[2].message, QStringLiteral("the statement says nothing after its verb"));
    EXPECT_EQ(errors[3].line, 4);
    EXPECT_EQ(errors[4].message,
              QStringLiteral("no program: a scenario starts with \"program FILE\""));
    const ScenarioResult r = run(QStringLiteral("program latch.il\n"
                                                "at 1s set X8=1\n"
                                                "at 2s expect D0\n"
                                                "at 3s expect (Y0\n"
                                                "at 1s expect Y0=1\n"));
    EXPECT_FALSE(r.ran);
    ASSERT_EQ(r.errors.size(), 4u) << why(r);
    EXPECT_EQ(r.errors[0].line, 2);
    EXPECT_TRUE(r.errors[0].message.startsWith(QStringLiteral("X8 is no device of Vigor")))
        << r.errors[0].message.toStdString();
    EXPECT_EQ(r.errors[1].message, QStringLiteral("D0 is a word: compare it (D0=5, D0>100)"));
    EXPECT_EQ(r.errors[2].message, QStringLiteral("a \")\" is missing"));
    EXPECT_EQ(r.errors[3].line, 5);
    EXPECT_FALSE(r.passed());
}

// `press` holds a key of the front panel as a person does (PL110 manual 5.2, 5.3): SWAP steps
// the pages through its bit; SET held 2 s opens the password page, where the keys enter the
// system password 1357 digit by digit (SWAP's bit does not reach the program there: the page
// stays); then SET edits the slave address (SMW4), UP raises it, SET stores it.
TEST(Scenario, PressHoldsAFrontPanelKeyAndTheTerminalEditsAsOnThePlc) {
    QString text = QStringLiteral("program panel.il --target pl110\n"
                                  "at 0s set SM4=1\n"
                                  "at 0s expect SM105=1\n"
                                  "at 100ms press SWAP\n"
                                  "at 300ms press swap\n"
                                  "at 500ms expect SM105=3\n"
                                  "at 600ms press SET for 2.5s\n");
    qint64 ms = 3200;
    const auto press = [&](const char *key, int times = 1) {
        for (int k = 0; k < times; ++k, ms += 200)
            text += QStringLiteral("at %1ms press %2\n").arg(ms).arg(QLatin1String(key));
    };
    press("UP");
    press("SWAP");
    press("UP", 3);
    press("SWAP");
    press("UP", 5);
    press("SWAP");
    press("UP", 7);
    press("SET");
    text += QStringLiteral("at %1ms expect SM109=1357 SM105=3 SM4=1\n").arg(ms);
    press("SET");
    press("UP", 2);
    press("SET");
    text += QStringLiteral("at %1ms expect SM4=3\n").arg(ms);
    // The program shows another page while the address is edited: the value entered is not
    // stored (5.2), the next SET finds no field on page 1.
    press("SET");
    press("UP");
    text += QStringLiteral("at %1ms set SM106=1\n").arg(ms);
    ms += 200;
    press("SET");
    text += QStringLiteral("at %1ms expect SM4=3 SM105=1\n").arg(ms);
    const ScenarioResult r =
        run(text, QStringLiteral("LD SM0.0\nMOV 1 V0\nEND\n"), rung::testing::pl110());
    EXPECT_TRUE(r.passed()) << why(r) << text.toStdString();
    EXPECT_EQ(r.expectations.size(), 5u);

    // SET pressed for less than 2 s is a press, not the password page: nothing is entered.
    const ScenarioResult shortHold =
        run(QStringLiteral("program panel.il\n"
                           "at 100ms press SET for 1.9s\n"
                           "at 2.1s press UP\n"
                           "at 2.3s press SET\n"
                           "at 2.5s expect SM109=0\n"),
            QStringLiteral("LD SM0.0\nMOV 1 V0\nEND\n"), rung::testing::pl110());
    EXPECT_TRUE(shortHold.passed()) << why(shortHold);
}

// Taps one after another (100 ms each, the next at the instant the last ends): each key is up
// before the next goes down, so SET starts editing the field SetPAR made editable (PL110
// manual 4.2.26, page 18 of 5.4), UP raises it, SET stores it.
TEST(Scenario, BackToBackTapsAreEachAPress) {
    const ScenarioResult r = run(QStringLiteral("program page.il\n"
                                                "at 0s expect SM105=18\n"
                                                "at 100ms press SET\n"
                                                "at 200ms press UP\n"
                                                "at 300ms press SET\n"
                                                "at 400ms expect VW0=1\n"),
                                 QStringLiteral("LD SM0.1\nMOV 2 SM103\nLD SM0.1\nMOV 18 SM104\n"
                                                "LD SM0.0\nSetPAR 1 2 VW0 0 1400\nLD SM0.0\n"
                                                "PosPAR 1 4 10 0\nEND\n"),
                                 rung::testing::pl110());
    EXPECT_TRUE(r.passed()) << why(r);
}

// A key the panel does not have, a PLC without keys and a press that names more than a key are
// errors with their lines, the keys listed.
TEST(Scenario, PressErrorsNameTheKeys) {
    const QString program = QStringLiteral("LD SM0.0\nMOV 1 V0\nEND\n");
    std::vector<ScenarioError> errors;
    parseScenario(QStringLiteral("program panel.il\n"
                                 "at 2s press SET UP\n"
                                 "at 3s press SET for 2 weeks\n"),
                  QStringLiteral("x.rungtest"), &errors);
    ASSERT_EQ(errors.size(), 2u);
    EXPECT_EQ(errors[0].line, 2);
    EXPECT_EQ(errors[0].message,
              QStringLiteral("press names one key, then \"for TIME\" if it is held: \"SET UP\""));
    EXPECT_EQ(errors[1].line, 3);
    EXPECT_EQ(errors[1].message, QStringLiteral("2 weeks is no time"));
    const ScenarioResult r = run(QStringLiteral("program panel.il\nat 1s press ENTER\n"), program,
                                 rung::testing::pl110());
    EXPECT_FALSE(r.ran);
    ASSERT_EQ(r.errors.size(), 1u) << why(r);
    EXPECT_EQ(r.errors[0].line, 2);
    EXPECT_EQ(r.errors[0].message,
              QStringLiteral("ENTER is no key of the PL110's front panel (its keys: SWAP, UP, "
                             "DOWN, SET)"));
    const ScenarioResult vigor = run(QStringLiteral("program latch.il\nat 1s press SET\n"));
    ASSERT_EQ(vigor.errors.size(), 1u) << why(vigor);
    EXPECT_EQ(vigor.errors[0].message,
              QStringLiteral("SET: the Vigor has no keys on its front panel to press"));
}

TEST(Scenario, TimesAreWrittenAsPeopleReadThem) {
    EXPECT_EQ(formatScenarioTime(150), QStringLiteral("150ms"));
    EXPECT_EQ(formatScenarioTime(35000), QStringLiteral("35s"));
    EXPECT_EQ(formatScenarioTime(12340), QStringLiteral("12.34s"));
    EXPECT_EQ(formatScenarioTime(125000), QStringLiteral("2min 5s"));
    EXPECT_EQ(formatScenarioTime(3600000), QStringLiteral("1h"));
}

TEST(Scenario, JUnitHasATestCasePerExpectation) {
    std::vector<ScenarioResult> results;
    results.push_back(run(QStringLiteral("program latch.il\nat 0s set X0=1\nat 1s expect "
                                         "Y0=1\nat 1s expect Y1=1\n")));
    results.push_back(run(QStringLiteral("period 10ms\n")));
    const QByteArray xml = scenarioJUnit(results);
    QXmlStreamReader reader(xml);
    int cases = 0;
    int failures = 0;
    int errors = 0;
    QString failureMessage;
    while (!reader.atEnd()) {
        if (reader.readNext() != QXmlStreamReader::StartElement)
            continue;
        if (reader.name() == QLatin1String("testcase"))
            ++cases;
        if (reader.name() == QLatin1String("failure")) {
            ++failures;
            failureMessage = reader.attributes().value(QStringLiteral("message")).toString();
        }
        if (reader.name() == QLatin1String("error"))
            ++errors;
        if (reader.name() == QLatin1String("testsuites")) {
            EXPECT_EQ(reader.attributes().value(QStringLiteral("tests")).toString(),
                      QStringLiteral("3"));
            EXPECT_EQ(reader.attributes().value(QStringLiteral("failures")).toString(),
                      QStringLiteral("1"));
        }
    }
    EXPECT_FALSE(reader.hasError()) << reader.errorString().toStdString();
    EXPECT_EQ(cases, 3);
    EXPECT_EQ(failures, 1);
    EXPECT_EQ(errors, 1);
    EXPECT_EQ(failureMessage, QStringLiteral("at 1s: expected Y1=1, seen Y1=0"));
}

// Decimal times are read exactly (64.9 s is no 64899.99... ms), in every unit.
TEST(Scenario, TimesAreReadExactly) {
    std::vector<ScenarioError> errors;
    const Scenario s = parseScenario(
        QStringLiteral("program x.il\nperiod 5ms\nat 64.9s expect Y0\nat 1.5min expect Y0\n"
                       "within 10scans expect Y0\nrun 1.25h\nat 0.0005s expect Y0\n"),
        QStringLiteral("x.rungtest"), &errors);
    ASSERT_EQ(errors.size(), 1u);
    EXPECT_EQ(errors[0].line, 7);
    EXPECT_EQ(errors[0].message, QStringLiteral("0.0005s is not a whole number of milliseconds"));
    ASSERT_EQ(s.statements.size(), 4u);
    EXPECT_EQ(s.period->ms, 5);
    EXPECT_EQ(s.statements[0].time.ms, 64900);
    EXPECT_EQ(s.statements[1].time.ms, 90000);
    EXPECT_EQ(s.statements[2].time.resolve(5), 50);
    EXPECT_EQ(s.statements[3].time.ms, 4500000);
}

#include "simulator/command_inbox.h"
#include "simulator/scenario_record.h"

namespace {

// A simulation as the session drives one: commands recorded, applied, then scans.
struct Recording {
    std::shared_ptr<const Program> program;
    Engine engine;
    ScanHistory history;
    explicit Recording(std::shared_ptr<const Program> p)
        : program(p)
        , engine(p) {
        history.start(engine);
    }
    void command(model::DeviceCommand::Kind kind, const char *device, qint64 value) {
        model::DeviceCommand d;
        d.kind = kind;
        d.address = std::get<model::Address>(
            model::parseAddress(program->layout->target(), QString::fromLatin1(device)));
        d.value = value;
        EngineCommand c;
        c.what = d;
        history.record(engine, c);
        QString error;
        ASSERT_TRUE(applyCommand(engine, c, &error)) << error.toStdString();
    }
    void scans(int n) {
        for (int k = 0; k < n; ++k) {
            engine.scan();
            history.afterScan(engine, 1000);
        }
    }
};

std::shared_ptr<const Program> latch(const QString &listing = kLatch) {
    const model::ParseResult parsed = model::parseInstructionList(rung::testing::vigor(), listing);
    return compileProgram(parsed.list).program;
}

} // namespace

// Record a simulation as a scenario: the inputs as worked, the outputs as seen; it passes on
// the program it was recorded from and says what a change changed.
TEST(ScenarioRecord, ASimulationBecomesAScenarioThatReplays) {
    Recording r(latch());
    const model::Address y0 =
        std::get<model::Address>(model::parseAddress(rung::testing::vigor(), u"Y0"));
    const model::Address y1 =
        std::get<model::Address>(model::parseAddress(rung::testing::vigor(), u"Y1"));
    using K = model::DeviceCommand::Kind;
    r.scans(5);
    r.command(K::WriteBit, "X0", 1);
    r.scans(10);
    r.command(K::WriteBit, "X0", 0);
    r.scans(250); // T0 (2 s) done: Y1 ON
    r.command(K::Force, "Y0", 0);
    r.scans(3);
    r.command(K::ReleaseAll, "Y0", 0);
    r.scans(2);
    QString error;
    const auto recorded = recordScenario(r.history, rung::testing::vigor(),
                                         QStringLiteral("latch.il"), {y0, y1}, &error);
    ASSERT_TRUE(recorded) << error.toStdString();
    EXPECT_TRUE(recorded->notes.isEmpty());
    EXPECT_EQ(recorded->text.section(QLatin1Char('\n'), 1),
              QStringLiteral("program latch.il\n"
                             "period 10ms\n"
                             "\n"
                             "at 0.05s set X0=1\n"
                             "at 0.14s expect Y0=1 Y1=0\n"
                             "at 0.15s set X0=0\n"
                             "at 2.64s expect Y0=1 Y1=1\n"
                             "at 2.65s force Y0=0\n"
                             "at 2.67s expect Y0=0 Y1=0\n"
                             "at 2.68s release all\n"
                             "at 2.69s expect Y0=0 Y1=0\n"));
    ListingLoader same{&rung::testing::vigor(), kLatch, {}};
    const ScenarioResult replay =
        runScenario(recorded->text, QStringLiteral("/p/latch.rungtest"), std::cref(same));
    EXPECT_TRUE(replay.passed()) << why(replay);
    // The timer made longer: the replay says so.
    QString longer = kLatch;
    longer.replace(QStringLiteral("K20"), QStringLiteral("K30"));
    ListingLoader changed{&rung::testing::vigor(), longer, {}};
    const ScenarioResult failed =
        runScenario(recorded->text, QStringLiteral("/p/latch.rungtest"), std::cref(changed));
    ASSERT_EQ(failed.failures.size(), 1u) << why(failed);
    EXPECT_EQ(failed.failures[0].message,
              QStringLiteral("at 2.64s: expected Y0=1 Y1=1, seen Y0=1 Y1=0"));
}

TEST(ScenarioRecord, NothingToRecordIsSaid) {
    Recording r(latch());
    QString error;
    EXPECT_FALSE(
        recordScenario(r.history, rung::testing::vigor(), QStringLiteral("x.il"), {}, &error));
    EXPECT_TRUE(error.startsWith(QStringLiteral("the simulation has run no scan yet")));
}

// An online PLC recorded as a scenario: the PLC here is an engine scanning every 10 ms, read
// every 70 ms as an online session refreshes (the history of its inputs and outputs, refresh
// by refresh); an input switched between two refreshes is seen at the next one. The scenario
// replays on the program and says what a longer timer changed.
TEST(ScenarioRecord, AnOnlinePlcsRefreshesBecomeAScenarioThatReplays) {
    const model::Target &t = rung::testing::vigor();
    const auto address = [&](const char *name) {
        return std::get<model::Address>(model::parseAddress(t, QString::fromLatin1(name)));
    };
    Recording plc(latch());
    model::HistoryRecorder history(plc.program->layout);
    const std::vector<model::Address> inputs{address("X0"), address("X1")};
    const std::vector<model::Address> outputs{address("Y0"), address("Y1")};
    for (const auto &a : inputs)
        ASSERT_TRUE(history.watch(a));
    for (const auto &a : outputs)
        ASSERT_TRUE(history.watch(a));
    quint64 refreshes = 0;
    const qint64 connectedAt = 500; // the session's time runs from the connection
    const auto runFor = [&](int scans) {
        for (int k = 0; k < scans; ++k) {
            plc.scans(1);
            const qint64 now = connectedAt + plc.engine.statistics().timeMs;
            if (plc.engine.statistics().scans % 7 == 0)
                history.record(++refreshes, now, plc.engine.words().data());
        }
    };
    using K = model::DeviceCommand::Kind;
    runFor(30);
    plc.command(K::WriteBit, "X0", 1); // after scan 30 (0.3 s): seen at the 0.35 s refresh
    runFor(20);
    plc.command(K::WriteBit, "X0", 0);
    runFor(260); // T0 (2 s) done: Y1 ON
    plc.command(K::WriteBit, "X1", 1);
    runFor(40);
    const qint64 from = connectedAt; // recording started with the connection
    const qint64 to = connectedAt + plc.engine.statistics().timeMs;
    QString error;
    const auto recorded = recordObservedScenario(history, t, QStringLiteral("latch.il"), inputs,
                                                 outputs, from, to, 10, &error);
    ASSERT_TRUE(recorded) << error.toStdString();
    EXPECT_EQ(recorded->notes.size(), 1);
    EXPECT_EQ(recorded->text.section(QLatin1Char('\n'), 1),
              QStringLiteral("program latch.il\n"
                             "period 10ms\n"
                             "\n"
                             "at 0.35s set X0=1\n"
                             "at 0.55s expect Y0=1 Y1=0\n"
                             "at 0.56s set X0=0\n"
                             "at 3.14s expect Y0=1 Y1=1\n"
                             "at 3.15s set X1=1\n"
                             "at 3.5s expect Y0=0 Y1=0\n"));
    ListingLoader same{&t, kLatch, {}};
    const ScenarioResult replay =
        runScenario(recorded->text, QStringLiteral("/p/latch.rungtest"), std::cref(same));
    EXPECT_TRUE(replay.passed()) << why(replay);
    QString longer = kLatch;
    longer.replace(QStringLiteral("K20"), QStringLiteral("K30"));
    ListingLoader changed{&t, longer, {}};
    const ScenarioResult failed =
        runScenario(recorded->text, QStringLiteral("/p/latch.rungtest"), std::cref(changed));
    ASSERT_EQ(failed.failures.size(), 1u) << why(failed);
    EXPECT_EQ(failed.failures[0].message,
              QStringLiteral("at 3.14s: expected Y0=1 Y1=1, seen Y0=1 Y1=0"));
    // Nothing read while recording: said.
    model::HistoryRecorder empty(plc.program->layout);
    EXPECT_FALSE(recordObservedScenario(empty, t, QStringLiteral("latch.il"), inputs, outputs, from,
                                        to, 10, &error));
    EXPECT_TRUE(error.startsWith(QStringLiteral("nothing was recorded"))) << error.toStdString();
}
