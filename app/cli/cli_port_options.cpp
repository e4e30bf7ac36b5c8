#include "cli_port_options.h"
#include "app/tr.h"

#include <QCoreApplication>

namespace rung::app {

bool takeValuedOptions(const QStringList &args, std::initializer_list<ValuedOption> options,
                       QString *error) {
    for (qsizetype i = 0; i < args.size(); ++i) {
        const ValuedOption *match = nullptr;
        for (const ValuedOption &o : options)
            if (args[i] == QLatin1String(o.name))
                match = &o;
        if (!match) {
            *error = PortOptionsTr::tr("unexpected argument %1").arg(args[i]);
            return false;
        }
        if (i + 1 >= args.size()) {
            *error = PortOptionsTr::tr("%1 needs a value").arg(args[i]);
            return false;
        }
        *match->value = args[++i];
    }
    return true;
}

bool parseLineOptions(const QString &baud, const QString &frame, comms::SerialSettings *line,
                      QString *error) {
    if (!baud.isEmpty()) {
        bool ok = false;
        const int value = baud.toInt(&ok);
        if (!ok || value < 50 || value > 4'000'000) {
            *error =
                PortOptionsTr::tr("--baud must be a number from 50 to 4000000; got %1").arg(baud);
            return false;
        }
        line->baud = value;
    }
    if (!frame.isEmpty() && !comms::parseFrameFormat(frame, line)) {
        *error = PortOptionsTr::tr(
                     "--frame must be data bits, parity and stop bits, e.g. 8N1 or 7E2; got %1")
                     .arg(frame);
        return false;
    }
    return true;
}

} // namespace rung::app
