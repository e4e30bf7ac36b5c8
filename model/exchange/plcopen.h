#pragma once

// PLCopen TC6 XML 2.01 (docs/plcopen.md): the ladder written as an LD body other IEC 61131-3
// tools read (Beremiz, OpenPLC, CODESYS), and LD bodies they wrote read back into a target's
// ladder. What a file holds that the target cannot take is listed by element and line, never
// dropped.

#include "model/project/project.h"

#include <QByteArray>
#include <QDateTime>
#include <QString>
#include <QStringList>

#include <map>
#include <optional>
#include <vector>

namespace rung::model {

// ---- names and addresses (plcopen_names.cpp) ------------------------------------------------

// A device as an IEC 61131-3 identifier: X0, DM0010, TIM000, IN000_01 (CPM1 000.01: a name
// does not start with a digit, so the area's key goes first), SM0_0.
QString iecName(const Target &target, const Address &address);
// The device an identifier names, if it names one of the target (the inverse of iecName, and
// a device as the target writes it without spaces: DM0010, TIM000).
std::optional<Address> deviceOfIecName(const Target &target, const QString &name,
                                       const ModelVariant *model = nullptr);

// The located-variable rule (docs/plcopen.md "Located variables"): %IXb.i is input 8b + i of
// the target's first physical input area, counted from its first element (Vigor X0..X7 =
// %IX0.0..%IX0.7, X10 = %IX1.0; CPM1 000.00..000.15 = %IX0.0..%IX1.7; PL110 I1 = %IX0.0), %QXb.i
// the same of the outputs; %IWn / %QWn the n-th analog input / output word; %MWn the n-th
// word of the data memory (Vigor D, CPM1 DM, PL110 V, VPC p). nullopt: no such device.
std::optional<Address> deviceOfLocation(const Target &target, const QString &location,
                                        const ModelVariant *model = nullptr);
// The location of a device by the same rule, or empty when it has none (M0, T0).
QString locationOfDevice(const Target &target, const Address &address);
// The area of the data memory %MWn names (Vigor D, CPM1 DM, PL110 V, VPC p); -1: none.
int dataMemoryArea(const Target &target);

// ---- export (plcopen_export.cpp) ----------------------------------------------------------

struct PlcopenExport {
    QByteArray xml;
    // Instructions written as blocks of the PLC's own (no IEC 61131-3 block does what they
    // do): another tool reads the file but not those blocks; counters written as IEC counters,
    // with what they do otherwise. Translated, one per kind.
    QStringList notes;
};
// `name`: the project's name (contentHeader, the POU is "main"). creationDateTime is now,
// unless `created` is valid (tests, reproducible builds).
PlcopenExport exportPlcopen(const Project &project, const QString &name,
                            const QDateTime &created = {});

// ---- import (plcopen_import.cpp) ----------------------------------------------------------

// Variable name -> device, from a mapping file (docs/plcopen.md "Mapping file"): one
// `NAME = DEVICE` a line, `#` comments.
struct DeviceMapping {
    std::map<QString, QString> devices;
};
// nullopt with *error (translated, with the line) when a line does not read.
std::optional<DeviceMapping> readDeviceMapping(const QString &text, QString *error);

// Something of the file not imported: the element, its line and why (translated).
struct ImportIssue {
    int line = 0;
    QString element; // "contact", "block SEL", "variable Motor", "pou Counter", ...
    QString message;
};

// A variable the program uses that no rule maps to a device, and the free device proposed
// for it (what a mapping file or the import dialog would give it).
struct UnmappedVariable {
    QString name;
    int line = 0;
    QString type;     // BOOL, INT, TON, ...
    QString proposed; // a free device of the target for it, empty when none is left
};

struct PlcopenImport {
    std::optional<Project> project;  // what could be imported (none when the file is no LD)
    std::vector<ImportIssue> issues; // everything not imported
    std::vector<UnmappedVariable> unmapped;
    QString fileTarget; // the target a Rung Studio export names, if any
    // What is imported but works otherwise than in the file (an IEC CTU as the target's
    // counter, which stops at its set value), translated, one per kind; and a Rung Studio file
    // whose instruction list no longer matches its ladder. Not issues: nothing is left out.
    QStringList notes;
    bool complete() const { return project && issues.empty() && unmapped.empty(); }
};

PlcopenImport importPlcopen(const QByteArray &xml, const Target &target, const ModelVariant *model,
                            const DeviceMapping &mapping = {});

} // namespace rung::model
