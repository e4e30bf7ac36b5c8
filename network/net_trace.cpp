#include "network/net_trace.h"
#include "network/tr.h"

#include "network/station.h"

#include "model/image/scan_csv.h"

#include <QCoreApplication>
#include <QRegularExpression>

namespace rung::network {

Station *stationDevice(const Network &network, const QString &text, QString *device,
                       QString *error) {
    const qsizetype slash = text.indexOf(QLatin1Char('/'));
    if (slash <= 0) {
        *error =
            TraceTr::tr("%1: name a station's device as STATION/DEVICE, e.g. %2/%3")
                .arg(text, network.stations().front()->name(),
                     network.stations().front()->target().areas.front().prefix +
                         QString::number(network.stations().front()->target().areas.front().first));
        return nullptr;
    }
    Station *s = network.station(text.left(slash));
    if (!s) {
        QStringList names;
        for (const auto &st : network.stations())
            names << st->name();
        *error = TraceTr::tr("%1: no station \"%2\" (the stations: %3)")
                     .arg(text, text.left(slash), names.join(QStringLiteral(", ")));
        return nullptr;
    }
    *device = text.mid(slash + 1);
    return s;
}

bool parseNetworkTraceOptions(const Network &network, const QStringList &args,
                              NetTraceRequest *request, QString *error) {
    static const QRegularExpression setRe(
        QStringLiteral("^(.+)=(-?\\d+|#[0-9A-Fa-f]{1,8})@(\\d+)$"));
    bool haveRows = false;
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
            const bool rows = a == QLatin1String("--scans");
            const qint64 most = rows ? simulator::kMaxTraceScans : 1000000000;
            if (!ok || n < 1 || n > most) {
                *error = TraceTr::tr("%1 needs a whole number from 1 to %2, not \"%3\"")
                             .arg(a)
                             .arg(most)
                             .arg(v);
                return false;
            }
            if (rows) {
                request->rows = quint64(n);
                haveRows = true;
            } else {
                request->periodMs = n;
            }
        } else if (a == QLatin1String("--set")) {
            const auto m = setRe.match(v);
            if (!m.hasMatch()) {
                *error = TraceTr::tr("--set needs STATION/DEV=VALUE@SCAN, not \"%1\"").arg(v);
                return false;
            }
            NetStimulus s;
            QString device;
            s.station = stationDevice(network, m.captured(1), &device, error);
            if (!s.station ||
                !simulator::parseTraceDevice(s.station->target(), device, &s.stimulus.address,
                                             error) ||
                !simulator::parseTraceValue(m.captured(2), &s.stimulus.value))
                return false;
            s.stimulus.scan = m.captured(3).toULongLong();
            request->stimuli.push_back(s);
        } else if (a == QLatin1String("--trace")) {
            for (const QString &name : v.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
                NetTraceColumn c;
                c.name = name.trimmed();
                QString device;
                // A prefix (cv:, sv:, hex:) goes before the station: hex:master/D1.
                QString kind;
                QString rest = c.name;
                static const QRegularExpression prefixRe(QStringLiteral("^(cv:|sv:|hex:)(.*)$"),
                                                         QRegularExpression::CaseInsensitiveOption);
                if (const auto pm = prefixRe.match(rest); pm.hasMatch()) {
                    kind = pm.captured(1);
                    rest = pm.captured(2);
                }
                c.station = stationDevice(network, rest, &device, error);
                if (!c.station || !simulator::parseTraceColumn(c.station->target(), kind + device,
                                                               &c.column, error))
                    return false;
                request->columns.push_back(c);
            }
        } else {
            *error = TraceTr::tr("unknown option %1").arg(a);
            return false;
        }
    }
    if (!haveRows || request->columns.empty()) {
        *error = TraceTr::tr("--scans and --trace are required");
        return false;
    }
    // A stimulus after the last row would never apply: said, not dropped.
    for (const NetStimulus &s : request->stimuli)
        if (s.stimulus.scan >= request->rows) {
            //: --set DEV=VALUE@N applies once N (%1) rows of scans have run; %2 rows run
            *error = TraceTr::tr("--set at %1 comes after the last row: it applies once %1 rows "
                                 "have run, and %2 run, so it would never apply")
                         .arg(s.stimulus.scan)
                         .arg(request->rows);
            return false;
        }
    std::stable_sort(request->stimuli.begin(), request->stimuli.end(),
                     [](const NetStimulus &x, const NetStimulus &y) {
                         return x.stimulus.scan < y.stimulus.scan;
                     });
    return true;
}

void runNetworkTrace(Network &network, const NetTraceRequest &request, QTextStream &out) {
    const qint64 period = request.periodMs > 0 ? request.periodMs : network.description().periodMs;
    QStringList names;
    for (const NetTraceColumn &c : request.columns)
        names << c.name;
    // The CSV of a program's trace (model/image/scan_csv.h): row k at the virtual time k x
    // period, the end of the k-th scan of a station scanning at that period.
    model::ScanCsvWriter csv(out, names);
    QStringList values(names.size());
    auto next = request.stimuli.begin();
    for (quint64 row = 1; row <= request.rows; ++row) {
        for (; next != request.stimuli.end() && next->stimulus.scan < row; ++next)
            simulator::applyStimulus(next->station->engine(), next->stimulus);
        const qint64 time = qint64(row) * period;
        network.runUntil(time * 1000);
        for (qsizetype k = 0; k < values.size(); ++k) {
            const NetTraceColumn &c = request.columns[std::size_t(k)];
            values[k] = simulator::traceValue(c.station->engine(), c.column);
        }
        csv.row(row, time, values);
    }
}

} // namespace rung::network
