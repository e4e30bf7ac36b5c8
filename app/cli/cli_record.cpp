#include "cli_record.h"

#include "cli_port_options.h"
#include "cli_stop_signals.h"

#include "app/tr.h"
#include "comms/driver/connection.h"
#include "comms/driver/relay.h"
#include "comms/transport/pty_transport.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFile>

namespace rung::app {

namespace {

// The capture is data a user keeps and compares: its labels are not translated.
const QString kToPlc = QStringLiteral("PC>PLC");
const QString kToPc = QStringLiteral("PLC>PC");

// A side of the relay: a new pseudo-terminal, an existing one, or a serial port.
std::unique_ptr<comms::Transport> makeSide(const QString &port, const comms::SerialSettings &line,
                                           QString *createdPath, QString *error) {
    if (port == QLatin1String("pty")) {
        auto pair = comms::PtyTransport::createPair(error);
        if (pair)
            *createdPath = pair->peerPath();
        return pair;
    }
    return comms::makePortTransport(port, line);
}

} // namespace

QString recordUsage() {
    return RecordTr::tr(
        "  rungstudio-cli record --pc PORT --plc PORT [--baud B] [--frame 8N1] [-o FILE]\n"
        "        [--seconds S]   (PORT: a serial port, a /dev/pts path, or pty for a new "
        "one)");
}

int runRecordCommand(const QStringList &args, QTextStream &out, QTextStream &err) {
    QString pcPort, plcPort, output, baudText, frame, secondsText;
    const auto fail = [&err](const QString &message) {
        err << message << '\n' << RecordTr::tr("usage:") << '\n' << recordUsage() << '\n';
        return 2;
    };
    QString error;
    comms::SerialSettings line;
    if (!takeValuedOptions(args,
                           {{"--pc", &pcPort},
                            {"--plc", &plcPort},
                            {"--baud", &baudText},
                            {"--frame", &frame},
                            {"--seconds", &secondsText},
                            {"-o", &output}},
                           &error))
        return fail(error);
    if (pcPort.isEmpty() || plcPort.isEmpty())
        return fail(RecordTr::tr("--pc and --plc are needed: the two ports to join"));
    if (!parseLineOptions(baudText, frame, &line, &error))
        return fail(error);
    double seconds = 0;
    if (!secondsText.isEmpty()) {
        bool ok = false;
        seconds = secondsText.toDouble(&ok);
        if (!ok || seconds <= 0)
            return fail(
                RecordTr::tr("--seconds must be a positive number; got %1").arg(secondsText));
    }

    QString pcCreated, plcCreated;
    auto pc = makeSide(pcPort, line, &pcCreated, &error);
    if (!pc) {
        err << RecordTr::tr("the PC's side: %1").arg(error) << '\n';
        return 2;
    }
    auto plc = makeSide(plcPort, line, &plcCreated, &error);
    if (!plc) {
        err << RecordTr::tr("the PLC's side: %1").arg(error) << '\n';
        return 2;
    }
    const QString pcName = pcCreated.isEmpty() ? pcPort : pcCreated;
    const QString plcName = plcCreated.isEmpty() ? plcPort : plcCreated;

    QFile file(output);
    QTextStream toFile(&file);
    QTextStream &capture = output.isEmpty() ? out : toFile;
    if (!output.isEmpty() && !file.open(QIODevice::WriteOnly | QIODevice::Text)) {
        err << RecordTr::tr("cannot write %1: %2").arg(output, file.errorString()) << '\n';
        return 2;
    }

    StopSignals stopSignals; // before the relay's threads start, so that they inherit the mask

    comms::Relay relay(std::move(pc), std::move(plc));
    if (!relay.start(&error)) {
        err << error << '\n';
        return 2;
    }
    // A script reads where to connect before anything else.
    if (!pcCreated.isEmpty())
        out << "pc " << pcCreated << Qt::endl;
    if (!plcCreated.isEmpty())
        out << "plc " << plcCreated << Qt::endl;
    const QDateTime start = relay.tap().start();
    capture << "# rungstudio-cli record: PC " << pcName << ", PLC " << plcName << ", " << line.baud
            << ' ' << comms::frameFormatText(line) << ", started "
            << start.toString(Qt::ISODateWithMs) << Qt::endl;
    err << RecordTr::tr("Passing bytes between %1 (PC) and %2 (PLC); stop with Ctrl+C")
               .arg(pcName, plcName)
        << Qt::endl;

    quint64 next = 0, lost = 0, records = 0, toPlc = 0, toPc = 0;
    const auto drain = [&] {
        const quint64 from = next;
        const std::vector<comms::TrafficRecord> batch = relay.tap().records(from, &next);
        // The tap keeps its last records only: a capture that fell behind says where.
        if (!batch.empty() && batch.front().sequence > from) {
            lost += batch.front().sequence - from;
            capture << "# " << (batch.front().sequence - from) << " records lost here" << '\n';
        }
        for (const comms::TrafficRecord &r : batch) {
            capture << comms::formatTrafficRecord(r, start, kToPlc, kToPc) << '\n';
            ++records;
            (r.direction == comms::TrafficRecord::Direction::Sent ? toPlc : toPc) +=
                quint64(r.bytes.size());
        }
        capture.flush();
    };
    QElapsedTimer clock;
    clock.start();
    while (relay.running()) {
        if (stopSignals.wait(100))
            break;
        drain();
        if (seconds > 0 && double(clock.elapsed()) >= seconds * 1000)
            break;
    }
    const QString failure = relay.failure();
    relay.stop();
    drain();
    err << RecordTr::tr("%1 bytes from the PC, %2 bytes from the PLC, in %3 records")
               .arg(toPlc)
               .arg(toPc)
               .arg(records)
        << '\n';
    if (lost > 0)
        err << RecordTr::tr(
                   "%1 records were lost: the capture was not written as fast as they came")
                   .arg(lost)
            << '\n';
    if (!failure.isEmpty()) {
        err << failure << '\n';
        return 2;
    }
    return 0;
}

} // namespace rung::app
