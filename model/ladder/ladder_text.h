#pragma once

// The plain-text drawing of a ladder (docs/ladder-text.md): what `rungstudio-cli convert
// --to ladder` writes and reads back exactly. Tests use it to write ladders that no
// instruction list can express, such as a reverse-current bridge.

#include "model/ladder/ladder.h"
#include "model/listing/il.h"

#include <QString>

#include <optional>
#include <vector>

namespace rung::model {

QString printLadderText(const LadderProgram &ladder);

// One contact as a short text, as project files store cells: "X0", "/X0" (NC), "^X0"
// (rising), "_X0" (falling), "D0>=K10" (compare), "~" (INV).
QString contactToText(const Target &target, const Contact &contact);
// The power-flow elements have no device: NOT is empty, PL110's P and N are "P", "N" (in the
// ladder text "~", "~P", "~N").
QString invertText(const Contact &contact);
// nullopt with *error set (translated) when the text is not a contact of the target.
std::optional<Contact> contactFromText(const Target &target, const QString &text, QString *error,
                                       const ModelVariant *model = nullptr);

struct LadderTextResult {
    LadderProgram ladder;
    std::vector<ParseError> errors;
    bool ok() const { return errors.empty(); }
};
// The target id the "LADDER <target> WIDTH <n>" header names; empty when the text has none.
QString ladderTextTarget(const QString &text);
LadderTextResult parseLadderText(const Target &target, const QString &text,
                                 const ModelVariant *model = nullptr);

} // namespace rung::model
