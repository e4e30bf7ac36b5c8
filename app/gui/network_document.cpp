#include "app/gui/network_document.h"

#include "model/comm/port_config.h"
#include "model/listing/il.h"
#include "model/project/project.h"
#include "model/target/target.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QUndoCommand>

namespace rung::app {

using network::BridgeDescription;
using network::FaultDescription;
using network::NetworkDescription;
using network::StationDescription;
using network::WireDescription;

// One edit: the network before and after, as values. redo() sets the after, undo() the before.
class NetworkEditCommand : public QUndoCommand {
public:
    NetworkEditCommand(NetworkDocument *document, NetworkDescription before,
                       NetworkDescription after, const QString &label)
        : QUndoCommand(label)
        , m_document(document)
        , m_before(std::move(before))
        , m_after(std::move(after)) {}
    void redo() override { m_document->apply(m_after); }
    void undo() override { m_document->apply(m_before); }

private:
    NetworkDocument *m_document;
    NetworkDescription m_before;
    NetworkDescription m_after;
};

namespace {

QString endStation(const QString &end) {
    return end.section(QLatin1Char('/'), 0, 0);
}

QString bridgeKindText(BridgeDescription::Kind kind) {
    switch (kind) {
    case BridgeDescription::Kind::Pty:
        return NetworkDocument::tr("pseudo-terminal");
    case BridgeDescription::Kind::Serial:
        return NetworkDocument::tr("serial port");
    case BridgeDescription::Kind::Tcp:
        return NetworkDocument::tr("TCP connection");
    case BridgeDescription::Kind::Listen:
        return NetworkDocument::tr("TCP listener");
    }
    return {};
}

} // namespace

NetworkDocument::NetworkDocument(QObject *parent)
    : QObject(parent) {
    connect(&m_undo, &QUndoStack::cleanChanged, this,
            [this](bool clean) { emit modifiedChanged(!clean); });
}

void NetworkDocument::newNetwork() {
    m_undo.clear();
    m_description = {};
    m_file.clear();
    m_infos.clear();
    emit filePathChanged(m_file);
    emit changed();
    emit modifiedChanged(false);
}

bool NetworkDocument::open(const QString &file, QString *error) {
    NetworkDescription d;
    if (!network::readNetworkFile(file, &d, error))
        return false;
    m_undo.clear();
    m_description = std::move(d);
    m_file = m_description.file;
    m_infos.clear();
    emit filePathChanged(m_file);
    emit changed();
    emit modifiedChanged(false);
    return true;
}

bool NetworkDocument::save(QStringList *notKept, QString *error, bool evenIfNotKept) {
    if (m_file.isEmpty()) {
        *error = tr("The network has no file yet: use Save As");
        return false;
    }
    return saveAs(m_file, notKept, error, evenIfNotKept);
}

bool NetworkDocument::saveAs(const QString &file, QStringList *notKept, QString *error,
                             bool evenIfNotKept) {
    NetworkDescription d = m_description;
    if (m_file.isEmpty()) {
        // A network never saved kept its programs as absolute paths for want of a folder: the
        // first save writes them relative to it, as a user writes them.
        const QDir dir = QFileInfo(file).absoluteDir();
        for (StationDescription &s : d.stations)
            s.program = QDir::fromNativeSeparators(dir.relativeFilePath(s.path));
    }
    if (!network::writeNetworkFile(d, file, notKept, error, evenIfNotKept))
        return false;
    const bool moved = file != m_file;
    m_file = file;
    // The programs stay where they are; their paths as the new file writes them.
    apply(d);
    m_undo.setClean();
    if (moved)
        emit filePathChanged(m_file);
    return true;
}

QString NetworkDocument::displayName() const {
    return m_file.isEmpty() ? tr("Untitled network") : QFileInfo(m_file).fileName();
}

void NetworkDocument::apply(const NetworkDescription &description) {
    m_description = description;
    m_description.file = m_file;
    const QDir dir = QFileInfo(m_file).absoluteDir();
    for (StationDescription &s : m_description.stations)
        if (!m_file.isEmpty() && !QDir::isAbsolutePath(s.program))
            s.program = QDir::fromNativeSeparators(dir.relativeFilePath(s.path));
    network::renumberNetwork(&m_description);
    emit changed();
}

void NetworkDocument::push(NetworkDescription after, const QString &label) {
    network::renumberNetwork(&after);
    m_undo.push(new NetworkEditCommand(this, m_description, std::move(after), label));
}

const StationDescription *NetworkDocument::station(const QString &name) const {
    for (const StationDescription &s : m_description.stations)
        if (s.name == name)
            return &s;
    return nullptr;
}

NetworkStationInfo NetworkDocument::stationInfo(const QString &name) const {
    const StationDescription *s = station(name);
    NetworkStationInfo info;
    if (!s) {
        info.target = &model::Target::defaultTarget();
        info.model = info.target->defaultModel().name;
        return info;
    }
    auto it = m_infos.find(s->path);
    if (it == m_infos.end()) {
        // Read once per program: a project names its target, model and ports; a listing or a
        // ladder text its target in a "; target:" line.
        NetworkStationInfo read;
        if (s->path.endsWith(QStringLiteral(".") + QLatin1String(model::kProjectExtension))) {
            model::ProjectError projectError;
            if (const auto project = model::loadProject(s->path, &projectError)) {
                read.target = project->target;
                read.model = project->model;
                read.projectPorts = project->ports;
            } else {
                read.problem = projectError.message;
            }
        } else {
            QFile f(s->path);
            if (f.open(QIODevice::ReadOnly))
                read.target = model::Target::byId(
                    model::declaredTarget(QString::fromUtf8(f.read(64 * 1024))));
            else
                read.problem = tr("%1: cannot read the program (%2)").arg(s->path, f.errorString());
        }
        it = m_infos.emplace(s->path, read).first;
    }
    info = it->second;
    if (!s->target.isEmpty())
        if (const model::Target *t = model::Target::byId(s->target); t && t != info.target) {
            info.target = t;
            info.model.clear();
        }
    if (!info.target)
        info.target = &model::Target::defaultTarget();
    if (!s->model.isEmpty())
        info.model = s->model;
    if (info.model.isEmpty() || !info.target->model(info.model))
        info.model = info.target->defaultModel().name;
    return info;
}

QStringList NetworkDocument::stationPorts(const QString &name) const {
    const StationDescription *s = station(name);
    if (!s)
        return {};
    const NetworkStationInfo info = stationInfo(name);
    QStringList named = s->ports.keys() + info.projectPorts.keys();
    for (const WireDescription &w : m_description.wires)
        for (const QString &e : w.ends)
            if (endStation(e) == name && e.contains(QLatin1Char('/')))
                named << e.section(QLatin1Char('/'), 1);
    for (const BridgeDescription &b : m_description.bridges)
        if (endStation(b.end) == name)
            named << b.end.section(QLatin1Char('/'), 1);
    QStringList out;
    for (const model::PortSpec &p : info.target->ports) {
        if (!p.on(info.model))
            continue;
        // A port only a program drives byte by byte (a VB-1COM module's slot: the table gives
        // the VB sixteen) is shown once something names it, not sixteen times empty.
        bool moduleOnly = true;
        for (const model::PortApplication &a : p.applications)
            moduleOnly = moduleOnly && a.programDriven;
        bool isNamed = false;
        for (const QString &n : named)
            isNamed = isNamed || n.compare(p.name, Qt::CaseInsensitive) == 0;
        if (!moduleOnly || isNamed)
            out << p.name;
    }
    // A name the table does not know is shown too (the network's check says it is wrong).
    for (const QString &n : named)
        if (!info.target->port(n) && !out.contains(n))
            out << n;
    return out;
}

QJsonObject NetworkDocument::effectivePortSettings(const QString &name, const QString &port) const {
    const StationDescription *s = station(name);
    if (!s)
        return {};
    const NetworkStationInfo info = stationInfo(name);
    std::vector<model::PortLayer> layers;
    if (info.projectPorts.contains(port))
        layers.push_back({info.projectPorts.value(port).toObject(), s->program});
    if (s->ports.contains(port))
        layers.push_back({s->ports.value(port).toObject(), s->where});
    return model::mergePortJson(layers);
}

const WireDescription *NetworkDocument::wireOf(const QString &end) const {
    for (const WireDescription &w : m_description.wires)
        if (w.ends.contains(end))
            return &w;
    return nullptr;
}

QString NetworkDocument::freeName(const QString &base) const {
    QString stem = base;
    // What a name may not hold (network::validNetworkName) becomes "_".
    for (QChar &c : stem)
        if (c.unicode() > 127 ||
            (!c.isLetterOrNumber() && c != QLatin1Char('_') && c != QLatin1Char('-')))
            c = QLatin1Char('_');
    stem = stem.left(28);
    if (stem.isEmpty())
        stem = QStringLiteral("plc");
    const auto taken = [this](const QString &n) {
        if (station(n))
            return true;
        for (const auto &d : m_description.devices)
            if (d.name == n)
                return true;
        return false;
    };
    if (!taken(stem))
        return stem;
    for (int i = 2;; ++i)
        if (const QString n = stem + QString::number(i); !taken(n))
            return n;
}

bool NetworkDocument::addStation(const StationDescription &s, QString *error) {
    if (!network::validNetworkName(s.name)) {
        *error = tr("\"%1\" is no station name (letters, digits, _ and -, at most 32)").arg(s.name);
        return false;
    }
    if (freeName(s.name) != s.name) {
        *error = tr("A station or device is already named \"%1\"").arg(s.name);
        return false;
    }
    if (s.path.isEmpty() || !QFileInfo::exists(s.path)) {
        *error = tr("%1: no such program").arg(s.path);
        return false;
    }
    if (!s.target.isEmpty() && !model::Target::byId(s.target)) {
        *error = tr("\"%1\" is no target").arg(s.target);
        return false;
    }
    NetworkDescription d = m_description;
    StationDescription added = s;
    if (added.program.isEmpty())
        added.program = m_file.isEmpty() ? QFileInfo(s.path).absoluteFilePath()
                                         : QFileInfo(m_file).absoluteDir().relativeFilePath(s.path);
    d.stations.push_back(added);
    push(std::move(d), tr("Add Station %1").arg(s.name));
    return true;
}

bool NetworkDocument::addExistingProgram(const QString &name, const QString &programFile,
                                         const QString &target, const QString &modelName,
                                         QString *error) {
    StationDescription s;
    s.name = name;
    s.path = QFileInfo(programFile).absoluteFilePath();
    s.target = target;
    s.model = modelName;
    return addStation(s, error);
}

bool NetworkDocument::addNewProject(const QString &name, const QString &projectFile,
                                    const QString &targetId, const QString &modelName,
                                    QString *error) {
    const model::Target *target = model::Target::byId(targetId);
    if (!target) {
        *error = tr("\"%1\" is no target").arg(targetId);
        return false;
    }
    if (!target->model(modelName)) {
        *error = tr("%1 has no model \"%2\"").arg(target->displayName, modelName);
        return false;
    }
    if (!network::validNetworkName(name) || freeName(name) != name) {
        StationDescription probe;
        probe.name = name;
        return addStation(probe, error);
    }
    if (QFileInfo::exists(projectFile)) {
        // Never over another file: the user's work may be in it.
        *error = tr("%1 exists already: choose another name").arg(projectFile);
        return false;
    }
    model::Project project;
    project.target = target;
    project.model = modelName;
    model::ProjectError projectError;
    if (!model::saveProject(project, projectFile, &projectError)) {
        *error = projectError.message;
        return false;
    }
    return addExistingProgram(name, projectFile, QString(), QString(), error);
}

void NetworkDocument::removeWireAt(NetworkDescription *d, std::size_t index) const {
    const QString wire = d->wires[index].name;
    d->wires.erase(d->wires.begin() + qsizetype(index));
    std::erase_if(d->faults, [&wire](const FaultDescription &f) {
        return f.kind != FaultDescription::Kind::Silent && f.wire == wire;
    });
}

QStringList NetworkDocument::removalConsequences(const QString &name) const {
    QStringList out;
    for (const WireDescription &w : m_description.wires) {
        QStringList mine;
        for (const QString &e : w.ends)
            if (endStation(e) == name && e.contains(QLatin1Char('/')))
                mine << e;
        if (mine.isEmpty())
            continue;
        if (w.ends.size() - mine.size() < 2) {
            out << tr("wire %1 (%2) goes: fewer than two ends are left")
                       .arg(w.name, w.ends.join(QStringLiteral(", ")));
            for (const FaultDescription &f : m_description.faults)
                if (f.kind != FaultDescription::Kind::Silent && f.wire == w.name)
                    out << tr("the fault %1 on wire %2 goes").arg(f.where, w.name);
        } else {
            out << tr("%1 comes off wire %2").arg(mine.join(QStringLiteral(", ")), w.name);
        }
    }
    for (const BridgeDescription &b : m_description.bridges)
        if (endStation(b.end) == name)
            out << tr("the bridge of %1 (%2) goes").arg(b.end, bridgeKindText(b.kind));
    for (const FaultDescription &f : m_description.faults)
        if (f.kind == FaultDescription::Kind::Silent && f.station == name)
            out << tr("the fault %1 (silent) goes").arg(f.where);
    return out;
}

bool NetworkDocument::removeStation(const QString &name, QString *error) {
    if (!station(name)) {
        *error = tr("No station is named \"%1\"").arg(name);
        return false;
    }
    NetworkDescription d = m_description;
    std::erase_if(d.stations, [&name](const StationDescription &s) { return s.name == name; });
    for (std::size_t i = d.wires.size(); i-- > 0;) {
        d.wires[i].ends.removeIf([&name](const QString &e) {
            return e.contains(QLatin1Char('/')) && endStation(e) == name;
        });
        if (d.wires[i].ends.size() < 2)
            removeWireAt(&d, i);
    }
    std::erase_if(d.bridges,
                  [&name](const BridgeDescription &b) { return endStation(b.end) == name; });
    std::erase_if(d.faults, [&name](const FaultDescription &f) {
        return f.kind == FaultDescription::Kind::Silent && f.station == name;
    });
    push(std::move(d), tr("Remove Station %1").arg(name));
    return true;
}

bool NetworkDocument::endExists(const QString &end, QString *error) const {
    if (!end.contains(QLatin1Char('/'))) {
        for (const auto &v : m_description.devices)
            if (v.name == end)
                return true;
        *error = tr("No station port or device is named \"%1\"").arg(end);
        return false;
    }
    const QString name = endStation(end);
    const QString port = end.section(QLatin1Char('/'), 1);
    if (!station(name)) {
        *error = tr("No station is named \"%1\"").arg(name);
        return false;
    }
    const NetworkStationInfo info = stationInfo(name);
    const model::PortSpec *spec = info.target->port(port);
    if (!spec || !spec->on(info.model) || spec->name != port) {
        *error =
            tr("%1 (%2 %3) has no port %4").arg(name, info.target->displayName, info.model, port);
        return false;
    }
    return true;
}

bool NetworkDocument::connectEnds(const QString &a, const QString &b, QString *error) {
    if (a == b) {
        *error = tr("A wire joins two different ends");
        return false;
    }
    if (!endExists(a, error) || !endExists(b, error))
        return false;
    NetworkDescription d = m_description;
    const auto find = [&d](const QString &end) -> qsizetype {
        for (std::size_t i = 0; i < d.wires.size(); ++i)
            if (d.wires[i].ends.contains(end))
                return qsizetype(i);
        return -1;
    };
    const qsizetype wa = find(a), wb = find(b);
    if (wa >= 0 && wa == wb) {
        *error = tr("%1 and %2 are on wire %3 already").arg(a, b, d.wires[std::size_t(wa)].name);
        return false;
    }
    if (wa >= 0 && wb >= 0) {
        // A port is on one wire at most: joining two wires makes one bus of both.
        WireDescription &keep = d.wires[std::size_t(wa)];
        const QString gone = d.wires[std::size_t(wb)].name;
        keep.ends += d.wires[std::size_t(wb)].ends;
        for (FaultDescription &f : d.faults)
            if (f.kind != FaultDescription::Kind::Silent && f.wire == gone)
                f.wire = keep.name;
        d.wires.erase(d.wires.begin() + wb);
    } else if (wa >= 0 || wb >= 0) {
        d.wires[std::size_t(wa >= 0 ? wa : wb)].ends << (wa >= 0 ? b : a);
    } else {
        WireDescription w;
        for (int i = 1;; ++i) {
            w.name = QStringLiteral("w%1").arg(i);
            bool taken = false;
            for (const WireDescription &other : d.wires)
                taken = taken || other.name == w.name;
            if (!taken)
                break;
        }
        // Named in the file unless its place gives it that name anyway.
        w.named = w.name != QStringLiteral("w%1").arg(d.wires.size() + 1);
        w.ends = {a, b};
        d.wires.push_back(w);
    }
    push(std::move(d), tr("Connect %1 to %2").arg(a, b));
    return true;
}

bool NetworkDocument::disconnectEnd(const QString &end, QString *error) {
    NetworkDescription d = m_description;
    for (std::size_t i = 0; i < d.wires.size(); ++i) {
        if (!d.wires[i].ends.contains(end))
            continue;
        d.wires[i].ends.removeAll(end);
        if (d.wires[i].ends.size() < 2)
            removeWireAt(&d, i);
        push(std::move(d), tr("Disconnect %1").arg(end));
        return true;
    }
    *error = tr("%1 is on no wire").arg(end);
    return false;
}

bool NetworkDocument::removeWire(const QString &wire, QString *error) {
    NetworkDescription d = m_description;
    for (std::size_t i = 0; i < d.wires.size(); ++i)
        if (d.wires[i].name == wire) {
            removeWireAt(&d, i);
            push(std::move(d), tr("Remove Wire %1").arg(wire));
            return true;
        }
    *error = tr("No wire is named \"%1\"").arg(wire);
    return false;
}

bool NetworkDocument::setPortSettings(const QString &name, const QString &port,
                                      const QJsonObject &settings, QString *error) {
    const StationDescription *s = station(name);
    if (!s) {
        *error = tr("No station is named \"%1\"").arg(name);
        return false;
    }
    if (!endExists(name + QLatin1Char('/') + port, error))
        return false;
    const NetworkStationInfo info = stationInfo(name);
    std::vector<model::PortLayer> layers;
    if (info.projectPorts.contains(port))
        layers.push_back({info.projectPorts.value(port).toObject(), s->program});
    layers.push_back({settings, s->where + QStringLiteral(".ports.") + port});
    model::PortConfig config;
    if (!model::readPortConfig(*info.target, info.target->model(info.model), port, layers, &config,
                               error))
        return false;
    if (s->ports.value(port).toObject() == settings &&
        s->ports.contains(port) == !settings.isEmpty())
        return true; // nothing changed: no undo step
    NetworkDescription d = m_description;
    for (StationDescription &e : d.stations)
        if (e.name == name) {
            if (settings.isEmpty())
                e.ports.remove(port);
            else
                e.ports.insert(port, settings);
        }
    push(std::move(d), tr("Port Settings of %1/%2").arg(name, port));
    return true;
}

bool NetworkDocument::addBridge(const BridgeDescription &bridge, QString *error) {
    for (const BridgeDescription &b : m_description.bridges)
        if (b.end == bridge.end) {
            *error = tr("%1 has a bridge already").arg(bridge.end);
            return false;
        }
    return setBridge(bridge, std::nullopt, error);
}

bool NetworkDocument::setBridge(const BridgeDescription &bridge,
                                const std::optional<QJsonObject> &portSettings, QString *error) {
    if (!bridge.end.contains(QLatin1Char('/'))) {
        *error = tr("A bridge goes from a station's port (STATION/PORT), not from \"%1\"")
                     .arg(bridge.end);
        return false;
    }
    if (!endExists(bridge.end, error))
        return false;
    if (bridge.kind != BridgeDescription::Kind::Pty && bridge.where.trimmed().isEmpty()) {
        *error = tr("A %1 bridge needs where it goes").arg(bridgeKindText(bridge.kind));
        return false;
    }
    if (bridge.kind == BridgeDescription::Kind::Tcp ||
        bridge.kind == BridgeDescription::Kind::Listen) {
        if (!network::splitHostPort(bridge.where)) {
            *error = tr("\"%1\" is not HOST:PORT").arg(bridge.where);
            return false;
        }
    }
    const QString name = endStation(bridge.end), port = bridge.end.section(QLatin1Char('/'), 1);
    const StationDescription *s = station(name);
    const NetworkStationInfo info = stationInfo(name);
    // The port's settings as they will be: the network's new ones over the project's.
    std::vector<model::PortLayer> layers;
    if (info.projectPorts.contains(port))
        layers.push_back({info.projectPorts.value(port).toObject(), s->program});
    layers.push_back({portSettings ? *portSettings : s->ports.value(port).toObject(),
                      s->where + QStringLiteral(".ports.") + port});
    model::PortConfig config;
    QString why;
    const bool read = model::readPortConfig(*info.target, info.target->model(info.model), port,
                                            layers, &config, &why);
    if (!read && portSettings) {
        *error = why;
        return false;
    }
    // CPU Link and Parallel Link publish no frames: nothing could cross a real line.
    if (read && !config.application->published) {
        *error = tr("%1 runs %2, whose frames are not published: it cannot be bridged")
                     .arg(bridge.end, QCoreApplication::translate("rung::model::Target",
                                                                  config.application->name));
        return false;
    }
    NetworkDescription d = m_description;
    bool replaced = false;
    for (BridgeDescription &b : d.bridges)
        if (b.end == bridge.end) {
            b.kind = bridge.kind;
            b.where = bridge.kind == BridgeDescription::Kind::Pty ? QString() : bridge.where;
            replaced = true;
        }
    if (!replaced)
        d.bridges.push_back(bridge);
    if (portSettings)
        for (StationDescription &e : d.stations)
            if (e.name == name) {
                if (portSettings->isEmpty())
                    e.ports.remove(port);
                else
                    e.ports.insert(port, *portSettings);
            }
    if (d.bridges == m_description.bridges && d.stations == m_description.stations)
        return true; // nothing changed: no undo step
    push(std::move(d),
         replaced ? tr("Change Bridge %1").arg(bridge.end) : tr("Add Bridge %1").arg(bridge.end));
    return true;
}

const BridgeDescription *NetworkDocument::bridgeOf(const QString &end) const {
    for (const BridgeDescription &b : m_description.bridges)
        if (b.end == end)
            return &b;
    return nullptr;
}

bool NetworkDocument::removeBridge(const QString &end, QString *error) {
    NetworkDescription d = m_description;
    if (std::erase_if(d.bridges, [&end](const BridgeDescription &b) { return b.end == end; }) ==
        0) {
        *error = tr("%1 has no bridge").arg(end);
        return false;
    }
    push(std::move(d), tr("Remove Bridge %1").arg(end));
    return true;
}

bool NetworkDocument::setPeriod(qint64 periodMs, QString *error) {
    if (periodMs < 1 || periodMs > 1000000) {
        *error = tr("The period is 1 to 1000000 ms, not %1").arg(periodMs);
        return false;
    }
    if (periodMs == m_description.periodMs && m_description.periodGiven)
        return true;
    NetworkDescription d = m_description;
    d.periodMs = periodMs;
    d.periodGiven = true;
    push(std::move(d), tr("Network Period %1 ms").arg(periodMs));
    return true;
}

} // namespace rung::app
