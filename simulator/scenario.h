#pragma once

// Scenario tests (docs/scenario-tests.md): a `.rungtest` file drives a program on virtual time
// and states what must hold. The file is read here (parseScenario), run on the scan engine
// (runScenario, scenario_run.cpp) and reported as JUnit XML (scenarioJUnit). Below the
// widgets: the command-line tool's `test` and the IDE's Tests dock run the same code.

#include "engine.h"

#include <QString>
#include <QStringList>

#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace rung::simulator {

// A time as written: a count of milliseconds or of scans ("10scan"), resolved with the period.
struct ScenarioTime {
    qint64 ms = 0;
    qint64 scans = 0;
    bool inScans = false;
    QString text; // as written, for the report
    qint64 resolve(qint64 periodMs) const { return inScans ? scans * periodMs : ms; }
};

struct ScenarioStatement {
    enum class Kind : std::uint8_t {
        Set,     // at T set DEV=VALUE ...
        Force,   // at T force DEV=VALUE ...
        Release, // at T release DEV ... | at T release all
        Expect,  // at T expect COND
        Within,  // within D expect COND (from the previous statement's time)
        Always,  // always expect COND (every scan of the run)
        Run,     // run T: the run goes on at least until T
        Press,   // at T press KEY [for D]: a key of the PLC's front panel, held D (100 ms)
    } kind = Kind::Set;
    int line = 0;
    ScenarioTime time; // at / within / run
    QString text;      // what follows set/force/release/expect, as written; press: the key
    std::optional<ScenarioTime> hold; // press ... for D
    QString source;                   // the whole statement as written, without its comment
};

struct Scenario {
    QString file;    // path (for the report and to find the program)
    QString program; // as written after `program`
    QString target;  // --target of the program line, or empty
    QString model;   // --model, or empty
    std::optional<ScenarioTime> period;
    int programLine = 0;
    std::vector<ScenarioStatement> statements;
};

struct ScenarioError {
    int line = 0;
    QString message; // translated
};

// Reads a scenario; every line that does not read is an error with its line (the scenario
// does not run then). A statement per line; `#` starts a comment.
Scenario parseScenario(const QString &text, const QString &file,
                       std::vector<ScenarioError> *errors);

// One expectation that did not hold.
struct ScenarioFailure {
    int line = 0;
    qint64 timeMs = 0;                   // the instant it was checked (the scan's start)
    QString statement;                   // the statement as written ("at 35s expect Y0=0 Y1=1")
    QString seen;                        // the values of the devices it names then ("Y0=1 Y1=0")
    QString message;                     // translated, whole: what, when and what was seen
    quint64 failingScans = 1;            // `always`: how many scans it failed in
    std::vector<model::Address> devices; // the devices it names (for a timing chart)
};

struct ScenarioResult {
    QString file;
    bool ran = false;                  // false: it did not start (errors says why)
    std::vector<ScenarioError> errors; // the file, the program or a statement
    std::vector<ScenarioFailure> failures;
    struct Expectation {
        int line = 0;
        QString statement; // as written
    };
    std::vector<Expectation> expectations; // every expectation, in the file's order
    QStringList runtimeErrors; // the program's own (division by zero ...): said, not failures
    qint64 durationMs = 0;     // virtual time run
    quint64 scans = 0;
    bool passed() const { return ran && errors.empty() && failures.empty(); }
};

// The program a scenario names, compiled, or why not (translated lines, each with its place).
struct ScenarioProgram {
    std::shared_ptr<const Program> program;
    QStringList errors;
};
// path: the program file (resolved against the scenario's folder), target / model as the
// program line names them (empty: the file's). The command-line tool loads files; the IDE
// hands its open document when the path is its project.
using ScenarioProgramLoader = std::function<ScenarioProgram(
    const QString &path, const QString &target, const QString &model)>;

// What a scenario drives on virtual time: one program on its engine (here), or a network of
// stations (the network room's, network/network_scenario.h; the simulator knows no network).
class ScenarioSubject {
public:
    virtual ~ScenarioSubject() = default;
    // The engine a device written in the scenario belongs to, and the device as that engine's
    // target writes it: a network's "st1/D0" is station st1's "D0". Null with *error (what
    // and why) when it names none.
    virtual Engine *engineFor(const QString &written, QString *device, QString *error) = 0;
    virtual qint64 defaultPeriodMs() const = 0;
    // Before the first step: the scenario's period, the virtual time one step moves on.
    virtual void start(qint64 periodMs) = 0;
    // One period: a program's one scan; a network's every event up to the period's end.
    virtual void step() = 0;
    // `release all`: every engine's forces.
    virtual void releaseAll() {}
    // The programs' own errors (a division by zero ...), said in the report, not failures.
    virtual QStringList runtimeErrors() const = 0;
};

// A network (`program plant.rungnet`) as a subject, or null with the reasons.
using ScenarioNetworkLoader =
    std::function<std::unique_ptr<ScenarioSubject>(const QString &path, QStringList *errors)>;

// Parses, loads the program and runs it on a fresh engine (docs/scenario-tests.md "How a
// scenario runs"). The default period is the engine's (10 ms); a network's is its file's.
// Without a network loader a scenario of a network does not start (the error says so).
ScenarioResult runScenario(const QString &text, const QString &file,
                           const ScenarioProgramLoader &loader,
                           const ScenarioNetworkLoader &networkLoader = {});
// The same from a parsed scenario and a program at hand; `afterScan`, when given, sees the
// engine after every scan (the timing chart of a run records from it).
ScenarioResult runScenario(const Scenario &scenario, const std::shared_ptr<const Program> &program,
                           const std::function<void(const Engine &)> &afterScan = {});
// The same on any subject.
ScenarioResult runScenario(const Scenario &scenario, ScenarioSubject &subject);

// A duration as the reports write it: "35s", "12.34s", "150ms", "2min 5s".
// A time in seconds with the decimals it needs, as a scenario reads it back ("65.32s", "3s").
QString formatSeconds(qint64 ms);
QString formatScenarioTime(qint64 ms);

// JUnit XML (the schema CI servers read: testsuites / testsuite / testcase / failure, error):
// a suite per scenario file, a test case per expectation.
QByteArray scenarioJUnit(const std::vector<ScenarioResult> &results);

} // namespace rung::simulator
