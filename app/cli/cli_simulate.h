#pragma once

#include <QStringList>
#include <QTextStream>

namespace rung::app {

// `rungstudio-cli simulate FILE [--target T] --scans N [--period MS]
//  [--set DEV=VALUE@SCAN]... --trace DEV[,DEV...]`; args = everything after "simulate".
// Prints CSV (scan,time_ms,DEV...) with one row per scan after its END. Exit codes as runCli:
// 0 ran, 1 the program has errors, 2 usage or I/O error.
int runSimulateCommand(const QStringList &args, QTextStream &out, QTextStream &err);

} // namespace rung::app
