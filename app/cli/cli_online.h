#pragma once

#include <QStringList>
#include <QTextStream>

namespace rung::app {

// `rungstudio-cli read --target T --protocol P (--port NAME | --tcp HOST:PORT | --pty PATH)
//  [--station N] [--baud B] [--frame 8N1] [--timeout MS] [--retries N] DEVICE...`
// prints DEVICE=VALUE lines; `write ... DEVICE=VALUE...` writes each in turn and stops at the
// first the PLC does not acknowledge. args = everything after "read" / "write". Exit codes:
// 0 done, 1 the PLC did not answer or refused (what was not done is named), 2 usage error
// or a port that cannot be opened (docs/cli.md).
// The lines `rungstudio-cli --help` prints for read and write.
QString onlineUsage();
int runReadCommand(const QStringList &args, QTextStream &out, QTextStream &err);
int runWriteCommand(const QStringList &args, QTextStream &out, QTextStream &err);

} // namespace rung::app
