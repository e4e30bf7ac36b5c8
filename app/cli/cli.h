#pragma once

#include <QStringList>
#include <QTextStream>

namespace rung::app {

// Runs `rungstudio-cli` with the given arguments (argv[0] first) writing to the given
// streams. Exit codes: 0 success / no errors, 1 the program has errors, 2 usage or I/O error.
int runCli(const QStringList &arguments, QTextStream &out, QTextStream &err);
int runCli(const QStringList &arguments); // stdout / stderr

} // namespace rung::app
