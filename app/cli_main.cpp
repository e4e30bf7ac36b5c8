#include "app/cli/cli.h"

#include <QCoreApplication>

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("rungstudio-cli"));
    return rung::app::runCli(QCoreApplication::arguments());
}
