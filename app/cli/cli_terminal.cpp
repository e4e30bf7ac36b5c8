#include "cli_terminal.h"

#include "cli_port_options.h"

#include "app/tr.h"
#include "comms/driver/connection.h"
#include "comms/driver/relay.h"

#include <QCoreApplication>
#include <QRegularExpression>

#include <optional>

namespace rung::app {

namespace {

// As `record` labels them, so that what this prints reads and replays as a capture.
const QString kSent = QStringLiteral("PC>PLC");
const QString kReceived = QStringLiteral("PLC>PC");

// A quoted text with the escapes a C string has: \r \n \t \\ \" \xNN.
std::optional<QByteArray> quotedBytes(QStringView body) {
    QByteArray out;
    for (qsizetype i = 0; i < body.size(); ++i) {
        const QChar c = body[i];
        if (c.unicode() > 0x7e)
            return std::nullopt;
        if (c != u'\\') {
            out += char(c.unicode());
            continue;
        }
        if (++i >= body.size())
            return std::nullopt;
        switch (body[i].unicode()) {
        case u'r':
            out += '\r';
            break;
        case u'n':
            out += '\n';
            break;
        case u't':
            out += '\t';
            break;
        case u'\\':
            out += '\\';
            break;
        case u'"':
            out += '"';
            break;
        case u'x': {
            if (i + 2 >= body.size())
                return std::nullopt;
            bool ok = false;
            const int value = body.mid(i + 1, 2).toInt(&ok, 16);
            if (!ok)
                return std::nullopt;
            out += char(value);
            i += 2;
            break;
        }
        default:
            return std::nullopt;
        }
    }
    return out;
}

std::optional<QByteArray> hexBytes(QStringView text) {
    QByteArray digits;
    for (const QChar c : text) {
        if (c.isSpace())
            continue;
        const bool hex =
            (c >= u'0' && c <= u'9') || (c >= u'a' && c <= u'f') || (c >= u'A' && c <= u'F');
        if (!hex)
            return std::nullopt;
        digits += char(c.unicode());
    }
    if (digits.isEmpty() || digits.size() % 2 != 0)
        return std::nullopt;
    return QByteArray::fromHex(digits);
}

// The bytes a line asks to send; an empty array for a line that sends nothing (blank, a
// comment, the PLC's side of a capture); nullopt for a line that is no bytes.
std::optional<QByteArray> lineBytes(const QString &line) {
    static const QRegularExpression capture(
        QStringLiteral("^\\d\\d:\\d\\d:\\d\\d\\.\\d+ (\\S+) ([0-9A-Fa-f ]+?)  \\|.*\\|$"));
    const QString trimmed = line.trimmed();
    if (trimmed.isEmpty() || trimmed.startsWith(u'#'))
        return QByteArray();
    if (const auto m = capture.match(trimmed); m.hasMatch())
        return m.captured(1) == kSent ? hexBytes(m.captured(2)) : QByteArray();
    if (trimmed.size() >= 2 && trimmed.startsWith(u'"') && trimmed.endsWith(u'"'))
        return quotedBytes(QStringView(trimmed).mid(1, trimmed.size() - 2));
    return hexBytes(trimmed);
}

} // namespace

QString terminalUsage() {
    return TerminalTr::tr(
        "  rungstudio-cli terminal --port PORT [--baud B] [--frame 8N1] [--wait MS]\n"
        "        (each line of stdin: hex bytes, \"text\\r\", or a capture line)");
}

int runTerminalCommand(const QStringList &args, QTextStream &in, QTextStream &out,
                       QTextStream &err) {
    QString port, baudText, frame, waitText;
    const auto fail = [&err](const QString &message) {
        err << message << '\n' << TerminalTr::tr("usage:") << '\n' << terminalUsage() << '\n';
        return 2;
    };
    QString error;
    comms::SerialSettings line;
    if (!takeValuedOptions(
            args,
            {{"--port", &port}, {"--baud", &baudText}, {"--frame", &frame}, {"--wait", &waitText}},
            &error))
        return fail(error);
    if (port.isEmpty())
        return fail(TerminalTr::tr("--port is needed"));
    if (!parseLineOptions(baudText, frame, &line, &error))
        return fail(error);
    int waitMs = 500;
    if (!waitText.isEmpty()) {
        bool ok = false;
        waitMs = waitText.toInt(&ok);
        if (!ok || waitMs < 1 || waitMs > 60'000)
            return fail(
                TerminalTr::tr("--wait must be a number from 1 to 60000; got %1").arg(waitText));
    }

    const std::unique_ptr<comms::Transport> transport = comms::makePortTransport(port, line);
    if (!transport->open(&error)) {
        err << error << '\n';
        return 2;
    }
    comms::TrafficTap tap;
    quint64 next = 0;
    const auto print = [&] {
        for (const comms::TrafficRecord &r : tap.records(next, &next))
            out << comms::formatTrafficRecord(r, tap.start(), kSent, kReceived) << '\n';
        out.flush();
    };
    // What arrives until the line has been quiet for waitMs.
    const auto listen = [&]() -> bool {
        while (true) {
            const comms::ReadResult r = transport->read(QDeadlineTimer(waitMs));
            if (r.status == comms::ReadResult::Status::Data) {
                tap.append(comms::TrafficRecord::Direction::Received, r.bytes);
                print();
                continue;
            }
            if (r.status == comms::ReadResult::Status::Failed) {
                err << r.message << '\n';
                return false;
            }
            return true;
        }
    };
    int number = 0;
    while (!in.atEnd()) {
        const QString text = in.readLine();
        ++number;
        const std::optional<QByteArray> bytes = lineBytes(text);
        if (!bytes) {
            err << TerminalTr::tr("line %1: \"%2\" is neither hex bytes (02 30 31), a quoted text "
                                  "(\"@00RD\\r\") nor a capture line")
                       .arg(number)
                       .arg(text.trimmed())
                << '\n';
            return 2;
        }
        if (bytes->isEmpty())
            continue;
        tap.append(comms::TrafficRecord::Direction::Sent, *bytes);
        print();
        if (!transport->write(*bytes, QDeadlineTimer(2000), &error)) {
            err << error << '\n';
            return 2;
        }
        if (!listen())
            return 2;
    }
    return 0;
}

} // namespace rung::app
