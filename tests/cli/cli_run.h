#pragma once

// `rungstudio-cli` run in-process, as the CLI tests call it: exit status and both streams.

#include "app/cli/cli.h"

#include <QStringList>
#include <QTextStream>

namespace rung::test {

struct CliRun {
    int code = 0;
    QString out;
    QString err;
};

inline CliRun cli(QStringList args) {
    CliRun r;
    QTextStream out(&r.out);
    QTextStream err(&r.err);
    args.prepend(QStringLiteral("rungstudio-cli"));
    r.code = rung::app::runCli(args, out, err);
    out.flush();
    err.flush();
    return r;
}

} // namespace rung::test
