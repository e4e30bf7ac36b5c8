// `rungstudio-cli terminal`: raw bytes to a PLC and what it answers, against the virtual PLC
// on a real pseudo-terminal, with the Computer Link examples of the Vigor M/VB/VH
// communication manual, B-5-3, verbatim.

#include "app/cli/cli_terminal.h"
#include "tests/cli/virtual_plc_fixture.h"

#include <gtest/gtest.h>

namespace rung::test {
namespace {

constexpr const char *kTerminalProgram = "; target: vigor\nLD M9000\nOUT Y0\nEND\n";

struct TerminalRun {
    int code = -1;
    QString out, err;
};

TerminalRun terminal(const QStringList &args, QString input) {
    QTextStream in(&input, QIODevice::ReadOnly);
    TerminalRun r;
    QTextStream out(&r.out);
    QTextStream err(&r.err);
    r.code = app::runTerminalCommand(args, in, out, err);
    out.flush();
    err.flush();
    return r;
}

// The hex of every line with the given direction, in order.
QStringList hexOf(const QString &output, const QString &direction) {
    QStringList found;
    for (const QString &line : output.split(u'\n', Qt::SkipEmptyParts))
        if (line.section(u' ', 1, 1) == direction)
            found << line.section(u' ', 2).section(QLatin1String("  |"), 0, 0);
    return found;
}

struct TerminalOnVirtualPlc : ::testing::Test {
    VirtualPlcUnderTest plc{
        kTerminalProgram, {model::ProtocolId::VigorLink, comms::modbus::Framing::Rtu, 0}, false};
    QStringList args() const {
        return {QStringLiteral("--port"), plc.path, QStringLiteral("--wait"),
                QStringLiteral("600")};
    }
};

TEST_F(TerminalOnVirtualPlc, HexLinesAreSentAndTheAnswersPrintedAsTheyCame) {
    ASSERT_TRUE(plc.ready());
    // The manual's 70H example (M10 ON) and then its first 51H example, the read of M8..M23
    // (Vigor M/VB/VH communication manual, B-5-3).
    const TerminalRun r =
        terminal(args(), QStringLiteral("02 30 30 37 30 30 34 30 41 03 39 46\n"
                                        "02 30 30 35 31 30 30 38 31 30 32 03 46 34\n"));
    ASSERT_EQ(r.code, 0) << r.err.toStdString();
    EXPECT_EQ(hexOf(r.out, QStringLiteral("PC>PLC")),
              QStringList({QStringLiteral("02 30 30 37 30 30 34 30 41 03 39 46"),
                           QStringLiteral("02 30 30 35 31 30 30 38 31 30 32 03 46 34")}));
    const QString answers = hexOf(r.out, QStringLiteral("PLC>PC")).join(u' ');
    // The ACK of vector 5, then M8..M15 = 04h (M10 is ON now) and M16..M23 = 00h.
    EXPECT_TRUE(answers.startsWith(QStringLiteral("06 30 30 37 30 30 30 03 32 41 "
                                                  "06 30 30 35 31 30 30 30 34 30 30 03")))
        << r.out.toStdString();
}

TEST_F(TerminalOnVirtualPlc, ACaptureReplaysItsPcSideAndSkipsThePlcs) {
    ASSERT_TRUE(plc.ready());
    const TerminalRun r = terminal(
        args(), QStringLiteral(
                    "# rungstudio-cli record: PC /dev/pts/5, PLC /dev/ttyUSB0, 19200 7E1\n"
                    "12:30:01.234567 PC>PLC 02 30 30 37 30 30 34 30 41 03 39 46  |.0070040A.9F|\n"
                    "12:30:01.241012 PLC>PC 06 30 30 37 30 30 30 03 32 41  |.007000.2A|\n"
                    "\n"
                    "\"\\x02"
                    "00710464\\x03"
                    "99\"\n"));
    ASSERT_EQ(r.code, 0) << r.err.toStdString();
    // The quoted text is vector 6 (M100 OFF) written as characters.
    EXPECT_EQ(hexOf(r.out, QStringLiteral("PC>PLC")),
              QStringList({QStringLiteral("02 30 30 37 30 30 34 30 41 03 39 46"),
                           QStringLiteral("02 30 30 37 31 30 34 36 34 03 39 39")}));
    EXPECT_EQ(hexOf(r.out, QStringLiteral("PLC>PC")).join(u' '),
              QStringLiteral("06 30 30 37 30 30 30 03 32 41 06 30 30 37 31 30 30 03 32 42"));
}

TEST(CliTerminal, ALineThatIsNoBytesIsNamedWithItsNumberAndNothingMoreIsSent) {
    VirtualPlcUnderTest plc(kTerminalProgram,
                            {model::ProtocolId::VigorLink, comms::modbus::Framing::Rtu, 0}, false);
    ASSERT_TRUE(plc.ready());
    const TerminalRun r = terminal(
        {QStringLiteral("--port"), plc.path, QStringLiteral("--wait"), QStringLiteral("50")},
        QStringLiteral("02 30\nLD X0\n02 30\n"));
    EXPECT_EQ(r.code, 2);
    EXPECT_TRUE(r.err.contains(QLatin1String("line 2: \"LD X0\""))) << r.err.toStdString();
    EXPECT_EQ(hexOf(r.out, QStringLiteral("PC>PLC")).size(), 1);
    EXPECT_EQ(terminal({QStringLiteral("--port"), plc.path}, QStringLiteral("\"\\q\"\n")).code, 2);
    EXPECT_EQ(terminal({QStringLiteral("--port"), plc.path}, QStringLiteral("0 2\n")).code, 0);
    EXPECT_EQ(terminal({QStringLiteral("--port"), plc.path}, QStringLiteral("023\n")).code, 2);
}

TEST(CliTerminal, APortThatCannotBeOpenedIsNamed) {
    const QString missing = QStringLiteral("/dev/ttyRUNG-no-such-port");
    const TerminalRun r = terminal({QStringLiteral("--port"), missing}, QString());
    EXPECT_EQ(r.code, 2);
    EXPECT_TRUE(r.err.contains(missing)) << r.err.toStdString();
    EXPECT_EQ(terminal({}, QString()).code, 2);
    EXPECT_EQ(
        terminal({QStringLiteral("--port"), missing, QStringLiteral("--wait"), QStringLiteral("0")},
                 QString())
            .code,
        2);
}

} // namespace
} // namespace rung::test
