#pragma once

// The listing tests' helpers: a family's listing parsed with its errors, and those errors as
// text for a failure's message.

#include "model/listing/il.h"

#include <string>

namespace rung::testing {

// The execution order example of PLC concepts (WPLSoft family) 1.5.1, verbatim.
inline constexpr const char *kExecutionOrderExample =
    "LD X0\nOR M0\nAND X1\nLD X3\nAND M1\nORB\nLD Y1\nAND X4\nLD T0\nAND M3\n"
    "ORB\nANB\nOUT Y1\nTMR T0 K10\n";

inline model::ParseResult parseListing(model::Family family, const QString &text) {
    return model::parseInstructionList(model::Target::get(family), text);
}

// "line:column message" per error, one a line.
inline std::string describeErrors(const model::ParseResult &r) {
    QString out;
    for (const model::ParseError &e : r.errors)
        out += QStringLiteral("%1:%2 %3\n").arg(e.line).arg(e.column).arg(e.message);
    return out.toStdString();
}

} // namespace rung::testing
