#pragma once

// The network open in the IDE (issue 30): its description (network/network_file.h), its file,
// whether it was changed, and the undo stack of its edits. Every edit is one undo command that
// holds the network as it was and as it becomes (values, no pointers into the document) and
// does its work in redo(); the views draw from description() and follow changed().

#include "network/network_file.h"

#include <QJsonObject>
#include <QObject>
#include <QUndoStack>

#include <map>
#include <optional>

namespace rung::model {
class Target;
} // namespace rung::model

namespace rung::app {

// What a station runs, as its program says it when the network does not (a project's target,
// model and port settings; a listing's "; target:" line).
struct NetworkStationInfo {
    const model::Target *target = nullptr; // never null: the default target when unknown
    QString model;                         // the model's name
    QJsonObject projectPorts;              // a project's own "ports"
    QString problem;                       // why the program could not be read; "" when it was
};

class NetworkDocument : public QObject {
    Q_OBJECT
public:
    explicit NetworkDocument(QObject *parent = nullptr);

    // A new, empty network (no file yet): its stations' programs are kept as absolute paths
    // until the first Save As makes them relative.
    void newNetwork();
    bool open(const QString &file, QString *error);
    // Save writes where the network came from; false with why (a network never saved needs
    // Save As). When the file could not hold everything, nothing is written and `notKept` says
    // what, unless `evenIfNotKept` (the user was asked: saveNetwork in network_view.h asks).
    bool save(QStringList *notKept, QString *error, bool evenIfNotKept = false);
    bool saveAs(const QString &file, QStringList *notKept, QString *error,
                bool evenIfNotKept = false);

    const network::NetworkDescription &description() const { return m_description; }
    QString filePath() const { return m_file; }
    QString displayName() const; // the file's name, or "Untitled network"
    bool isModified() const { return !m_undo.isClean(); }
    QUndoStack *undoStack() { return &m_undo; }

    NetworkStationInfo stationInfo(const QString &station) const;
    const network::StationDescription *station(const QString &name) const;
    // The ports a view shows for a station: those its model has but the ones only a program
    // drives (VB-1COM slots) not named anywhere, then any named in the network or the project.
    QStringList stationPorts(const QString &station) const;
    // A port's settings as the station runs them: the project's, the network's over them.
    QJsonObject effectivePortSettings(const QString &station, const QString &port) const;
    // The wire an end ("station/PORT" or a device) is on; nullptr when none.
    const network::WireDescription *wireOf(const QString &end) const;
    // A name for a new station, unique among stations and devices: base, base2, base3, ...
    QString freeName(const QString &base) const;

    // The edits. Each is one undo step; false with why (translated) when refused, the network
    // unchanged.
    bool addStation(const network::StationDescription &station, QString *error);
    // A station running an existing project, listing or ladder text; target and model may be
    // empty (the program's own).
    bool addExistingProgram(const QString &name, const QString &programFile, const QString &target,
                            const QString &model, QString *error);
    // Writes a new, empty project of the target and model at `projectFile` (which must not
    // exist), then adds a station running it.
    bool addNewProject(const QString &name, const QString &projectFile, const QString &target,
                       const QString &model, QString *error);
    // What else goes with a station (its wires' ends, wires left with one end, bridges and
    // faults on them), one line each, translated: to be said before removeStation.
    QStringList removalConsequences(const QString &station) const;
    bool removeStation(const QString &station, QString *error);
    // Joins two ends: a new wire, or the end added to the wire the other is on.
    bool connectEnds(const QString &a, const QString &b, QString *error);
    // Takes an end off its wire (the wire goes when one end is left, with its faults).
    bool disconnectEnd(const QString &end, QString *error);
    // Removes a wire with all its ends (and its faults).
    bool removeWire(const QString &wire, QString *error);
    // The network's settings of a port (an empty object removes them: the project's or the
    // defaults apply), checked against the target's table.
    bool setPortSettings(const QString &station, const QString &port, const QJsonObject &settings,
                         QString *error);
    bool addBridge(const network::BridgeDescription &bridge, QString *error);
    // Makes the port's bridge or changes the one it has (its place in the file kept), and with
    // it the network's settings of the port when `portSettings` is given (the rate and format
    // the bridge's line opens at): one undo step.
    bool setBridge(const network::BridgeDescription &bridge,
                   const std::optional<QJsonObject> &portSettings, QString *error);
    // The bridge of a port ("s5/CP2"); nullptr when it has none.
    const network::BridgeDescription *bridgeOf(const QString &end) const;
    bool removeBridge(const QString &end, QString *error);
    bool setPeriod(qint64 periodMs, QString *error);

signals:
    void changed();
    void modifiedChanged(bool modified);
    void filePathChanged(const QString &file);

private:
    friend class NetworkEditCommand;
    void push(network::NetworkDescription after, const QString &label);
    void apply(const network::NetworkDescription &description);
    bool endExists(const QString &end, QString *error) const;
    void removeWireAt(network::NetworkDescription *d, std::size_t index) const;

    network::NetworkDescription m_description;
    QString m_file;
    QUndoStack m_undo;
    mutable std::map<QString, NetworkStationInfo> m_infos; // by the program's path
};

} // namespace rung::app
