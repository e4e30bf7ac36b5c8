// Nothing cut off in English, Hungarian or Italian: every dialog the window opens is wide
// enough for its title in a window manager's title bar, and every label, button and combo box
// of it, and of the window at 1366x768 and at 1024x600, is at least as large as its text needs.

#include "app/gui/debug_controller.h"
#include "app/gui/eliding_label.h"
#include "app/gui/language.h"
#include "app/gui/main_window.h"
#include "app/gui/simulation_controller.h"
#include "app/gui/status_bar.h"
#include "editor/ladder_painter.h"
#include "editor/ladder_view.h"
#include "editor/timing_canvas.h"
#include "editor/timing_chart.h"
#include "model/target/address.h"
#include "simulator/session.h"

#include <QAbstractButton>
#include <QApplication>
#include <QComboBox>
#include <QDialog>
#include <QDockWidget>
#include <QFontMetrics>
#include <QHeaderView>
#include <QLabel>
#include <QMessageBox>
#include <QRegularExpression>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QStatusBar>
#include <QTabBar>
#include <QTemporaryDir>
#include <QTimer>

#include "tests/editor/window_fixture.h"

#include <gtest/gtest.h>

#include <functional>

using namespace rung;

namespace {

QString tr(const char *context, const char *text) {
    return QCoreApplication::translate(context, text);
}

QString nameOf(const QWidget *w) {
    return QString::fromLatin1(w->metaObject()->className()) + QLatin1Char('#') + w->objectName();
}

// The texts of `root` (and its children) that do not fit their widget, as "widget: text".
QStringList cutTexts(QWidget *root) {
    QStringList cut;
    QList<QWidget *> widgets = root->findChildren<QWidget *>();
    widgets.prepend(root);
    for (QWidget *w : widgets) {
        if (!w->isVisible() || w->window() != root->window())
            continue;
        if (auto *label = qobject_cast<QLabel *>(w)) {
            if (label->text().isEmpty() || label->pixmap().isNull() == false)
                continue;
            // An access key with no field to go to shows its '&' ("&Compare").
            static const QRegularExpression accessKey(QStringLiteral("(^|[^&])&[^&\\s]"));
            if (!label->buddy() && label->textFormat() != Qt::RichText &&
                !Qt::mightBeRichText(label->text()) && accessKey.match(label->text()).hasMatch())
                cut << QStringLiteral("%1 shows its '&': %2").arg(nameOf(w), label->text());
            const bool fits = label->wordWrap()
                                  ? label->height() >= label->heightForWidth(label->width())
                                  : label->width() >= label->sizeHint().width();
            if (!fits)
                cut << QStringLiteral("%1 (%2 px of %3): %4")
                           .arg(nameOf(w))
                           .arg(label->width())
                           .arg(label->sizeHint().width())
                           .arg(label->text());
        } else if (auto *button = qobject_cast<QAbstractButton *>(w)) {
            if (!button->text().isEmpty() && button->width() < button->sizeHint().width())
                cut << QStringLiteral("%1 (%2 px of %3): %4")
                           .arg(nameOf(w))
                           .arg(button->width())
                           .arg(button->sizeHint().width())
                           .arg(button->text());
        } else if (auto *combo = qobject_cast<QComboBox *>(w)) {
            if (combo->width() < combo->minimumSizeHint().width())
                cut << QStringLiteral("%1: %2").arg(nameOf(w), combo->currentText());
        } else if (auto *tabs = qobject_cast<QTabBar *>(w)) {
            for (int i = 0; i < tabs->count(); ++i)
                if (tabs->tabRect(i).width() <
                    tabs->fontMetrics().horizontalAdvance(tabs->tabText(i)))
                    cut << QStringLiteral("%1 tab: %2").arg(nameOf(w), tabs->tabText(i));
        } else if (auto *header = qobject_cast<QHeaderView *>(w)) {
            // Every column but a stretched last one is as wide as its title.
            if (header->orientation() != Qt::Horizontal || !header->model())
                continue;
            for (int i = 0; i < header->count(); ++i) {
                if (header->isSectionHidden(i) ||
                    (i == header->count() - 1 && header->stretchLastSection()))
                    continue;
                const QString title = header->model()->headerData(i, Qt::Horizontal).toString();
                if (header->sectionSize(i) < header->fontMetrics().horizontalAdvance(title) + 8)
                    cut << QStringLiteral("%1 column %2 (%3 px): %4")
                               .arg(nameOf(header->parentWidget()))
                               .arg(i)
                               .arg(header->sectionSize(i))
                               .arg(title);
            }
        }
    }
    return cut;
}

// The width a title bar needs: the title in bold and, beside it, the icon and buttons of a
// title bar; under openbox seven text heights of them still cut "Nuovo progetto", eight did not.
int titleNeeds(const QWidget *dialog) {
    QFont bold = dialog->font();
    bold.setBold(true);
    return QFontMetrics(bold).horizontalAdvance(dialog->windowTitle()) +
           8 * QFontMetrics(bold).height();
}

struct Seen {
    QString title;
    QStringList problems;
};

// Runs `open`, which shows a modal dialog; looks at the dialog once it is on screen, then
// closes it (and any dialog that follows it).
Seen inspectDialog(const std::function<void()> &open) {
    Seen seen;
    std::function<void()> look = [&seen] {
        auto *dialog = qobject_cast<QDialog *>(QApplication::activeModalWidget());
        if (!dialog) {
            seen.problems << QStringLiteral("no dialog");
            return;
        }
        seen.title = dialog->windowTitle();
        if (dialog->width() < titleNeeds(dialog))
            seen.problems << QStringLiteral("title \"%1\": %2 px of %3")
                                 .arg(dialog->windowTitle())
                                 .arg(dialog->width())
                                 .arg(titleNeeds(dialog));
        seen.problems << cutTexts(dialog);
        dialog->reject();
    };
    QTimer::singleShot(0, look);
    open();
    QCoreApplication::processEvents(); // the look, had no dialog come
    // A dialog the first one led to (Replace Device asks twice) goes too.
    while (auto *next = qobject_cast<QDialog *>(QApplication::activeModalWidget()))
        next->reject();
    return seen;
}

struct DialogFit : test::WindowFixture, ::testing::WithParamInterface<const char *> {
    QTemporaryDir dir;
    void SetUp() override {
        WindowFixture::SetUp();
        ASSERT_TRUE(app::setLanguage(QString::fromLatin1(GetParam()), false));
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
        QCoreApplication::processEvents();
        load("LD X0\nOUT Y0\nEND\n");
        window.document()->markSaved();
        window.resize(1366, 768);
        window.show();
        QCoreApplication::processEvents();
    }
    void TearDown() override {
        app::setLanguage(QStringLiteral("en"), false);
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
    }
    QAction *entry(const char *context, const char *text) {
        QAction *a = test::menuAction(window, tr(context, text).remove(QLatin1Char('&')));
        EXPECT_NE(a, nullptr) << text;
        return a;
    }
    void expectFits(const char *what, const std::function<void()> &open) {
        const Seen seen = inspectDialog(open);
        EXPECT_FALSE(seen.title.isEmpty()) << what;
        EXPECT_TRUE(seen.problems.isEmpty())
            << GetParam() << ": " << what << ": "
            << seen.problems.join(QStringLiteral("; ")).toStdString();
    }
};

} // namespace

TEST_P(DialogFit, EveryDialogFitsItsTitleAndTexts) {
    const char *mw = "rung::app::MainWindow";
    const char *files = "rung::app::FileController";
    const char *simulation = "rung::app::SimulationMenu";
    expectFits("New Project", [&] { entry(files, "&New Project...")->trigger(); });
    expectFits("Find Device", [&] { entry(mw, "&Find Device...")->trigger(); });
    expectFits("Replace Device", [&] { entry(mw, "Replace &Device...")->trigger(); });
    expectFits("Rung Comment", [&] { window.editRungComment(); });
    expectFits("Keyboard", [&] { entry(mw, "&Keyboard...")->trigger(); });
    expectFits("About", [&] { entry(mw, "&About Rung Studio")->trigger(); });
    // The simulation's and the debugger's dialogs: "Ciklus…tatása", "Esegui… nsioni" and a
    // literal "&Compare" were cut or shown so.
    expectFits("Run Scans", [&] { entry(simulation, "Run Sc&ans...")->trigger(); });
    expectFits("Run For", [&] { entry(simulation, "R&un For...")->trigger(); });
    expectFits("Breakpoint Condition", [&] { window.debugging()->editBreakpointCondition(0); });
    // Save the changes? (New Project on a changed program asks first.)
    window.document()->insertRung(0, window.document()->ladder().rungs.front());
    expectFits("Unsaved changes", [&] { entry(files, "&New Project...")->trigger(); });
    window.document()->markSaved();
    // Qt's own file dialogs, as under a desktop without one of its own: the size and date
    // columns' titles whole ("Dimensione" was cut).
    QCoreApplication::setAttribute(Qt::AA_DontUseNativeDialogs, true);
    expectFits("Open", [&] { entry(files, "&Open...")->trigger(); });
    expectFits("Export Instruction List",
               [&] { entry(files, "&Export Instruction List...")->trigger(); });
    QCoreApplication::setAttribute(Qt::AA_DontUseNativeDialogs, false);
    // A file that cannot be opened.
    expectFits("Cannot open the file",
               [&] { window.openFile(dir.filePath(QStringLiteral("none.rung"))); });
    // An export name that names a file that exists.
    const QString existing = dir.filePath(QStringLiteral("latch.pdf"));
    QFile(existing).open(QIODevice::WriteOnly);
    expectFits("Replace File", [&] {
        window.completeSavePath(dir.filePath(QStringLiteral("latch")), {QStringLiteral("pdf")});
    });
}

// The window at 1366x768 and at 1024x600: the docks, the tabs, the tables' headers and the
// status bar show their texts whole.
TEST_P(DialogFit, TheWindowShowsItsTextsWholeOnSmallScreens) {
    auto *project = window.findChild<QDockWidget *>(QStringLiteral("projectDock"));
    auto *crossReference = window.findChild<QDockWidget *>(QStringLiteral("crossReferenceDock"));
    ASSERT_NE(project, nullptr);
    ASSERT_NE(crossReference, nullptr);
    for (const QSize size : {QSize(1366, 768), QSize(1024, 600)}) {
        window.resize(size);
        // The project and the cross reference share a place: each in turn in front.
        for (QDockWidget *front : {project, crossReference}) {
            front->raise();
            QCoreApplication::processEvents();
            const QStringList cut = cutTexts(&window);
            EXPECT_TRUE(cut.isEmpty())
                << GetParam() << " at " << size.width() << ", " << front->objectName().toStdString()
                << " in front: " << cut.join(QStringLiteral("; ")).toStdString();
        }
    }
    project->raise();
}

INSTANTIATE_TEST_SUITE_P(Languages, DialogFit, ::testing::Values("en", "hu", "it"),
                         [](const auto &info) { return std::string(info.param); });

namespace {

// The status bar's fields show their whole texts (an ElidingLabel its full text).
QStringList elidedFields(QStatusBar *bar) {
    QStringList cut;
    for (auto *label : bar->findChildren<app::ElidingLabel *>())
        if (label->isVisible() && label->text() != label->fullText())
            cut << QStringLiteral("%1: \"%2\" of \"%3\"")
                       .arg(label->objectName(), label->text(), label->fullText());
    return cut;
}

} // namespace

// Issue 31's clipped texts at 1366x768: the status bar's fields while a past scan is shown, a
// long message before them, the force badge beside a contact's device, a MOV box's values and
// the timing chart's cursors over its ruler.
TEST_P(DialogFit, TheStatusBarTheLadderAndTheChartShowTheirTextsWhole) {
    app::SimulationController *sim = window.simulation();
    const auto paused = [&] {
        return QTest::qWaitFor(
            [&] { return sim->runState() == model::MonitorSource::RunState::Paused; }, 5000);
    };
    const auto settle = [] {
        for (int i = 0; i < 5; ++i)
            QCoreApplication::processEvents();
    };
    load("LD X1\nOUT Y0\nLD M9000\nMOV K12345 D0\nMOV D0 D1\nEND\n");
    ASSERT_TRUE(sim->runScans(200));
    ASSERT_TRUE(paused());
    sim->showHistoryScan(150);
    settle();
    auto *bar = qobject_cast<app::StatusBar *>(window.statusBar());
    ASSERT_NE(bar, nullptr);
    EXPECT_TRUE(QTest::qWaitFor([&] { return elidedFields(bar).isEmpty(); }, 2000))
        << GetParam() << ": " << elidedFields(bar).join(QStringLiteral("; ")).toStdString();
    // A message longer than its room ends in "…" a gap before the first field.
    bar->showMessage(QStringLiteral("Connection to the PLC lost: no answer within 1000 ms. "
                                    "Trying again. ")
                         .repeated(4));
    settle();
    EXPECT_TRUE(bar->shownMessage().endsWith(QChar(0x2026))) << bar->shownMessage().toStdString();
    for (QWidget *field : bar->findChildren<QWidget *>(Qt::FindDirectChildrenOnly)) {
        if (field->isVisible()) {
            EXPECT_LE(bar->messageArea().right() + 8, field->x())
                << field->objectName().toStdString();
        }
    }
    bar->clearMessage();
    sim->returnToLive();

    // The MOV box (rung 2, row 2): "D0 = 12345  D1 = 12345", each value whole.
    editor::LadderView *ladder = window.ladderView();
    const auto movValues = [&] {
        const model::RungOverlay o = ladder->overlay(1);
        return o.output(1) ? o.output(1)->value : QString();
    };
    ASSERT_TRUE(
        QTest::qWaitFor([&] { return movValues().contains(QStringLiteral("D1 = 12345")); }, 5000))
        << movValues().toStdString();
    {
        const editor::LadderMetrics m = ladder->metrics();
        const editor::LadderPainter painter(window.document()->project(), m);
        const model::Rung &rung = window.document()->ladder().rungs[1];
        const QRectF inner = painter.boxTextRect(painter.outputRect(rung, 1));
        const QFontMetricsF fm(painter.liveFont());
        const QStringList lines = editor::LadderPainter::valueLines(movValues(), fm, inner.width());
        for (const QString &line : lines)
            EXPECT_LE(fm.horizontalAdvance(line), inner.width())
                << GetParam() << ": " << line.toStdString();
    }

    // A forced contact: its device's label ("X1", a CPM1's "000.00") is drawn the same as
    // without the force, the badge beside the contact, not over the label's last character.
    struct Forced {
        model::Family family;
        const char *model;
        const char *listing;
        const char *device;
    };
    for (const Forced &f :
         {Forced{model::Family::Vigor, "VB", "LD X1\nOUT Y0\nEND\n", "X1"},
          Forced{model::Family::Cpm1, nullptr, "LD 000.00\nOUT 010.00\nEND(01)\n", "000.00"}}) {
        const model::Target &target = model::Target::get(f.family);
        window.newProject(target,
                          f.model ? QString::fromLatin1(f.model) : target.defaultModel().name);
        load(f.listing);
        ASSERT_TRUE(sim->singleScan());
        ASSERT_TRUE(paused());
        settle();
        ladder->setCursor({0, 1, 0}); // the cursor's frame off the contact
        const QRect cell = ladder->cellRectOnScreen({0, 0, 0});
        // Above the contact's symbol (whose heavy bars reach a little above it when it
        // conducts) and inside the dashed outline of a forced element.
        const int symbolTop = cell.top() + static_cast<int>(ladder->metrics().rowHeight * 0.35);
        const QRect label(cell.left() + 5, cell.top() + 5, cell.width() - 10,
                          symbolTop - 4 - (cell.top() + 5));
        ladder->viewport()->repaint();
        const QImage before = ladder->viewport()->grab().toImage();
        const auto device =
            std::get<model::Address>(model::parseAddress(target, QString::fromLatin1(f.device)));
        sim->session()->force(device, true);
        ASSERT_TRUE(QTest::qWaitFor(
            [&] {
                const auto s = sim->session()->snapshot();
                return s && s->forced(device);
            },
            5000));
        ASSERT_TRUE(QTest::qWaitFor([&] { return ladder->overlay(0).isForced(0, 0); }, 5000));
        ladder->viewport()->repaint();
        const QImage after = ladder->viewport()->grab().toImage();
        int changed = 0;
        for (int y = label.top(); y <= label.bottom(); ++y)
            for (int x = label.left(); x <= label.right(); ++x)
                changed += before.pixel(x, y) != after.pixel(x, y);
        EXPECT_EQ(changed, 0) << GetParam() << ": " << f.device << ": " << changed
                              << " pixels of the label changed";
        sim->stop();
    }

    // The chart's cursors never stand over a number of its ruler.
    window.newProject(model::Target::get(model::Family::Vigor), QStringLiteral("VB"));
    load("LD M9000\nADD D0 K1 D0\nEND\n");
    ASSERT_TRUE(sim->runScans(300));
    ASSERT_TRUE(paused());
    auto *chartDock = window.findChild<QDockWidget *>(QStringLiteral("timingChartDock"));
    ASSERT_NE(chartDock, nullptr);
    chartDock->show();
    chartDock->raise();
    settle();
    editor::TimingChart *chart = window.timingChart();
    editor::TimingCanvas *canvas = chart->canvas();
    int numbers = 0;
    for (qint64 t = 0; t <= 3000; t += 25) {
        chart->placeCursor(0, t);
        chart->placeCursor(1, t + 310);
        const std::vector<QRectF> labels = canvas->rulerLabels(canvas->size());
        const std::vector<QRectF> tags = canvas->cursorTags(canvas->size());
        numbers += static_cast<int>(labels.size());
        for (const QRectF &label : labels)
            for (const QRectF &tag : tags)
                EXPECT_FALSE(label.intersects(tag)) << GetParam() << " at " << t << " ms";
    }
    EXPECT_GT(numbers, 0);
}

// The Connection dock in its column (Ctrl+W without a port shows it): every setting, button
// and notice in sight, not behind a sideways scroll bar (its protocol, Refresh and Connect
// were cut at 1366x768 in all three languages), over a serial port and over TCP.
TEST_P(DialogFit, TheConnectionDockFitsItsColumn) {
    auto *dock = window.findChild<QDockWidget *>(QStringLiteral("connectionDock"));
    ASSERT_NE(dock, nullptr);
    auto *scroll = qobject_cast<QScrollArea *>(dock->widget());
    ASSERT_NE(scroll, nullptr);
    auto *tcp = dock->findChild<QAbstractButton *>(QStringLiteral("connectionViaTcp"));
    auto *serial = dock->findChild<QAbstractButton *>(QStringLiteral("connectionViaSerial"));
    ASSERT_TRUE(tcp && serial);
    dock->show();
    dock->raise();
    for (const QSize size : {QSize(1366, 768), QSize(1024, 600)}) {
        window.resize(size);
        for (QAbstractButton *via : {tcp, serial}) {
            via->click();
            for (int k = 0; k < 3; ++k)
                QCoreApplication::processEvents();
            const std::string where = std::string(GetParam()) + " at " +
                                      std::to_string(size.width()) + ", " +
                                      via->objectName().toStdString();
            EXPECT_FALSE(scroll->horizontalScrollBar()->isVisible())
                << where << ": the panel needs " << scroll->widget()->minimumSizeHint().width()
                << " px, the dock shows " << scroll->viewport()->width();
            const QStringList cut = cutTexts(dock);
            EXPECT_TRUE(cut.isEmpty())
                << where << ": " << cut.join(QStringLiteral("; ")).toStdString();
        }
    }
}
