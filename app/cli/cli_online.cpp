#include "cli_online.h"

#include "app/tr.h"
#include "comms/driver/connection.h"
#include "comms/driver/driver.h"
#include "model/image/snapshot.h"
#include "model/target/address.h"
#include "model/target/target.h"

#include <QCoreApplication>

namespace rung::app {

namespace {

QString onlineUsageText() {
    return OnlineTr::tr("usage:") + QLatin1Char('\n') + onlineUsage();
}

struct Options {
    const model::Target *target = nullptr;
    comms::ConnectionSettings settings;
    QStringList items; // devices, or DEVICE=VALUE
};

bool parseOptions(const QStringList &args, Options *o, QString *error) {
    QString targetId, protocol, port, tcp, pty, station, baud, frame, timeout, retries;
    const struct {
        const char *name;
        QString *value;
    } valued[] = {{"--target", &targetId}, {"--protocol", &protocol}, {"--port", &port},
                  {"--tcp", &tcp},         {"--pty", &pty},           {"--station", &station},
                  {"--baud", &baud},       {"--frame", &frame},       {"--timeout", &timeout},
                  {"--retries", &retries}};
    for (qsizetype i = 0; i < args.size(); ++i) {
        bool taken = false;
        for (const auto &v : valued) {
            if (args[i] != QLatin1String(v.name))
                continue;
            if (i + 1 >= args.size()) {
                *error = OnlineTr::tr("%1 needs a value").arg(args[i]);
                return false;
            }
            *v.value = args[++i];
            taken = true;
        }
        if (taken)
            continue;
        if (args[i].startsWith(QLatin1String("--"))) {
            *error = OnlineTr::tr("unknown option %1").arg(args[i]);
            return false;
        }
        o->items << args[i];
    }
    if (targetId.isEmpty() || protocol.isEmpty()) {
        *error = OnlineTr::tr("--target and --protocol are needed");
        return false;
    }
    o->target = model::Target::byId(targetId);
    if (!o->target) {
        *error = OnlineTr::tr("unknown target %1").arg(targetId);
        return false;
    }
    comms::ProtocolKind kind;
    if (!comms::parseProtocolKind(protocol, &kind)) {
        *error = OnlineTr::tr("unknown protocol %1: vigor, modbus, modbus-tcp or hostlink")
                     .arg(protocol);
        return false;
    }
    o->settings = comms::defaultSettings(kind);
    const int places = int(!port.isEmpty()) + int(!tcp.isEmpty()) + int(!pty.isEmpty());
    if (places != 1) {
        *error = OnlineTr::tr("give exactly one of --port, --tcp and --pty");
        return false;
    }
    if (kind == comms::ProtocolKind::ModbusTcp && tcp.isEmpty()) {
        *error =
            OnlineTr::tr("modbus-tcp needs --tcp HOST:PORT (for RTU frames on a port: modbus)");
        return false;
    }
    if (!tcp.isEmpty()) {
        const qsizetype colon = tcp.lastIndexOf(u':');
        bool ok = false;
        const int number = colon > 0 ? tcp.mid(colon + 1).toInt(&ok) : 0;
        if (!ok || number < 1 || number > 65535) {
            *error = OnlineTr::tr("--tcp needs HOST:PORT, e.g. 127.0.0.1:502; got %1").arg(tcp);
            return false;
        }
        o->settings.via = comms::ConnectionSettings::Via::Tcp;
        o->settings.host = tcp.left(colon);
        o->settings.tcpPort = quint16(number);
    } else {
        o->settings.via = pty.isEmpty() ? comms::ConnectionSettings::Via::Serial
                                        : comms::ConnectionSettings::Via::Pty;
        o->settings.port = pty.isEmpty() ? port : pty;
    }
    const auto number = [error](const QString &text, const char *option, int lowest, int highest,
                                int *value) {
        if (text.isEmpty())
            return true;
        bool ok = false;
        const int n = text.toInt(&ok);
        if (!ok || n < lowest || n > highest) {
            *error = OnlineTr::tr("%1 must be a number from %2 to %3; got %4")
                         .arg(QLatin1String(option))
                         .arg(lowest)
                         .arg(highest)
                         .arg(text);
            return false;
        }
        *value = n;
        return true;
    };
    if (!number(station, "--station", 0, 255, &o->settings.station) ||
        !number(baud, "--baud", 50, 4000000, &o->settings.serial.baud) ||
        !number(timeout, "--timeout", 10, 60000, &o->settings.link.timeoutMs) ||
        !number(retries, "--retries", 0, 10, &o->settings.link.retries))
        return false;
    if (!frame.isEmpty() && !comms::parseFrameFormat(frame, &o->settings.serial)) {
        *error =
            OnlineTr::tr("--frame must be data bits, parity and stop bits, e.g. 8N1 or 7E2; got %1")
                .arg(frame);
        return false;
    }
    if (o->items.isEmpty()) {
        *error = OnlineTr::tr("no device given");
        return false;
    }
    return true;
}

// The driver, its port not opened yet; exit code 0, or 2 with the reason on err.
int makeDriver(const Options &o, std::unique_ptr<comms::Driver> *driver, QTextStream &err) {
    QString error;
    *driver =
        comms::Driver::create(*o.target, o.settings.protocol, comms::makeTransport(o.settings),
                              o.settings.station, comms::lineTiming(o.settings), &error);
    if (!*driver) {
        err << error << '\n';
        return 2;
    }
    return 0;
}

// Opens the link; exit code 0, or 2 with the reason on err.
int openLink(comms::Driver &driver, QTextStream &err) {
    QString error;
    if (!driver.link().open(&error)) {
        err << error << '\n';
        return 2;
    }
    return 0;
}

int connect(const Options &o, std::unique_ptr<comms::Driver> *driver, QTextStream &err) {
    if (const int code = makeDriver(o, driver, err))
        return code;
    return openLink(**driver, err);
}

// A value as written on the command line: a decimal number (signed) or 0x hexadecimal; a
// bit also ON / OFF.
bool parseValue(const QString &text, qint64 *value) {
    const QString t = text.trimmed();
    if (t.compare(QLatin1String("ON"), Qt::CaseInsensitive) == 0) {
        *value = 1;
        return true;
    }
    if (t.compare(QLatin1String("OFF"), Qt::CaseInsensitive) == 0) {
        *value = 0;
        return true;
    }
    bool ok = false;
    if (t.startsWith(QLatin1String("0x"), Qt::CaseInsensitive))
        *value = t.mid(2).toLongLong(&ok, 16);
    else
        *value = t.toLongLong(&ok, 10);
    return ok;
}

bool parseDevice(const model::Target &target, const QString &text, model::Address *address,
                 QTextStream &err) {
    const auto parsed = model::parseAddress(target, QStringView(text).trimmed());
    if (const auto *e = std::get_if<model::AddressError>(&parsed)) {
        // The parser's message names the device already.
        err << e->message << '\n';
        return false;
    }
    *address = std::get<model::Address>(parsed);
    return true;
}

bool isBit(const model::Target &target, const model::Address &a) {
    return a.bit >= 0 || target.area(a.area).kind == model::AreaKind::Bit;
}

} // namespace

QString onlineUsage() {
    return OnlineTr::tr(
        "  rungstudio-cli read  --target T --protocol vigor|modbus|modbus-tcp|hostlink\n"
        "        (--port NAME | --tcp HOST:PORT | --pty PATH) [--station N] [--baud B]\n"
        "        [--frame 8N1] [--timeout MS] [--retries N] DEVICE...\n"
        "  rungstudio-cli write (the same options) DEVICE=VALUE...\n"
        "Exit status of read and write: 0 done, 1 the PLC did not answer or refused, "
        "2 usage, device, value or port error.");
}

int runReadCommand(const QStringList &args, QTextStream &out, QTextStream &err) {
    Options o;
    QString error;
    if (!parseOptions(args, &o, &error)) {
        err << error << '\n' << onlineUsageText() << '\n';
        return 2;
    }
    // Every device is checked before the port is opened: a typo costs no time on the line.
    std::vector<model::Address> devices;
    for (const QString &item : o.items) {
        model::Address a;
        if (!parseDevice(*o.target, item, &a, err))
            return 2;
        devices.push_back(a);
    }
    std::unique_ptr<comms::Driver> driver;
    if (const int code = connect(o, &driver, err))
        return code;
    const comms::Driver::Plan plan = driver->plan(devices);
    for (const auto &[address, why] : plan.unmapped) {
        err << why << '\n';
        return 2;
    }
    std::vector<std::int32_t> words(std::size_t(driver->layout()->wordCount()), 0);
    std::vector<std::pair<model::Address, QString>> refused;
    const comms::DriverError e = driver->refresh(plan, words, &refused);
    if (!e.ok()) {
        err << e.message << '\n';
        return 1;
    }
    model::Snapshot image;
    image.layout = driver->layout();
    image.words = std::move(words);
    for (std::size_t i = 0; i < devices.size(); ++i) {
        const model::Address &a = devices[i];
        const auto bad = std::find_if(refused.begin(), refused.end(),
                                      [&a](const auto &r) { return r.first == a; });
        if (bad != refused.end())
            continue;
        out << o.items[qsizetype(i)].trimmed() << '=' << driver->number(image, a) << '\n';
    }
    for (const auto &[address, why] : refused)
        err << why << '\n';
    return refused.empty() ? 0 : 1;
}

int runWriteCommand(const QStringList &args, QTextStream &out, QTextStream &err) {
    static_cast<void>(out);
    Options o;
    QString error;
    if (!parseOptions(args, &o, &error)) {
        err << error << '\n' << onlineUsageText() << '\n';
        return 2;
    }
    // Every item is checked before the port is opened and anything is written: nothing of a
    // mistyped line is written.
    std::vector<model::DeviceCommand> commands;
    for (const QString &item : o.items) {
        const qsizetype eq = item.indexOf(u'=');
        if (eq <= 0) {
            err << OnlineTr::tr("%1: write DEVICE=VALUE").arg(item) << '\n';
            return 2;
        }
        model::Address a;
        if (!parseDevice(*o.target, item.left(eq), &a, err))
            return 2;
        qint64 value = 0;
        if (!parseValue(item.mid(eq + 1), &value) ||
            (isBit(*o.target, a) && value != 0 && value != 1)) {
            err << OnlineTr::tr(
                       "%1: %2 is not a value for %3 (a bit takes 0 or 1, ON or OFF; a word "
                       "a number, 0x for hexadecimal)")
                       .arg(item, item.mid(eq + 1), item.left(eq))
                << '\n';
            return 2;
        }
        commands.push_back({isBit(*o.target, a) ? model::DeviceCommand::Kind::WriteBit
                                                : model::DeviceCommand::Kind::WriteWord,
                            a, value});
    }
    std::unique_ptr<comms::Driver> driver;
    if (const int code = makeDriver(o, &driver, err))
        return code;
    // A number typed for a word becomes the word the PLC keeps (a CPM1 timer's BCD digits),
    // every one before the port is opened.
    for (std::size_t i = 0; i < commands.size(); ++i) {
        model::DeviceCommand &c = commands[i];
        if (c.kind != model::DeviceCommand::Kind::WriteWord)
            continue;
        QString why;
        const std::optional<qint64> word = driver->wordOf(c.address, c.value, &why);
        if (!word) {
            err << OnlineTr::tr("%1: %2").arg(o.items[qsizetype(i)], why) << '\n';
            return 2;
        }
        c.value = *word;
    }
    if (const int code = openLink(*driver, err))
        return code;
    for (std::size_t i = 0; i < commands.size(); ++i) {
        QString notice;
        const comms::DriverError e = driver->execute(commands[i], &notice);
        if (!notice.isEmpty())
            err << OnlineTr::tr("note: %1").arg(notice) << '\n';
        if (e.ok())
            continue;
        err << e.message << '\n';
        if (i + 1 < commands.size())
            err << OnlineTr::tr("not written: %1")
                       .arg(o.items.mid(qsizetype(i) + 1).join(QLatin1String(" ")))
                << '\n';
        return e.kind == comms::DriverError::Kind::BadDevice ||
                       e.kind == comms::DriverError::Kind::Unsupported
                   ? 2
                   : 1;
    }
    return 0;
}

} // namespace rung::app
