// A box's operands in the ladder (editor/ladder_painter.cpp): seven operands (the PL110's
// COM / EXP, PL110 manual 4.2.21) wrap onto the lines the box has, between words, instead of
// being cut after the third; only what still does not fit is elided, at the end.

#include "editor/ladder_painter.h"

#include <QFont>
#include <QFontMetricsF>

#include <gtest/gtest.h>

using rung::editor::LadderPainter;

TEST(LadderBoxText, OperandsWrapBetweenWordsOntoTheLinesThereAre) {
    const QFontMetricsF fm{QFont()};
    const QString operands = QStringLiteral("1 READ 1 WORD 10000 V0 10");
    const double width = fm.horizontalAdvance(QStringLiteral("1 READ 1 WORD"));
    const QStringList two = LadderPainter::wrappedLines(operands, fm, width, 3);
    EXPECT_EQ(two, (QStringList{QStringLiteral("1 READ 1 WORD"), QStringLiteral("10000 V0 10")}));
    for (const QString &line : two)
        EXPECT_LE(fm.horizontalAdvance(line), width) << line.toStdString();

    // One line only: the rest elided on it, never silently dropped.
    const QStringList one = LadderPainter::wrappedLines(operands, fm, width, 1);
    ASSERT_EQ(one.size(), 1);
    EXPECT_TRUE(one.front().startsWith(QStringLiteral("1 READ"))) << one.front().toStdString();
    EXPECT_TRUE(one.front().endsWith(QChar(0x2026))) << one.front().toStdString();

    // Two lines for three lines' worth: the second holds the rest, elided.
    const QString longer = QStringLiteral("2 READWRITE 255 WORD 65535 V100 16");
    const QStringList cut = LadderPainter::wrappedLines(
        longer, fm, fm.horizontalAdvance(QStringLiteral("2 READWRITE")), 2);
    ASSERT_EQ(cut.size(), 2);
    EXPECT_EQ(cut.front(), QStringLiteral("2 READWRITE"));
    EXPECT_TRUE(cut.back().startsWith(QStringLiteral("255 WORD"))) << cut.back().toStdString();
    EXPECT_TRUE(cut.back().endsWith(QChar(0x2026))) << cut.back().toStdString();

    EXPECT_EQ(LadderPainter::wrappedLines(QStringLiteral("K10"), fm, 1000, 2),
              QStringList{QStringLiteral("K10")});
}
