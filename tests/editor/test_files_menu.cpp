// File > Examples (the manuals' examples of every target, opened as untitled copies) and
// File > Open Recent (remembered in the settings for the next start).

#include "app/gui/example_titles.h"
#include "app/gui/file_dialogs.h"
#include "app/gui/installed_files.h"
#include "app/gui/language.h"
#include "app/gui/main_window.h"
#include "editor/il_editor.h"

#include "model/ladder/ladder_text.h"
#include "model/project/project.h"

#include <QApplication>
#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenu>
#include <QMenuBar>
#include <QRegularExpression>
#include <QSettings>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTimer>

#include "tests/editor/window_fixture.h"
#include "app/gui/network_window.h"

#include <QDir>

#include <gtest/gtest.h>

using namespace rung;

TEST(FilesMenu, ExamplesForEveryTargetOpenAsUntitledCopies) {
    app::MainWindow window;
    QMenu *examples = test::submenu(window, QStringLiteral("Examples"));
    ASSERT_NE(examples, nullptr);
    QStringList targets;
    for (QAction *sub : examples->actions()) {
        ASSERT_NE(sub->menu(), nullptr);
        // The networks open in windows of their own (ExamplesIncludeTheManualsNetworks).
        if (sub->menu()->objectName() == QStringLiteral("networkExamplesMenu"))
            continue;
        targets << sub->text();
        ASSERT_FALSE(sub->menu()->actions().isEmpty()) << sub->text().toStdString();
        for (QAction *example : sub->menu()->actions()) {
            example->trigger();
            EXPECT_EQ(window.document()->target().displayName, sub->text())
                << example->text().toStdString();
            EXPECT_GT(window.document()->ladder().rungs.size(), 1u);
            EXPECT_TRUE(window.document()->path().isEmpty()); // Save asks where
            EXPECT_FALSE(window.document()->isModified());
        }
    }
    for (model::Family f : model::Target::families())
        EXPECT_TRUE(targets.contains(model::Target::get(f).displayName))
            << model::Target::get(f).displayName.toStdString();
}

// File > Examples > Networks: every network of the manuals' communication chapters, each
// opening in a window of its own, the program shown in the main window kept.
TEST(FilesMenu, ExamplesIncludeTheManualsNetworks) {
    app::MainWindow window;
    QMenu *examples = test::submenu(window, QStringLiteral("Examples"));
    ASSERT_NE(examples, nullptr);
    QMenu *networks = examples->findChild<QMenu *>(QStringLiteral("networkExamplesMenu"));
    ASSERT_NE(networks, nullptr);
    const QDir folder(QStringLiteral(RUNG_SOURCE_DIR "/resources/examples/networks"));
    const auto files = folder.entryList(QDir::Dirs | QDir::NoDotAndDotDot);
    ASSERT_EQ(networks->actions().size(), files.size());
    const int rungs = int(window.document()->ladder().rungs.size());
    for (QAction *example : networks->actions()) {
        example->trigger();
        EXPECT_FALSE(files.contains(example->text())) << example->text().toStdString(); // a title
        EXPECT_EQ(window.findChildren<app::NetworkWindow *>().size(), 1)
            << example->text().toStdString();
        for (app::NetworkWindow *w : window.findChildren<app::NetworkWindow *>())
            delete w;
    }
    EXPECT_EQ(int(window.document()->ladder().rungs.size()), rungs);
}

// Titles to read, not file names: the resource "vigor/traffic-light.rung" is "Traffic light",
// "cpm1/difu-difd.rung" names its two instructions as the manual writes them.
TEST(FilesMenu, ExamplesHaveReadableTitles) {
    app::MainWindow window;
    QMenu *examples = test::submenu(window, QStringLiteral("Examples"));
    ASSERT_NE(examples, nullptr);
    QStringList titles;
    for (QAction *sub : examples->actions())
        for (QAction *example : sub->menu()->actions())
            titles << example->text();
    EXPECT_TRUE(titles.contains(QStringLiteral("Traffic light"))) << titles.join(',').toStdString();
    EXPECT_TRUE(titles.contains(QStringLiteral("DIFU / DIFD"))) << titles.join(',').toStdString();
    for (const QString &title : titles)
        EXPECT_FALSE(title.contains(QLatin1Char('-')) && !title.contains(QLatin1Char(' ')))
            << title.toStdString();
}

// Every example named in words has a title of its own to translate (a new example without one
// would show its file name in every language).
TEST(FilesMenu, EveryExampleNamedInWordsHasATranslatableTitle) {
    const QStringList titled = app::examplesWithTitles();
    ASSERT_FALSE(app::examplesFolder().isEmpty());
    QDirIterator it(app::examplesFolder(), {QStringLiteral("*.rung")}, QDir::Files,
                    QDirIterator::Subdirectories);
    int examples = 0;
    while (it.hasNext()) {
        const QFileInfo file(it.next());
        ++examples;
        const model::Target *target = model::Target::byId(file.dir().dirName());
        ASSERT_NE(target, nullptr) << file.filePath().toStdString();
        const bool mnemonics =
            app::exampleTitle(target, file.baseName()) ==
            file.baseName().toUpper().replace(QLatin1Char('-'), QStringLiteral(" / "));
        EXPECT_TRUE(mnemonics || titled.contains(file.baseName())) << file.filePath().toStdString();
    }
    EXPECT_GE(examples, 13);
}

// The examples speak to the user about the program, not about where they came from: no
// citation of a manual ("PLC concepts (WPLSoft family) 1.9") or docs file names in their
// comments.
TEST(FilesMenu, ExampleCommentsSpeakTheUsersWords) {
    ASSERT_FALSE(app::examplesFolder().isEmpty());
    QDirIterator it(app::examplesFolder(), {QStringLiteral("*.rung")}, QDir::Files,
                    QDirIterator::Subdirectories);
    const QRegularExpression sources(QStringLiteral("\\bseed\\b|docs/|\\.md\\b|manual"),
                                     QRegularExpression::CaseInsensitiveOption);
    while (it.hasNext()) {
        const QString path = it.next();
        model::ProjectError error;
        const auto project = model::loadProject(path, &error);
        ASSERT_TRUE(project) << path.toStdString() << ": " << error.message.toStdString();
        QStringList comments;
        for (const model::Rung &rung : project->program.rungs)
            comments << rung.comment;
        for (const model::Symbol &symbol : project->symbols)
            comments << symbol.comment;
        for (const QString &comment : comments)
            EXPECT_FALSE(comment.contains(sources))
                << path.toStdString() << ": " << comment.toStdString();
    }
}

// In Hungarian and Italian the examples read in the user's words; the mnemonics stay as the
// manuals write them.
TEST(FilesMenu, ExampleTitlesFollowTheLanguage) {
    app::MainWindow window;
    const auto titles = [&window](const char *examplesMenu) {
        QStringList all;
        QMenu *examples = test::submenu(window, QString::fromUtf8(examplesMenu));
        if (examples)
            for (QAction *sub : examples->actions())
                for (QAction *example : sub->menu()->actions())
                    all << example->text();
        return all;
    };
    ASSERT_TRUE(titles("Examples").contains(QStringLiteral("Traffic light")));
    struct Expected {
        const char *code, *menu, *trafficLight;
    };
    for (const Expected &e :
         {Expected{"hu", "Példák", "Közlekedési lámpa"}, Expected{"it", "Esempi", "Semaforo"}}) {
        ASSERT_TRUE(app::setLanguage(QString::fromLatin1(e.code), false));
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
        QCoreApplication::processEvents();
        const QStringList translated = titles(e.menu);
        EXPECT_TRUE(translated.contains(QString::fromUtf8(e.trafficLight)))
            << e.code << ": " << translated.join(',').toStdString();
        EXPECT_TRUE(translated.contains(QStringLiteral("DIFU / DIFD"))) << e.code;
        EXPECT_FALSE(translated.contains(QStringLiteral("Flasher"))) << e.code;
    }
    app::setLanguage(QStringLiteral("en"), false);
    QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
}

TEST(FilesMenu, RecentFilesAreRememberedNewestFirst) {
    QSettings().remove(QStringLiteral("files/recent"));
    QTemporaryDir dir;
    const QString a = dir.filePath(QStringLiteral("a.rung"));
    const QString b = dir.filePath(QStringLiteral("b.rung"));
    {
        app::MainWindow window;
        window.newProject(model::Target::get(model::Family::Vigor), QStringLiteral("VB"));
        ASSERT_TRUE(window.saveTo(a));
        ASSERT_TRUE(window.saveTo(b));
        ASSERT_TRUE(window.openFile(a, QString(), true));
    }
    app::MainWindow next; // the next start
    QMenu *recent = test::submenu(next, QStringLiteral("Open Recent"));
    ASSERT_NE(recent, nullptr);
    ASSERT_GE(recent->actions().size(), 2);
    EXPECT_EQ(recent->actions().at(0)->text(), QStringLiteral("a.rung"));
    EXPECT_EQ(recent->actions().at(1)->text(), QStringLiteral("b.rung"));
    recent->actions().at(1)->trigger();
    EXPECT_EQ(next.document()->path(), b);
    QSettings().remove(QStringLiteral("files/recent"));
}

// A ladder text (docs/ladder-text.md, what `rungstudio-cli convert --to ladder` writes) opens
// as its drawing, for the PLC its header names, not as an instruction list full of errors.
TEST(FilesMenu, ALadderTextOpensAsItsDrawing) {
    app::MainWindow window;
    window.newProject(model::Target::get(model::Family::Cpm1), QString());
    for (const char *name : {"bridge_corrected.ladder", "bridge.ladder"}) {
        const QString path = QStringLiteral(RUNG_TEST_DATA_DIR "/ladder/") + QLatin1String(name);
        QFile file(path);
        ASSERT_TRUE(file.open(QIODevice::ReadOnly)) << name;
        const model::LadderTextResult drawn = model::parseLadderText(
            model::Target::get(model::Family::Vigor), QString::fromUtf8(file.readAll()));
        ASSERT_TRUE(drawn.ok()) << name;
        ASSERT_TRUE(window.openFile(path, QString(), true)) << name;
        EXPECT_EQ(window.document()->target().id, QStringLiteral("vigor")) << name;
        EXPECT_EQ(window.document()->ladder().rungs, drawn.ladder.rungs) << name;
        // The list shows the program's own listing: no text as typed with syntax errors.
        EXPECT_EQ(window.ilEditor()->text(), window.document()->listingText()) << name;
        EXPECT_FALSE(window.ilEditor()->text().contains(QStringLiteral("LADDER"))) << name;
        EXPECT_TRUE(window.document()->path().isEmpty()) << name; // Save asks where
    }
}

TEST(FilesMenu, ALadderTextThatDoesNotReadSaysWhere) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("bad.ladder"));
    {
        QFile out(path);
        ASSERT_TRUE(out.open(QIODevice::WriteOnly));
        out.write("LADDER vigor WIDTH 8\nRUNG 1 ROWS 1 COLUMNS 1\n|-[ X9 ]--(OUT Y0)\n");
    }
    app::MainWindow window;
    const auto before = window.document()->ladder().rungs;
    EXPECT_FALSE(window.openFile(path, QString(), true));
    EXPECT_EQ(window.document()->ladder().rungs, before);
    const QString message = window.statusBar()->currentMessage();
    EXPECT_TRUE(message.contains(QStringLiteral("line 3"))) << message.toStdString();
}

TEST(FilesMenu, OpenOffersLadderTexts) {
    app::MainWindow window;
    QStringList filters;
    QTimer::singleShot(0, &window, [&filters] {
        if (auto *dialog = qobject_cast<QFileDialog *>(QApplication::activeModalWidget())) {
            filters = dialog->nameFilters();
            dialog->reject();
        }
    });
    QAction *open = test::menuAction(window, QStringLiteral("Open..."));
    ASSERT_NE(open, nullptr);
    open->trigger();
    EXPECT_TRUE(filters.join(u';').contains(QStringLiteral("*.ladder")))
        << filters.join(u';').toStdString();
}

namespace {

// What a file dialog of the menu entry `entry` shows (`read`), the dialog then cancelled.
QString askedByDialog(app::MainWindow &window, const char *entry,
                      QString (*read)(const QFileDialog &)) {
    QString seen;
    QTimer::singleShot(0, &window, [&seen, read] {
        if (auto *dialog = qobject_cast<QFileDialog *>(QApplication::activeModalWidget())) {
            seen = read(*dialog);
            dialog->reject();
        }
    });
    if (QAction *action = test::menuAction(window, QString::fromLatin1(entry)))
        action->trigger();
    return seen;
}

// The folder the File > Open dialog starts in.
QString openDialogFolder(app::MainWindow &window) {
    return askedByDialog(window, "Open...",
                         [](const QFileDialog &d) { return d.directory().absolutePath(); });
}

// The file the Save As dialog proposes.
QString saveAsProposal(app::MainWindow &window) {
    return askedByDialog(window, "Save As...",
                         [](const QFileDialog &d) { return d.selectedFiles().value(0); });
}

} // namespace

// File > Open starts where the project is, not in the folder the IDE was started from; a new
// project's dialog starts where a file was last opened.
TEST(FilesMenu, OpenStartsInTheProjectsFolderThenTheLastOneUsed) {
    QTemporaryDir dir;
    QTemporaryDir other;
    ASSERT_NE(QDir(dir.path()).canonicalPath(), QDir::currentPath());
    app::MainWindow window;
    ASSERT_TRUE(window.saveTo(dir.filePath(QStringLiteral("latch.rung"))));
    EXPECT_EQ(QDir(openDialogFolder(window)).canonicalPath(), QDir(dir.path()).canonicalPath());
    // Taking a file from the other folder remembers it for a new project.
    app::rememberFileDialogFolder(other.filePath(QStringLiteral("x.rung")));
    app::MainWindow fresh;
    EXPECT_EQ(QDir(openDialogFolder(fresh)).canonicalPath(), QDir(other.path()).canonicalPath());
}

// A listing opened from a file is named after it (the title, the project pane, the printed
// header), not "Untitled", and Save As proposes a project of the same name beside it; with
// errors in the listing too. A project opened next is named by its own file.
TEST(FilesMenu, AnImportedListingIsNamedAfterItsFileAndSavesBesideIt) {
    QTemporaryDir dir;
    const auto write = [&dir](const QString &name, const QByteArray &text) {
        QFile out(dir.filePath(name));
        EXPECT_TRUE(out.open(QIODevice::WriteOnly));
        out.write(text);
        return out.fileName();
    };
    const QString good = write(QStringLiteral("traffic.il"), "LD X0\nOUT Y0\nEND\n");
    const QString bad = write(QStringLiteral("broken.txt"), "LD X8\nOUT Y0\nEND\n");
    app::MainWindow window;
    ASSERT_TRUE(window.openFile(good, QStringLiteral("vigor"), true));
    EXPECT_TRUE(window.document()->path().isEmpty()); // Save asks where
    EXPECT_EQ(window.document()->name(), QStringLiteral("traffic.il"));
    EXPECT_TRUE(window.windowTitle().startsWith(QStringLiteral("traffic.il")))
        << window.windowTitle().toStdString();
    EXPECT_EQ(QFileInfo(saveAsProposal(window)).absoluteFilePath(),
              QFileInfo(dir.filePath(QStringLiteral("traffic.rung"))).absoluteFilePath());

    ASSERT_TRUE(window.openFile(bad, QStringLiteral("vigor"), true));
    EXPECT_EQ(window.document()->name(), QStringLiteral("broken.txt"));
    EXPECT_TRUE(window.windowTitle().startsWith(QStringLiteral("broken.txt")))
        << window.windowTitle().toStdString();
    EXPECT_EQ(QFileInfo(saveAsProposal(window)).fileName(), QStringLiteral("broken.rung"));

    const QString project = dir.filePath(QStringLiteral("kept.rung"));
    ASSERT_TRUE(window.saveTo(project));
    EXPECT_EQ(window.document()->name(), QStringLiteral("kept.rung"));
    EXPECT_TRUE(window.windowTitle().startsWith(QStringLiteral("kept.rung")))
        << window.windowTitle().toStdString();
    ASSERT_TRUE(window.openFile(good, QStringLiteral("vigor"), true));
    ASSERT_TRUE(window.openFile(project, QString(), true));
    EXPECT_EQ(window.document()->name(), QStringLiteral("kept.rung"));
}

// An example opens as an untitled copy named by its title; Save As proposes its file name.
TEST(FilesMenu, AnExampleIsNamedByItsTitle) {
    app::MainWindow window;
    QAction *traffic = nullptr;
    if (QMenu *examples = test::submenu(window, QStringLiteral("Examples")))
        for (QAction *sub : examples->actions())
            for (QAction *example : sub->menu()->actions())
                if (example->text() == QStringLiteral("Traffic light"))
                    traffic = example;
    ASSERT_NE(traffic, nullptr);
    traffic->trigger();
    EXPECT_TRUE(window.document()->path().isEmpty());
    EXPECT_EQ(window.document()->name(), QStringLiteral("Traffic light"));
    EXPECT_TRUE(window.windowTitle().startsWith(QStringLiteral("Traffic light")))
        << window.windowTitle().toStdString();
    EXPECT_EQ(QFileInfo(saveAsProposal(window)).fileName(), QStringLiteral("traffic-light.rung"));
}
