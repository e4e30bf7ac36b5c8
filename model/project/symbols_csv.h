#pragma once

// The symbol table as CSV, for spreadsheets and the vendor tools' device-comment lists:
// "device,name,comment", RFC 4180 quoting (a field may hold commas, quotes and line breaks).
// Reading also takes ';' as the separator (spreadsheets in many locales write it), a UTF-8
// byte-order mark, CRLF line ends and an optional header row.

#include "model/project/project.h"

#include <QString>

#include <vector>

namespace rung::model {

QString symbolsToCsv(const Target &target, const std::vector<Symbol> &symbols);

struct SymbolsCsv {
    std::vector<Symbol> symbols; // in file order; a device listed again replaces itself
    int errorLine = 0;           // 1-based line of the first bad record
    QString error;
    bool ok() const { return error.isEmpty(); }
};

SymbolsCsv symbolsFromCsv(const Target &target, const ModelVariant *modelVariant,
                          const QString &text);

} // namespace rung::model
