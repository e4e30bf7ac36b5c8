#pragma once

// A project file: JSON, human-readable and diff-friendly, with a schema version
// (docs/project-format.md). Saved atomically.

#include "model/image/value_format.h"
#include "model/ladder/ladder.h"

#include <QJsonObject>
#include <QString>

#include <map>
#include <optional>
#include <vector>

namespace rung::model {

struct Symbol {
    Address address;
    QString name;
    QString comment;
    friend bool operator==(const Symbol &, const Symbol &) = default;
};

// A row of the symbol table that is no symbol yet, as typed: no device, or one the target does
// not have (X9 on a Vigor). Kept in the project so that Save never drops what was typed.
struct PendingSymbol {
    QString device, name, comment;
    friend bool operator==(const PendingSymbol &, const PendingSymbol &) = default;
};

struct WatchList {
    QString name;
    QStringList devices; // as the target writes them
    // How a row's word value is shown, by device; a device not here shows as Decimal.
    std::map<QString, ValueFormat> formats;
    ValueFormat format(const QString &device) const {
        const auto it = formats.find(device);
        return it == formats.end() ? ValueFormat::Decimal : it->second;
    }
    friend bool operator==(const WatchList &, const WatchList &) = default;
};

struct Project {
    const Target *target = nullptr;
    QString model; // ModelVariant::name
    LadderProgram program;
    std::vector<Symbol> symbols;
    std::map<Address, qint64> setValues; // VPC timer/counter set values kept in the PLC
    std::vector<WatchList> watchLists;
    // The instruction list as the user typed it when it had errors the program could not take
    // (the program above is then the last valid one): saved so that reopening shows what was
    // typed, errors and all. Empty when the list and the program agree.
    QString pendingListing;
    std::vector<PendingSymbol> pendingSymbols; // after the symbols in the table, marked
    // The PLC's serial port settings (what Ladder Master calls the "2nd COM Port Setting"),
    // port name -> settings as docs/network-format.md describes them; a network file may
    // override them. Kept as written.
    QJsonObject ports;

    const Symbol *symbol(const Address &address) const;
};

constexpr int kProjectSchemaVersion = 1;
constexpr const char *kProjectExtension = "rung";

struct ProjectError {
    QString message; // translated: what, where (line/column or JSON path) and why
};

std::optional<Project> loadProject(const QString &path, ProjectError *error);
std::optional<Project> projectFromJson(const QByteArray &json, ProjectError *error);
QByteArray projectToJson(const Project &project);
bool saveProject(const Project &project, const QString &path, ProjectError *error);

} // namespace rung::model
