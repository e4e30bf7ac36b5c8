// The instruction list beside the ladder in a PLCopen export (docs/plcopen.md "The instruction
// list"): in the POU's addData, the listing `convert --to il` writes; one POU, one LD body, so
// that no tool reads the program twice; on import the ladder is the program, and a listing
// that no longer matches it is noted.

#include "model/convert/convert.h"
#include "model/exchange/plcopen.h"
#include "model/exchange/plcopen_xml.h"
#include "model/ladder/ladder_text.h"

#include "tests/model/plcopen_test_util.h"
#include "tests/targets.h"

#include <gtest/gtest.h>

using namespace rung::model;
using rung::testing::exampleProjects;
using rung::testing::issues;
using rung::testing::listing;
using rung::testing::vigor;

namespace {

// The POUs of a file, and the listing of Rung Studio's addData in the first one.
struct Pous {
    int count = 0;
    int bodies = 0;
    QString listing;
    QString listingTarget;
};

Pous pousOf(const QByteArray &xml) {
    QString error;
    const auto root = readXmlTree(xml, &error);
    EXPECT_TRUE(root) << error.toStdString();
    Pous out;
    if (!root)
        return out;
    for (const XmlNode *pou : root->child("types")->child("pous")->all("pou")) {
        ++out.count;
        out.bodies += static_cast<int>(pou->all("body").size());
        if (const XmlNode *add = pou->child("addData"))
            for (const XmlNode *d : add->all("data"))
                if (d->attribute("name") ==
                    QLatin1String("urn:rungstudio:plcopen:instructionList")) {
                    EXPECT_EQ(d->attribute("handleUnknown"), QStringLiteral("preserve"));
                    out.listing = d->children.front().text;
                    out.listingTarget = d->children.front().attribute("target");
                }
    }
    return out;
}

} // namespace

TEST(PlcopenListing, TheInstructionListGoesBesideTheLadderInOnePou) {
    for (const QString &path : exampleProjects()) {
        ProjectError error;
        const auto p = loadProject(path, &error);
        ASSERT_TRUE(p) << error.message.toStdString();
        const PlcopenExport out = exportPlcopen(*p, QStringLiteral("x"));
        const Pous pous = pousOf(out.xml);
        EXPECT_EQ(pous.count, 1) << path.toStdString();
        EXPECT_EQ(pous.bodies, 1) << path.toStdString();
        // The listing the vendor's tool downloads, as `convert --to il` writes it.
        EXPECT_EQ(pous.listing, printInstructionList(ladderToList(p->program).list))
            << path.toStdString();
        EXPECT_EQ(pous.listingTarget, p->target->id);
        // The ladder is what is imported: the listing matches it, so nothing is noted.
        const PlcopenImport back = importPlcopen(out.xml, *p->target, nullptr);
        ASSERT_TRUE(back.complete()) << path.toStdString() << issues(back);
        EXPECT_TRUE(back.notes.isEmpty()) << back.notes.join('\n').toStdString();
    }
}

// A file whose ladder another tool changed keeps the old listing: the ladder is imported and
// the note says the listing differs.
TEST(PlcopenListing, AListingThatNoLongerMatchesTheLadderIsNoted) {
    ProjectError error;
    const auto p = loadProject(
        QStringLiteral(RUNG_SOURCE_DIR "/resources/examples/vigor/delay-off.rung"), &error);
    ASSERT_TRUE(p) << error.message.toStdString();
    QByteArray xml = exportPlcopen(*p, QStringLiteral("x")).xml;
    ASSERT_TRUE(xml.contains("<variable>X0</variable>"));
    xml.replace("<variable>X0</variable>", "<variable>X7</variable>");
    const PlcopenImport r = importPlcopen(xml, vigor(), nullptr);
    ASSERT_TRUE(r.complete()) << issues(r);
    EXPECT_TRUE(listing(*r.project).contains(QStringLiteral("X7")));
    EXPECT_EQ(r.notes, QStringList{QStringLiteral(
                           "the instruction list in the file differs from its ladder (another tool "
                           "changed the ladder?): the ladder is imported")});
}

// A ladder no listing expresses (a bridge, PLC concepts (WPLSoft family) 1.8) is written as a
// ladder alone, and the note says why the listing is missing.
TEST(PlcopenListing, ALadderWithoutAListingIsWrittenAloneAndSaysSo) {
    const LadderTextResult bridge =
        parseLadderText(vigor(), QStringLiteral("LADDER vigor WIDTH 8\n"
                                                "RUNG 1 ROWS 3 COLUMNS 3\n"
                                                "|-[ X0 ]-+----------[ X1 ]-+(OUT Y0)\n"
                                                "|        |                 |\n"
                                                "|        +-[ X2 ]-+        +\n"
                                                "|                 |        |\n"
                                                "|-[ X3 ]----------+-[ X4 ]-+\n"));
    ASSERT_TRUE(bridge.ok());
    Project p;
    p.target = &vigor();
    p.model = vigor().defaultModel().name;
    p.program = bridge.ladder;
    const PlcopenExport out = exportPlcopen(p, QStringLiteral("bridge"));
    EXPECT_TRUE(pousOf(out.xml).listing.isEmpty());
    ASSERT_EQ(out.notes.size(), 1);
    EXPECT_TRUE(out.notes[0].startsWith(QStringLiteral(
        "the instruction list is not written beside the ladder: rung 1 does not convert (")))
        << out.notes[0].toStdString();
}
