#include "model/checks/diagnostic.h"

#include <algorithm>
#include <tuple>

namespace rung::model {

void sortDiagnostics(std::vector<Diagnostic> &diagnostics) {
    // Listing findings first by line and column, then ladder findings by rung, row and cell;
    // stable so findings at one place keep the order the checks found them in.
    auto key = [](const Diagnostic &d) {
        const Location &l = d.location;
        return std::make_tuple(l.line > 0 ? 0 : 1, l.line, l.column, l.rung, l.row, l.cell);
    };
    std::stable_sort(diagnostics.begin(), diagnostics.end(),
                     [&](const Diagnostic &a, const Diagnostic &b) { return key(a) < key(b); });
}

bool hasErrors(const std::vector<Diagnostic> &diagnostics) {
    return std::any_of(diagnostics.begin(), diagnostics.end(),
                       [](const Diagnostic &d) { return d.severity == Severity::Error; });
}

} // namespace rung::model
