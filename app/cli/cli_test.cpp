#include "cli_test.h"
#include "app/tr.h"

#include "cli_common.h"
#include "cli_load_program.h"
#include "cli_network.h"

#include "network/network_scenario.h"
#include "simulator/scenario.h"

#include <QCoreApplication>
#include <QDirIterator>
#include <QFileInfo>
#include <QSaveFile>

#include <algorithm>

namespace rung::app {

namespace {

const QString kExtension = QStringLiteral("rungtest");

// The program a scenario names, loaded and prepared as `simulate` does (its errors as
// `simulate` prints them).
simulator::ScenarioProgram loadScenarioProgram(const QString &path, const QString &target,
                                               const QString &model) {
    simulator::ScenarioProgram out;
    ProgramOptions options;
    options.file = path;
    options.target = target;
    options.model = model;
    QString messages;
    QTextStream stream(&messages);
    LoadedProgram loaded;
    if (loadProgram(options, &loaded, stream) == 0)
        out.program = loaded.program;
    stream.flush();
    out.errors = messages.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    return out;
}

} // namespace

QString testUsage() {
    return TestTr::tr("  rungstudio-cli test FILE|DIR... [--junit OUT.xml]   (scenario tests, "
                      ".rungtest)");
}

int runTestCommand(const QStringList &args, QTextStream &out, QTextStream &err) {
    QStringList inputs;
    QString junit;
    for (qsizetype i = 0; i < args.size(); ++i) {
        if (args[i] == QLatin1String("--junit")) {
            if (i + 1 >= args.size()) {
                err << TestTr::tr("--junit needs a value") << '\n' << testUsage() << '\n';
                return 2;
            }
            junit = args[++i];
        } else if (args[i].startsWith(QLatin1String("--"))) {
            err << TestTr::tr("unknown option %1").arg(args[i]) << '\n' << testUsage() << '\n';
            return 2;
        } else {
            inputs << args[i];
        }
    }
    if (inputs.isEmpty()) {
        err << TestTr::tr("no scenario given") << '\n' << testUsage() << '\n';
        return 2;
    }
    QStringList files;
    for (const QString &input : inputs) {
        const QFileInfo info(input);
        if (info.isDir()) {
            QStringList found;
            QDirIterator it(input, {QStringLiteral("*.") + kExtension}, QDir::Files,
                            QDirIterator::Subdirectories);
            while (it.hasNext())
                found << it.next();
            std::sort(found.begin(), found.end());
            if (found.isEmpty()) {
                err << TestTr::tr("%1: no .%2 file in the folder").arg(input, kExtension) << '\n';
                return 2;
            }
            files << found;
        } else if (info.exists()) {
            files << input;
        } else {
            err << TestTr::tr("%1: no such file or folder").arg(input) << '\n';
            return 2;
        }
    }
    std::vector<simulator::ScenarioResult> results;
    int failed = 0;
    int expectations = 0;
    int failedExpectations = 0;
    for (const QString &file : files) {
        QByteArray bytes;
        QString error;
        if (!readInputFile(file, &bytes, &error)) {
            err << error << '\n';
            return 2;
        }
        simulator::ScenarioResult r = simulator::runScenario(
            QString::fromUtf8(bytes), file, loadScenarioProgram,
            [](const QString &path, QStringList *errors) {
                return network::networkScenarioSubject(path, cliProgramLoader(), errors);
            });
        for (const simulator::ScenarioError &e : r.errors)
            out << QStringLiteral("%1:%2: %3: %4")
                       .arg(file)
                       .arg(e.line)
                       .arg(TestTr::tr("error"), e.message)
                << '\n';
        for (const simulator::ScenarioFailure &f : r.failures)
            out << QStringLiteral("%1:%2: %3").arg(file).arg(f.line).arg(f.message) << '\n';
        for (const QString &note : r.runtimeErrors)
            err << QStringLiteral("%1: %2: %3").arg(file, TestTr::tr("note"), note) << '\n';
        if (!r.passed())
            ++failed;
        expectations += static_cast<int>(r.expectations.size());
        std::vector<int> lines;
        for (const simulator::ScenarioFailure &f : r.failures)
            lines.push_back(f.line);
        std::sort(lines.begin(), lines.end());
        failedExpectations +=
            static_cast<int>(std::unique(lines.begin(), lines.end()) - lines.begin());
        results.push_back(std::move(r));
    }
    //: The summary of a test run: %1 scenario files, %2 expectations, %3 failed expectations,
    //: %4 scenarios that failed or did not run.
    out << TestTr::tr("%1 scenario(s), %2 expectation(s): %3 failed; %4 scenario(s) did not pass")
               .arg(results.size())
               .arg(expectations)
               .arg(failedExpectations)
               .arg(failed)
        << '\n';
    if (!junit.isEmpty()) {
        const QByteArray xml = simulator::scenarioJUnit(results);
        QSaveFile f(junit);
        if (!f.open(QIODevice::WriteOnly) || f.write(xml) != xml.size() || !f.commit()) {
            err << TestTr::tr("cannot write %1: %2").arg(junit, f.errorString()) << '\n';
            return 2;
        }
    }
    return failed == 0 ? 0 : 1;
}

} // namespace rung::app
