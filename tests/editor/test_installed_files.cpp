// Rung Studio as a desktop application: the files it finds beside itself (examples, the user
// guide), Help > About, the window's icon, the file types the desktop entry and the MIME file
// declare (the window opens each one the desktop entry names), and the man page against --help.

#include "app/gui/about_dialog.h"
#include "app/gui/command_line.h"
#include "app/gui/installed_files.h"
#include "app/gui/main_window.h"
#include "app/gui/network_window.h"
#include "editor/il_editor.h"

#include "model/ladder/ladder_text.h"
#include "model/project/project.h"

#include "tests/cli/man_page.h"
#include "tests/editor/window_fixture.h"

#include <Qsci/qsciglobal.h>

#include <QApplication>
#include <QCommandLineParser>
#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QFileInfo>
#include <QLabel>
#include <QRegularExpression>
#include <QSettings>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QXmlStreamReader>

#include <gtest/gtest.h>

#include <map>

using namespace rung;

namespace {

const QString kPackagingDir = QStringLiteral(RUNG_SOURCE_DIR "/packaging/");

// The files under `folder`, relative to it, sorted.
QStringList installedFilesUnder(const QString &folder) {
    QStringList files;
    QDirIterator it(folder, QDir::Files, QDirIterator::Subdirectories);
    while (it.hasNext())
        files << QDir(folder).relativeFilePath(it.next());
    files.sort();
    return files;
}

// The desktop entry's MimeType list.
QStringList desktopMimeTypes() {
    const QString entry = test::readText(kPackagingDir + "io.github.rungstudio.RungStudio.desktop");
    for (const QString &line : entry.split(QLatin1Char('\n')))
        if (line.startsWith(QLatin1String("MimeType=")))
            return line.mid(9).split(QLatin1Char(';'), Qt::SkipEmptyParts);
    return {};
}

struct DeclaredMimeType {
    QStringList globs;
    QString subClassOf;
    std::vector<std::pair<QString, QString>> magic; // offset range, value
};

// The types packaging/io.github.rungstudio.RungStudio.xml declares.
std::map<QString, DeclaredMimeType> declaredMimeTypes() {
    std::map<QString, DeclaredMimeType> types;
    QFile file(kPackagingDir + "io.github.rungstudio.RungStudio.xml");
    if (!file.open(QIODevice::ReadOnly))
        return types;
    QXmlStreamReader xml(&file);
    QString current;
    while (!xml.atEnd()) {
        if (xml.readNext() != QXmlStreamReader::StartElement)
            continue;
        const auto a = xml.attributes();
        if (xml.name() == QLatin1String("mime-type"))
            current = a.value(QLatin1String("type")).toString();
        else if (xml.name() == QLatin1String("glob"))
            types[current].globs << a.value(QLatin1String("pattern")).toString();
        else if (xml.name() == QLatin1String("sub-class-of"))
            types[current].subClassOf = a.value(QLatin1String("type")).toString();
        else if (xml.name() == QLatin1String("match"))
            types[current].magic.emplace_back(a.value(QLatin1String("offset")).toString(),
                                              a.value(QLatin1String("value")).toString());
    }
    EXPECT_FALSE(xml.hasError()) << xml.errorString().toStdString();
    return types;
}

QString installedExampleProject() {
    return app::examplesFolder() + QStringLiteral("/vigor/traffic-light.rung");
}

} // namespace

// File > Examples reads the folder installed beside the program (share/rungstudio/examples);
// the build folder lays it out at the same place, with every example of resources/examples.
TEST(InstalledFiles, ExamplesAreFoundBesideTheProgram) {
    const QString folder = app::examplesFolder();
    ASSERT_FALSE(folder.isEmpty());
    EXPECT_TRUE(folder.endsWith(QLatin1String("/share/rungstudio/examples")))
        << folder.toStdString();
    EXPECT_TRUE(
        folder.startsWith(QDir(QCoreApplication::applicationDirPath() + "/..").absolutePath()))
        << folder.toStdString();
    const QStringList shipped = installedFilesUnder(folder);
    EXPECT_EQ(shipped, installedFilesUnder(QStringLiteral(RUNG_SOURCE_DIR "/resources/examples")));
    EXPECT_GE(shipped.size(), 13);
}

TEST(InstalledFiles, TheUserGuideIsShippedWithItsPagesLinked) {
    const QString guide = app::userGuidePath();
    ASSERT_FALSE(guide.isEmpty());
    const QString text = test::readText(guide);
    EXPECT_TRUE(text.contains(QLatin1String("Rung Studio user guide")));
    if (guide.endsWith(QLatin1String(".html"))) {
        // Every page's links within the documentation (another page, a picture) lead to a file
        // that is there: a page links the rendered page, never the Markdown source.
        const QDir docs = QFileInfo(guide).dir();
        const QRegularExpression link(QStringLiteral("href=\"([^\":#]+)"));
        int links = 0;
        for (const QString &page : docs.entryList({QStringLiteral("*.html")})) {
            const QString html = test::readText(docs.filePath(page));
            for (auto it = link.globalMatch(html); it.hasNext(); ++links) {
                const QString target = it.next().captured(1);
                EXPECT_FALSE(target.endsWith(QLatin1String(".md"))) << page.toStdString();
                EXPECT_TRUE(QFileInfo::exists(docs.filePath(target)))
                    << page.toStdString() << ": " << target.toStdString();
            }
        }
        EXPECT_GT(links, 20);
    }
    EXPECT_FALSE(app::installedDocument(QStringLiteral("copyright")).isEmpty());
}

TEST(About, NamesTheVersionThePartsTheirLicencesAndLinksTheGuide) {
    app::AboutDialog dialog;
    dialog.show();
    QStringList texts;
    for (QLabel *label : dialog.findChildren<QLabel *>())
        texts << label->text();
    const QString all = texts.join(QLatin1Char('\n'));
    // The version the package's release names (tests/cli/test_man_pages.cpp holds that one to
    // the program's --version).
    const QString metainfo =
        test::readText(kPackagingDir + "io.github.rungstudio.RungStudio.metainfo.xml");
    const QString version = QRegularExpression(QStringLiteral("<release version=\"([^\"]+)\""))
                                .match(metainfo)
                                .captured(1);
    ASSERT_FALSE(version.isEmpty());
    EXPECT_TRUE(all.contains(QStringLiteral("Rung Studio ") + version)) << all.toStdString();
    for (const QString &part :
         {QStringLiteral("Qt"), QStringLiteral("QScintilla"), QStringLiteral("libserialport")})
        EXPECT_TRUE(all.contains(QStringLiteral("<td>%1</td>").arg(part))) << part.toStdString();
    EXPECT_TRUE(all.contains(QString::fromLatin1(qVersion())));
    EXPECT_TRUE(all.contains(QStringLiteral(QSCINTILLA_VERSION_STR)));
    EXPECT_TRUE(all.contains(QStringLiteral("GNU LGPL, version 3")));
    EXPECT_TRUE(all.contains(QStringLiteral("GNU GPL, version 3")));
    auto *guide = dialog.findChild<QLabel *>(QStringLiteral("aboutGuide"));
    ASSERT_NE(guide, nullptr);
    const QUrl url = app::AboutDialog::userGuideUrl();
    ASSERT_TRUE(url.isValid());
    EXPECT_TRUE(QFileInfo::exists(url.toLocalFile()));
    EXPECT_TRUE(guide->text().contains(url.toString(QUrl::FullyEncoded)));
    EXPECT_TRUE(guide->openExternalLinks());
    EXPECT_NE(dialog.findChild<QLabel *>(QStringLiteral("aboutLicences")), nullptr);
}

TEST(About, IsOnTheHelpMenu) {
    app::MainWindow window;
    QAction *about = window.findChild<QAction *>(QStringLiteral("aboutAction"));
    ASSERT_NE(about, nullptr);
    EXPECT_EQ(about->text().remove(QLatin1Char('&')), QStringLiteral("About Rung Studio"));
}

// The window's and the taskbar's icon: the product's drawing, the 16, 22 and 24 px sizes from
// their own pixel-grid drawings rather than the large one shrunk (blurred lines).
TEST(AppIcon, HasEverySizeAndItsOwnSmallDrawings) {
    const QIcon icon = app::applicationIcon();
    ASSERT_FALSE(icon.isNull());
    for (int size : {16, 22, 24, 32, 48, 256})
        EXPECT_EQ(icon.pixmap(size, size).size(), QSize(size, size)) << size;
    for (int size : {16, 22, 24}) {
        const QImage small =
            icon.pixmap(size, size).toImage().convertToFormat(QImage::Format_ARGB32);
        const QImage drawn = QIcon(QStringLiteral(":/icons/rungstudio-%1.svg").arg(size))
                                 .pixmap(size, size)
                                 .toImage()
                                 .convertToFormat(QImage::Format_ARGB32);
        const QImage shrunk = QIcon(QStringLiteral(":/icons/io.github.rungstudio.RungStudio.svg"))
                                  .pixmap(size, size)
                                  .toImage()
                                  .convertToFormat(QImage::Format_ARGB32);
        EXPECT_EQ(small, drawn) << size;
        EXPECT_NE(small, shrunk) << size;
    }
}

// What the desktop entry offers to open (a double-click in a file manager), the window opens.
TEST(FileTypes, TheWindowOpensEveryTypeTheDesktopEntryNames) {
    const auto declared = declaredMimeTypes();
    const QStringList offered = desktopMimeTypes();
    ASSERT_GE(offered.size(), 2);
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    model::ProjectError error;
    const auto project = model::loadProject(installedExampleProject(), &error);
    ASSERT_TRUE(project) << error.message.toStdString();
    for (const QString &type : offered) {
        const auto found = declared.find(type);
        ASSERT_NE(found, declared.end()) << type.toStdString() << " is not declared";
        ASSERT_FALSE(found->second.globs.isEmpty()) << type.toStdString();
        for (const QString &glob : found->second.globs) {
            const QString path = dir.filePath(QStringLiteral("file") + glob.mid(1));
            // A real file of the type, as the product writes it.
            if (glob == QLatin1String("*.rung")) {
                ASSERT_TRUE(model::saveProject(*project, path, &error));
            } else if (glob == QLatin1String("*.ladder")) {
                model::LadderProgram ladder = project->program;
                ladder.target = project->target;
                QFile file(path);
                ASSERT_TRUE(file.open(QIODevice::WriteOnly));
                file.write(model::printLadderText(ladder).toUtf8());
            } else if (glob == QLatin1String("*.rungtest")) {
                // A scenario naming a project beside it: the window opens that project.
                ASSERT_TRUE(model::saveProject(
                    *project, dir.filePath(QStringLiteral("tested.rung")), &error));
                QFile file(path);
                ASSERT_TRUE(file.open(QIODevice::WriteOnly));
                file.write("program tested.rung\nat 1s expect Y0=0\n");
            } else if (glob == QLatin1String("*.rungnet")) {
                // A network of one station running that project: it opens in a window of
                // its own, and the main window keeps what it shows.
                ASSERT_TRUE(model::saveProject(
                    *project, dir.filePath(QStringLiteral("station.rung")), &error));
                QFile file(path);
                ASSERT_TRUE(file.open(QIODevice::WriteOnly));
                file.write(R"({"stations": [{"name": "a", "program": "station.rung"}]})");
                file.close();
                app::MainWindow window;
                EXPECT_TRUE(window.openFile(path, QString(), true)) << glob.toStdString();
                EXPECT_EQ(window.findChildren<app::NetworkWindow *>().size(), 1);
                continue;
            } else {
                FAIL() << "no sample for " << glob.toStdString() << ": add one here";
            }
            app::MainWindow window;
            EXPECT_TRUE(window.openFile(path, QString(), true)) << glob.toStdString();
            EXPECT_EQ(window.document()->ladder().rungs.size(), project->program.rungs.size())
                << glob.toStdString();
        }
    }
}

// Every type the MIME file declares is one the window opens: the desktop entry names it. A
// network (since issue 30) opens in a window of its own; one that cannot be built says why,
// naming the file, and is not read as an instruction list.
TEST(FileTypes, EveryDeclaredTypeIsOpened) {
    const auto declared = declaredMimeTypes();
    const QStringList offered = desktopMimeTypes();
    ASSERT_GE(declared.size(), 4u);
    EXPECT_TRUE(offered.contains(QStringLiteral("text/x-rungstudio-test")));
    EXPECT_TRUE(offered.contains(QStringLiteral("application/x-rungstudio-network")));
    for (const auto &[type, mime] : declared) {
        EXPECT_TRUE(offered.contains(type)) << type.toStdString();
        EXPECT_FALSE(mime.subClassOf.isEmpty()) << type.toStdString();
    }
    const auto network = declared.find(QStringLiteral("application/x-rungstudio-network"));
    ASSERT_NE(network, declared.end());
    EXPECT_EQ(network->second.globs, QStringList{QStringLiteral("*.rungnet")});
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("plant.rungnet"));
    QFile file(path);
    ASSERT_TRUE(file.open(QIODevice::WriteOnly));
    file.write("{\"stations\": []}\n");
    file.close();
    app::MainWindow window;
    EXPECT_FALSE(window.openFile(path, QString(), true)) << path.toStdString();
    const QString said = window.statusBar()->currentMessage();
    EXPECT_TRUE(said.contains(QStringLiteral("plant.rungnet")) &&
                said.contains(QStringLiteral("at least one station")))
        << said.toStdString();
    EXPECT_FALSE(window.ilEditor()->text().contains(QLatin1String("stations")));
}

// The project's magic is its own first key as saveProject writes it, within the offsets the
// MIME file gives: a .rung renamed or mailed without its extension is still a project.
TEST(FileTypes, TheProjectMagicMatchesWhatSaveWrites) {
    const auto declared = declaredMimeTypes();
    const auto found = declared.find(QStringLiteral("application/x-rungstudio-project"));
    ASSERT_NE(found, declared.end());
    EXPECT_EQ(found->second.subClassOf, QStringLiteral("application/json"));
    ASSERT_FALSE(found->second.magic.empty());
    QTemporaryDir dir;
    model::ProjectError error;
    const auto project = model::loadProject(installedExampleProject(), &error);
    ASSERT_TRUE(project);
    const QString path = dir.filePath(QStringLiteral("saved.rung"));
    ASSERT_TRUE(model::saveProject(*project, path, &error));
    QFile file(path);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    const QByteArray head = file.read(256);
    bool matched = false;
    for (const auto &[offset, value] : found->second.magic) {
        const int first = offset.section(QLatin1Char(':'), 0, 0).toInt();
        const int last = offset.section(QLatin1Char(':'), 1, 1).toInt();
        const qsizetype at = head.indexOf(value.toUtf8());
        matched = matched || (at >= first && at <= last);
    }
    EXPECT_TRUE(matched) << head.left(80).toStdString();
}

// The man pages (English, Hungarian, Italian) name the options `rungstudio --help` prints, no
// more and no fewer.
TEST(ManPage, GuiOptionsAreThoseOfHelp) {
    QCommandLineParser parser;
    app::describeGuiArguments(parser);
    const QStringList inHelp = test::optionsIn(parser.helpText());
    EXPECT_TRUE(inHelp.contains(QStringLiteral("--target")));
    EXPECT_TRUE(inHelp.contains(QStringLiteral("--version")));
    for (const char *page : {"man/rungstudio.1", "man/hu/rungstudio.1", "man/it/rungstudio.1"}) {
        const QStringList inPage =
            test::optionsIn(test::manText(test::readText(kPackagingDir + QLatin1String(page))));
        EXPECT_EQ(inPage, inHelp) << page << "\nman: " << inPage.join(' ').toStdString()
                                  << "\nhelp: " << inHelp.join(' ').toStdString();
    }
}
