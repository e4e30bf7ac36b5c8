#include "trace.h"

#include "model/image/scan_csv.h"
#include "model/target/address.h"
#include "simulator/tr.h"

#include <QCoreApplication>
#include <QRegularExpression>

#include <algorithm>
#include <variant>

namespace rung::simulator {

namespace {

bool device(const model::Target &target, const QString &text, model::Address *address,
            QString *error) {
    const auto parsed = model::parseAddress(target, text.trimmed());
    if (const auto *e = std::get_if<model::AddressError>(&parsed)) {
        *error = TraceTr::tr("unknown device %1: %2").arg(text, e->message);
        return false;
    }
    *address = std::get<model::Address>(parsed);
    return true;
}

bool isWord(const model::Target &target, const model::Address &a) {
    const model::AreaKind k = target.area(a.area).kind;
    return a.bit < 0 && (k == model::AreaKind::Word || k == model::AreaKind::Channel);
}

bool isTimerOrCounter(const model::Target &target, const model::Address &a) {
    const model::AreaKind k = target.area(a.area).kind;
    return a.bit < 0 && (k == model::AreaKind::Timer || k == model::AreaKind::Counter);
}

} // namespace

bool parseTraceDevice(const model::Target &target, const QString &text, model::Address *address,
                      QString *error) {
    return device(target, text, address, error);
}

bool parseTraceValue(const QString &value, qint64 *into) {
    bool ok = false;
    *into = value.startsWith(QLatin1Char('#')) ? value.mid(1).toLongLong(&ok, 16)
                                               : value.toLongLong(&ok);
    return ok;
}

bool parseTraceColumn(const model::Target &target, const QString &name, TraceColumn *column,
                      QString *error) {
    TraceColumn c;
    c.name = name.trimmed();
    QString dev = c.name;
    if (dev.startsWith(QLatin1String("cv:"), Qt::CaseInsensitive)) {
        c.kind = TraceColumn::Kind::Word;
        dev = dev.mid(3);
    } else if (dev.startsWith(QLatin1String("sv:"), Qt::CaseInsensitive)) {
        c.kind = TraceColumn::Kind::SetValue;
        dev = dev.mid(3);
    } else if (dev.startsWith(QLatin1String("hex:"), Qt::CaseInsensitive)) {
        c.kind = TraceColumn::Kind::Hex; // BCD words read as their digits
        dev = dev.mid(4);
    }
    if (!device(target, dev, &c.address, error))
        return false;
    if (c.kind == TraceColumn::Kind::Bit && isWord(target, c.address))
        c.kind = TraceColumn::Kind::Word;
    *column = c;
    return true;
}

void applyStimulus(Engine &engine, const TraceStimulus &s) {
    const model::Target &target = engine.layout().target();
    if (isTimerOrCounter(target, s.address))
        engine.writeSetValue(s.address, s.value);
    else if (isWord(target, s.address))
        engine.writeWord(s.address, s.value);
    else
        engine.setBit(s.address, s.value != 0);
}

QString traceValue(const Engine &engine, const TraceColumn &c) {
    switch (c.kind) {
    case TraceColumn::Kind::Bit:
        return engine.bit(c.address) ? QStringLiteral("1") : QStringLiteral("0");
    case TraceColumn::Kind::Word:
        return QString::number(engine.value(c.address));
    case TraceColumn::Kind::SetValue:
        return QString::number(engine.setValue(c.address));
    case TraceColumn::Kind::Hex:
        return QLatin1Char('#') +
               QStringLiteral("%1")
                   .arg(static_cast<std::uint32_t>(engine.value(c.address)) & 0xFFFFu, 4, 16,
                        QLatin1Char('0'))
                   .toUpper();
    }
    return {};
}

bool parseTraceOptions(const model::Target &target, const QStringList &args, TraceRequest *request,
                       QString *error) {
    // A value is a number, or a word written in hexadecimal digits as CPM1 listings write
    // their # constants (--set "200=#6103@1": the word 6103h).
    static const QRegularExpression setRe(
        QStringLiteral("^(.+)=(-?\\d+|#[0-9A-Fa-f]{1,8})@(\\d+)$"));
    bool haveScans = false;
    for (qsizetype i = 0; i < args.size(); ++i) {
        const QString &a = args[i];
        if (i + 1 >= args.size() || !a.startsWith(QLatin1String("--"))) {
            *error = a.startsWith(QLatin1String("--"))
                         ? TraceTr::tr("%1 needs a value").arg(a)
                         : TraceTr::tr("unexpected argument %1").arg(a);
            return false;
        }
        const QString v = args[++i];
        if (a == QLatin1String("--scans") || a == QLatin1String("--period")) {
            bool ok = false;
            const qint64 n = v.toLongLong(&ok);
            const bool scans = a == QLatin1String("--scans");
            const qint64 most = scans ? kMaxTraceScans : 1000000000;
            if (!ok || n < 1) {
                *error = TraceTr::tr("%1 needs a whole number from 1 to %2, not \"%3\"")
                             .arg(a)
                             .arg(most)
                             .arg(v);
                return false;
            }
            if (n > most) {
                // A trace prints a row per scan: an unbounded run would never end.
                *error = scans ? TraceTr::tr("--scans %1 is more than the %2 scans one trace runs "
                                             "(a row each); run it in parts")
                                     .arg(v)
                                     .arg(most)
                               : TraceTr::tr("--period %1 is more than %2 ms").arg(v).arg(most);
                return false;
            }
            if (scans) {
                request->scans = static_cast<quint64>(n);
                haveScans = true;
            } else {
                request->periodMs = n;
            }
        } else if (a == QLatin1String("--set")) {
            const auto m = setRe.match(v);
            if (!m.hasMatch()) {
                *error = TraceTr::tr("--set needs DEV=VALUE@SCAN, not \"%1\"").arg(v);
                return false;
            }
            TraceStimulus s;
            if (!device(target, m.captured(1), &s.address, error))
                return false;
            bool ok = false;
            const QString value = m.captured(2);
            s.value = value.startsWith(QLatin1Char('#')) ? value.mid(1).toLongLong(&ok, 16)
                                                         : value.toLongLong(&ok);
            s.scan = m.captured(3).toULongLong(&ok);
            request->stimuli.push_back(s);
        } else if (a == QLatin1String("--trace")) {
            for (const QString &name : v.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
                TraceColumn c;
                if (!parseTraceColumn(target, name, &c, error))
                    return false;
                request->columns.push_back(c);
            }
        } else {
            *error = TraceTr::tr("unknown option %1").arg(a);
            return false;
        }
    }
    if (!haveScans || request->columns.empty()) {
        *error = TraceTr::tr("--scans and --trace are required");
        return false;
    }
    // A stimulus after the last scan would never apply: said, not dropped.
    for (qsizetype i = 0; i + 1 < args.size(); i += 2)
        if (args[i] == QLatin1String("--set")) {
            const auto m = setRe.match(args[i + 1]);
            if (m.captured(3).toULongLong() >= request->scans) {
                //: --set DEV=VALUE@N applies once N (%2) scans have run; %3 scans run
                *error = TraceTr::tr("--set %1 comes after the last scan: it applies once %2 scans "
                                     "have run, and %3 run, so it would never apply")
                             .arg(args[i + 1])
                             .arg(m.captured(3).toULongLong())
                             .arg(request->scans);
                return false;
            }
        }
    std::stable_sort(
        request->stimuli.begin(), request->stimuli.end(),
        [](const TraceStimulus &x, const TraceStimulus &y) { return x.scan < y.scan; });
    return true;
}

void runTrace(const std::shared_ptr<const Program> &program, const TraceRequest &request,
              QTextStream &out, std::vector<RuntimeError> *runtimeErrors) {
    const model::Target &target = program->layout->target();
    Engine engine(program);
    engine.setPeriodMs(request.periodMs);
    QStringList names;
    for (const TraceColumn &c : request.columns)
        names << c.name;
    model::ScanCsvWriter csv(out, names);
    QStringList values(names.size());
    auto next = request.stimuli.begin();
    for (quint64 scan = 0; scan < request.scans; ++scan) {
        for (; next != request.stimuli.end() && next->scan <= scan; ++next) {
            if (isTimerOrCounter(target, next->address))
                engine.writeSetValue(next->address, next->value);
            else if (isWord(target, next->address))
                engine.writeWord(next->address, next->value);
            else
                engine.setBit(next->address, next->value != 0);
        }
        engine.scan();
        for (qsizetype k = 0; k < values.size(); ++k) {
            const TraceColumn &c = request.columns[static_cast<std::size_t>(k)];
            switch (c.kind) {
            case TraceColumn::Kind::Bit:
                values[k] = engine.bit(c.address) ? QStringLiteral("1") : QStringLiteral("0");
                break;
            case TraceColumn::Kind::Word:
                values[k] = QString::number(engine.value(c.address));
                break;
            case TraceColumn::Kind::SetValue:
                values[k] = QString::number(engine.setValue(c.address));
                break;
            case TraceColumn::Kind::Hex:
                values[k] = QLatin1Char('#') +
                            QStringLiteral("%1")
                                .arg(static_cast<std::uint32_t>(engine.value(c.address)) & 0xFFFFu,
                                     4, 16, QLatin1Char('0'))
                                .toUpper();
                break;
            }
        }
        csv.row(engine.statistics().scans, engine.statistics().timeMs, values);
    }
    if (runtimeErrors)
        *runtimeErrors = engine.runtimeErrors();
}

} // namespace rung::simulator
