#include "scenario_record.h"
#include "simulator/tr.h"

#include "model/target/address.h"

#include <QCoreApplication>

#include <algorithm>

namespace rung::simulator {

namespace {

QString device(const model::Target &t, const model::Address &a) {
    return model::formatAddress(t, a);
}

// The outputs' values after `scan` scans, as an expectation ("Y0=1 Y1=0").
QString seen(const ScanHistory &history, const model::Target &t,
             const std::vector<model::Address> &outputs, quint64 scan) {
    const auto snapshot = history.rebuild(scan);
    if (!snapshot)
        return {};
    QStringList parts;
    for (const model::Address &a : outputs)
        parts << QStringLiteral("%1=%2").arg(device(t, a)).arg(snapshot->bit(a) ? 1 : 0);
    return parts.join(QLatin1Char(' '));
}

} // namespace

std::optional<RecordedScenario> recordScenario(const ScanHistory &history, const model::Target &t,
                                               const QString &programLine,
                                               const std::vector<model::Address> &outputs,
                                               QString *error) {
    const ScanHistory::Window window = history.window();
    if (window.empty() || window.lastScan == 0) {
        *error = ScenarioTr::tr("the simulation has run no scan yet: run it, work its inputs, then "
                                "record");
        return std::nullopt;
    }
    if (window.firstScan > 0) {
        *error =
            ScenarioTr::tr("the simulation's history no longer holds its start (it keeps the last "
                           "hour): stop it, run it again and record sooner");
        return std::nullopt;
    }
    RecordedScenario out;
    const qint64 period = history.firstPeriodMs();
    QStringList lines;
    lines << QStringLiteral("# %1").arg(
                 ScenarioTr::tr("Recorded from a simulation: the inputs as they "
                                "were worked, the outputs as they were seen."))
          << QStringLiteral("program %1").arg(programLine)
          << QStringLiteral("period %1ms").arg(period) << QString();
    const std::vector<ScanHistory::Recorded> events = history.recorded();
    auto time = [period](quint64 scan) {
        return formatSeconds(static_cast<qint64>(scan) * period);
    };
    bool periodNoted = false;
    bool insideNoted = false;
    std::size_t k = 0;
    quint64 previous = 0;
    bool first = true;
    while (k < events.size()) {
        const quint64 scan = events[k].scan;
        // The outputs seen just before these commands (after the scans run since the last).
        if (!first && scan > previous) {
            const QString values = seen(history, t, outputs, scan);
            if (!values.isEmpty() && !outputs.empty())
                lines << QStringLiteral("at %1 expect %2").arg(time(scan - 1), values);
        }
        QStringList sets;
        for (; k < events.size() && events[k].scan == scan; ++k) {
            const ScanHistory::Recorded &e = events[k];
            if (e.position >= 0 && !insideNoted) {
                insideNoted = true;
                out.notes << ScenarioTr::tr("a command given while a scan was stopped inside is "
                                            "applied at the start of the next scan");
            }
            if (std::holds_alternative<ScanHistory::SetPeriod>(e.action)) {
                if (!periodNoted)
                    out.notes << ScenarioTr::tr("the period was changed during the simulation: the "
                                                "scenario runs at the first one, %1 ms")
                                     .arg(period);
                periodNoted = true;
                continue;
            }
            const EngineCommand &c = std::get<EngineCommand>(e.action);
            if (const auto *d = std::get_if<model::DeviceCommand>(&c.what)) {
                using K = model::DeviceCommand::Kind;
                const QString name = device(t, d->address);
                switch (d->kind) {
                case K::WriteBit:
                case K::WriteWord:
                case K::WriteSetValue:
                    sets << QStringLiteral("at %1 set %2=%3").arg(time(scan), name).arg(d->value);
                    break;
                case K::Force:
                    sets << QStringLiteral("at %1 force %2=%3").arg(time(scan), name).arg(d->value);
                    break;
                case K::Release:
                    sets << QStringLiteral("at %1 release %2").arg(time(scan), name);
                    break;
                case K::ReleaseAll:
                    sets << QStringLiteral("at %1 release all").arg(time(scan));
                    break;
                }
            } else {
                out.notes << ScenarioTr::tr(
                                 "a power cycle, reset or online edit at %1 is not in the "
                                 "scenario")
                                 .arg(time(scan));
            }
        }
        lines << sets;
        previous = scan;
        first = false;
    }
    // The outputs at the end of the run.
    if (!outputs.empty()) {
        const QString values = seen(history, t, outputs, window.lastScan);
        if (!values.isEmpty())
            lines << QStringLiteral("at %1 expect %2").arg(time(window.lastScan - 1), values);
    }
    out.text = lines.join(QLatin1Char('\n')) + QLatin1Char('\n');
    return out;
}

std::optional<RecordedScenario>
recordObservedScenario(const model::HistoryRecorder &history, const model::Target &t,
                       const QString &programLine, const std::vector<model::Address> &inputs,
                       const std::vector<model::Address> &outputs, qint64 fromMs, qint64 toMs,
                       qint64 periodMs, QString *error) {
    const qint64 period = std::max<qint64>(1, periodMs);
    struct Event {
        qint64 at = 0;   // rounded up to the period, from fromMs
        qint64 seen = 0; // as observed, from fromMs
        std::size_t input = 0;
        std::int32_t value = 0;
    };
    std::vector<Event> events;
    bool anything = false;
    for (std::size_t i = 0; i < inputs.size(); ++i) {
        const auto changes = history.changes(inputs[i], fromMs, toMs);
        anything = anything || !changes.empty();
        // The scenario starts at power-on, every input 0: an input first read as 0 has not
        // changed.
        std::int32_t last = 0;
        for (const model::HistoryRecorder::Change &c : changes) {
            if (c.value == last)
                continue;
            last = c.value;
            const qint64 seen = std::max<qint64>(0, c.timeMs - fromMs);
            events.push_back({(seen + period - 1) / period * period, seen, i, c.value});
        }
    }
    for (const model::Address &a : outputs)
        anything = anything || !history.changes(a, fromMs, toMs).empty();
    if (!anything) {
        *error = ScenarioTr::tr("nothing was recorded: the PLC's inputs and outputs were not read "
                                "while recording");
        return std::nullopt;
    }
    std::stable_sort(events.begin(), events.end(),
                     [](const Event &a, const Event &b) { return a.at < b.at; });
    // The outputs as they were seen just before `seenMs`, as an expectation.
    const auto expectation = [&](qint64 seenMs) {
        QStringList parts;
        for (const model::Address &a : outputs)
            if (const auto v = history.valueAtTime(a, fromMs + seenMs))
                parts << QStringLiteral("%1=%2").arg(device(t, a)).arg(*v);
        return parts.join(QLatin1Char(' '));
    };
    RecordedScenario out;
    QStringList lines;
    lines << QStringLiteral("# %1").arg(
                 ScenarioTr::tr("Recorded from an online PLC: its inputs and outputs as each "
                                "refresh read them."))
          << QStringLiteral("program %1").arg(programLine)
          << QStringLiteral("period %1ms").arg(period) << QString();
    out.notes << ScenarioTr::tr("the PLC was read refresh by refresh: what changed between two "
                                "refreshes is not in the scenario, and the scenario runs at a "
                                "%1 ms scan, not the PLC's own")
                     .arg(period);
    qint64 previous = -1;
    for (std::size_t k = 0; k < events.size();) {
        const qint64 at = events[k].at;
        if (previous >= 0 && at - period > previous && !outputs.empty()) {
            const QString values = expectation(events[k].seen - 1);
            if (!values.isEmpty())
                lines << QStringLiteral("at %1 expect %2").arg(formatSeconds(at - period), values);
        }
        // One statement per input at this time: its last value.
        QStringList sets;
        std::vector<std::size_t> done;
        for (std::size_t j = events.size(); j-- > k;) {
            if (events[j].at != at ||
                std::find(done.begin(), done.end(), events[j].input) != done.end())
                continue;
            done.push_back(events[j].input);
            sets.prepend(QStringLiteral("%1=%2")
                             .arg(device(t, inputs[events[j].input]))
                             .arg(events[j].value));
        }
        lines << QStringLiteral("at %1 set %2").arg(formatSeconds(at), sets.join(QLatin1Char(' ')));
        while (k < events.size() && events[k].at == at)
            ++k;
        previous = at;
    }
    const qint64 end = (toMs - fromMs) / period * period;
    if (!outputs.empty() && end > previous) {
        const QString values = expectation(toMs - fromMs);
        if (!values.isEmpty())
            lines << QStringLiteral("at %1 expect %2").arg(formatSeconds(end), values);
    }
    out.text = lines.join(QLatin1Char('\n')) + QLatin1Char('\n');
    return out;
}

} // namespace rung::simulator
