// The man page of rungstudio-cli (packaging/man/rungstudio-cli.1) against what the program
// says of itself: the same commands and options as `--help`, the same version as `--version`;
// and the package's other version marks (the Debian changelog, the AppStream release) agree.

#include "tests/cli/man_page.h"

#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QProcess>
#include <QRegularExpression>

#include <gtest/gtest.h>

using namespace rung;

namespace {

// The real program, as a user or a package script runs it, in the C locale.
QString runInstalledTool(const QStringList &args) {
    QProcess p;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("LANG"), QStringLiteral("C"));
    env.insert(QStringLiteral("LC_ALL"), QStringLiteral("C"));
    p.setProcessEnvironment(env);
    p.start(QStringLiteral(RUNG_CLI_PATH), args);
    if (!p.waitForFinished(30000))
        return QString();
    return QString::fromUtf8(p.readAllStandardOutput());
}

// The page in English, Hungarian and Italian.
const char *const kCliManPages[] = {"rungstudio-cli.1", "hu/rungstudio-cli.1",
                                    "it/rungstudio-cli.1"};

QString cliManPage(const char *page) {
    return test::readText(QStringLiteral(RUNG_SOURCE_DIR "/packaging/man/") + QLatin1String(page));
}

QString cliProgramVersion() {
    return runInstalledTool({QStringLiteral("--version")})
        .trimmed()
        .section(QLatin1Char(' '), 1, 1); // "rungstudio-cli 0.1.0"
}

// The commands `--help` lists (a line "  rungstudio-cli NAME ..."), sorted, each once.
QStringList commandsIn(const QString &help) {
    QStringList commands;
    const QRegularExpression command(QStringLiteral("^\\s*rungstudio-cli ([a-z]+)\\b"),
                                     QRegularExpression::MultilineOption);
    for (auto it = command.globalMatch(help); it.hasNext();)
        commands << it.next().captured(1);
    commands.removeDuplicates();
    commands.sort();
    return commands;
}

} // namespace

TEST(ManPage, CliOptionsAreThoseOfHelp) {
    const QString help = runInstalledTool({QStringLiteral("--help")});
    ASSERT_TRUE(help.contains(QLatin1String("usage:"))) << help.toStdString();
    const QStringList inHelp = test::optionsIn(help);
    EXPECT_GE(inHelp.size(), 25);
    for (const char *name : kCliManPages) {
        const QString page = cliManPage(name);
        ASSERT_FALSE(page.isEmpty()) << name;
        const QStringList inPage = test::optionsIn(test::manText(page));
        EXPECT_EQ(inPage, inHelp) << name << "\nman: " << inPage.join(' ').toStdString()
                                  << "\nhelp: " << inHelp.join(' ').toStdString();
    }
}

TEST(ManPage, CliCommandsAreThoseOfHelp) {
    const QString help = runInstalledTool({QStringLiteral("--help")});
    const QStringList inHelp = commandsIn(help);
    EXPECT_GE(inHelp.size(), 8);
    // A command is a tagged paragraph of its own (".TP" then ".B check").
    const QRegularExpression tagged(QStringLiteral("^\\.TP\\n\\.B ([a-z]+)$"),
                                    QRegularExpression::MultilineOption);
    for (const char *name : kCliManPages) {
        QStringList inPage;
        for (auto it = tagged.globalMatch(test::manText(cliManPage(name))); it.hasNext();)
            inPage << it.next().captured(1);
        inPage.sort();
        EXPECT_EQ(inPage, inHelp) << name << "\nman: " << inPage.join(' ').toStdString()
                                  << "\nhelp: " << inHelp.join(' ').toStdString();
    }
}

// The bash completion offers the commands `--help` lists, no more and no fewer.
TEST(ManPage, BashCompletionOffersTheCommandsOfHelp) {
    const QString help = runInstalledTool({QStringLiteral("--help")});
    const QStringList inHelp = commandsIn(help);
    const QString script =
        test::readText(QStringLiteral(RUNG_SOURCE_DIR "/packaging/completion/rungstudio-cli"));
    const QRegularExpressionMatch listed =
        QRegularExpression(QStringLiteral("local commands=\"([a-z ]+)\"")).match(script);
    ASSERT_TRUE(listed.hasMatch());
    QStringList inScript = listed.captured(1).split(QLatin1Char(' '), Qt::SkipEmptyParts);
    inScript.sort();
    EXPECT_EQ(inScript, inHelp) << "completion: " << inScript.join(' ').toStdString()
                                << "\nhelp: " << inHelp.join(' ').toStdString();
}

// The version a user reads in the man page's header, the package's changelog and the software
// centre's release list is the one the program prints.
TEST(ManPage, VersionsAgreeWithTheProgram) {
    const QString version = cliProgramVersion();
    ASSERT_TRUE(
        QRegularExpression(QStringLiteral("^\\d+\\.\\d+\\.\\d+$")).match(version).hasMatch())
        << version.toStdString();
    QDirIterator pages(QStringLiteral(RUNG_SOURCE_DIR "/packaging/man"), {QStringLiteral("*.1")},
                       QDir::Files, QDirIterator::Subdirectories);
    int count = 0;
    for (; pages.hasNext(); ++count) {
        const QString page = pages.next();
        EXPECT_TRUE(
            test::readText(page).contains(QStringLiteral("\"Rung Studio %1\"").arg(version)))
            << page.toStdString();
    }
    EXPECT_GE(count, 2);
    const QString changelog =
        test::readText(QStringLiteral(RUNG_SOURCE_DIR "/packaging/debian/changelog"));
    EXPECT_TRUE(changelog.startsWith(QStringLiteral("rungstudio (%1) ").arg(version)))
        << changelog.left(60).toStdString();
    const QString metainfo = test::readText(
        QStringLiteral(RUNG_SOURCE_DIR "/packaging/io.github.rungstudio.RungStudio.metainfo.xml"));
    const QRegularExpression release(QStringLiteral("<release version=\"([^\"]+)\""));
    EXPECT_EQ(release.match(metainfo).captured(1), version);
}
