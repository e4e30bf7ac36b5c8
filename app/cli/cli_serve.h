#pragma once

#include <QStringList>
#include <QTextStream>

namespace rung::app {

// rungstudio-cli serve FILE [--target T] [--model M]
//     --protocol vigor|modbus|modbus-tcp|hostlink (--pty | --port NAME | --tcp HOST:PORT)
//     [--station N] [--baud B] [--format 8N1] [--period MS] [--fault NAME]
// Runs the program in real time as a virtual PLC until SIGINT or SIGTERM (exit 0). The first
// line of out says where it is reached (the /dev/pts/N path, HOST:PORT, the port's name).
int runServeCommand(const QStringList &args, QTextStream &out, QTextStream &err);

} // namespace rung::app
