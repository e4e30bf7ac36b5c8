#include "application.h"

#include "command_line.h"
#include "dialogs.h"
#include "language.h"
#include "main_window.h"

#include "editor/ladder_view.h"

#include <QAction>
#include <QApplication>
#include <QCommandLineParser>
#include <QMessageBox>
#include <QScreen>
#include <QTimer>

namespace rung::app {

int runGui(int argc, char **argv) {
    QApplication app(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("RungStudio"));
    QApplication::setApplicationName(QStringLiteral("Rung Studio"));
    QApplication::setApplicationVersion(QStringLiteral(RUNG_VERSION));

    // The language chosen in the Language menu, else the system's when we have it.
    setLanguage(startLanguage(), false);

    QCommandLineParser parser;
    describeGuiArguments(parser);
    parser.process(app); // --help, --version and unknown options end here
    const GuiArguments arguments = readGuiArguments(parser);

    MainWindow window;
    window.show();
    if (!arguments.ok())
        messageBox(QMessageBox::Critical, &window,
                   QApplication::translate("rung::app::Gui", "Rung Studio"), arguments.error);
    else
        window.start(arguments.file, arguments.target);
    if (!arguments.screenshot.isEmpty()) {
        const QString path = arguments.screenshot;
        // scripts/screenshot.sh: RUNG_SCREENSHOT_DIALOG=new|save|open pictures that dialog
        // over the window (the whole screen), as the user meets it.
        const QString dialog = qEnvironmentVariable("RUNG_SCREENSHOT_DIALOG");
        QTimer::singleShot(1200, &window, [&window, &app, path, dialog] {
            window.ladderView()->setFocus();
            window.ladderView()->setCursor({1, 0, 1});
            if (dialog.isEmpty()) {
                QTimer::singleShot(300, &window, [&window, &app, path] {
                    window.grab().save(path);
                    app.quit();
                });
                return;
            }
            // The dialog runs its own event loop: the picture is taken from inside it, and
            // exit() ends that loop and the application's.
            QTimer::singleShot(1000, &app, [path] {
                QGuiApplication::primaryScreen()->grabWindow(0).save(path);
                QCoreApplication::exit(0);
            });
            const auto byKey = [&window](QKeySequence::StandardKey key) -> QAction * {
                for (QAction *a : window.findChildren<QAction *>())
                    if (a->shortcut() == QKeySequence(key))
                        return a;
                return nullptr;
            };
            if (dialog == QLatin1String("save")) {
                window.document()->markUnsaved();
                window.close();
            } else if (QAction *a = byKey(dialog == QLatin1String("open") ? QKeySequence::Open
                                                                          : QKeySequence::New)) {
                a->trigger();
            }
        });
    }
    return app.exec();
}

} // namespace rung::app
