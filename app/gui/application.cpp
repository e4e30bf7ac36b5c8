#include "application.h"

#include "main_window.h"

#include "editor/ladder_view.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QLibraryInfo>
#include <QLocale>
#include <QSettings>
#include <QTimer>
#include <QTranslator>

namespace rung::app {

int runGui(int argc, char **argv) {
    QApplication app(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("RungStudio"));
    QApplication::setApplicationName(QStringLiteral("Rung Studio"));
    QApplication::setApplicationVersion(QStringLiteral(RUNG_VERSION));

    // The language chosen in the Language menu, else the system's when we have it.
    QString language = QSettings().value(QStringLiteral("ui/language")).toString();
    if (language.isEmpty())
        language = QLocale::system().name().left(2);
    QTranslator translator;
    QTranslator qtTranslator;
    if (translator.load(QStringLiteral(":/i18n/rungstudio_%1").arg(language)))
        QApplication::installTranslator(&translator);
    if (qtTranslator.load(QStringLiteral("qtbase_%1").arg(language),
                          QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        QApplication::installTranslator(&qtTranslator);

    QCommandLineParser parser;
    parser.setApplicationDescription(QApplication::translate(
        "rung::app::Gui", "Ladder and instruction-list IDE for small PLCs"));
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addPositionalArgument(
        QStringLiteral("file"),
        QApplication::translate("rung::app::Gui",
                                "A project (.rung) or an instruction list to open"));
    QCommandLineOption target(
        QStringLiteral("target"),
        QApplication::translate("rung::app::Gui",
                                "Target of an instruction list: vpc, vigor, cpm1, pl110"),
        QStringLiteral("T"));
    QCommandLineOption screenshot(
        QStringLiteral("screenshot"),
        QApplication::translate("rung::app::Gui", "Save a picture of the window and quit"),
        QStringLiteral("PNG"));
    parser.addOption(target);
    parser.addOption(screenshot);
    parser.process(app);

    MainWindow window;
    window.show();
    const QStringList files = parser.positionalArguments();
    if (!files.isEmpty())
        window.openFile(files.front(), parser.value(target));
    else
        window.offerRecovery();
    if (parser.isSet(screenshot)) {
        const QString path = parser.value(screenshot);
        QTimer::singleShot(1200, &window, [&window, &app, path] {
            window.ladderView()->setFocus();
            window.ladderView()->setCursor({1, 0, 1});
            QTimer::singleShot(300, &window, [&window, &app, path] {
                window.grab().save(path);
                app.quit();
            });
        });
    }
    return app.exec();
}

} // namespace rung::app
