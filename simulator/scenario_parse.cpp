#include "scenario.h"
#include "simulator/tr.h"

#include <QCoreApplication>
#include <QRegularExpression>

// Reading a `.rungtest` file (docs/scenario-tests.md): the statements and their times. What a
// statement says about devices is read when the program, and so the target, is known
// (scenario_run.cpp).

namespace rung::simulator {

namespace {

// A comment starts at a '#' at the start of a line or after a space, unless a hexadecimal
// digit follows it: "#0150" is a CPM1 word written in its digits ("DM 0010 = #0150").
QString withoutComment(const QString &line) {
    for (qsizetype i = 0; i < line.size(); ++i) {
        if (line[i] != QLatin1Char('#'))
            continue;
        const bool afterSpace = i == 0 || line[i - 1].isSpace();
        const bool digitFollows =
            i + 1 < line.size() && QStringLiteral("0123456789abcdefABCDEF").contains(line[i + 1]);
        if (afterSpace && !digitFollows)
            return line.left(i);
    }
    return line;
}

const QString kTime = QStringLiteral("(\\d+(?:\\.\\d+)?)\\s*(ms|s|min|h|scans?)");

// The time of a statement: a number and its unit. nullopt when it is none.
std::optional<ScenarioTime> readScenarioTime(const QString &number, const QString &unitText,
                                             QString *error) {
    const QString unit = unitText.toLower();
    ScenarioTime t;
    t.text = number + unitText;
    // Decimal digits read exactly: 64.9 s is 64900 ms, which a double does not hold.
    const QStringList parts = number.split(QLatin1Char('.'));
    bool ok = parts.size() <= 2 && parts[0].size() <= 9;
    const qint64 whole = ok ? parts[0].toLongLong(&ok) : 0;
    const QString fractionText = parts.size() == 2 ? parts[1] : QString();
    if (!ok || fractionText.size() > 6)
        return std::nullopt;
    qint64 scale = 1;
    for (qsizetype i = 0; i < fractionText.size(); ++i)
        scale *= 10;
    const qint64 fraction = fractionText.isEmpty() ? 0 : fractionText.toLongLong(&ok);
    if (!ok)
        return std::nullopt;
    if (unit.startsWith(QLatin1String("scan"))) {
        if (fraction != 0) {
            *error = ScenarioTr::tr("%1: a number of scans is whole").arg(t.text);
            return std::nullopt;
        }
        t.inScans = true;
        t.scans = whole;
        return t;
    }
    const qint64 factor = unit == QLatin1String("ms")    ? 1
                          : unit == QLatin1String("s")   ? 1000
                          : unit == QLatin1String("min") ? 60000
                                                         : 3600000;
    // A week of virtual time is 60 million scans at 10 ms: far beyond a test, and a bound.
    constexpr qint64 kMaxMs = 7LL * 24 * 3600000;
    if (whole > kMaxMs / factor) {
        *error = ScenarioTr::tr("%1 is more than a week of virtual time").arg(t.text);
        return std::nullopt;
    }
    if ((fraction * factor) % scale != 0) {
        *error = ScenarioTr::tr("%1 is not a whole number of milliseconds").arg(t.text);
        return std::nullopt;
    }
    const qint64 ms = whole * factor + fraction * factor / scale;
    t.ms = ms;
    return t;
}

} // namespace

Scenario parseScenario(const QString &text, const QString &file,
                       std::vector<ScenarioError> *errors) {
    static const QRegularExpression program(
        QStringLiteral("^program\\s+(\"[^\"]+\"|.+?)((?:\\s+--\\S+\\s+\\S+)*)$"),
        QRegularExpression::CaseInsensitiveOption);
    static const QRegularExpression period(QStringLiteral("^period\\s+") + kTime +
                                               QStringLiteral("$"),
                                           QRegularExpression::CaseInsensitiveOption);
    static const QRegularExpression at(
        QStringLiteral("^at\\s+") + kTime +
            QStringLiteral("\\s+(set|force|release|expect|press)\\b\\s*(.*)$"),
        QRegularExpression::CaseInsensitiveOption);
    static const QRegularExpression within(QStringLiteral("^within\\s+") + kTime +
                                               QStringLiteral("\\s+expect\\b\\s*(.*)$"),
                                           QRegularExpression::CaseInsensitiveOption);
    static const QRegularExpression always(QStringLiteral("^always\\s+expect\\b\\s*(.*)$"),
                                           QRegularExpression::CaseInsensitiveOption);
    static const QRegularExpression run(QStringLiteral("^run\\s+") + kTime + QStringLiteral("$"),
                                        QRegularExpression::CaseInsensitiveOption);
    static const QRegularExpression pressHold(QStringLiteral("^(\\S+)\\s+for\\s+") + kTime +
                                                  QStringLiteral("$"),
                                              QRegularExpression::CaseInsensitiveOption);
    Scenario s;
    s.file = file;
    const QStringList lines = text.split(QLatin1Char('\n'));
    auto fail = [errors](int line, const QString &message) { errors->push_back({line, message}); };
    for (qsizetype i = 0; i < lines.size(); ++i) {
        const int lineNo = static_cast<int>(i) + 1;
        const QString line = withoutComment(lines[i]).trimmed();
        if (line.isEmpty())
            continue;
        QString timeError;
        auto time = [&](const QRegularExpressionMatch &m) {
            auto t = readScenarioTime(m.captured(1), m.captured(2), &timeError);
            if (!t)
                fail(lineNo, timeError.isEmpty()
                                 ? ScenarioTr::tr("%1 is no time").arg(m.captured(0))
                                 : timeError);
            return t;
        };
        if (const auto m = program.match(line); m.hasMatch()) {
            if (!s.program.isEmpty()) {
                fail(lineNo, ScenarioTr::tr("a scenario runs one program; the first is on line %1")
                                 .arg(s.programLine));
                continue;
            }
            s.program = m.captured(1);
            if (s.program.startsWith(QLatin1Char('"')))
                s.program = s.program.mid(1, s.program.size() - 2);
            s.programLine = lineNo;
            const QStringList options =
                m.captured(2).simplified().split(QLatin1Char(' '), Qt::SkipEmptyParts);
            for (qsizetype k = 0; k + 1 < options.size(); k += 2) {
                if (options[k] == QLatin1String("--target"))
                    s.target = options[k + 1];
                else if (options[k] == QLatin1String("--model"))
                    s.model = options[k + 1];
                else
                    fail(lineNo,
                         ScenarioTr::tr("unknown option %1 (--target, --model)").arg(options[k]));
            }
            continue;
        }
        if (const auto m = period.match(line); m.hasMatch()) {
            const auto t = time(m);
            if (t && (t->inScans || t->ms < 1))
                fail(lineNo, ScenarioTr::tr("the period is a time of at least 1 ms"));
            else if (t)
                s.period = *t;
            continue;
        }
        ScenarioStatement st;
        st.line = lineNo;
        st.source = line;
        if (const auto m = at.match(line); m.hasMatch()) {
            const auto t = time(m);
            if (!t)
                continue;
            st.time = *t;
            const QString verb = m.captured(3).toLower();
            st.kind = verb == QLatin1String("set")       ? ScenarioStatement::Kind::Set
                      : verb == QLatin1String("force")   ? ScenarioStatement::Kind::Force
                      : verb == QLatin1String("release") ? ScenarioStatement::Kind::Release
                      : verb == QLatin1String("press")   ? ScenarioStatement::Kind::Press
                                                         : ScenarioStatement::Kind::Expect;
            st.text = m.captured(4).trimmed();
            if (st.kind == ScenarioStatement::Kind::Press) {
                // One key, held for a time or for a tap's 100 ms.
                static const QRegularExpression keyFor(QStringLiteral("^(\\S+)\\s+for\\s+(.*)$"),
                                                       QRegularExpression::CaseInsensitiveOption);
                const QRegularExpressionMatch withFor = keyFor.match(st.text);
                if (withFor.hasMatch()) {
                    const QRegularExpressionMatch held = pressHold.match(st.text);
                    QString holdError;
                    if (held.hasMatch())
                        st.hold = readScenarioTime(held.captured(2), held.captured(3), &holdError);
                    if (!st.hold) {
                        fail(lineNo, holdError.isEmpty()
                                         ? ScenarioTr::tr("%1 is no time").arg(withFor.captured(2))
                                         : holdError);
                        continue;
                    }
                    st.text = withFor.captured(1);
                } else if (st.text.contains(QLatin1Char(' '))) {
                    fail(lineNo, ScenarioTr::tr("press names one key, then \"for TIME\" if it "
                                                "is held: \"%1\"")
                                     .arg(st.text));
                    continue;
                }
            }
        } else if (const auto w = within.match(line); w.hasMatch()) {
            const auto t = time(w);
            if (!t)
                continue;
            st.kind = ScenarioStatement::Kind::Within;
            st.time = *t;
            st.text = w.captured(3).trimmed();
        } else if (const auto a = always.match(line); a.hasMatch()) {
            st.kind = ScenarioStatement::Kind::Always;
            st.text = a.captured(1).trimmed();
        } else if (const auto r = run.match(line); r.hasMatch()) {
            const auto t = time(r);
            if (!t)
                continue;
            st.kind = ScenarioStatement::Kind::Run;
            st.time = *t;
        } else {
            fail(lineNo,
                 ScenarioTr::tr("\"%1\" is no statement (program, period, at TIME set|force|"
                                "release|expect|press, within TIME expect, always expect, run "
                                "TIME)")
                     .arg(line));
            continue;
        }
        if (st.kind != ScenarioStatement::Kind::Run && st.text.isEmpty()) {
            fail(lineNo, ScenarioTr::tr("the statement says nothing after its verb"));
            continue;
        }
        s.statements.push_back(st);
    }
    if (s.program.isEmpty())
        fail(1, ScenarioTr::tr("no program: a scenario starts with \"program FILE\""));
    return s;
}

QString formatSeconds(qint64 ms) {
    QString s = QString::number(static_cast<double>(ms) / 1000.0, 'f', 3);
    while (s.endsWith(QLatin1Char('0')))
        s.chop(1);
    if (s.endsWith(QLatin1Char('.')))
        s.chop(1);
    return s + QLatin1Char('s');
}

QString formatScenarioTime(qint64 ms) {
    if (ms < 1000)
        return QStringLiteral("%1ms").arg(ms);
    if (ms < 60000)
        return formatSeconds(ms);
    const qint64 minutes = ms / 60000;
    const qint64 rest = ms % 60000;
    if (minutes >= 60) {
        const QString hours = QStringLiteral("%1h").arg(minutes / 60);
        return minutes % 60 == 0 && rest == 0
                   ? hours
                   : hours + QLatin1Char(' ') + formatScenarioTime((minutes % 60) * 60000 + rest);
    }
    return rest == 0 ? QStringLiteral("%1min").arg(minutes)
                     : QStringLiteral("%1min %2").arg(minutes).arg(formatScenarioTime(rest));
}

} // namespace rung::simulator
