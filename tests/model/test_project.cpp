#include "model/convert/convert.h"
#include "model/project/project.h"

#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QJsonDocument>
#include <QRandomGenerator>
#include <QTemporaryDir>

#include <gtest/gtest.h>

using namespace rung::model;

namespace {

Project sample() {
    const Target &t = Target::get(Family::Vigor);
    ParseResult parsed = parseInstructionList(
        t, QStringLiteral("; start\nLD X0\nOR Y0\nANI X1\nOUT Y0\nLD X2\nMPS\nAND "
                          "X3\nOUT Y1\nMPP\nTMR T0 K10\nEND\n"));
    EXPECT_TRUE(parsed.ok());
    Project p;
    p.target = &t;
    p.model = QStringLiteral("VB");
    p.program = listToLadder(parsed.list).ladder;
    p.symbols = {{std::get<Address>(parseAddress(t, u"X0")), QStringLiteral("Start"),
                  QStringLiteral("green button")}};
    p.setValues[std::get<Address>(parseAddress(t, u"T0"))] = 10;
    p.watchLists = {{QStringLiteral("Main"),
                     {QStringLiteral("X0"), QStringLiteral("Y0"), QStringLiteral("D0")},
                     {{QStringLiteral("D0"), ValueFormat::Hex}}}};
    return p;
}

QByteArray readAll(const QString &path) {
    QFile f(path);
    f.open(QIODevice::ReadOnly);
    return f.readAll();
}

std::string why(const char *json) {
    ProjectError e;
    EXPECT_FALSE(projectFromJson(QByteArray(json), &e).has_value());
    return e.message.toStdString();
}

} // namespace

TEST(ProjectFile, SaveAndLoadKeepEverything) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("a.rung"));
    const Project p = sample();
    ProjectError error;
    ASSERT_TRUE(saveProject(p, path, &error)) << error.message.toStdString();
    auto loaded = loadProject(path, &error);
    ASSERT_TRUE(loaded.has_value()) << error.message.toStdString();
    EXPECT_EQ(loaded->target, p.target);
    EXPECT_EQ(loaded->model, p.model);
    EXPECT_EQ(loaded->program.rungs, p.program.rungs);
    ASSERT_EQ(loaded->symbols.size(), 1u);
    EXPECT_EQ(loaded->symbols[0].name, QStringLiteral("Start"));
    EXPECT_EQ(loaded->setValues, p.setValues);
    ASSERT_EQ(loaded->watchLists.size(), 1u);
    EXPECT_EQ(loaded->watchLists[0].devices, p.watchLists[0].devices);
    EXPECT_EQ(loaded->watchLists[0], p.watchLists[0]); // the row formats too
    EXPECT_EQ(loaded->watchLists[0].format(QStringLiteral("D0")), ValueFormat::Hex);
    EXPECT_EQ(loaded->watchLists[0].format(QStringLiteral("X0")), ValueFormat::Decimal);
    // Writing it again gives the same bytes: the format is stable for diffs.
    EXPECT_EQ(projectToJson(*loaded), readAll(path));
}

TEST(ProjectFile, IsReadableJsonWithASchemaVersion) {
    const QByteArray json = projectToJson(sample());
    EXPECT_TRUE(json.contains("\"format\": \"rungstudio-project\""));
    EXPECT_TRUE(json.contains("\"schema\": 1"));
    EXPECT_TRUE(json.contains("\"X0\""));
    EXPECT_TRUE(json.contains("\"OUT Y0\""));
}

TEST(ProjectFile, MalformedJsonNamesLineAndColumn) {
    EXPECT_EQ(why("{\n  \"format\": \"rungstudio-project\",\n  \"schema\": 1,,\n}"),
              "Line 3, column 16 (byte 51): the file is not valid JSON (unterminated object)");
}

TEST(ProjectFile, TruncatedFileIsAClearError) {
    const QByteArray json = projectToJson(sample());
    ProjectError e;
    EXPECT_FALSE(projectFromJson(json.left(json.size() / 2), &e).has_value());
    EXPECT_TRUE(e.message.contains(QStringLiteral("not valid JSON"))) << e.message.toStdString();
}

TEST(ProjectFile, NewerSchemaIsRefusedWithTheReason) {
    EXPECT_EQ(why("{\"format\": \"rungstudio-project\", \"schema\": 7, \"target\": \"vigor\"}"),
              "The project was written by a newer Rung Studio (schema 7); this version reads "
              "schema 1 and older");
}

TEST(ProjectFile, WrongContentNamesThePath) {
    EXPECT_EQ(why("{\"format\": \"rungstudio-project\", \"schema\": 1, \"target\": \"s7\"}"),
              "\"target\": unknown PLC family \"s7\"");
    EXPECT_EQ(why("{\"format\": \"rungstudio-project\", \"schema\": 1, \"target\": \"vigor\", "
                  "\"rungs\": [{\"rows\": 1, "
                  "\"columns\": 1, \"cells\": [[\"X8\"]], \"outputs\": []}]}"),
              "rungs[0].cells[0][0]: X8: X is numbered in octal");
    EXPECT_EQ(why("[1, 2]"),
              "The file is JSON but not a Rung Studio project (no top-level object)");
}

TEST(ProjectFile, RandomBytesAndHugeFilesAreRefused) {
    QByteArray noise(4096, '\0');
    QRandomGenerator rng(7);
    for (char &c : noise)
        c = static_cast<char>(rng.bounded(256));
    ProjectError e;
    EXPECT_FALSE(projectFromJson(noise, &e).has_value());
    EXPECT_FALSE(e.message.isEmpty());
    QTemporaryDir dir;
    const QString big = dir.filePath(QStringLiteral("big.rung"));
    QFile f(big);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    ASSERT_TRUE(f.resize(100LL * 1024 * 1024)); // 100 MB, sparse
    f.close();
    EXPECT_FALSE(loadProject(big, &e).has_value());
    EXPECT_TRUE(e.message.contains(QStringLiteral("100 MB"))) << e.message.toStdString();
}

TEST(ProjectFile, FailedSaveLeavesTheOldFileUntouched) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("keep.rung"));
    ProjectError error;
    ASSERT_TRUE(saveProject(sample(), path, &error));
    const QByteArray before = readAll(path);
    // A directory where the file should go: the save fails and says why.
    EXPECT_FALSE(saveProject(sample(), dir.filePath(QStringLiteral("missing/dir/x.rung")), &error));
    EXPECT_TRUE(error.message.contains(QStringLiteral("missing/dir/x.rung")));
    EXPECT_EQ(readAll(path), before);
}

TEST(ProjectFile, WrongTypesAreErrorsNotSilentlyEmpty) {
    EXPECT_EQ(why("{\"format\": \"rungstudio-project\", \"schema\": 1, \"target\": \"vigor\", "
                  "\"rungs\": 5}"),
              "rungs: an array is expected");
    EXPECT_EQ(why("{\"format\": \"rungstudio-project\", \"schema\": 1, \"target\": \"vigor\", "
                  "\"rungs\": [{\"rows\": 1, \"columns\": 1, \"cells\": [[7]]}]}"),
              "rungs[0].cells[0][0]: a cell is a string (\"\", \"-\" or a contact)");
    EXPECT_EQ(why("{\"format\": \"rungstudio-project\", \"schema\": 1, \"target\": \"vigor\", "
                  "\"symbols\": [\"X0\"]}"),
              "symbols[0]: an object with \"device\" and \"name\" is expected");
    EXPECT_EQ(why("{\"format\": \"rungstudio-project\", \"schema\": 1, \"target\": \"vigor\", "
                  "\"watchLists\": [{\"name\": \"a\", \"devices\": [1]}]}"),
              "watchLists[0].devices[0]: a device name is expected");
    EXPECT_EQ(why("{\"format\": \"rungstudio-project\", \"schema\": 1, \"target\": \"vigor\", "
                  "\"watchLists\": [{\"name\": \"a\", \"devices\": [\"D0\"], "
                  "\"formats\": {\"D0\": \"roman\"}}]}"),
              "watchLists[0].formats.D0: \"roman\" is no format (dec, signed, hex, bin, bcd)");
}

TEST(ProjectFile, WatchRowFormatsAreSavedOnlyWhereNotDecimal) {
    // A project written before the formats existed opens with every row in decimal, and one
    // without other formats is written as it was (no "formats" key).
    ProjectError e;
    const auto old = projectFromJson(
        "{\"format\": \"rungstudio-project\", \"schema\": 1, \"target\": \"vigor\", "
        "\"watchLists\": [{\"name\": \"Main\", \"devices\": [\"X0\", \"D0\"]}]}",
        &e);
    ASSERT_TRUE(old.has_value()) << e.message.toStdString();
    EXPECT_TRUE(old->watchLists[0].formats.empty());
    EXPECT_FALSE(projectToJson(*old).contains("formats"));
    Project p = *old;
    p.watchLists[0].formats[QStringLiteral("D0")] = ValueFormat::Bcd;
    p.watchLists[0].formats[QStringLiteral("X0")] = ValueFormat::Decimal;
    p.watchLists[0].formats[QStringLiteral("D9")] = ValueFormat::Hex; // no such row
    const QByteArray json = projectToJson(p);
    EXPECT_TRUE(json.contains("\"formats\": { \"D0\": \"bcd\" }")) << json.toStdString();
    EXPECT_FALSE(json.contains("D9"));
}

TEST(ProjectFile, SetValuesMustBeWholeNumbersInRange) {
    // 1e300 would overflow the conversion to an integer: refused before it.
    EXPECT_EQ(why("{\"format\": \"rungstudio-project\", \"schema\": 1, \"target\": \"vigor\", "
                  "\"setValues\": {\"T0\": 1e300}}"),
              "setValues.T0: a whole number between -2147483647 and 2147483647 is expected");
    EXPECT_EQ(why("{\"format\": \"rungstudio-project\", \"schema\": 1, \"target\": \"vigor\", "
                  "\"setValues\": {\"T0\": 1.5}}"),
              "setValues.T0: a whole number between -2147483647 and 2147483647 is expected");
}

TEST(ProjectFile, BoxInputRowsAreValidated) {
    const char *prefix = "{\"format\": \"rungstudio-project\", \"schema\": 1, \"target\": "
                         "\"vigor\", \"rungs\": [{\"rows\": 2, \"columns\": 1, \"cells\": "
                         "[[\"X0\"], [\"X1\"]], \"outputs\": ";
    // OUT takes one input: no input rows may be given.
    EXPECT_EQ(why((std::string(prefix) + "[[0, \"OUT Y0\", [0, 1]]]}]}").c_str()),
              "rungs[0].outputs: \"OUT Y0\" takes up to 1 input rows, one box per rung");
    EXPECT_EQ(why((std::string(prefix) + "[[0, \"OUT Y0\"], [0, \"OUT Y1\"]]}]}").c_str()),
              "rungs[0].outputs: row 0 has two outputs");
}

TEST(ProjectFile, EveryExampleReadsBackToTheSameBytes) {
    int count = 0;
    QDirIterator it(QStringLiteral(RUNG_SOURCE_DIR "/resources/examples"),
                    {QStringLiteral("*.rung")}, QDir::Files, QDirIterator::Subdirectories);
    while (it.hasNext()) {
        const QString path = it.next();
        ProjectError error;
        const auto project = loadProject(path, &error);
        ASSERT_TRUE(project.has_value())
            << path.toStdString() << ": " << error.message.toStdString();
        EXPECT_EQ(projectToJson(*project), readAll(path)) << path.toStdString();
        const auto again = projectFromJson(projectToJson(*project), &error);
        ASSERT_TRUE(again.has_value()) << error.message.toStdString();
        EXPECT_EQ(again->program.rungs, project->program.rungs) << path.toStdString();
        ++count;
    }
    EXPECT_GE(count, 12);
}

// A device or a pipe has no size to check first: the loader reads no more than the limit.
TEST(ProjectFile, AnEndlessDeviceIsRefusedAtTheLimit) {
    if (!QFile::exists(QStringLiteral("/dev/zero")))
        GTEST_SKIP() << "no /dev/zero";
    ProjectError error;
    EXPECT_FALSE(loadProject(QStringLiteral("/dev/zero"), &error).has_value());
    EXPECT_TRUE(error.message.contains(QStringLiteral("larger than 64 MB")))
        << error.message.toStdString();
}

// Save while the instruction list has an error: the text as typed goes into the file with the
// last valid program, and comes back as it was.
TEST(ProjectFile, TheListAsTypedWithItsErrorsIsKept) {
    Project p = sample();
    p.pendingListing = QStringLiteral("LD X8\nOUT Y1\n; not yet\n");
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("typed.rung"));
    ProjectError error;
    ASSERT_TRUE(saveProject(p, path, &error)) << error.message.toStdString();
    EXPECT_TRUE(readAll(path).contains("\"pendingListing\": \"LD X8\\nOUT Y1\\n; not yet\\n\""));
    const auto back = loadProject(path, &error);
    ASSERT_TRUE(back) << error.message.toStdString();
    EXPECT_EQ(back->pendingListing, p.pendingListing);
    EXPECT_EQ(back->program.rungs, p.program.rungs); // the last valid program, alongside
}

TEST(ProjectFile, AFileWithoutTheListAsTypedHasNone) {
    // As written before the key existed (and by every save with a valid list): no key at all.
    const QByteArray old = "{\"format\": \"rungstudio-project\", \"schema\": 1, \"target\": "
                           "\"vigor\", \"model\": \"VB\", \"rungs\": []}";
    ProjectError error;
    const auto p = projectFromJson(old, &error);
    ASSERT_TRUE(p) << error.message.toStdString();
    EXPECT_TRUE(p->pendingListing.isEmpty());
    EXPECT_FALSE(projectToJson(sample()).contains("pendingListing"));
    EXPECT_FALSE(projectFromJson("{\"format\": \"rungstudio-project\", \"schema\": 1, "
                                 "\"target\": \"vigor\", \"pendingListing\": 5}",
                                 &error));
    EXPECT_EQ(error.message.toStdString(), "pendingListing: a string is expected");
}

namespace {

// The lines of `after` that are not in `before` and those of `before` not in `after`, as a
// line diff counts them (the files here have no repeated lines that matter).
int changedLines(const QByteArray &before, const QByteArray &after) {
    const QList<QByteArray> x = before.split('\n');
    const QList<QByteArray> y = after.split('\n');
    int changed = 0;
    for (const QByteArray &line : x)
        changed += y.contains(line) ? 0 : 1;
    for (const QByteArray &line : y)
        changed += x.contains(line) ? 0 : 1;
    return changed;
}

} // namespace

// docs/version-control.md: one contact, one symbol, one set value each change one line of the
// file; the keys stand in one fixed order, what a reader wants first at the top.
TEST(ProjectFile, TheLayoutServesADiff) {
    Project p = sample();
    const QByteArray before = projectToJson(p);
    EXPECT_TRUE(before.startsWith("{\n    \"format\": \"rungstudio-project\",\n    \"schema\": 1,\n"
                                  "    \"target\": \"vigor\",\n    \"model\": \"VB\",\n    "
                                  "\"rungs\": [\n"))
        << before.toStdString();
    EXPECT_TRUE(before.contains("\n    \"symbols\": [\n        { \"device\": \"X0\", \"name\": "
                                "\"Start\", \"comment\": \"green button\" }\n    ],\n"))
        << before.toStdString();
    EXPECT_TRUE(before.endsWith("}\n"));
    // A contact made normally closed.
    Project q = p;
    Rung &rung = q.program.rungs.front();
    for (Cell &c : rung.cells)
        if (c.kind == CellKind::Contact && c.contact.mode == ContactMode::Normal) {
            c.contact.mode = ContactMode::Negated;
            break;
        }
    EXPECT_EQ(changedLines(before, projectToJson(q)), 2);
    // A symbol renamed, a set value changed.
    q = p;
    q.symbols[0].name = QStringLiteral("Go");
    EXPECT_EQ(changedLines(before, projectToJson(q)), 2);
    q = p;
    q.setValues.begin()->second = 99;
    EXPECT_EQ(changedLines(before, projectToJson(q)), 2);
    // Set values in the order of the devices, not of their texts.
    q = p;
    const Target &t = *p.target;
    q.setValues[std::get<Address>(parseAddress(t, u"T10"))] = 1;
    q.setValues[std::get<Address>(parseAddress(t, u"T2"))] = 2;
    const QByteArray values = projectToJson(q);
    EXPECT_LT(values.indexOf("\"T2\": 2"), values.indexOf("\"T10\": 1")) << values.toStdString();
    // Text with quotes, backslashes, line breaks and other scripts reads back as written.
    q = p;
    q.program.rungs.front().comment =
        QStringLiteral("a \"quoted\" \\ back\nslash\t\u00e1rv\u00edzt\u0001");
    ProjectError error;
    const auto back = projectFromJson(projectToJson(q), &error);
    ASSERT_TRUE(back) << error.message.toStdString();
    EXPECT_EQ(back->program.rungs.front().comment, q.program.rungs.front().comment);
}

// Files written before the layout of docs/version-control.md (QJsonDocument's: keys in
// alphabetical order, one value a line) read as before, and the next save keeps everything.
TEST(ProjectFile, TheOldLayoutReadsAndSavesToTheSameProject) {
    ProjectError error;
    const QString path = QStringLiteral(RUNG_TEST_DATA_DIR "/project/old-layout.rung");
    const auto old = loadProject(path, &error);
    ASSERT_TRUE(old) << error.message.toStdString();
    EXPECT_FALSE(old->symbols.empty());
    EXPECT_FALSE(old->watchLists.empty());
    const QByteArray saved = projectToJson(*old);
    EXPECT_NE(saved, readAll(path));
    const auto again = projectFromJson(saved, &error);
    ASSERT_TRUE(again) << error.message.toStdString();
    EXPECT_EQ(again->program.rungs, old->program.rungs);
    EXPECT_EQ(again->symbols, old->symbols);
    EXPECT_EQ(again->watchLists, old->watchLists);
    EXPECT_EQ(again->setValues, old->setValues);
    EXPECT_EQ(again->model, old->model);
    EXPECT_EQ(projectToJson(*again), saved);
    // Everything a file holds, in the old layout: the same project.
    Project rich = sample();
    rich.pendingListing = QStringLiteral("LD X8\nOUT Y1\n");
    rich.pendingSymbols = {{QStringLiteral("X9"), QStringLiteral("Spare"), QStringLiteral("c")}};
    const QByteArray oldLayout =
        QJsonDocument::fromJson(projectToJson(rich)).toJson(QJsonDocument::Indented);
    const auto fromOld = projectFromJson(oldLayout, &error);
    ASSERT_TRUE(fromOld) << error.message.toStdString();
    EXPECT_EQ(projectToJson(*fromOld), projectToJson(rich));
}

// The PLC's port settings ("2nd COM Port Setting", docs/network-format.md): kept as written,
// one port a line, checked against the target's table with the place and the reason.
TEST(ProjectFile, PortSettingsAreKeptAndChecked) {
    Project p = sample();
    p.ports = QJsonDocument::fromJson(R"({"CP2": {"application": "computer-link", "station": 5,
                                          "baud": 9600}})")
                  .object();
    const QByteArray json = projectToJson(p);
    EXPECT_TRUE(json.contains(R"("CP2": {"application":"computer-link","baud":9600,"station":5})"))
        << json.toStdString();
    ProjectError e;
    const auto loaded = projectFromJson(json, &e);
    ASSERT_TRUE(loaded.has_value()) << e.message.toStdString();
    EXPECT_EQ(loaded->ports, p.ports);
    EXPECT_EQ(projectToJson(*loaded), json);
    // A project without settings writes no key.
    EXPECT_FALSE(projectToJson(sample()).contains("\"ports\""));
    QByteArray wrong = json;
    wrong.replace("9600", "12345");
    EXPECT_FALSE(projectFromJson(wrong, &e).has_value());
    EXPECT_TRUE(e.message.contains(QStringLiteral("ports.CP2.baud: 12345 is not a rate")))
        << e.message.toStdString();
}
