#include "cli.h"

namespace rung::app {

int runCli(const QStringList &arguments, QTextStream &out, QTextStream &err)
{
    Q_UNUSED(arguments);
    Q_UNUSED(out);
    err << "usage: rungstudio-cli check|convert|simulate FILE ...\n";
    return 2;
}

int runCli(const QStringList &arguments)
{
    QTextStream out(stdout);
    QTextStream err(stderr);
    return runCli(arguments, out, err);
}

} // namespace rung::app
