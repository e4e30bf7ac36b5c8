#pragma once

// The plain-text drawing of a ladder (docs/ladder-text.md): what `rungstudio-cli convert
// --to ladder` writes and reads back exactly. Tests use it to write ladders that no
// instruction list can express, such as a reverse-current bridge.

#include "il.h"
#include "ladder.h"

#include <QString>

#include <vector>

namespace rung::model {

QString printLadderText(const LadderProgram &ladder);

struct LadderTextResult {
    LadderProgram ladder;
    std::vector<ParseError> errors;
    bool ok() const { return errors.empty(); }
};
LadderTextResult parseLadderText(const Target &target, const QString &text,
                                 const ModelVariant *model = nullptr);

} // namespace rung::model
