#include "application.h"

#include "about_dialog.h"
#include "command_line.h"
#include "dialogs.h"
#include "language.h"
#include "main_window.h"

#include "simulation_controller.h"

#include "editor/document.h"
#include "editor/ladder_view.h"
#include "editor/timing_chart.h"
#include "editor/watch_list_view.h"
#include "model/target/address.h"

#include <QAction>
#include <QApplication>
#include <QCommandLineParser>
#include <QDockWidget>
#include <QMenu>
#include <QMessageBox>
#include <QScreen>
#include <QTimer>

namespace rung::app {

namespace {

void nameApplication() {
    QCoreApplication::setOrganizationName(QStringLiteral("RungStudio"));
    QCoreApplication::setApplicationName(QStringLiteral("Rung Studio"));
    QCoreApplication::setApplicationVersion(QStringLiteral(RUNG_VERSION));
}

// --help and --version answer without a display, as other programs' do (a package's scripts
// and the man page's test ask them on machines that have none).
bool asksForHelpOrVersion(int argc, char **argv) {
    for (int i = 1; i < argc; ++i) {
        const QByteArray arg(argv[i]);
        if (arg == "--") // what follows is a file name
            return false;
        if (arg == "-h" || arg == "--help" || arg == "--help-all" || arg == "-v" ||
            arg == "--version" || arg == "-?")
            return true;
    }
    return false;
}

} // namespace

int runGui(int argc, char **argv) {
    if (asksForHelpOrVersion(argc, argv)) {
        QCoreApplication app(argc, argv);
        nameApplication();
        setLanguage(startLanguage(), false);
        QCommandLineParser parser;
        describeGuiArguments(parser);
        parser.process(app); // prints and exits
        return 0;
    }
    QApplication app(argc, argv);
    nameApplication();
    // The taskbar's icon: the window's on X11, the desktop entry's (by its name) on Wayland.
    QApplication::setWindowIcon(applicationIcon());
    QGuiApplication::setDesktopFileName(QStringLiteral("io.github.rungstudio.RungStudio"));

    // The language chosen in the Language menu, else the system's when we have it.
    setLanguage(startLanguage(), false);

    QCommandLineParser parser;
    describeGuiArguments(parser);
    parser.process(app); // unknown options end here
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
            if (dialog == QLatin1String("panels") || dialog == QLatin1String("chart")) {
                // A running simulation with the monitoring docks in use: the watch table in
                // several formats, or the timing chart with a trigger armed.
                const bool chart = dialog == QLatin1String("chart");
                window.simulation()->setSpeed(chart ? 10.0 : 1.0);
                window.simulation()->run();
                // The project's own devices (no device names here: they belong to the
                // target tables): the named ones, then the words the program uses.
                const editor::Document &doc = *window.document();
                const model::Target &t = doc.target();
                QStringList named, words;
                for (const model::Symbol &s : doc.project().symbols)
                    named << model::formatAddress(t, s.address);
                for (const model::Instruction &ins : doc.listing().list.instructions)
                    for (const model::Operand &o : ins.operands) {
                        const QString name = model::formatAddress(t, o.address);
                        if (o.kind == model::Operand::Kind::Device && o.address.valid() &&
                            o.address.bit < 0 &&
                            t.area(o.address.area).kind != model::AreaKind::Bit &&
                            !words.contains(name) && words.size() < 4)
                            words << name;
                    }
                editor::WatchListView *watch = window.watchListView();
                watch->addDevices(words + named); // the formats in view first
                const model::ValueFormat formats[] = {
                    model::ValueFormat::Decimal, model::ValueFormat::Hex,
                    model::ValueFormat::Binary, model::ValueFormat::Bcd};
                const QModelIndex list = watch->model()->index(0, 0);
                for (int k = 0; k < static_cast<int>(words.size()); ++k)
                    if (const QModelIndex row = watch->model()->index(k, 0, list); row.isValid())
                        watch->setFormat(row, formats[k]);
                editor::TimingChart *timing = window.timingChart();
                timing->addDevices(named);
                if (named.size() >= 3)
                    timing->armTrigger(named[2] + QStringLiteral(" rises"),
                                       model::Trigger::Action::Mark);
                timing->setMsPerPixel(80);
                const char *raise = chart ? "timingChartDock" : "watchDock";
                if (auto *d = window.findChild<QDockWidget *>(QString::fromLatin1(raise))) {
                    d->show();
                    d->raise();
                    window.resizeDocks({d}, {chart ? 330 : 220}, Qt::Vertical);
                }
                QTimer::singleShot(chart ? 8000 : 4000, &window, [&window, &app, path, chart] {
                    if (chart)
                        window.timingChart()->placeCursor(0, 35000);
                    // The status bar lays the history marks out over a few posted events.
                    QTimer::singleShot(chart ? 300 : 0, &window, [&window, &app, path] {
                        window.grab().save(path);
                        app.quit();
                    });
                });
                return;
            }
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
            if (dialog == QLatin1String("examples")) {
                // File > Examples open at its first family, as found beside the program.
                if (auto *examples = window.findChild<QMenu *>(QStringLiteral("examplesMenu"))) {
                    examples->popup(window.mapToGlobal(QPoint(40, 40)));
                    if (!examples->actions().isEmpty() && examples->actions().first()->menu())
                        examples->setActiveAction(examples->actions().first());
                }
            } else if (dialog == QLatin1String("about")) {
                if (auto *a = window.findChild<QAction *>(QStringLiteral("aboutAction")))
                    a->trigger();
            } else if (dialog == QLatin1String("save")) {
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
