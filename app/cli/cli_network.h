#pragma once

// The command-line tool on a network file (.rungnet, docs/network-format.md): simulate it,
// check it, serve it with its bridges (docs/cli.md).

#include "network/network.h"

#include <QStringList>
#include <QTextStream>

namespace rung::app {

bool isNetworkFile(const QString &file);
// The network's lines of the tool's usage.
QString networkUsage();

// The stations' programs loaded as `simulate` loads one program (cli_load_program.h): a
// listing, a ladder text or a project, checked, compiled; the errors with their places.
network::ProgramLoader cliProgramLoader();

// `simulate NET.rungnet --scans N [--period MS] [--set NAME/DEV=V@SCAN]... --trace NAME/DEV,...
// [--traffic FILE]`: args after the file.
int runNetworkSimulate(const QString &file, const QStringList &args, QTextStream &out,
                       QTextStream &err);

// `check NET.rungnet`: each station's program as `check` checks one (its findings named by
// the program's file), then the network: port settings, wiring, the LINK / MBUS tables
// (network/check.h). 0 clean, 1 errors, 2 usage or I/O.
int runNetworkCheck(const QString &file, const QStringList &args, QTextStream &out,
                    QTextStream &err);

// `serve NET.rungnet`: the network in real time with its bridges (docs/network.md,
// "Bridges"): one line on stdout per bridge, "STATION/PORT WHERE", flushed at once, then
// running until SIGINT or SIGTERM (exit 0) or a line fails (exit 2).
int runNetworkServe(const QString &file, const QStringList &args, QTextStream &out,
                    QTextStream &err);

} // namespace rung::app
