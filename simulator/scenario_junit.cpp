#include "scenario.h"

#include <QFileInfo>
#include <QXmlStreamWriter>

// Scenario results as JUnit XML, the report CI servers read (Jenkins, GitLab, GitHub's test
// reporters): <testsuites> with a <testsuite> per scenario file and a <testcase> per
// expectation; a failed expectation holds a <failure>, a scenario that did not run an <error>.

namespace rung::simulator {

QByteArray scenarioJUnit(const std::vector<ScenarioResult> &results) {
    QByteArray out;
    QXmlStreamWriter xml(&out);
    xml.setAutoFormatting(true);
    xml.writeStartDocument();
    int tests = 0;
    int failures = 0;
    int errors = 0;
    for (const ScenarioResult &r : results) {
        tests += r.ran ? static_cast<int>(r.expectations.size()) : 1;
        errors += r.ran ? 0 : 1;
        for (const ScenarioResult::Expectation &e : r.expectations)
            failures += std::any_of(r.failures.begin(), r.failures.end(),
                                    [&e](const ScenarioFailure &f) { return f.line == e.line; })
                            ? 1
                            : 0;
    }
    xml.writeStartElement(QStringLiteral("testsuites"));
    xml.writeAttribute(QStringLiteral("name"), QStringLiteral("rungstudio-cli test"));
    xml.writeAttribute(QStringLiteral("tests"), QString::number(tests));
    xml.writeAttribute(QStringLiteral("failures"), QString::number(failures));
    xml.writeAttribute(QStringLiteral("errors"), QString::number(errors));
    for (const ScenarioResult &r : results) {
        const QString suite = QFileInfo(r.file).completeBaseName();
        xml.writeStartElement(QStringLiteral("testsuite"));
        xml.writeAttribute(QStringLiteral("name"), suite);
        xml.writeAttribute(QStringLiteral("file"), r.file);
        int suiteFailures = 0;
        for (const ScenarioResult::Expectation &e : r.expectations)
            suiteFailures +=
                std::any_of(r.failures.begin(), r.failures.end(),
                            [&e](const ScenarioFailure &f) { return f.line == e.line; })
                    ? 1
                    : 0;
        xml.writeAttribute(QStringLiteral("tests"),
                           QString::number(r.ran ? r.expectations.size() : 1));
        xml.writeAttribute(QStringLiteral("failures"), QString::number(suiteFailures));
        xml.writeAttribute(QStringLiteral("errors"), QString::number(r.ran ? 0 : 1));
        // Virtual time: the time the program ran, not the time the test took.
        xml.writeAttribute(QStringLiteral("time"),
                           QString::number(static_cast<double>(r.durationMs) / 1000.0, 'f', 3));
        if (!r.ran) {
            xml.writeStartElement(QStringLiteral("testcase"));
            xml.writeAttribute(QStringLiteral("classname"), suite);
            xml.writeAttribute(QStringLiteral("name"), QStringLiteral("load"));
            xml.writeStartElement(QStringLiteral("error"));
            QStringList lines;
            for (const ScenarioError &e : r.errors)
                lines << QStringLiteral("%1:%2: %3").arg(r.file).arg(e.line).arg(e.message);
            xml.writeAttribute(QStringLiteral("message"), lines.value(0));
            xml.writeCharacters(lines.join(QLatin1Char('\n')));
            xml.writeEndElement();
            xml.writeEndElement();
        }
        for (const ScenarioResult::Expectation &e : r.expectations) {
            if (!r.ran)
                break;
            xml.writeStartElement(QStringLiteral("testcase"));
            xml.writeAttribute(QStringLiteral("classname"), suite);
            xml.writeAttribute(QStringLiteral("name"),
                               QStringLiteral("line %1: %2").arg(e.line).arg(e.statement));
            xml.writeAttribute(QStringLiteral("file"), r.file);
            xml.writeAttribute(QStringLiteral("line"), QString::number(e.line));
            for (const ScenarioFailure &f : r.failures) {
                if (f.line != e.line)
                    continue;
                xml.writeStartElement(QStringLiteral("failure"));
                xml.writeAttribute(QStringLiteral("message"), f.message);
                xml.writeCharacters(
                    QStringLiteral("%1:%2: %3").arg(r.file).arg(f.line).arg(f.message));
                xml.writeEndElement();
            }
            xml.writeEndElement();
        }
        if (!r.runtimeErrors.isEmpty())
            xml.writeTextElement(QStringLiteral("system-err"),
                                 r.runtimeErrors.join(QLatin1Char('\n')));
        xml.writeEndElement();
    }
    xml.writeEndElement();
    xml.writeEndDocument();
    return out;
}

} // namespace rung::simulator
