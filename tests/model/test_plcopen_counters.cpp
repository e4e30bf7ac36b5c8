// Counters as IEC 61131-3 CTU / CTD / CTUD (docs/plcopen.md "Counters"): every target's counters
// written as the IEC block that counts alike, validated and read back the same; the same files
// without Rung Studio's notes (as another tool keeps them) read as the target's counters; IEC
// counters the target cannot take listed, and what it does otherwise noted.

#include "model/compare/compare.h"
#include "model/convert/convert.h"
#include "model/exchange/plcopen.h"
#include "model/exchange/plcopen_xml.h"

#include "tests/model/plcopen_test_util.h"
#include "tests/targets.h"

#include <QRegularExpression>
#include <QTemporaryDir>

#include <gtest/gtest.h>

using namespace rung::model;
using rung::testing::cpm1;
using rung::testing::deviceAt;
using rung::testing::issues;
using rung::testing::listing;
using rung::testing::pl110;
using rung::testing::schemaErrors;
using rung::testing::vigor;
using rung::testing::vpc;

namespace {

Project counterProject(const Target &t, const char *text) {
    const ParseResult parsed = parseInstructionList(t, QString::fromLatin1(text));
    EXPECT_TRUE(parsed.ok()) << text;
    const ToLadderResult ladder = listToLadder(parsed.list);
    EXPECT_TRUE(ladder.ok()) << text;
    Project p;
    p.target = &t;
    p.model = t.defaultModel().name;
    p.program = ladder.ladder;
    return p;
}

// Each target's counters, with their resets where they stand, set values in words and
// counters no IEC block does alike.
const char *const kVigor = "LD X0\nRST C1\n"                      // an RST before its counter
                           "LD X1\nCNT C1 K5\n"                   // CTU C1
                           "LD X2\nRST C1\nOUT Y0\n"              // a second RST, in a rung of two
                           "LD C1\nOUT Y1\n"                      // the bit: C1.Q
                           "LD X3\nCNT C200 K30000\n"             // 32-bit: CTU_DINT
                           "LD X4\nCNT C2 D0\n"                   // PV from a word
                           "LD X5\nRST C2\n"                      //
                           "LD>= C1 K3\nOUT Y2\n"                 // the value: C1.CV
                           "LD X6\nMOV C1 D10\nEND\n";            //
const char *const kCpm1 = "LD 000.00\nLD 000.01\nCNT 001 #0010\n" // CTD
                          "LD 000.02\nLD 000.03\nLD 000.04\nCNTR(12) 002 #0005\n" // wraps
                          "LD 000.05\nLD 000.06\nCNT 003 DM 0001\n"               // BCD in a word
                          "LD CNT 001\nOUT 010.00\nEND(01)\n";
const char *const kPl110 = "LD I1\nLD I2\nLD I3\nMUP C1 5\n"    // CTUD, R the reset
                           "LD I4\nLD I5\nLD I6\nMDOWN C2 V3\n" // CTUD, LD the reset
                           "LD C1\nOUT Q1\nLD C2\nOUT Q2\nEND\n";
const char *const kVpc = "LD i00\nLD i01\nCNT05\n" // counts down: CTD
                         "LD i02\nLD i03\nCNT20\n" // counts up: CTU
                         "LD c05\nOUT o00\nEND\n";

std::vector<Project> counterProjects() {
    std::vector<Project> out{counterProject(vigor(), kVigor), counterProject(cpm1(), kCpm1),
                             counterProject(pl110(), kPl110), counterProject(vpc(), kVpc)};
    // The VPC keeps its counters' set values in the PLC (VPC user's manual, III).
    out.back().setValues[deviceAt(vpc(), "c05")] = 10;
    out.back().setValues[deviceAt(vpc(), "c20")] = 7;
    return out;
}

// The file as another tool keeps it that reads Rung Studio's notes as unknown data: without
// them.
QByteArray withoutOurNotes(const QByteArray &xml) {
    QString text = QString::fromUtf8(xml);
    text.remove(QRegularExpression(QStringLiteral("<addData>.*?</addData>"),
                                   QRegularExpression::DotMatchesEverythingOption));
    return text.toUtf8();
}

// The LD body's elements of an exported file by localId, and the one with this attribute.
struct Body {
    std::unique_ptr<XmlNode> root;
    std::vector<const XmlNode *> elements;
    explicit Body(const QByteArray &xml) {
        QString error;
        root = readXmlTree(xml, &error);
        EXPECT_TRUE(root) << error.toStdString();
        const XmlNode *ld =
            root->child("types")->child("pous")->child("pou")->child("body")->child("LD");
        for (const XmlNode &n : ld->children)
            elements.push_back(&n);
    }
    const XmlNode *byId(const QString &id) const {
        for (const XmlNode *n : elements)
            if (n->attribute("localId") == id)
                return n;
        return nullptr;
    }
    const XmlNode *with(const char *attribute, const QString &value) const {
        for (const XmlNode *n : elements)
            if (n->attribute(attribute) == value)
                return n;
        return nullptr;
    }
    // What an input of a block is connected to: each source's variable, expression or name.
    QStringList sources(const XmlNode &block, const char *formal) const {
        QStringList out;
        for (const XmlNode *v : block.child("inputVariables")->all("variable"))
            if (v->attribute("formalParameter") == QLatin1String(formal))
                for (const XmlNode *c : v->child("connectionPointIn")->all("connection")) {
                    const XmlNode *src = byId(c->attribute("refLocalId"));
                    if (!src)
                        out << QStringLiteral("?");
                    else if (src->child("variable"))
                        out << src->child("variable")->text.trimmed();
                    else if (src->child("expression"))
                        out << src->child("expression")->text.trimmed();
                    else
                        out << src->name + QLatin1Char(' ') + src->attribute("name");
                }
        return out;
    }
    QStringList outputs(const XmlNode &block) const {
        QStringList out;
        for (const XmlNode *v : block.child("outputVariables")->all("variable"))
            out << v->attribute("formalParameter");
        return out;
    }
};

} // namespace

// Every target's counters come back the same, through files that validate against the schema.
TEST(PlcopenCounters, EveryTargetsCountersComeBackTheSame) {
    QTemporaryDir dir;
    QStringList files;
    for (const Project &p : counterProjects()) {
        const PlcopenExport out = exportPlcopen(p, QStringLiteral("counters"));
        const QString path = dir.filePath(p.target->id + QStringLiteral(".xml"));
        QFile f(path);
        ASSERT_TRUE(f.open(QIODevice::WriteOnly));
        f.write(out.xml);
        files << path;
        const PlcopenImport back = importPlcopen(out.xml, *p.target, nullptr);
        ASSERT_TRUE(back.complete()) << p.target->id.toStdString() << "\n" << issues(back);
        const Comparison c = compareProjects(p, *back.project);
        EXPECT_TRUE(c.equal()) << p.target->id.toStdString() << "\n"
                               << comparisonText(c, {}, {}).toStdString();
        EXPECT_TRUE(back.notes.isEmpty()) << back.notes.join('\n').toStdString();
    }
    EXPECT_EQ(schemaErrors(files), "");
}

// Vigor CNT is a CTU: CU its input, R every RST of the counter through a connector at the
// RST's place and a continuation at the block, PV the set value (a word's variable), Q its
// bit, CV its value; a 32-bit counter a CTU_DINT.
TEST(PlcopenCounters, VigorCountersAreCtuWithTheirResetsWiredToR) {
    const PlcopenExport out = exportPlcopen(counterProject(vigor(), kVigor), QStringLiteral("c"));
    const Body body(out.xml);
    const XmlNode *c1 = body.with("instanceName", QStringLiteral("C1"));
    ASSERT_TRUE(c1);
    EXPECT_EQ(c1->attribute("typeName"), QStringLiteral("CTU"));
    EXPECT_EQ(body.sources(*c1, "CU"), QStringList{QStringLiteral("X1")});
    EXPECT_EQ(body.sources(*c1, "R"), QStringList({QStringLiteral("continuation RESET_C1"),
                                                   QStringLiteral("continuation RESET_C1_2")}));
    EXPECT_EQ(body.sources(*c1, "PV"), QStringList{QStringLiteral("5")});
    EXPECT_EQ(body.outputs(*c1), QStringList({QStringLiteral("Q"), QStringLiteral("CV")}));
    // Each connector stands where its RST stood, fed by that rung's contact.
    for (const auto &[name, contact] : {std::pair{"RESET_C1", "X0"}, {"RESET_C1_2", "X2"}}) {
        const XmlNode *k = body.with("name", QString::fromLatin1(name));
        ASSERT_TRUE(k && k->name == QLatin1String("connector")) << name;
        const XmlNode *src =
            body.byId(k->child("connectionPointIn")->child("connection")->attribute("refLocalId"));
        ASSERT_TRUE(src);
        EXPECT_EQ(src->child("variable")->text, QLatin1String(contact));
    }
    const XmlNode *first = body.with("name", QStringLiteral("RESET_C1"));
    EXPECT_LT(first->line, c1->line); // the RST before the counter stays before it
    const XmlNode *c200 = body.with("instanceName", QStringLiteral("C200"));
    ASSERT_TRUE(c200);
    EXPECT_EQ(c200->attribute("typeName"), QStringLiteral("CTU_DINT"));
    EXPECT_TRUE(body.sources(*c200, "R").isEmpty()); // never reset: R left FALSE
    const XmlNode *c2 = body.with("instanceName", QStringLiteral("C2"));
    ASSERT_TRUE(c2);
    EXPECT_EQ(body.sources(*c2, "PV"), QStringList{QStringLiteral("D0")});
    // The bit and the value as IEC tools name them.
    EXPECT_TRUE(out.xml.contains("<variable>C1.Q</variable>"));
    const XmlNode *ge = body.with("typeName", QStringLiteral("GE"));
    ASSERT_TRUE(ge);
    EXPECT_EQ(body.sources(*ge, "IN1"), QStringList{QStringLiteral("C1.CV")});
    const XmlNode *move = body.with("typeName", QStringLiteral("MOVE"));
    ASSERT_TRUE(move);
    EXPECT_EQ(body.sources(*move, "IN"), QStringList{QStringLiteral("C1.CV")});
    EXPECT_TRUE(out.xml.contains("<derived name=\"CTU\"/>"));
    EXPECT_EQ(out.notes,
              QStringList{QStringLiteral(
                  "CNT is written as an IEC CTU: Vigor's CNT stops counting at its set value, "
                  "where CV counts on past PV (Q is the same); its reset is an RST, which acts "
                  "where it stands in the program, not when the counter runs as R does")});
}

// CPM1 CNT counts down with a reset input (Omron CPM1 guide, CNT): a CTD, LD its reset. CNTR(12)
// wraps around and a set value in a channel is BCD: blocks of the CPM1's own, saying why.
// PL110 MUP and MDOWN are CTUDs (PL110 manual 4.2.5), the input they lack FALSE, their bit QU /
// QD. VPC CNT00..15 count down, CNT16..31 up (VPC user's manual, III).
TEST(PlcopenCounters, DownAndUpDownCountersAreCtdAndCtud) {
    const std::vector<Project> projects = counterProjects();
    const PlcopenExport omron = exportPlcopen(projects[1], QStringLiteral("c"));
    Body body(omron.xml);
    const XmlNode *cnt = body.with("instanceName", QStringLiteral("CNT001"));
    ASSERT_TRUE(cnt);
    EXPECT_EQ(cnt->attribute("typeName"), QStringLiteral("CTD"));
    EXPECT_EQ(body.sources(*cnt, "CD"), QStringList{QStringLiteral("IN000_00")});
    EXPECT_EQ(body.sources(*cnt, "LD"), QStringList{QStringLiteral("IN000_01")});
    EXPECT_EQ(body.sources(*cnt, "PV"), QStringList{QStringLiteral("10")});
    EXPECT_TRUE(body.with("typeName", QStringLiteral("CNTR")));
    EXPECT_FALSE(body.with("instanceName", QStringLiteral("CNT003"))); // a block of its own
    EXPECT_EQ(omron.notes,
              QStringList({QStringLiteral("CNT is written as a block of CPM1's own (CPM1 reads a "
                                          "set value in a word as BCD digits, where PV is a "
                                          "number): other tools read the file but do not know "
                                          "this block"),
                           QStringLiteral("CNTR is written as a block of CPM1's own (CPM1's "
                                          "CNTR(12) wraps around at its limits, where IEC's CTUD "
                                          "stops): other tools read the file but do not know "
                                          "this block"),
                           QStringLiteral("CNT is written as an IEC CTD: CPM1's CNT stops "
                                          "counting at 0, where CV counts on below 0 (Q is the "
                                          "same), and it is OFF until it has counted down, where "
                                          "a CTD is ON until LD first loads PV")}));

    const PlcopenExport pl = exportPlcopen(projects[2], QStringLiteral("c"));
    body = Body(pl.xml);
    const XmlNode *mup = body.with("instanceName", QStringLiteral("C1"));
    const XmlNode *mdown = body.with("instanceName", QStringLiteral("C2"));
    ASSERT_TRUE(mup && mdown);
    EXPECT_EQ(mup->attribute("typeName"), QStringLiteral("CTUD"));
    EXPECT_EQ(body.sources(*mup, "CU"), QStringList{QStringLiteral("I1")});
    EXPECT_EQ(body.sources(*mup, "CD"), QStringList{QStringLiteral("I2")});
    EXPECT_EQ(body.sources(*mup, "R"), QStringList{QStringLiteral("I3")});
    EXPECT_EQ(body.sources(*mup, "LD"), QStringList{QStringLiteral("FALSE")});
    EXPECT_EQ(body.sources(*mdown, "LD"), QStringList{QStringLiteral("I6")});
    EXPECT_EQ(body.sources(*mdown, "R"), QStringList{QStringLiteral("FALSE")});
    EXPECT_EQ(body.sources(*mdown, "PV"), QStringList{QStringLiteral("V3")});
    EXPECT_EQ(body.outputs(*mup),
              QStringList({QStringLiteral("QU"), QStringLiteral("QD"), QStringLiteral("CV")}));
    EXPECT_TRUE(pl.xml.contains("<variable>C1.QU</variable>"));
    EXPECT_TRUE(pl.xml.contains("<variable>C2.QD</variable>"));

    const PlcopenExport v = exportPlcopen(projects[3], QStringLiteral("c"));
    body = Body(v.xml);
    ASSERT_TRUE(body.with("instanceName", QStringLiteral("c05")));
    EXPECT_EQ(body.with("instanceName", QStringLiteral("c05"))->attribute("typeName"),
              QStringLiteral("CTD"));
    EXPECT_EQ(body.sources(*body.with("instanceName", QStringLiteral("c05")), "PV"),
              QStringList{QStringLiteral("10")});
    EXPECT_EQ(body.with("instanceName", QStringLiteral("c20"))->attribute("typeName"),
              QStringLiteral("CTU"));
}

// The same files as another tool keeps them, without Rung Studio's notes: the IEC counters
// read as each target's counters, with the notes of what they do otherwise. A Vigor R is an
// RST right after its counter, the RSTs' conditions OR-ed (as R reads them).
TEST(PlcopenCounters, IecCountersOfAnotherToolReadAsTheTargetsCounters) {
    const std::vector<Project> projects = counterProjects();
    const Project &vigorProject = projects[0];
    PlcopenImport r = importPlcopen(
        withoutOurNotes(exportPlcopen(vigorProject, QStringLiteral("c")).xml), vigor(), nullptr);
    ASSERT_TRUE(r.complete()) << issues(r);
    EXPECT_EQ(listing(*r.project), QStringLiteral("LD X1\nCNT C1 K5\nLD X0\nOR X2\nRST C1\n"
                                                  "LD X2\nOUT Y0\nLD C1\nOUT Y1\n"
                                                  "LD X3\nCNT C200 K30000\n"
                                                  "LD X4\nCNT C2 D0\nLD X5\nRST C2\n"
                                                  "LD>= C1 K3\nOUT Y2\nLD X6\nMOV C1 D10\nEND\n"));
    EXPECT_EQ(r.notes, QStringList{QStringLiteral(
                           "CTU (C1, C200, C2) is imported as Vigor's CNT: Vigor's CNT stops "
                           "counting at its set value, where CV counts on past PV (Q is the "
                           "same); its reset is an RST, which acts where it stands in the program, "
                           "not when the counter runs as R does")});

    r = importPlcopen(withoutOurNotes(exportPlcopen(projects[2], QStringLiteral("c")).xml), pl110(),
                      nullptr);
    ASSERT_TRUE(r.complete()) << issues(r);
    EXPECT_EQ(listing(*r.project), listing(projects[2]));
    EXPECT_EQ(r.notes.size(), 2);

    // The VPC's set value comes back as the counter's, kept in the project.
    r = importPlcopen(withoutOurNotes(exportPlcopen(projects[3], QStringLiteral("c")).xml), vpc(),
                      nullptr);
    ASSERT_TRUE(r.complete()) << issues(r);
    EXPECT_EQ(listing(*r.project), listing(projects[3]));
    EXPECT_EQ(r.project->setValues, projects[3].setValues);
}

namespace {

// A small LD program with one IEC counter of `type`, its inputs from contacts of a, b, c, d
// (in the order given), PV a literal, Q to a coil q and CV to a variable n.
QByteArray counterFile(const char *type, const QStringList &inputs, const char *pv = "4") {
    QString vars;
    const char *names[] = {"a", "b", "c", "d"};
    for (int i = 0; i < inputs.size(); ++i)
        vars += QStringLiteral("<variable name=\"%1\"><type><BOOL/></type></variable>")
                    .arg(QLatin1String(names[i]));
    vars += QStringLiteral("<variable name=\"q\"><type><BOOL/></type></variable>");
    vars += QStringLiteral("<variable name=\"n\"><type><INT/></type></variable>"
                           "<variable name=\"k\"><type><derived name=\"%1\"/></type></variable>")
                .arg(QLatin1String(type));
    QString body = QStringLiteral(
        "<leftPowerRail localId=\"1\" height=\"200\" width=\"3\"><position x=\"0\" y=\"0\"/>"
        "<connectionPointOut formalParameter=\"\"/></leftPowerRail>\n");
    QString pins;
    for (int i = 0; i < inputs.size(); ++i) {
        body += QStringLiteral("<contact localId=\"%1\" height=\"15\" width=\"21\"><position "
                               "x=\"50\" y=\"%2\"/><connectionPointIn><connection "
                               "refLocalId=\"1\"/></connectionPointIn><connectionPointOut/>"
                               "<variable>%3</variable></contact>\n")
                    .arg(10 + i)
                    .arg(20 + 20 * i)
                    .arg(QLatin1String(names[i]));
        pins += QStringLiteral("<variable formalParameter=\"%1\"><connectionPointIn><connection "
                               "refLocalId=\"%2\"/></connectionPointIn></variable>")
                    .arg(inputs[i])
                    .arg(10 + i);
    }
    body += QStringLiteral("<inVariable localId=\"20\" height=\"20\" width=\"40\"><position "
                           "x=\"40\" y=\"100\"/><connectionPointOut/><expression>%1</expression>"
                           "</inVariable>\n")
                .arg(QLatin1String(pv));
    pins += QStringLiteral("<variable formalParameter=\"PV\"><connectionPointIn><connection "
                           "refLocalId=\"20\"/></connectionPointIn></variable>");
    const QString q = QString::fromLatin1(type) == QLatin1String("CTUD") ? QStringLiteral("QU")
                                                                         : QStringLiteral("Q");
    body += QStringLiteral("<block localId=\"30\" typeName=\"%1\" instanceName=\"k\" height=\"80\" "
                           "width=\"60\"><position x=\"150\" y=\"20\"/><inputVariables>%2"
                           "</inputVariables><inOutVariables/><outputVariables><variable "
                           "formalParameter=\"%3\"><connectionPointOut/></variable><variable "
                           "formalParameter=\"CV\"><connectionPointOut/></variable>"
                           "</outputVariables></block>\n")
                .arg(QLatin1String(type), pins, q);
    body += QStringLiteral("<coil localId=\"40\" height=\"15\" width=\"21\"><position x=\"300\" "
                           "y=\"20\"/><connectionPointIn><connection refLocalId=\"30\" "
                           "formalParameter=\"%1\"/></connectionPointIn><connectionPointOut/>"
                           "<variable>q</variable></coil>\n"
                           "<outVariable localId=\"41\" height=\"20\" width=\"40\"><position "
                           "x=\"300\" y=\"60\"/><connectionPointIn><connection refLocalId=\"30\" "
                           "formalParameter=\"CV\"/></connectionPointIn><expression>n"
                           "</expression></outVariable>\n")
                .arg(q);
    return QStringLiteral(
               "<?xml version=\"1.0\"?>\n<project xmlns=\"http://www.plcopen.org/xml/tc6_0201\">"
               "<fileHeader companyName=\"x\" productName=\"x\" productVersion=\"1\" "
               "creationDateTime=\"2024-01-01T00:00:00\"/><contentHeader "
               "name=\"x\"><coordinateInfo>"
               "<fbd><scaling x=\"1\" y=\"1\"/></fbd><ld><scaling x=\"1\" y=\"1\"/></ld><sfc>"
               "<scaling x=\"1\" "
               "y=\"1\"/></sfc></coordinateInfo></contentHeader><types><dataTypes/>"
               "<pous><pou name=\"p\" pouType=\"program\"><interface><localVars>%1</localVars>"
               "</interface><body><LD>\n%2</LD></body></pou></pous></types></project>\n")
        .arg(vars, body)
        .toUtf8();
}

DeviceMapping mapping(const char *text) {
    QString error;
    const auto m = readDeviceMapping(QString::fromLatin1(text), &error);
    EXPECT_TRUE(m) << error.toStdString();
    return m.value_or(DeviceMapping{});
}

} // namespace

// A CTD on the CPM1 is its CNT, CV to a variable its present value made binary (BIN); a CTU
// there counts the other way: imported with a note, CV listed. On the Vigor a CTD is a CNT the
// other way round, its LD an RST.
TEST(PlcopenCounters, EachTargetTakesTheIecCounterItCountsAlikeOrSaysWhy) {
    const QByteArray ctd = counterFile("CTD", {QStringLiteral("CD"), QStringLiteral("LD")});
    PlcopenImport r =
        importPlcopen(ctd, cpm1(), nullptr,
                      mapping("a = 000.00\nb = 000.01\nq = 010.00\nn = DM 0005\nk = CNT 004\n"));
    ASSERT_TRUE(r.complete()) << issues(r);
    EXPECT_EQ(listing(*r.project), QStringLiteral("LD 000.00\nLD 000.01\nCNT 004 #0004\n"
                                                  "LD CNT 004\nOUT 010.00\n"
                                                  "LD 253.13\nBIN(23) CNT 004 DM 0005\nEND(01)\n"));
    ASSERT_EQ(r.notes.size(), 1);
    EXPECT_TRUE(r.notes[0].startsWith(QStringLiteral("CTD (k) is imported as CPM1's CNT: ")));

    const QByteArray ctu = counterFile("CTU", {QStringLiteral("CU"), QStringLiteral("R")});
    r = importPlcopen(ctu, cpm1(), nullptr,
                      mapping("a = 000.00\nb = 000.01\nq = 010.00\nn = DM 0005\nk = CNT 004\n"));
    ASSERT_TRUE(r.project);
    EXPECT_EQ(issues(r), "9: outVariable n: k.CV is not imported: CNT 004 counts the other way, "
                         "its present value is not CV\n");
    EXPECT_EQ(listing(*r.project), QStringLiteral("LD 000.00\nLD 000.01\nCNT 004 #0004\n"
                                                  "LD CNT 004\nOUT 010.00\nEND(01)\n"));
    EXPECT_EQ(r.notes, QStringList{QStringLiteral(
                           "CTU (k) is imported as CPM1's CNT, which counts the other way: its "
                           "bit is CTU's Q once R has been ON, and its present value is not CV")});

    r = importPlcopen(ctd, vigor(), nullptr, mapping("a = X0\nb = X1\nq = Y0\nn = D5\nk = C4\n"));
    ASSERT_TRUE(r.project);
    EXPECT_EQ(issues(r), "9: outVariable n: k.CV is not imported: C4 counts the other way, its "
                         "present value is not CV\n");
    EXPECT_EQ(listing(*r.project),
              QStringLiteral("LD X0\nCNT C4 K4\nLD X1\nRST C4\nLD C4\nOUT Y0\nEND\n"));

    // An R and a CU left open are never ON: the reset input of a two-input counter takes the
    // always-ON contact negated.
    r = importPlcopen(counterFile("CTU", {QStringLiteral("CU")}), vpc(), nullptr,
                      mapping("a = i00\nq = o00\nn = p05\n"));
    ASSERT_EQ(r.unmapped.size(), 1u) << issues(r);
    EXPECT_EQ(r.unmapped[0].proposed, QStringLiteral("c16")); // the first that counts up
    r = importPlcopen(counterFile("CTU", {QStringLiteral("CU")}), vpc(), nullptr,
                      mapping("a = i00\nq = o00\nn = p05\nk = c16\n"));
    ASSERT_TRUE(r.complete()) << issues(r);
    EXPECT_EQ(listing(*r.project), QStringLiteral("LD i00\nLD NOT r88\nCNT16\nLD c16\nOUT o00\n"
                                                  "LD r88\nOUT p05,c16\nEND\n"));
    EXPECT_EQ(r.project->setValues.at(deviceAt(vpc(), "c16")), 4);
}

TEST(PlcopenCounters, CountersNoTargetCounterDoesAlikeAreListed) {
    // Vigor has no up/down counter; a CTUD with both R and LD fits neither of PL110's; CPM1's
    // CNTR wraps around.
    const QByteArray ctud =
        counterFile("CTUD", {QStringLiteral("CU"), QStringLiteral("CD"), QStringLiteral("R")});
    PlcopenImport r = importPlcopen(ctud, vigor(), nullptr,
                                    mapping("a = X0\nb = X1\nc = X2\nq = Y0\nn = D5\nk = C4\n"));
    // What its Q feeds goes with it, and says so; its CV's variable is listed with the block.
    EXPECT_EQ(issues(r), "8: block CTUD: Vigor has no counter that counts as CTUD does on C4\n"
                         "9: coil q: its power comes from block CTUD (line 8), which is not "
                         "imported\n");
    r = importPlcopen(ctud, cpm1(), nullptr,
                      mapping("a = 000.00\nb = 000.01\nc = 000.02\nq = 010.00\nn = DM 0005\n"
                              "k = CNT 004\n"));
    EXPECT_EQ(issues(r), "8: block CTUD: CPM1 has no counter that counts as CTUD does on CNT 004\n"
                         "9: coil q: its power comes from block CTUD (line 8), which is not "
                         "imported\n");
    const QByteArray both = counterFile("CTUD", {QStringLiteral("CU"), QStringLiteral("CD"),
                                                 QStringLiteral("R"), QStringLiteral("LD")});
    r = importPlcopen(both, pl110(), nullptr,
                      mapping("a = I1\nb = I2\nc = I3\nd = I4\nq = Q1\nn = V5\nk = C4\n"));
    EXPECT_EQ(issues(r),
              "9: block CTUD: it uses CD, CU, LD, R together, which no counter of PL110 has\n"
              "10: coil q: its power comes from block CTUD (line 9), which is not imported\n");
    EXPECT_EQ(listing(*r.project), QStringLiteral("END\n")); // the coil and CV went with it
    r = importPlcopen(ctud, pl110(), nullptr,
                      mapping("a = I1\nb = I2\nc = I3\nq = Q1\nn = V5\nk = C4\n"));
    ASSERT_TRUE(r.complete()) << issues(r);
    EXPECT_EQ(listing(*r.project), QStringLiteral("LD I1\nLD I2\nLD I3\nMUP C4 4\nLD C4\nOUT Q1\n"
                                                  "LD SM0.0\nMOV C4 V5\nEND\n"));
}
