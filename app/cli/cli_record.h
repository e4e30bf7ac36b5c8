#pragma once

#include <QStringList>
#include <QTextStream>

namespace rung::app {

// `rungstudio-cli record --pc PORT --plc PORT [--baud B] [--frame 8N1] [-o FILE] [--seconds S]`
// joins two ports and passes every byte on in both directions, writing each with its time and
// direction (comms::Relay). PORT is a serial port, a pseudo-terminal path, or `pty` for a new
// pseudo-terminal, whose path is printed first (`pc /dev/pts/N`). Runs until SIGINT, SIGTERM,
// --seconds or a side failing. args = everything after "record". Exit codes: 0 stopped as
// asked, 2 usage error, a port that cannot be opened or a side that failed (docs/cli.md).
QString recordUsage();
int runRecordCommand(const QStringList &args, QTextStream &out, QTextStream &err);

} // namespace rung::app
