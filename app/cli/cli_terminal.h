#pragma once

#include <QStringList>
#include <QTextStream>

namespace rung::app {

// `rungstudio-cli terminal --port PORT [--baud B] [--frame 8N1] [--wait MS]`: a raw serial
// terminal. Each line read from `in` is sent as bytes: hex pairs (`02 30 30 35 31`), a quoted
// text with C escapes (`"@00RD00000001*\r"`), or a line of a `record` capture (its PC>PLC
// bytes are sent again, its PLC>PC lines skipped), so a capture can be replayed. After each,
// what arrives until the line is quiet for --wait ms is printed as capture lines. args =
// everything after "terminal". Exit codes: 0 input ended, 2 usage error, a line that is no
// bytes (named with its number), or a port that cannot be opened or fails (docs/cli.md).
QString terminalUsage();
int runTerminalCommand(const QStringList &args, QTextStream &in, QTextStream &out,
                       QTextStream &err);

} // namespace rung::app
