#include "application.h"

#include "command_line.h"
#include "main_window.h"

#include "editor/ladder_view.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QLibraryInfo>
#include <QLocale>
#include <QMessageBox>
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
    // English has a catalogue too: its plural forms ("1 rung", "2 rungs"). It is the
    // fallback for a language we do not have, and for the C locale.
    if (translator.load(QStringLiteral(":/i18n/rungstudio_%1").arg(language)) ||
        translator.load(QStringLiteral(":/i18n/rungstudio_en")))
        QApplication::installTranslator(&translator);
    if (qtTranslator.load(QStringLiteral("qtbase_%1").arg(language),
                          QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        QApplication::installTranslator(&qtTranslator);

    QCommandLineParser parser;
    describeGuiArguments(parser);
    parser.process(app); // --help, --version and unknown options end here
    const GuiArguments arguments = readGuiArguments(parser);

    MainWindow window;
    window.show();
    if (!arguments.ok())
        QMessageBox::critical(&window, QApplication::translate("rung::app::Gui", "Rung Studio"),
                              arguments.error);
    else
        window.start(arguments.file, arguments.target);
    if (!arguments.screenshot.isEmpty()) {
        const QString path = arguments.screenshot;
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
