// `convert --to plcopen` and `--from plcopen` (docs/plcopen.md), as a user runs them.

#include <QDirIterator>
#include <QFile>
#include <QTemporaryDir>

#include "tests/cli/cli_run.h"
#include "tests/test_files.h"

#include <gtest/gtest.h>

namespace {

using rung::test::cli;
using rung::test::CliRun;

QString exampleDir() {
    return QStringLiteral(RUNG_SOURCE_DIR "/resources/examples");
}

QString pump() {
    return QStringLiteral(RUNG_TEST_DATA_DIR "/plcopen/pump.xml");
}

} // namespace

TEST(CliPlcopen, ExportWritesXmlAndSaysWhatOtherToolsWillNotKnow) {
    QTemporaryDir dir;
    const QString out = dir.filePath(QStringLiteral("keep.xml"));
    const CliRun r =
        cli({QStringLiteral("convert"), exampleDir() + QStringLiteral("/cpm1/keep.rung"),
             QStringLiteral("--to"), QStringLiteral("plcopen"), QStringLiteral("-o"), out});
    EXPECT_EQ(r.code, 0) << r.err.toStdString();
    QFile f(out);
    ASSERT_TRUE(f.open(QIODevice::ReadOnly));
    EXPECT_TRUE(f.readAll().startsWith("<?xml"));
    EXPECT_TRUE(r.err.contains(QStringLiteral("note: KEEP is written as a block of CPM1's own")))
        << r.err.toStdString();
}

// Export, import and compare, with the tool: every example the same.
TEST(CliPlcopen, EveryExampleComesBackTheSameThroughTheTool) {
    QTemporaryDir dir;
    int count = 0;
    QDirIterator it(exampleDir(), {QStringLiteral("*.rung")}, QDir::Files,
                    QDirIterator::Subdirectories);
    while (it.hasNext()) {
        const QString path = it.next();
        const QString target = QFileInfo(path).dir().dirName();
        const QString xml = dir.filePath(QStringLiteral("x.xml"));
        const QString back = dir.filePath(QStringLiteral("back.rung"));
        CliRun r = cli({QStringLiteral("convert"), path, QStringLiteral("--to"),
                        QStringLiteral("plcopen"), QStringLiteral("-o"), xml});
        ASSERT_EQ(r.code, 0) << path.toStdString() << r.err.toStdString();
        r = cli({QStringLiteral("convert"), xml, QStringLiteral("--from"),
                 QStringLiteral("plcopen"), QStringLiteral("--target"), target,
                 QStringLiteral("--to"), QStringLiteral("project"), QStringLiteral("-o"), back});
        ASSERT_EQ(r.code, 0) << path.toStdString() << r.err.toStdString();
        r = cli({QStringLiteral("diff"), path, back});
        EXPECT_EQ(r.code, 0) << r.out.toStdString();
        ++count;
    }
    EXPECT_GE(count, 12);
}

// A file of another tool: located variables mapped by the rule, the others listed with a free
// device proposed and a mapping file to start from; nothing written until they have devices.
TEST(CliPlcopen, ImportListsWhatHasNoDeviceAndTakesAMappingFile) {
    QTemporaryDir dir;
    const QString out = dir.filePath(QStringLiteral("pump.il"));
    CliRun r = cli({QStringLiteral("convert"), pump(), QStringLiteral("--from"),
                    QStringLiteral("plcopen"), QStringLiteral("--to"), QStringLiteral("il")});
    EXPECT_EQ(r.code, 2);
    EXPECT_TRUE(r.err.contains(QStringLiteral("--from plcopen needs --target")));
    r = cli({QStringLiteral("convert"), pump(), QStringLiteral("--from"), QStringLiteral("plcopen"),
             QStringLiteral("--target"), QStringLiteral("vigor"), QStringLiteral("--to"),
             QStringLiteral("il"), QStringLiteral("-o"), out});
    EXPECT_EQ(r.code, 1);
    EXPECT_FALSE(QFile::exists(out));
    EXPECT_TRUE(r.err.contains(QStringLiteral("pump.xml:23: error: variable delay (TON) names no "
                                              "device of Vigor; proposed: T0\n")))
        << r.err.toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("--map FILE):\ndelay = T0\nlatched = M0\n")))
        << r.err.toStdString();
    // The proposals as a mapping file: the program is imported.
    const QString map =
        rung::test::writeFile(dir, QStringLiteral("pump.map"), "delay = T0\nlatched = M0\n");
    r = cli({QStringLiteral("convert"), pump(), QStringLiteral("--from"), QStringLiteral("plcopen"),
             QStringLiteral("--target"), QStringLiteral("vigor"), QStringLiteral("--map"), map,
             QStringLiteral("--to"), QStringLiteral("il")});
    EXPECT_EQ(r.code, 0) << r.err.toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("LD T0\nSET M0\n"))) << r.out.toStdString();
    // For a PLC without the comparison: listed; --force writes the rest and exits 1.
    const QString omron = rung::test::writeFile(dir, QStringLiteral("omron.map"),
                                                "delay = TIM 001\nlatched = HR00.00\n");
    r = cli({QStringLiteral("convert"), pump(), QStringLiteral("--from"), QStringLiteral("plcopen"),
             QStringLiteral("--target"), QStringLiteral("cpm1"), QStringLiteral("--map"), omron,
             QStringLiteral("--to"), QStringLiteral("project"), QStringLiteral("-o"), out});
    EXPECT_EQ(r.code, 1);
    EXPECT_FALSE(QFile::exists(out));
    EXPECT_TRUE(r.err.contains(QStringLiteral("pump.xml:94: error: block GT: CPM1 has no "
                                              "compare contact >")))
        << r.err.toStdString();
    r = cli({QStringLiteral("convert"), pump(), QStringLiteral("--from"), QStringLiteral("plcopen"),
             QStringLiteral("--target"), QStringLiteral("cpm1"), QStringLiteral("--map"), omron,
             QStringLiteral("--to"), QStringLiteral("project"), QStringLiteral("-o"), out,
             QStringLiteral("--force")});
    EXPECT_EQ(r.code, 1);
    EXPECT_TRUE(QFile::exists(out));
    EXPECT_TRUE(r.err.contains(QStringLiteral("written without what is listed above (--force)")));
}

// Counters: the export says which counters are IEC counters and what they do otherwise; the
// import of another tool's CTU says how it is imported, as a note beside the errors.
TEST(CliPlcopen, CountersAreNotedBothWays) {
    QTemporaryDir dir;
    const QString xml = dir.filePath(QStringLiteral("count.xml"));
    CliRun r = cli({QStringLiteral("convert"),
                    exampleDir() + QStringLiteral("/vigor/counting-range-extension.rung"),
                    QStringLiteral("--to"), QStringLiteral("plcopen"), QStringLiteral("-o"), xml});
    EXPECT_EQ(r.code, 0) << r.err.toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("note: CNT is written as an IEC CTU: Vigor's CNT "
                                              "stops counting at its set value")))
        << r.err.toStdString();
    const QString foreign =
        QStringLiteral(RUNG_TEST_DATA_DIR "/plcopen/foreign/openplc-7-segments.xml");
    const QString map = rung::test::writeFile(
        dir, QStringLiteral("seg.map"),
        "TON0 = T0\nTOF0 = T1\nCTU0 = C0\nsquare_wave = M0\nctu_reset = M1\ncurrent_count = D0\n");
    r = cli({QStringLiteral("convert"), foreign, QStringLiteral("--from"),
             QStringLiteral("plcopen"), QStringLiteral("--target"), QStringLiteral("vigor"),
             QStringLiteral("--map"), map, QStringLiteral("--to"), QStringLiteral("il"),
             QStringLiteral("--force")});
    EXPECT_EQ(r.code, 1); // the TOF is listed
    EXPECT_TRUE(r.err.contains(QStringLiteral("openplc-7-segments.xml: note: CTU (CTU0) is "
                                              "imported as Vigor's CNT: ")))
        << r.err.toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("openplc-7-segments.xml:249: error: block TOF: ")));
    EXPECT_TRUE(r.out.contains(QStringLiteral("LD M0\nCNT C0 K10\nLD M1\nRST C0\n")))
        << r.out.toStdString();
}
