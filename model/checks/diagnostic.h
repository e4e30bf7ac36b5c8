#pragma once

// A finding of the checks or the parser: stable code, severity, place, translated message,
// and where possible a fix.

#include "model/ladder/ladder.h"

#include <QString>

#include <optional>
#include <vector>

namespace rung::model {

enum class Severity : std::uint8_t { Error, Warning, Info };

struct Location {
    // Listing location (1-based); line == 0 when the finding is on the ladder only.
    int line = 0;
    int column = 0;
    // Ladder location (0-based); rung == -1 when the finding is on the listing only.
    int rung = -1;
    int row = -1;
    int cell = -1; // cell column; == Rung::columns for the output column

    bool onListing() const { return line > 0; }
    bool onLadder() const { return rung >= 0; }
    friend bool operator==(const Location &, const Location &) = default;
};

struct Fix {
    QString label; // translated: "Duplicate the shared contact into each branch"
    // Either replace listing lines [firstLine, lastLine] with text ...
    int firstLine = 0;
    int lastLine = 0;
    QString listing;
    // ... or replace ladder rungs [firstRung, lastRung] with these.
    int firstRung = -1;
    int lastRung = -1;
    std::vector<Rung> rungs;
};

struct Diagnostic {
    QString code; // stable, e.g. "RC001"; see docs/diagnostics.md
    Severity severity = Severity::Error;
    Location location;
    std::vector<Location> related; // the other places involved (the second coil, the cells)
    QString message;               // translated
    std::optional<Fix> fix;
};

// Order by place: listing line, then rung/row/cell.
void sortDiagnostics(std::vector<Diagnostic> &diagnostics);
bool hasErrors(const std::vector<Diagnostic> &diagnostics);

} // namespace rung::model
