// Writing a network file (docs/network-format.md): the description back to JSON that a person
// can read and a version control diff line by line.

#include "network/network_file.h"
#include "network/tr.h"

#include <QDir>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QSaveFile>

#include <algorithm>

namespace rung::network {

namespace {

constexpr int kLineWidth = 100;

// The order keys are written in: the order of network-format.md's tables. Keys not listed
// follow by name; keys that are numbers (a device's registers) in numeric order.
int keyRank(const QString &key) {
    static const QStringList order = {
        QStringLiteral("comment"),   QStringLiteral("format"),    QStringLiteral("period"),
        QStringLiteral("stations"),  QStringLiteral("devices"),   QStringLiteral("wires"),
        QStringLiteral("bridges"),   QStringLiteral("faults"),    QStringLiteral("name"),
        QStringLiteral("kind"),      QStringLiteral("port"),      QStringLiteral("program"),
        QStringLiteral("target"),    QStringLiteral("model"),     QStringLiteral("application"),
        QStringLiteral("role"),      QStringLiteral("speed"),     QStringLiteral("station"),
        QStringLiteral("mode"),      QStringLiteral("baud"),      QStringLiteral("frame"),
        QStringLiteral("slaves"),    QStringLiteral("range"),     QStringLiteral("timeout"),
        QStringLiteral("retry"),     QStringLiteral("start"),     QStringLiteral("end"),
        QStringLiteral("delay"),     QStringLiteral("pty"),       QStringLiteral("serial"),
        QStringLiteral("tcp"),       QStringLiteral("listen"),    QStringLiteral("wire"),
        QStringLiteral("from"),      QStringLiteral("to"),        QStringLiteral("byte"),
        QStringLiteral("xor"),       QStringLiteral("registers"), QStringLiteral("inputRegisters"),
        QStringLiteral("coils"),     QStringLiteral("inputs"),    QStringLiteral("answers"),
        QStringLiteral("expect"),    QStringLiteral("reply"),     QStringLiteral("expectText"),
        QStringLiteral("replyText"), QStringLiteral("ends"),      QStringLiteral("ports")};
    const qsizetype i = order.indexOf(key);
    return i < 0 ? int(order.size()) : int(i);
}

bool keyBefore(const QString &a, const QString &b, bool topLevel) {
    // The top level's comment says what the network is: first. A station's or a device's
    // comment goes after its settings.
    const auto rank = [topLevel](const QString &k) {
        if (!topLevel && k == QLatin1String("comment"))
            return 1000;
        return keyRank(k);
    };
    const int ra = rank(a), rb = rank(b);
    if (ra != rb)
        return ra < rb;
    bool na = false, nb = false;
    const qlonglong ia = a.toLongLong(&na), ib = b.toLongLong(&nb);
    if (na && nb)
        return ia < ib;
    if (na != nb)
        return na;
    return a < b;
}

QByteArray scalar(const QJsonValue &v) {
    // QJsonDocument writes a value only inside a list: the list's brackets come off.
    QByteArray text = QJsonDocument(QJsonArray{v}).toJson(QJsonDocument::Compact);
    return text.mid(1, text.size() - 2);
}

QByteArray indentOf(int level) {
    return QByteArray(level * 4, ' ');
}

QStringList orderedKeys(const QJsonObject &o, bool topLevel) {
    QStringList keys = o.keys();
    std::stable_sort(keys.begin(), keys.end(), [topLevel](const QString &a, const QString &b) {
        return keyBefore(a, b, topLevel);
    });
    return keys;
}

QByteArray oneLine(const QJsonValue &v, bool topLevel = false) {
    if (v.isObject()) {
        const QJsonObject o = v.toObject();
        QByteArrayList parts;
        for (const QString &k : orderedKeys(o, topLevel))
            parts << scalar(k) + ": " + oneLine(o.value(k));
        return '{' + parts.join(", ") + '}';
    }
    if (v.isArray()) {
        QByteArrayList parts;
        for (const QJsonValue &e : v.toArray())
            parts << oneLine(e);
        return '[' + parts.join(", ") + ']';
    }
    return scalar(v);
}

// `v` at nesting `level`, starting at `column`: on one line when it fits, else its items one a
// line, each written the same way.
QByteArray pretty(const QJsonValue &v, int level, int column, bool topLevel = false) {
    const QByteArray flat = oneLine(v, topLevel);
    if ((!v.isObject() && !v.isArray()) || (!topLevel && column + flat.size() <= kLineWidth))
        return flat;
    const QByteArray inner = indentOf(level + 1);
    QByteArrayList lines;
    if (v.isObject()) {
        const QJsonObject o = v.toObject();
        if (o.isEmpty())
            return "{}";
        for (const QString &k : orderedKeys(o, topLevel)) {
            const QByteArray head = inner + scalar(k) + ": ";
            lines << head + pretty(o.value(k), level + 1, int(head.size()));
        }
        return "{\n" + lines.join(",\n") + '\n' + indentOf(level) + '}';
    }
    const QJsonArray a = v.toArray();
    if (a.isEmpty())
        return "[]";
    for (const QJsonValue &e : a)
        lines << inner + pretty(e, level + 1, int(inner.size()));
    return "[\n" + lines.join(",\n") + '\n' + indentOf(level) + ']';
}

QString programFor(const StationDescription &s, const QDir &dir, bool haveDir) {
    if (QDir::isAbsolutePath(s.program) || !haveDir || s.path.isEmpty())
        return s.program;
    return QDir::fromNativeSeparators(dir.relativeFilePath(s.path));
}

QJsonObject stationJson(const StationDescription &s, const QDir &dir, bool haveDir) {
    QJsonObject o;
    o.insert(QStringLiteral("name"), s.name);
    o.insert(QStringLiteral("program"), programFor(s, dir, haveDir));
    if (!s.target.isEmpty())
        o.insert(QStringLiteral("target"), s.target);
    if (!s.model.isEmpty())
        o.insert(QStringLiteral("model"), s.model);
    if (s.periodMs > 0)
        o.insert(QStringLiteral("period"), s.periodMs);
    if (!s.ports.isEmpty())
        o.insert(QStringLiteral("ports"), s.ports);
    if (!s.comment.isUndefined())
        o.insert(QStringLiteral("comment"), s.comment);
    return o;
}

QString defaultWireName(std::size_t index) {
    return QStringLiteral("w%1").arg(index + 1);
}

QJsonValue wireJson(const WireDescription &w, std::size_t index) {
    QJsonArray ends;
    for (const QString &e : w.ends)
        ends.append(e);
    // An unnamed wire is named by its place: written as a plain list only while its name is
    // still the one its place gives, so that an edit above it never renames it.
    if (!w.named && w.name == defaultWireName(index))
        return ends;
    return QJsonObject{{QStringLiteral("name"), w.name}, {QStringLiteral("ends"), ends}};
}

QJsonObject bridgeJson(const BridgeDescription &b) {
    QJsonObject o{{QStringLiteral("port"), b.end}};
    switch (b.kind) {
    case BridgeDescription::Kind::Pty:
        o.insert(QStringLiteral("pty"), true);
        break;
    case BridgeDescription::Kind::Serial:
        o.insert(QStringLiteral("serial"), b.where);
        break;
    case BridgeDescription::Kind::Tcp:
        o.insert(QStringLiteral("tcp"), b.where);
        break;
    case BridgeDescription::Kind::Listen:
        o.insert(QStringLiteral("listen"), b.where);
        break;
    }
    return o;
}

QJsonObject faultJson(const FaultDescription &f) {
    QJsonObject o;
    const auto given = [&f](const char *key, bool notDefault) {
        return notDefault || f.given.contains(QLatin1String(key));
    };
    switch (f.kind) {
    case FaultDescription::Kind::Cut:
    case FaultDescription::Kind::Silent:
        if (f.kind == FaultDescription::Kind::Cut) {
            o.insert(QStringLiteral("kind"), QStringLiteral("cut"));
            o.insert(QStringLiteral("wire"), f.wire);
        } else {
            o.insert(QStringLiteral("kind"), QStringLiteral("silent"));
            o.insert(QStringLiteral("station"), f.station);
        }
        if (given("from", f.fromMs != 0))
            o.insert(QStringLiteral("from"), f.fromMs);
        if (f.toMs >= 0)
            o.insert(QStringLiteral("to"), f.toMs);
        break;
    case FaultDescription::Kind::Corrupt:
        o.insert(QStringLiteral("kind"), QStringLiteral("corrupt"));
        o.insert(QStringLiteral("wire"), f.wire);
        if (given("frame", f.frame != 0))
            o.insert(QStringLiteral("frame"), f.frame);
        if (given("byte", f.byte != 0))
            o.insert(QStringLiteral("byte"), f.byte);
        if (given("xor", f.mask != 1))
            o.insert(QStringLiteral("xor"), f.mask);
        break;
    }
    return o;
}

template <typename T, typename F>
void compareLists(const std::vector<T> &a, const std::vector<T> &b, const char *what, F same,
                  QStringList *out) {
    if (a.size() != b.size()) {
        *out << NetworkFileTr::tr("%1: %2 items where there were %3")
                    .arg(QLatin1String(what))
                    .arg(b.size())
                    .arg(a.size());
        return;
    }
    for (std::size_t i = 0; i < a.size(); ++i)
        if (!same(a[i], b[i]))
            *out
                << NetworkFileTr::tr("%1[%2]: written differently").arg(QLatin1String(what)).arg(i);
}

} // namespace

QByteArray networkToJson(const NetworkDescription &d, const QString &file) {
    const bool haveDir = !file.isEmpty();
    const QDir dir = QFileInfo(file).absoluteDir();
    QJsonObject root;
    if (!d.comment.isUndefined())
        root.insert(QStringLiteral("comment"), d.comment);
    if (!d.format.isUndefined())
        root.insert(QStringLiteral("format"), d.format);
    if (d.periodGiven || d.periodMs != 10)
        root.insert(QStringLiteral("period"), d.periodMs);
    QJsonArray stations;
    for (const StationDescription &s : d.stations)
        stations.append(stationJson(s, dir, haveDir));
    root.insert(QStringLiteral("stations"), stations);
    if (!d.devices.empty()) {
        QJsonArray devices;
        for (const DeviceDescription &v : d.devices)
            devices.append(v.json);
        root.insert(QStringLiteral("devices"), devices);
    }
    if (!d.wires.empty()) {
        QJsonArray wires;
        for (std::size_t i = 0; i < d.wires.size(); ++i)
            wires.append(wireJson(d.wires[i], i));
        root.insert(QStringLiteral("wires"), wires);
    }
    if (!d.bridges.empty()) {
        QJsonArray bridges;
        for (const BridgeDescription &b : d.bridges)
            bridges.append(bridgeJson(b));
        root.insert(QStringLiteral("bridges"), bridges);
    }
    if (!d.faults.empty()) {
        QJsonArray faults;
        for (const FaultDescription &f : d.faults)
            faults.append(faultJson(f));
        root.insert(QStringLiteral("faults"), faults);
    }
    return pretty(root, 0, 0, true) + '\n';
}

QStringList networkDifferences(const NetworkDescription &a, const NetworkDescription &b) {
    QStringList out;
    if (a.periodMs != b.periodMs)
        out << QStringLiteral("period");
    if (a.comment != b.comment)
        out << QStringLiteral("comment");
    if (a.format != b.format)
        out << QStringLiteral("format");
    compareLists(
        a.stations, b.stations, "stations",
        [](StationDescription x, StationDescription y) {
            x.where = y.where;
            // The program's text may change with the file's folder; where it is may not.
            return x.name == y.name && QFileInfo(x.path) == QFileInfo(y.path) &&
                   x.target == y.target && x.model == y.model && x.periodMs == y.periodMs &&
                   x.ports == y.ports && x.comment == y.comment;
        },
        &out);
    compareLists(
        a.devices, b.devices, "devices",
        [](DeviceDescription x, const DeviceDescription &y) {
            x.where = y.where;
            return x == y;
        },
        &out);
    compareLists(
        a.wires, b.wires, "wires",
        [](const WireDescription &x, const WireDescription &y) {
            return x.name == y.name && x.ends == y.ends;
        },
        &out);
    compareLists(
        a.bridges, b.bridges, "bridges",
        [](BridgeDescription x, const BridgeDescription &y) {
            x.path = y.path;
            return x == y;
        },
        &out);
    compareLists(
        a.faults, b.faults, "faults",
        [](FaultDescription x, const FaultDescription &y) {
            x.where = y.where;
            return x == y;
        },
        &out);
    return out;
}

void renumberNetwork(NetworkDescription *d) {
    for (std::size_t i = 0; i < d->stations.size(); ++i)
        d->stations[i].where = QStringLiteral("stations[%1]").arg(i);
    for (std::size_t i = 0; i < d->devices.size(); ++i)
        d->devices[i].where = QStringLiteral("devices[%1]").arg(i);
    for (std::size_t i = 0; i < d->wires.size(); ++i)
        d->wires[i].where = QStringLiteral("wires[%1]").arg(i);
    for (std::size_t i = 0; i < d->bridges.size(); ++i)
        d->bridges[i].path = QStringLiteral("bridges[%1]").arg(i);
    for (std::size_t i = 0; i < d->faults.size(); ++i)
        d->faults[i].where = QStringLiteral("faults[%1]").arg(i);
}

bool writeNetworkFile(const NetworkDescription &d, const QString &file, QStringList *notKept,
                      QString *error, bool evenIfNotKept) {
    const QByteArray json = networkToJson(d, file);
    NetworkDescription back;
    QString why;
    notKept->clear();
    if (!parseNetwork(json, file, &back, &why))
        *notKept << why;
    else
        *notKept = networkDifferences(d, back);
    if (!notKept->isEmpty() && !evenIfNotKept) {
        *error = NetworkFileTr::tr("%1: not saved: the file would not hold everything (%2)")
                     .arg(file, notKept->join(QStringLiteral("; ")));
        return false;
    }
    QSaveFile out(file);
    if (!out.open(QIODevice::WriteOnly) || out.write(json) != json.size() || !out.commit()) {
        *error =
            NetworkFileTr::tr("%1: cannot write the network (%2)").arg(file, out.errorString());
        return false;
    }
    return true;
}

} // namespace rung::network
