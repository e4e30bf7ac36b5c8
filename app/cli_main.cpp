#include "app/cli/cli.h"
#include "app/cli/cli_language.h"

#include <QCoreApplication>
#include <QLocale>
#include <QTranslator>

#include <cstdio>

int main(int argc, char **argv) {
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("rungstudio-cli"));
    QStringList arguments = QCoreApplication::arguments();
    QString language;
    QString error;
    if (!rung::app::takeLanguageOption(&arguments, &language, &error)) {
        std::fputs(qPrintable(error + QLatin1Char('\n')), stderr);
        return 2;
    }
    // Messages follow --lang, else the locale as other command-line tools' do
    // (LANG=hu_HU.UTF-8); the C/POSIX locale, which scripts and CI use, gets English, whose
    // catalogue holds only the plural forms ("needs 1 operand", "needs 2 operands").
    QTranslator translator;
#ifdef RUNG_HAS_CATALOGUES
    const bool loaded = language.isEmpty()
                            ? translator.load(QLocale::system(), QStringLiteral("rungstudio"),
                                              QStringLiteral("_"), QStringLiteral(":/i18n"))
                            : translator.load(QStringLiteral(":/i18n/rungstudio_%1").arg(language));
    if (loaded || translator.load(QStringLiteral(":/i18n/rungstudio_en")))
        QCoreApplication::installTranslator(&translator);
#endif
    return rung::app::runCli(arguments);
}
