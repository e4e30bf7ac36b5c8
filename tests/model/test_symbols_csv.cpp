// The symbol table as CSV (model/project/symbols_csv.h), read and written without a display.

#include "model/project/symbols_csv.h"
#include "model/target/address.h"
#include "tests/targets.h"

#include <gtest/gtest.h>

using namespace rung::model;

namespace {

Address address(const char *text) {
    return std::get<Address>(parseAddress(rung::testing::vigor(), QString::fromLatin1(text)));
}

} // namespace

TEST(SymbolsCsv, WrittenAndReadBackWithCommasQuotesAndLineBreaks) {
    const std::vector<Symbol> symbols = {
        {address("X0"), QStringLiteral("Start"), QStringLiteral("green, big; left")},
        {address("Y0"), QStringLiteral("Pump \"A\""), QStringLiteral("line one\nline two")},
        {address("M7"), QStringLiteral("Fault"), QString()}};
    const QString text = symbolsToCsv(rung::testing::vigor(), symbols);
    EXPECT_TRUE(text.contains(QStringLiteral("\"Pump \"\"A\"\"\""))) << text.toStdString();
    const SymbolsCsv back = symbolsFromCsv(rung::testing::vigor(), nullptr, text);
    ASSERT_TRUE(back.ok()) << back.error.toStdString();
    EXPECT_EQ(back.symbols, symbols);
}

TEST(SymbolsCsv, ReadsWhatSpreadsheetsWrite) {
    const Target &vigor = rung::testing::vigor();
    // Semicolons, a byte-order mark, CRLF, a header in capitals, blank lines, a device again.
    const QString text =
        QString(QChar(0xfeff)) + QStringLiteral("Device;Name;Comment\r\nX0;Start;\"a; b\"\r\n\r\n"
                                                "Y1;Lamp;\r\nX0;Begin;again\r\n");
    const SymbolsCsv csv = symbolsFromCsv(vigor, nullptr, text);
    ASSERT_TRUE(csv.ok()) << csv.error.toStdString();
    ASSERT_EQ(csv.symbols.size(), 2u);
    EXPECT_EQ(csv.symbols[0].name, QStringLiteral("Begin")); // the later row wins
    EXPECT_EQ(csv.symbols[0].comment, QStringLiteral("again"));
    EXPECT_EQ(csv.symbols[1].address, address("Y1"));
    // A bad device is reported on the line where its record starts.
    const SymbolsCsv bad =
        symbolsFromCsv(vigor, nullptr, QStringLiteral("X0,A,\"two\nlines\"\nX9,B,\n"));
    EXPECT_FALSE(bad.ok());
    EXPECT_EQ(bad.errorLine, 3);
    EXPECT_EQ(bad.error, QStringLiteral("X9: X is numbered in octal"));
    EXPECT_TRUE(bad.symbols.empty());
}
