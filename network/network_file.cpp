#include "network/network_file.h"
#include "network/tr.h"

#include "model/project/file_read.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QRegularExpression>
#include <QSet>

namespace rung::network {

namespace {

// A network file holds names and settings: a few kilobytes. 8 MB, as a listing.
constexpr qint64 kMaxNetworkBytes = 8 * 1024 * 1024;

QString at(const QString &path, const QString &key) {
    return path.isEmpty() ? key : path + QLatin1Char('.') + key;
}

QString item(const QString &path, qsizetype index) {
    return QStringLiteral("%1[%2]").arg(path).arg(index);
}

bool string(const QJsonObject &o, const char *key, const QString &path, bool required,
            QString *into, QString *error) {
    const QJsonValue v = o.value(QLatin1String(key));
    if (v.isUndefined() && !required)
        return true;
    if (!v.isString() || v.toString().isEmpty()) {
        *error = v.isUndefined()
                     ? NetworkFileTr::tr("%1: missing").arg(at(path, QLatin1String(key)))
                     : NetworkFileTr::tr("%1: needs a text").arg(at(path, QLatin1String(key)));
        return false;
    }
    *into = v.toString();
    return true;
}

bool number(const QJsonObject &o, const char *key, const QString &path, qint64 lowest,
            qint64 highest, qint64 *into, QString *error) {
    const QJsonValue v = o.value(QLatin1String(key));
    if (v.isUndefined())
        return true;
    const double d = v.toDouble(-1e300);
    if (!v.isDouble() || d != double(qint64(d)) || d < double(lowest) || d > double(highest)) {
        *error = NetworkFileTr::tr("%1: needs a whole number from %2 to %3")
                     .arg(at(path, QLatin1String(key)))
                     .arg(lowest)
                     .arg(highest);
        return false;
    }
    *into = qint64(d);
    return true;
}

bool array(const QJsonObject &o, const char *key, QJsonArray *into, QString *error) {
    const QJsonValue v = o.value(QLatin1String(key));
    if (v.isUndefined())
        return true;
    if (!v.isArray()) {
        *error = NetworkFileTr::tr("%1: needs a list").arg(QLatin1String(key));
        return false;
    }
    *into = v.toArray();
    return true;
}

} // namespace

bool validNetworkName(const QString &name) {
    static const QRegularExpression re(QStringLiteral("^[A-Za-z0-9_-]{1,32}$"));
    return re.match(name).hasMatch();
}

bool onlyJsonKeys(const QJsonObject &o, const QStringList &keys, const QString &path,
                  QString *error) {
    for (auto it = o.begin(); it != o.end(); ++it)
        if (!keys.contains(it.key())) {
            *error = NetworkFileTr::tr("%1: unknown key (this object takes: %2)")
                         .arg(at(path, it.key()), keys.join(QStringLiteral(", ")));
            return false;
        }
    return true;
}

bool readNetworkFile(const QString &file, NetworkDescription *description, QString *error) {
    QByteArray bytes;
    QString ioError;
    const model::ReadStatus status = model::readAtMost(file, kMaxNetworkBytes, &bytes, &ioError);
    if (status != model::ReadStatus::Ok) {
        *error = model::readFailure(status, file, kMaxNetworkBytes, ioError);
        return false;
    }
    return parseNetwork(bytes, file, description, error);
}

bool parseNetwork(const QByteArray &json, const QString &file, NetworkDescription *d,
                  QString *error) {
    *d = {};
    d->file = file;
    QJsonParseError parse;
    const QJsonDocument doc = QJsonDocument::fromJson(json, &parse);
    if (parse.error != QJsonParseError::NoError) {
        const qsizetype offset = parse.offset;
        const QByteArray before = json.left(offset);
        const qsizetype line = before.count('\n') + 1;
        const qsizetype column = offset - (before.lastIndexOf('\n') + 1) + 1;
        *error = NetworkFileTr::tr("%1: line %2, column %3: the file is not valid JSON (%4)")
                     .arg(file)
                     .arg(line)
                     .arg(column)
                     .arg(parse.errorString());
        return false;
    }
    if (!doc.isObject()) {
        *error =
            NetworkFileTr::tr("%1: a network file is a JSON object with \"stations\" and \"wires\"")
                .arg(file);
        return false;
    }
    const QJsonObject root = doc.object();
    const QString prefix = file + QStringLiteral(": ");
    auto fail = [&](const QString &why) {
        *error = prefix + why;
        return false;
    };
    QString why;
    if (!onlyJsonKeys(root,
                      {QStringLiteral("format"), QStringLiteral("period"),
                       QStringLiteral("stations"), QStringLiteral("devices"),
                       QStringLiteral("wires"), QStringLiteral("bridges"), QStringLiteral("faults"),
                       QStringLiteral("comment")},
                      QString(), &why) ||
        !number(root, "period", QString(), 1, 1000000, &d->periodMs, &why))
        return fail(why);
    d->periodGiven = root.contains(QLatin1String("period"));
    d->comment = root.value(QLatin1String("comment"));
    d->format = root.value(QLatin1String("format"));
    const QDir dir = QFileInfo(file).absoluteDir();
    QSet<QString> names;
    QJsonArray list;
    if (!array(root, "stations", &list, &why))
        return fail(why);
    if (list.isEmpty())
        return fail(NetworkFileTr::tr("stations: a network needs at least one station"));
    for (qsizetype i = 0; i < list.size(); ++i) {
        const QString where = item(QStringLiteral("stations"), i);
        if (!list[i].isObject())
            return fail(NetworkFileTr::tr("%1: needs an object").arg(where));
        const QJsonObject o = list[i].toObject();
        StationDescription s;
        s.where = where;
        if (!onlyJsonKeys(o,
                          {QStringLiteral("name"), QStringLiteral("program"),
                           QStringLiteral("target"), QStringLiteral("model"),
                           QStringLiteral("period"), QStringLiteral("ports"),
                           QStringLiteral("comment")},
                          where, &why) ||
            !string(o, "name", where, true, &s.name, &why) ||
            !string(o, "program", where, true, &s.program, &why) ||
            !string(o, "target", where, false, &s.target, &why) ||
            !string(o, "model", where, false, &s.model, &why) ||
            !number(o, "period", where, 1, 1000000, &s.periodMs, &why))
            return fail(why);
        if (!validNetworkName(s.name))
            return fail(
                NetworkFileTr::tr("%1: \"%2\" is no name (letters, digits, _ and -, at most 32)")
                    .arg(at(where, QStringLiteral("name")), s.name));
        if (names.contains(s.name))
            return fail(NetworkFileTr::tr("%1: a second \"%2\"; names are unique")
                            .arg(at(where, QStringLiteral("name")), s.name));
        names.insert(s.name);
        const QJsonValue ports = o.value(QLatin1String("ports"));
        if (!ports.isUndefined() && !ports.isObject())
            return fail(NetworkFileTr::tr("%1: needs an object of ports")
                            .arg(at(where, QStringLiteral("ports"))));
        s.ports = ports.toObject();
        s.comment = o.value(QLatin1String("comment"));
        for (auto it = s.ports.begin(); it != s.ports.end(); ++it)
            if (!it.value().isObject())
                return fail(NetworkFileTr::tr("%1: needs an object of settings")
                                .arg(at(at(where, QStringLiteral("ports")), it.key())));
        s.path = dir.filePath(s.program);
        d->stations.push_back(s);
    }
    list = {};
    if (!array(root, "devices", &list, &why))
        return fail(why);
    for (qsizetype i = 0; i < list.size(); ++i) {
        const QString where = item(QStringLiteral("devices"), i);
        if (!list[i].isObject())
            return fail(NetworkFileTr::tr("%1: needs an object").arg(where));
        DeviceDescription v;
        v.where = where;
        v.json = list[i].toObject();
        if (!string(v.json, "name", where, true, &v.name, &why) ||
            !string(v.json, "kind", where, true, &v.kind, &why))
            return fail(why);
        if (!validNetworkName(v.name))
            return fail(
                NetworkFileTr::tr("%1: \"%2\" is no name (letters, digits, _ and -, at most 32)")
                    .arg(at(where, QStringLiteral("name")), v.name));
        if (names.contains(v.name))
            return fail(NetworkFileTr::tr("%1: a second \"%2\"; names are unique")
                            .arg(at(where, QStringLiteral("name")), v.name));
        names.insert(v.name);
        if (v.kind != QLatin1String("modbus-slave") && v.kind != QLatin1String("line"))
            return fail(NetworkFileTr::tr("%1: \"%2\" is no kind of device (modbus-slave, line)")
                            .arg(at(where, QStringLiteral("kind")), v.kind));
        d->devices.push_back(v);
    }
    list = {};
    if (!array(root, "wires", &list, &why))
        return fail(why);
    QSet<QString> wireNames;
    for (qsizetype i = 0; i < list.size(); ++i) {
        const QString where = item(QStringLiteral("wires"), i);
        WireDescription w;
        w.where = where;
        w.name = QStringLiteral("w%1").arg(i + 1);
        QJsonArray ends;
        if (list[i].isArray()) {
            ends = list[i].toArray();
        } else if (list[i].isObject()) {
            const QJsonObject o = list[i].toObject();
            w.named = o.contains(QLatin1String("name"));
            if (!onlyJsonKeys(o, {QStringLiteral("name"), QStringLiteral("ends")}, where, &why) ||
                !string(o, "name", where, false, &w.name, &why) || !array(o, "ends", &ends, &why))
                return fail(why);
        } else {
            return fail(
                NetworkFileTr::tr("%1: needs a list of ends, [\"a/CP2\", \"b/CP2\"]").arg(where));
        }
        if (wireNames.contains(w.name))
            return fail(NetworkFileTr::tr("%1: a second wire \"%2\"").arg(where, w.name));
        wireNames.insert(w.name);
        if (ends.size() < 2)
            return fail(NetworkFileTr::tr("%1: a wire joins at least two ends").arg(where));
        for (qsizetype k = 0; k < ends.size(); ++k) {
            if (!ends[k].isString())
                return fail(NetworkFileTr::tr("%1: needs \"STATION/PORT\" or a device's name")
                                .arg(item(where, k)));
            w.ends << ends[k].toString();
        }
        d->wires.push_back(w);
    }
    list = {};
    if (!array(root, "bridges", &list, &why))
        return fail(why);
    for (qsizetype i = 0; i < list.size(); ++i) {
        const QString where = item(QStringLiteral("bridges"), i);
        if (!list[i].isObject())
            return fail(NetworkFileTr::tr("%1: needs an object").arg(where));
        const QJsonObject o = list[i].toObject();
        BridgeDescription b;
        b.path = where;
        if (!onlyJsonKeys(o,
                          {QStringLiteral("port"), QStringLiteral("pty"), QStringLiteral("serial"),
                           QStringLiteral("tcp"), QStringLiteral("listen")},
                          where, &why) ||
            !string(o, "port", where, true, &b.end, &why))
            return fail(why);
        const int kinds =
            int(o.contains(QLatin1String("pty"))) + int(o.contains(QLatin1String("serial"))) +
            int(o.contains(QLatin1String("tcp"))) + int(o.contains(QLatin1String("listen")));
        if (kinds != 1)
            return fail(NetworkFileTr::tr("%1: a bridge goes to one of \"pty\": true, \"serial\": "
                                          "\"/dev/ttyUSB0\", \"tcp\": \"HOST:PORT\", "
                                          "\"listen\": \"HOST:PORT\"")
                            .arg(where));
        if (o.contains(QLatin1String("pty"))) {
            b.kind = BridgeDescription::Kind::Pty;
        } else if (o.contains(QLatin1String("serial"))) {
            b.kind = BridgeDescription::Kind::Serial;
            if (!string(o, "serial", where, true, &b.where, &why))
                return fail(why);
        } else if (o.contains(QLatin1String("tcp"))) {
            b.kind = BridgeDescription::Kind::Tcp;
            if (!string(o, "tcp", where, true, &b.where, &why))
                return fail(why);
        } else {
            b.kind = BridgeDescription::Kind::Listen;
            if (!string(o, "listen", where, true, &b.where, &why))
                return fail(why);
        }
        d->bridges.push_back(b);
    }
    list = {};
    if (!array(root, "faults", &list, &why))
        return fail(why);
    for (qsizetype i = 0; i < list.size(); ++i) {
        const QString where = item(QStringLiteral("faults"), i);
        if (!list[i].isObject())
            return fail(NetworkFileTr::tr("%1: needs an object").arg(where));
        const QJsonObject o = list[i].toObject();
        FaultDescription f;
        f.where = where;
        QString kind;
        if (!string(o, "kind", where, true, &kind, &why))
            return fail(why);
        qint64 frame = 0, byte = 0, mask = 1;
        for (const char *key : {"from", "to", "frame", "byte", "xor"})
            if (o.contains(QLatin1String(key)))
                f.given << QLatin1String(key);
        if (kind == QLatin1String("cut") || kind == QLatin1String("silent")) {
            f.kind = kind == QLatin1String("cut") ? FaultDescription::Kind::Cut
                                                  : FaultDescription::Kind::Silent;
            const char *what = f.kind == FaultDescription::Kind::Cut ? "wire" : "station";
            if (!onlyJsonKeys(o,
                              {QStringLiteral("kind"), QLatin1String(what), QStringLiteral("from"),
                               QStringLiteral("to")},
                              where, &why) ||
                !string(o, what, where, true,
                        f.kind == FaultDescription::Kind::Cut ? &f.wire : &f.station, &why) ||
                !number(o, "from", where, 0, qint64(1) << 40, &f.fromMs, &why) ||
                !number(o, "to", where, 0, qint64(1) << 40, &f.toMs, &why))
                return fail(why);
            if (f.toMs >= 0 && f.toMs <= f.fromMs)
                return fail(NetworkFileTr::tr("%1: \"to\" comes before \"from\"").arg(where));
        } else if (kind == QLatin1String("corrupt")) {
            f.kind = FaultDescription::Kind::Corrupt;
            if (!onlyJsonKeys(o,
                              {QStringLiteral("kind"), QStringLiteral("wire"),
                               QStringLiteral("frame"), QStringLiteral("byte"),
                               QStringLiteral("xor")},
                              where, &why) ||
                !string(o, "wire", where, true, &f.wire, &why) ||
                !number(o, "frame", where, 0, 1 << 30, &frame, &why) ||
                !number(o, "byte", where, 0, 1 << 20, &byte, &why) ||
                !number(o, "xor", where, 1, 255, &mask, &why))
                return fail(why);
            f.frame = int(frame);
            f.byte = int(byte);
            f.mask = int(mask);
        } else {
            return fail(NetworkFileTr::tr("%1: \"%2\" is no fault (cut, silent, corrupt)")
                            .arg(at(where, QStringLiteral("kind")), kind));
        }
        d->faults.push_back(f);
    }
    return true;
}

std::optional<HostPort> splitHostPort(const QString &where) {
    const qsizetype colon = where.lastIndexOf(QLatin1Char(':'));
    if (colon <= 0)
        return std::nullopt;
    bool ok = false;
    const uint port = where.mid(colon + 1).toUInt(&ok);
    if (!ok || port > 65535)
        return std::nullopt;
    return HostPort{where.left(colon), int(port)};
}

} // namespace rung::network
