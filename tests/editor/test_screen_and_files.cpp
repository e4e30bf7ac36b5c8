// The window on a small screen, and the names export dialogs write.

#include "app/gui/main_window.h"
#include "app/gui/simulation_controller.h"
#include "editor/document.h"
#include "editor/ladder_view.h"

#include <QApplication>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QScreen>
#include <QSettings>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTimer>

#include "tests/editor/window_fixture.h"

#include <gtest/gtest.h>

using namespace rung;

TEST(Screen, TheFirstWindowOpensWithinTheAvailableScreen) {
    // No remembered geometry: as on a first start (the offscreen screen is 800x600, smaller
    // than the 1400x900 the window would like).
    QSettings().remove(QStringLiteral("window/geometry"));
    app::MainWindow window;
    const QRect available = window.screen()->availableGeometry();
    ASSERT_LT(available.width(), 1400);
    EXPECT_LE(window.width(), available.width());
    EXPECT_LE(window.height(), available.height());
    EXPECT_GT(window.width(), available.width() / 2); // and still uses the room there is
}

// What the user arranged comes back at the next start: the window's size and the docks (a
// closed dock stays closed, a resized one keeps its size).
TEST(Screen, TheNextStartRestoresTheWindowAndItsDocks) {
    QSettings().remove(QStringLiteral("window/geometry"));
    QSettings().remove(QStringLiteral("window/state"));
    QSize arranged;
    {
        app::MainWindow window;
        window.show();
        window.resize(700, 600); // above the window's least height (its toolbars and status)
        auto *problems = window.findChild<QDockWidget *>(QStringLiteral("problemsDock"));
        ASSERT_NE(problems, nullptr);
        problems->close();
        QApplication::processEvents();
        arranged = window.size();
        ASSERT_TRUE(window.close()); // nothing to save: closes, remembering the layout
    }
    app::MainWindow next;
    next.show();
    QApplication::processEvents();
    EXPECT_EQ(next.size(), arranged);
    auto *problems = next.findChild<QDockWidget *>(QStringLiteral("problemsDock"));
    ASSERT_NE(problems, nullptr);
    EXPECT_FALSE(problems->isVisible());
    auto *project = next.findChild<QDockWidget *>(QStringLiteral("projectDock"));
    ASSERT_NE(project, nullptr);
    EXPECT_TRUE(project->isVisible());
    QSettings().remove(QStringLiteral("window/geometry"));
    QSettings().remove(QStringLiteral("window/state"));
}

// A netbook's 1024x600: the window fits, the ladder keeps most of the room, the project and
// problems docks and the status bar stay on screen, the toolbar's buttons are reachable.
TEST(Screen, ALayoutThatWorksDownTo1024x600) {
    // The layout of a first start: the ladder and the list as tabs (side by side, each of the
    // two gets half of the room by choice).
    for (const char *key : {"window/geometry", "window/state", "view/sideBySide", "view/split"})
        QSettings().remove(QString::fromLatin1(key));
    app::MainWindow window;
    window.show();
    const QSize minimum = window.minimumSizeHint().expandedTo(window.minimumSize());
    EXPECT_LE(minimum.width(), 1024);
    EXPECT_LE(minimum.height(), 600 - 32); // a panel or title bar takes the rest
    window.resize(1024, 600 - 32);
    QApplication::processEvents();
    ASSERT_EQ(window.size(), QSize(1024, 600 - 32));
    const QRect inside = window.rect();
    const auto onScreen = [&](QWidget *w) {
        return w && w->isVisible() &&
               inside.contains(QRect(w->mapTo(&window, QPoint(0, 0)), w->size()));
    };
    auto *project = window.findChild<QDockWidget *>(QStringLiteral("projectDock"));
    auto *problems = window.findChild<QDockWidget *>(QStringLiteral("problemsDock"));
    EXPECT_TRUE(onScreen(project));
    EXPECT_TRUE(onScreen(problems));
    EXPECT_TRUE(onScreen(window.statusBar()));
    EXPECT_TRUE(onScreen(window.ladderView()));
    // The drawing keeps the larger part; the docks keep enough to be read.
    EXPECT_GE(window.ladderView()->width(), 1024 / 2);
    EXPECT_GE(window.ladderView()->height(), 250);
    EXPECT_GE(problems->height(), 80);
    EXPECT_GE(project->width(), 200);
    // The status bar's parts are whole.
    for (QLabel *label : window.statusBar()->findChildren<QLabel *>()) {
        if (label->isVisible() && !label->text().isEmpty()) {
            EXPECT_GE(label->width(), label->sizeHint().width()) << label->text().toStdString();
        }
    }
}

// The first simulation opens the terminals and the run controls in the project's column, not
// as a column of their own (the offscreen screen is 800 px wide: the narrow layout of
// dock_layout.h), the terminals apart from the tabs so that both are seen together (issue 31).
// On a narrow screen a second column would cut the ladder's coils off.
TEST(Screen, TheFirstSimulationLeavesTheLadderItsWidth) {
    for (const char *key : {"window/geometry", "window/state", "view/sideBySide", "view/split"})
        QSettings().remove(QString::fromLatin1(key));
    app::MainWindow window;
    window.resize(1366, 768 - 32);
    window.show();
    std::vector<model::Diagnostic> errors;
    ASSERT_TRUE(window.document()->setListing(QStringLiteral("LD X0\nOUT Y0\nEND\n"), &errors));
    for (int k = 0; k < 5; ++k) // the first start's dock sizes settle
        QApplication::processEvents();
    const int before = window.ladderView()->width();
    ASSERT_TRUE(window.simulation()->run());
    for (int k = 0; k < 5; ++k)
        QApplication::processEvents();
    auto *project = window.findChild<QDockWidget *>(QStringLiteral("projectDock"));
    auto *io = window.findChild<QDockWidget *>(QStringLiteral("ioDock"));
    auto *controls = window.findChild<QDockWidget *>(QStringLiteral("simulationDock"));
    ASSERT_TRUE(project && io && controls);
    EXPECT_TRUE(io->isVisible());
    EXPECT_FALSE(io->visibleRegion().isEmpty()); // the terminals in front
    EXPECT_TRUE(controls->isVisible());
    const QList<QDockWidget *> tabs = window.tabifiedDockWidgets(project);
    EXPECT_FALSE(tabs.contains(io));
    EXPECT_EQ(window.dockWidgetArea(io), Qt::LeftDockWidgetArea);
    EXPECT_TRUE(tabs.contains(controls));
    EXPECT_FALSE(controls->visibleRegion().isEmpty()); // the run controls in front too
    EXPECT_EQ(window.ladderView()->width(), before);
    for (QDockWidget *dock : window.findChildren<QDockWidget *>()) {
        if (dock->isVisible()) {
            EXPECT_NE(window.dockWidgetArea(dock), Qt::RightDockWidgetArea)
                << dock->objectName().toStdString();
        }
    }
    window.simulation()->stop();
}

using SavePath = test::WindowFixture;

TEST_F(SavePath, TheChosenFormatsExtensionIsAddedWhenMissing) {
    QTemporaryDir dir;
    const QString latch = dir.filePath(QStringLiteral("latch"));
    EXPECT_EQ(window.completeSavePath(latch, {QStringLiteral("pdf")}),
              latch + QStringLiteral(".pdf"));
    EXPECT_EQ(window.completeSavePath(latch + QStringLiteral(".PDF"), {QStringLiteral("pdf")}),
              latch + QStringLiteral(".PDF"));
    // Either of a list's extensions is kept; none gets the first.
    EXPECT_EQ(window.completeSavePath(latch + QStringLiteral(".txt"),
                                      {QStringLiteral("il"), QStringLiteral("txt")}),
              latch + QStringLiteral(".txt"));
    EXPECT_EQ(window.completeSavePath(latch, {QStringLiteral("il"), QStringLiteral("txt")}),
              latch + QStringLiteral(".il"));
    EXPECT_TRUE(window.completeSavePath(QString(), {QStringLiteral("il")}).isEmpty()); // cancelled
}

TEST_F(SavePath, AnAddedExtensionThatNamesAnExistingFileAsksBeforeReplacingIt) {
    QTemporaryDir dir;
    const QString latch = dir.filePath(QStringLiteral("latch"));
    QFile existing(latch + QStringLiteral(".csv"));
    ASSERT_TRUE(existing.open(QIODevice::WriteOnly));
    existing.close();
    auto answer = [](QMessageBox::StandardButton button, bool *asked) {
        QTimer::singleShot(0, [button, asked] {
            if (auto *box = qobject_cast<QMessageBox *>(QApplication::activeModalWidget())) {
                *asked = box->text().contains(QStringLiteral("latch.csv"));
                box->button(button)->click();
            }
        });
    };
    bool asked = false;
    answer(QMessageBox::No, &asked);
    EXPECT_TRUE(window.completeSavePath(latch, {QStringLiteral("csv")}).isEmpty());
    EXPECT_TRUE(asked);
    asked = false;
    answer(QMessageBox::Yes, &asked);
    EXPECT_EQ(window.completeSavePath(latch, {QStringLiteral("csv")}),
              latch + QStringLiteral(".csv"));
    EXPECT_TRUE(asked);
}

namespace {

// Drives the dialogs a menu entry opens, as a user would: in the (non-native) file dialog it
// goes to `dir`, types `name` and accepts; a question after it is answered with `answer`, its
// text kept in `asked`. Every dialog is closed by a deadline, so no test can hang on one.
struct SaveDialogDriver {
    QString dir;
    QString name;
    QMessageBox::StandardButton answer = QMessageBox::No;
    QString asked;
    bool sawFileDialog = false;
    QTimer timer;
    QElapsedTimer since;

    SaveDialogDriver(const QString &folder, const QString &typed)
        : dir(folder)
        , name(typed) {
        QCoreApplication::setAttribute(Qt::AA_DontUseNativeDialogs, true);
        since.start();
        timer.setInterval(20);
        QObject::connect(&timer, &QTimer::timeout, [this] { step(); });
        timer.start();
    }
    ~SaveDialogDriver() { QCoreApplication::setAttribute(Qt::AA_DontUseNativeDialogs, false); }
    void step() {
        QWidget *modal = QApplication::activeModalWidget();
        if (since.elapsed() > 10000) {
            if (modal)
                modal->close();
            return;
        }
        if (auto *files = qobject_cast<QFileDialog *>(modal)) {
            sawFileDialog = true;
            files->setDirectory(dir);
            auto *edit = files->findChild<QLineEdit *>(QStringLiteral("fileNameEdit"));
            if (!edit) {
                files->reject();
                return;
            }
            edit->clear();
            QTest::keyClicks(edit, name);
            static_cast<QDialog *>(files)->accept(); // QFileDialog::accept, as its Save button
        } else if (auto *box = qobject_cast<QMessageBox *>(modal)) {
            asked = box->text();
            if (QAbstractButton *button = box->button(answer))
                button->click();
            else
                box->reject();
        }
    }
};

QByteArray contents(const QString &path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

} // namespace

// Export Instruction List... as the user meets it: the file dialog, `latch` typed, and the
// whole listing lands in latch.il (the format's extension added, no file named `latch`).
TEST_F(SavePath, ExportInstructionListThroughTheMenuAddsTheExtension) {
    load("LD X0\nOUT Y0\nEND\n");
    QTemporaryDir dir;
    QAction *entry = test::menuAction(window, QStringLiteral("Export Instruction List..."));
    ASSERT_NE(entry, nullptr);
    {
        SaveDialogDriver driver(dir.path(), QStringLiteral("latch"));
        entry->trigger();
        EXPECT_TRUE(driver.sawFileDialog);
        EXPECT_TRUE(driver.asked.isEmpty()) << driver.asked.toStdString(); // nothing to replace
    }
    EXPECT_FALSE(QFileInfo::exists(dir.filePath(QStringLiteral("latch"))));
    EXPECT_EQ(QString::fromUtf8(contents(dir.filePath(QStringLiteral("latch.il")))),
              window.document()->listingText());
}

// A file of the completed name exists: the export asks before replacing it, and No keeps it.
TEST_F(SavePath, ExportInstructionListAsksBeforeReplacingAFile) {
    load("LD X0\nOUT Y0\nEND\n");
    QTemporaryDir dir;
    const QString latch = dir.filePath(QStringLiteral("latch.il"));
    {
        QFile old(latch);
        ASSERT_TRUE(old.open(QIODevice::WriteOnly));
        old.write("old work\n");
    }
    QAction *entry = test::menuAction(window, QStringLiteral("Export Instruction List..."));
    ASSERT_NE(entry, nullptr);
    {
        SaveDialogDriver driver(dir.path(), QStringLiteral("latch"));
        driver.answer = QMessageBox::No;
        entry->trigger();
        EXPECT_TRUE(driver.sawFileDialog);
        EXPECT_TRUE(driver.asked.contains(QStringLiteral("latch.il")))
            << driver.asked.toStdString();
    }
    EXPECT_EQ(contents(latch), QByteArray("old work\n"));
    {
        SaveDialogDriver driver(dir.path(), QStringLiteral("latch"));
        driver.answer = QMessageBox::Yes;
        entry->trigger();
        EXPECT_TRUE(driver.asked.contains(QStringLiteral("latch.il")))
            << driver.asked.toStdString();
    }
    EXPECT_EQ(QString::fromUtf8(contents(latch)), window.document()->listingText());
}
