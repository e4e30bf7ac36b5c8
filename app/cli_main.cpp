#include "app/cli/cli.h"

#include <QCoreApplication>
#include <QLocale>
#include <QTranslator>

int main(int argc, char **argv) {
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("rungstudio-cli"));
    // Messages follow the locale as other command-line tools' do (LANG=hu_HU.UTF-8); the
    // C/POSIX locale, which scripts and CI use, gets English, whose catalogue holds only
    // the plural forms ("needs 1 operand", "needs 2 operands").
    QTranslator translator;
#ifdef RUNG_HAS_CATALOGUES
    if (translator.load(QLocale::system(), QStringLiteral("rungstudio"), QStringLiteral("_"),
                        QStringLiteral(":/i18n")) ||
        translator.load(QStringLiteral(":/i18n/rungstudio_en")))
        QCoreApplication::installTranslator(&translator);
#endif
    return rung::app::runCli(QCoreApplication::arguments());
}
