// `check`, `convert` and `simulate` agree on every golden program (issue 14: "check, convert
// and simulate agree on every operand"): what the simulator runs, check passes without an
// error, and the ladder the converter draws lists back to the same program.

#include "model/checks/checks.h"
#include "model/convert/convert.h"
#include "model/listing/il.h"
#include "simulator/compiler.h"

#include <QDir>
#include <QFile>
#include <QRegularExpression>

#include <gtest/gtest.h>

using namespace rung;

namespace {

QString goldenDir() {
    return QStringLiteral(RUNG_TEST_DATA_DIR "/sim");
}

std::vector<std::string> programs() {
    std::vector<std::string> names;
    for (const QString &il : QDir(goldenDir()).entryList({QStringLiteral("*.il")}, QDir::Files))
        names.push_back(QFileInfo(il).completeBaseName().toStdString());
    return names;
}

class GoldenAgreement : public ::testing::TestWithParam<std::string> {};

} // namespace

TEST_P(GoldenAgreement, CheckConvertAndSimulateTakeTheSameProgram) {
    QFile f(goldenDir() + QLatin1Char('/') + QString::fromStdString(GetParam()) +
            QStringLiteral(".il"));
    ASSERT_TRUE(f.open(QIODevice::ReadOnly | QIODevice::Text));
    const QString text = QString::fromUtf8(f.readAll());
    static const QRegularExpression targetRe(QStringLiteral("^; target: (\\w+)"));
    const model::Target *target = model::Target::byId(targetRe.match(text).captured(1));
    ASSERT_NE(target, nullptr);
    const model::ParseResult parsed = model::parseInstructionList(*target, text);
    ASSERT_TRUE(parsed.ok());
    ASSERT_TRUE(simulator::compileProgram(parsed.list).ok());
    for (const model::Diagnostic &d : model::checkList(parsed.list))
        EXPECT_NE(d.severity, model::Severity::Error)
            << d.location.line << ": " << d.message.toStdString() << " [" << d.code.toStdString()
            << "]";
    const model::ToLadderResult ladder = model::listToLadder(parsed.list);
    ASSERT_TRUE(ladder.ok());
    const model::ToListingResult back = model::ladderToList(ladder.ladder);
    ASSERT_TRUE(back.ok());
    model::PrintOptions bare;
    bare.comments = false;
    EXPECT_EQ(model::printInstructionList(back.list, bare).toStdString(),
              model::printInstructionList(parsed.list, bare).toStdString());
}

INSTANTIATE_TEST_SUITE_P(Manuals, GoldenAgreement, ::testing::ValuesIn(programs()),
                         [](const ::testing::TestParamInfo<std::string> &info) {
                             return info.param;
                         });
