// PLCopen TC6 XML 2.01 (docs/plcopen.md): export validated against the schema with xmllint,
// the located-variable rule, import of files laid out as other tools write them, and the round
// trip of every example project and of random programs of every target.

#include "model/compare/compare.h"
#include "model/convert/convert.h"
#include "model/exchange/plcopen.h"
#include "model/target/address.h"

#include "tests/model/plcopen_test_util.h"
#include "tests/model/random_program.h"
#include "tests/targets.h"

#include <QDirIterator>
#include <QFile>
#include <QProcess>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QTemporaryDir>

#include <gtest/gtest.h>

using namespace rung::model;
using rung::testing::cpm1;
using rung::testing::deviceAt;
using rung::testing::exampleProjects;
using rung::testing::issues;
using rung::testing::listing;
using rung::testing::pl110;
using rung::testing::schemaPath;
using rung::testing::vigor;
using rung::testing::vpc;

TEST(PlcopenNames, DevicesAreIecIdentifiersAndBack) {
    const std::pair<const Target *, const char *> cases[] = {
        {&vigor(), "X10"},    {&cpm1(), "000.01"}, {&cpm1(), "DM 0010"}, {&cpm1(), "TIM 000"},
        {&cpm1(), "HR00.05"}, {&pl110(), "SM0.0"}, {&pl110(), "V10"},    {&vpc(), "i00"}};
    for (const auto &[t, device] : cases) {
        const Address a = deviceAt(*t, device);
        const QString name = iecName(*t, a);
        EXPECT_TRUE(
            QRegularExpression(QStringLiteral("^[A-Za-z_][A-Za-z0-9_]*$")).match(name).hasMatch())
            << name.toStdString();
        const auto back = deviceOfIecName(*t, name);
        ASSERT_TRUE(back) << name.toStdString();
        EXPECT_EQ(*back, a) << device;
    }
    EXPECT_EQ(iecName(cpm1(), deviceAt(cpm1(), "000.01")), QStringLiteral("IN000_01"));
    EXPECT_EQ(iecName(cpm1(), deviceAt(cpm1(), "DM 0010")), QStringLiteral("DM0010"));
    EXPECT_FALSE(deviceOfIecName(vigor(), QStringLiteral("start_button")));
    EXPECT_FALSE(deviceOfIecName(vigor(), QStringLiteral("X8"))); // octal
}

// docs/plcopen.md "Located variables", case by case.
TEST(PlcopenNames, LocatedVariablesFollowTheDocumentedRule) {
    const struct {
        const Target *target;
        const char *location;
        const char *device;
    } cases[] = {
        {&vigor(), "%IX0.0", "X0"},    {&vigor(), "%IX0.7", "X7"},    {&vigor(), "%IX1.0", "X10"},
        {&vigor(), "%QX0.1", "Y1"},    {&vigor(), "%MW10", "D10"},    {&vigor(), "%MW200", "D200"},
        {&cpm1(), "%IX0.0", "000.00"}, {&cpm1(), "%IX1.7", "000.15"}, {&cpm1(), "%IX2.0", "001.00"},
        {&cpm1(), "%QX0.0", "010.00"}, {&cpm1(), "%MW5", "DM 0005"},  {&pl110(), "%IX0.0", "I1"},
        {&pl110(), "%QX1.0", "Q9"},    {&pl110(), "%IW0", "AI1"},     {&vigor(), "%IW1", "VR2"},
        {&pl110(), "%MW3", "V3"},      {&vpc(), "%IX0.5", "i05"},     {&vpc(), "%QX1.1", "o09"},
        {&vpc(), "%IW1", "a01"},       {&vpc(), "%QW0", "d00"},       {&vpc(), "%MW7", "p07"},
    };
    for (const auto &c : cases) {
        const auto a = deviceOfLocation(*c.target, QString::fromLatin1(c.location));
        ASSERT_TRUE(a) << c.target->id.toStdString() << " " << c.location;
        EXPECT_EQ(formatAddress(*c.target, *a), QString::fromLatin1(c.device)) << c.location;
        EXPECT_EQ(locationOfDevice(*c.target, *a), QString::fromLatin1(c.location)) << c.device;
    }
    // No such device: beyond the area, a bit above 7, a word where the target has none.
    EXPECT_FALSE(deviceOfLocation(vigor(), QStringLiteral("%IX64.0")));
    EXPECT_FALSE(deviceOfLocation(vigor(), QStringLiteral("%IX0.8")));
    EXPECT_FALSE(deviceOfLocation(vigor(), QStringLiteral("%IW2"))); // VR1, VR2 only
    EXPECT_FALSE(deviceOfLocation(vigor(), QStringLiteral("%MX0.0")));
    EXPECT_TRUE(locationOfDevice(vigor(), deviceAt(vigor(), "M0")).isEmpty());
    EXPECT_TRUE(locationOfDevice(cpm1(), deviceAt(cpm1(), "200.00")).isEmpty());
}

TEST(PlcopenExport, EveryExampleValidatesAgainstTheSchema) {
    if (QStandardPaths::findExecutable(QStringLiteral("xmllint")).isEmpty())
        FAIL() << "xmllint is missing: scripts/install-deps.sh installs libxml2-utils";
    const QString schema = schemaPath();
    ASSERT_TRUE(QFile::exists(schema)) << "no PLCopen schema at " << schema.toStdString();
    QTemporaryDir dir;
    QStringList files;
    for (const QString &path : exampleProjects()) {
        ProjectError error;
        const auto p = loadProject(path, &error);
        ASSERT_TRUE(p) << error.message.toStdString();
        const QString out =
            dir.filePath(QFileInfo(path).completeBaseName() + QStringLiteral(".xml"));
        QFile f(out);
        ASSERT_TRUE(f.open(QIODevice::WriteOnly));
        f.write(exportPlcopen(*p, QFileInfo(path).completeBaseName()).xml);
        files << out;
    }
    ASSERT_GE(files.size(), 12);
    files << QStringLiteral(RUNG_TEST_DATA_DIR "/plcopen/pump.xml"); // the import tests' input
    QProcess xmllint;
    xmllint.start(QStringLiteral("xmllint"),
                  QStringList{QStringLiteral("--noout"), QStringLiteral("--schema"), schema} +
                      files);
    ASSERT_TRUE(xmllint.waitForFinished(120000));
    EXPECT_EQ(xmllint.exitCode(), 0) << xmllint.readAllStandardError().toStdString();
}

// Export then import gives the same program (the comparison of docs/version-control.md finds
// no difference), symbols, set values and watch lists included.
TEST(PlcopenRoundTrip, EveryExampleComesBackTheSame) {
    for (const QString &path : exampleProjects()) {
        ProjectError error;
        const auto p = loadProject(path, &error);
        ASSERT_TRUE(p) << error.message.toStdString();
        const PlcopenExport out = exportPlcopen(*p, QStringLiteral("x"));
        const PlcopenImport back = importPlcopen(out.xml, *p->target, p->target->model(p->model));
        ASSERT_TRUE(back.complete()) << path.toStdString() << "\n" << issues(back);
        const Comparison c = compareProjects(*p, *back.project);
        EXPECT_TRUE(c.equal()) << path.toStdString() << "\n"
                               << comparisonText(c, {}, {}).toStdString();
        EXPECT_EQ(back.project->model, p->model);
        EXPECT_EQ(back.project->symbols, p->symbols) << path.toStdString();
    }
}

TEST(PlcopenRoundTrip, RandomProgramsOfEveryTargetComeBackTheSame) {
    for (const Family family : Target::families()) {
        const Target &t = Target::get(family);
        for (std::uint64_t seed = 1; seed <= 40; ++seed) {
            rung::testing::RandomProgramOptions options;
            options.rungs = 6;
            options.extended = true;
            const QString text = rung::testing::randomProgram(t, seed, options);
            const ParseResult parsed = parseInstructionList(t, text);
            ASSERT_TRUE(parsed.ok()) << text.toStdString();
            const ToLadderResult ladder = listToLadder(parsed.list);
            if (!ladder.ok())
                continue;
            Project p;
            p.target = &t;
            p.model = t.defaultModel().name;
            p.program = ladder.ladder;
            const PlcopenImport back =
                importPlcopen(exportPlcopen(p, QStringLiteral("r")).xml, t, nullptr);
            ASSERT_TRUE(back.complete()) << t.id.toStdString() << " seed " << seed << "\n"
                                         << text.toStdString() << issues(back);
            const Comparison c = compareProjects(p, *back.project);
            EXPECT_TRUE(c.equal()) << t.id.toStdString() << " seed " << seed << "\n"
                                   << text.toStdString() << comparisonText(c, {}, {}).toStdString();
        }
    }
}

namespace {

// tests/data/plcopen/pump.xml: an LD program laid out as IEC tools write one (one left rail
// for all rungs, positions, executionOrderId 0, located variables, a TON instance, a
// comparison with EN, literals in IEC form), written for these tests after the schema, not
// taken from another tool.
QByteArray foreignFile() {
    QFile f(QStringLiteral(RUNG_TEST_DATA_DIR "/plcopen/pump.xml"));
    EXPECT_TRUE(f.open(QIODevice::ReadOnly));
    return f.readAll();
}
const QByteArray kForeign = foreignFile();

} // namespace

// Located variables map by the rule; the others (a TON instance, a plain BOOL) need a device:
// proposed free ones, given by a mapping file.
TEST(PlcopenImport, AFileLaidOutAsOtherToolsWriteOneImportsWithAMapping) {
    const PlcopenImport first = importPlcopen(kForeign, vigor(), nullptr);
    EXPECT_FALSE(first.complete());
    // What waits for those devices is not listed as not importable besides.
    EXPECT_TRUE(first.issues.empty()) << issues(first);
    ASSERT_EQ(first.unmapped.size(), 2u) << issues(first);
    EXPECT_EQ(first.unmapped[0].name, QStringLiteral("delay"));
    EXPECT_EQ(first.unmapped[0].type, QStringLiteral("TON"));
    EXPECT_EQ(first.unmapped[0].proposed, QStringLiteral("T0"));
    EXPECT_EQ(first.unmapped[0].line, 23);
    EXPECT_EQ(first.unmapped[1].name, QStringLiteral("latched"));
    EXPECT_EQ(first.unmapped[1].proposed, QStringLiteral("M0"));

    QString error;
    const auto mapping = readDeviceMapping(QStringLiteral("# the pump's devices\n"
                                                          "delay = T0\n  latched=M100  \n"),
                                           &error);
    ASSERT_TRUE(mapping) << error.toStdString();
    const PlcopenImport r = importPlcopen(kForeign, vigor(), nullptr, *mapping);
    ASSERT_TRUE(r.complete()) << issues(r);
    EXPECT_EQ(listing(*r.project), QStringLiteral("LD X0\nOR Y0\nANI X1\nOUT Y0\n"
                                                  "LD Y0\nTMR T0 K50\n"
                                                  "LD T0\nSET M100\n"
                                                  "LD M100\nAND> D10 K100\nOUT Y1\n"
                                                  "END\n"));
    // The variables' names and documentation are the devices' symbols.
    const Symbol *start = r.project->symbol(deviceAt(vigor(), "X0"));
    ASSERT_TRUE(start);
    EXPECT_EQ(start->name, QStringLiteral("start"));
    EXPECT_EQ(start->comment, QStringLiteral("green button"));
    ASSERT_TRUE(r.project->symbol(deviceAt(vigor(), "T0")));
    EXPECT_EQ(r.project->symbol(deviceAt(vigor(), "T0"))->name, QStringLiteral("delay"));
}

// The same file for the CPM1: its devices by the located rule, its timer's units (BCD set
// value, 100 ms), and the comparison it has no contact for listed, the rest imported.
TEST(PlcopenImport, TheSameFileForAnotherTargetTakesItsDevicesAndTimerUnits) {
    QString error;
    const auto mapping =
        readDeviceMapping(QStringLiteral("delay = TIM 001\nlatched = HR00.00\n"), &error);
    ASSERT_TRUE(mapping);
    const PlcopenImport r = importPlcopen(kForeign, cpm1(), nullptr, *mapping);
    ASSERT_TRUE(r.project);
    EXPECT_FALSE(r.complete());
    ASSERT_EQ(r.issues.size(), 3u) << issues(r);
    EXPECT_EQ(r.issues[0].line, 94);
    EXPECT_EQ(r.issues[0].element, QStringLiteral("block GT"));
    EXPECT_EQ(r.issues[0].message, QStringLiteral("CPM1 has no compare contact >"));
    EXPECT_EQ(r.issues[1].message,
              QStringLiteral("its power goes to block GT (line 94), which is not imported"));
    EXPECT_EQ(r.issues[2].element, QStringLiteral("coil alarm"));
    EXPECT_EQ(r.issues[2].message,
              QStringLiteral("its power comes from block GT (line 94), which is not imported"));
    EXPECT_EQ(listing(*r.project),
              QStringLiteral("LD 000.00\nOR 010.00\nAND NOT 000.01\nOUT 010.00\n"
                             "LD 010.00\nTIM 001 #0050\n"
                             "LD TIM 001\nSET HR00.00\n"
                             "END(01)\n"));
}

// Every element the target cannot take is listed with its line: a block without an
// equivalent, an IEC jump, a body in ST, a function block; nothing is dropped silently.
TEST(PlcopenImport, WhatCannotBeImportedIsListedByElementAndLine) {
    QByteArray xml(kForeign);
    xml.replace("<variable name=\"latched\">",
                "<variable name=\"sel\"><type><INT/></type></variable>\n"
                "            <variable name=\"latched\">");
    // A SEL block fed by the start contact, and a jump.
    xml.replace(
        "          </LD>",
        "            <block localId=\"20\" typeName=\"SEL\" height=\"40\" width=\"40\">\n"
        "              <position x=\"200\" y=\"300\"/>\n"
        "              <inputVariables>\n"
        "                <variable formalParameter=\"G\"><connectionPointIn><connection "
        "refLocalId=\"21\"/></connectionPointIn></variable>\n"
        "              </inputVariables>\n"
        "              <inOutVariables/><outputVariables/>\n"
        "            </block>\n"
        "            <contact localId=\"21\" height=\"15\" width=\"21\">\n"
        "              <position x=\"50\" y=\"300\"/>\n"
        "              <connectionPointIn><connection refLocalId=\"1\"/></connectionPointIn>\n"
        "              <variable>start</variable>\n"
        "            </contact>\n"
        "            <jump localId=\"22\" label=\"done\" height=\"10\" width=\"10\">\n"
        "              <position x=\"300\" y=\"340\"/>\n"
        "              <connectionPointIn><connection refLocalId=\"1\"/></connectionPointIn>\n"
        "            </jump>\n"
        "          </LD>");
    xml.replace("    </pous>",
                "      <pou name=\"helper\" pouType=\"functionBlock\"><body><ST><xhtml:p>x := "
                "1;</xhtml:p></ST></body></pou>\n"
                "    </pous>");
    QString error;
    const auto mapping = readDeviceMapping(QStringLiteral("delay = T0\nlatched = M100\n"), &error);
    const PlcopenImport r = importPlcopen(xml, vigor(), nullptr, *mapping);
    EXPECT_FALSE(r.complete());
    ASSERT_TRUE(r.project); // the rest is there, for --force
    const std::string all = issues(r);
    auto has = [&](const char *element, const char *text) {
        return std::any_of(r.issues.begin(), r.issues.end(), [&](const ImportIssue &i) {
            return i.element == QLatin1String(element) && i.message.contains(QLatin1String(text)) &&
                   i.line > 0;
        });
    };
    EXPECT_TRUE(has("block SEL", "this block is not imported")) << all;
    EXPECT_TRUE(has("contact start", "its power goes to block SEL")) << all;
    EXPECT_TRUE(has("jump", "IEC jumps, labels and returns are not imported")) << all;
    EXPECT_TRUE(has("pou helper", "a functionBlock is not imported")) << all;
    EXPECT_TRUE(has("variable sel", "the ladder does not use it")) << all;
    const auto sel = std::find_if(r.issues.begin(), r.issues.end(), [](const ImportIssue &i) {
        return i.element == QLatin1String("block SEL");
    });
    EXPECT_EQ(xml.left(xml.indexOf("typeName=\"SEL\"")).count('\n') + 1, sel->line);
}

TEST(PlcopenImport, BadFilesSayWhatAndWhere) {
    PlcopenImport r = importPlcopen("<project><types>", vigor(), nullptr);
    ASSERT_EQ(r.issues.size(), 1u);
    EXPECT_TRUE(r.issues[0].message.contains(QStringLiteral("not well-formed XML")))
        << r.issues[0].message.toStdString();
    EXPECT_FALSE(r.project);
    r = importPlcopen("<?xml version=\"1.0\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\"/>",
                      vigor(), nullptr);
    ASSERT_EQ(r.issues.size(), 1u);
    EXPECT_EQ(r.issues[0].line, 2);
    EXPECT_TRUE(
        r.issues[0].message.startsWith(QStringLiteral("not a PLCopen TC6 XML 2.01 project")));
    QString error;
    EXPECT_FALSE(readDeviceMapping(QStringLiteral("delay = T0\nlatched\n"), &error));
    EXPECT_EQ(error, QStringLiteral("line 2: \"latched\" is not NAME = DEVICE"));
    // A mapping to a device the target does not have is said, not taken.
    const auto bad = readDeviceMapping(QStringLiteral("delay = T0\nlatched = X8\n"), &error);
    r = importPlcopen(kForeign, vigor(), nullptr, *bad);
    EXPECT_TRUE(std::any_of(r.issues.begin(), r.issues.end(), [](const ImportIssue &i) {
        return i.message.startsWith(QStringLiteral("the mapping file gives X8:"));
    })) << issues(r);
}

// Beremiz writes a configuration's constants as globalVars constant="true" with an initial
// value: the ladder's use of one is that literal. Of two programs, the one the configuration's
// task runs is the program, though it comes second.
TEST(PlcopenImport, GlobalConstantsAreLiteralsAndTheTasksProgramIsTheProgram) {
    QByteArray xml(kForeign);
    ASSERT_TRUE(xml.contains("<expression>100</expression>"));
    xml.replace("<expression>100</expression>", "<expression>limit</expression>");
    xml.replace("        </resource>\n",
                "        </resource>\n"
                "        <globalVars constant=\"true\"><variable name=\"limit\"><type><INT/></type>"
                "<initialValue><simpleValue value=\"100\"/></initialValue></variable>"
                "</globalVars>\n");
    xml.replace("      <pou name=\"main\" pouType=\"program\">",
                "      <pou name=\"helper\" pouType=\"program\"><body><ST><xhtml:p>x := 1;"
                "</xhtml:p></ST></body></pou>\n"
                "      <pou name=\"main\" pouType=\"program\">");
    QString error;
    const auto mapping = readDeviceMapping(QStringLiteral("delay = T0\nlatched = M100\n"), &error);
    ASSERT_TRUE(mapping);
    const PlcopenImport r = importPlcopen(xml, vigor(), nullptr, *mapping);
    ASSERT_TRUE(r.project);
    EXPECT_EQ(issues(r), "14: pou helper: a second program is not imported: a project is one "
                         "ladder (the program main is)\n");
    EXPECT_EQ(listing(*r.project), QStringLiteral("LD X0\nOR Y0\nANI X1\nOUT Y0\n"
                                                  "LD Y0\nTMR T0 K50\n"
                                                  "LD T0\nSET M100\n"
                                                  "LD M100\nAND> D10 K100\nOUT Y1\n"
                                                  "END\n"));
}
