// The rooms and their arrows (docs/architecture.md): an include runs down only. model uses
// nothing of ours; simulator and comms use model; network uses simulator and comms;
// editor uses model alone; app uses them all. Below editor no file includes QtGui or
// QtWidgets, so the command-line tool and the tests run without a display. These tests read
// the source tree and name the file and line that breaks the rule.

#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QFileInfo>
#include <QLibraryInfo>
#include <QRegularExpression>

#include <gtest/gtest.h>

#include <map>
#include <optional>
#include <set>

namespace {

const QString kTreeRoot = QStringLiteral(RUNG_SOURCE_DIR);

const QStringList kRooms = {QStringLiteral("model"),  QStringLiteral("simulator"),
                            QStringLiteral("comms"),  QStringLiteral("network"),
                            QStringLiteral("editor"), QStringLiteral("app")};

// What each room may include besides itself.
const std::map<QString, std::set<QString>> &allowed() {
    static const std::map<QString, std::set<QString>> arrows = {
        {QStringLiteral("model"), {}},
        {QStringLiteral("simulator"), {QStringLiteral("model")}},
        {QStringLiteral("comms"), {QStringLiteral("model")}},
        {QStringLiteral("network"),
         {QStringLiteral("model"), QStringLiteral("simulator"), QStringLiteral("comms")}},
        {QStringLiteral("editor"), {QStringLiteral("model")}},
        {QStringLiteral("app"),
         {QStringLiteral("model"), QStringLiteral("simulator"), QStringLiteral("comms"),
          QStringLiteral("network"), QStringLiteral("editor")}},
    };
    return arrows;
}

// The room of a path relative to the source root ("editor/ladder_view.h" -> "editor").
std::optional<QString> roomOf(const QString &relative) {
    const QString first = relative.section(QLatin1Char('/'), 0, 0);
    if (kRooms.contains(first))
        return first;
    return std::nullopt;
}

// An include of ours, as a path relative to the source root: "model/x.h" as written, or a
// name beside the including file ("tr.h", "../model/x.h"). Empty: not one of ours.
QString resolve(const QString &includer, const QString &name) {
    const QDir root(kTreeRoot);
    const QString beside = QFileInfo(includer).dir().filePath(name);
    if (QFileInfo::exists(beside))
        return QDir::cleanPath(root.relativeFilePath(beside));
    if (QFileInfo::exists(root.filePath(name)))
        return QDir::cleanPath(name);
    return {};
}

struct Include {
    int line = 0; // 1-based
    QString name; // as written between the quotes or brackets
    bool quoted = false;
};

std::vector<Include> includesOfText(const QString &text) {
    static const QRegularExpression re(QStringLiteral(R"(^\s*#\s*include\s*([<"])([^>"]+)[>"])"));
    std::vector<Include> out;
    const QStringList lines = text.split(QLatin1Char('\n'));
    for (int k = 0; k < lines.size(); ++k) {
        const QRegularExpressionMatch m = re.match(lines[k]);
        if (m.hasMatch())
            out.push_back({k + 1, m.captured(2), m.captured(1) == QLatin1String("\"")});
    }
    return out;
}

std::vector<Include> includesOf(const QString &path) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) {
        ADD_FAILURE() << "cannot read " << path.toStdString();
        return {};
    }
    return includesOfText(QString::fromUtf8(f.readAll()));
}

QStringList sourcesOf(const QString &room) {
    QStringList files;
    const QString dir = kTreeRoot + QLatin1Char('/') + room;
    if (!QFileInfo::exists(dir))
        return files;
    QDirIterator it(dir, {QStringLiteral("*.cpp"), QStringLiteral("*.h")}, QDir::Files,
                    QDirIterator::Subdirectories);
    while (it.hasNext())
        files << it.next();
    files.sort();
    return files;
}

// A header of QtGui or QtWidgets: named with its module ("QtGui/QColor", <QtWidgets>) or a
// class header the installed modules hold (<QColor>, <QWidget>).
bool isGuiHeader(const QString &name) {
    for (const char *module : {"QtGui", "QtWidgets"}) {
        const QString m = QLatin1String(module);
        if (name == m || name.startsWith(m + QLatin1Char('/')))
            return true;
        if (!name.contains(QLatin1Char('/')) && name.startsWith(QLatin1Char('Q')) &&
            QFileInfo::exists(QLibraryInfo::path(QLibraryInfo::HeadersPath) + QLatin1Char('/') + m +
                              QLatin1Char('/') + name))
            return true;
    }
    return false;
}

// The broken arrows of a file (`relative` to the source root) that has `includes`:
// "file:line: text" per include.
QStringList brokenArrows(const QString &relative, const std::vector<Include> &includes) {
    QStringList out;
    const QString path = kTreeRoot + QLatin1Char('/') + relative;
    const std::optional<QString> room = roomOf(relative);
    if (!room)
        return out;
    const std::set<QString> &may = allowed().at(*room);
    for (const Include &inc : includes) {
        if (!inc.quoted)
            continue;
        const QString target = resolve(path, inc.name);
        const std::optional<QString> to = target.isEmpty() ? std::nullopt : roomOf(target);
        if (!to || *to == *room || may.count(*to))
            continue;
        out << QStringLiteral("%1:%2: %3 includes %4 (%5 may use %6)")
                   .arg(relative)
                   .arg(inc.line)
                   .arg(*room, inc.name, *room,
                        may.empty()
                            ? QStringLiteral("nothing of ours")
                            : QStringList(may.begin(), may.end()).join(QLatin1String(", ")));
    }
    return out;
}

} // namespace

TEST(RoomIncludes, TheRoomsAreFound) {
    // The guards below would pass on an empty tree; make sure they read the real one.
    EXPECT_TRUE(
        sourcesOf(QStringLiteral("model")).contains(kTreeRoot + QStringLiteral("/model/tr.h")));
    EXPECT_GT(sourcesOf(QStringLiteral("editor")).size(), 20);
    EXPECT_GT(sourcesOf(QStringLiteral("simulator")).size(), 20);
    EXPECT_GT(sourcesOf(QStringLiteral("comms")).size(), 20);
}

TEST(RoomIncludes, EveryIncludeRunsDownTheArrows) {
    for (const QString &room : kRooms)
        for (const QString &path : sourcesOf(room))
            for (const QString &broken :
                 brokenArrows(QDir(kTreeRoot).relativeFilePath(path), includesOf(path)))
                ADD_FAILURE() << broken.toStdString();
}

TEST(RoomIncludes, NothingBelowTheEditorIncludesQtGuiOrQtWidgets) {
    for (const char *room : {"model", "simulator", "comms", "network"})
        for (const QString &path : sourcesOf(QLatin1String(room)))
            for (const Include &inc : includesOf(path))
                EXPECT_FALSE(!inc.quoted && isGuiHeader(inc.name))
                    << QDir(kTreeRoot).relativeFilePath(path).toStdString() << ':' << inc.line
                    << ": includes <" << inc.name.toStdString()
                    << ">; below the editor only QtCore (QtNetwork in comms) is used";
}

// The guards catch what they are meant to catch: a file written against the arrows.
TEST(RoomIncludes, TheGuardsCatchAnIncludeAgainstTheArrows) {
    // A model header that includes the editor by its path from the root, the simulator by a
    // path beside it, model itself, and a QtGui class.
    const std::vector<Include> includes =
        includesOfText(QStringLiteral("#include \"editor/document.h\"\n"
                                      "#include \"../simulator/engine.h\"\n"
                                      "#include \"model/tr.h\"\n"
                                      "#include \"tr.h\"\n"
                                      "#include <QColor>\n"));
    ASSERT_EQ(includes.size(), 5u);
    const QStringList broken = brokenArrows(QStringLiteral("model/probe.h"), includes);
    ASSERT_EQ(broken.size(), 2) << broken.join(QLatin1Char('\n')).toStdString();
    EXPECT_EQ(broken[0], QStringLiteral("model/probe.h:1: model includes editor/document.h "
                                        "(model may use nothing of ours)"));
    EXPECT_EQ(broken[1], QStringLiteral("model/probe.h:2: model includes ../simulator/engine.h "
                                        "(model may use nothing of ours)"));
    // The editor may use model, not the simulator.
    EXPECT_EQ(brokenArrows(QStringLiteral("editor/probe.h"), includes).size(), 1);
    // app may use them all.
    EXPECT_TRUE(brokenArrows(QStringLiteral("app/gui/probe.h"), includes).isEmpty());
    EXPECT_TRUE(isGuiHeader(QStringLiteral("QtWidgets/QWidget")));
    EXPECT_TRUE(isGuiHeader(QStringLiteral("QtGui")));
    EXPECT_FALSE(isGuiHeader(QStringLiteral("QString")));
    EXPECT_FALSE(isGuiHeader(QStringLiteral("QtCore/QString")));
    if (QFileInfo::exists(QLibraryInfo::path(QLibraryInfo::HeadersPath) +
                          QStringLiteral("/QtGui/QColor"))) {
        EXPECT_TRUE(isGuiHeader(includes[4].name));
    }
}
