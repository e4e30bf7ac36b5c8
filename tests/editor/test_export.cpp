// Export of the ladder (PNG, SVG, PDF = the printout), symbol names in place of addresses,
// and rung comments, through the main window as the menus call them.

#include "app/gui/ladder_export.h"
#include "app/gui/main_window.h"
#include "editor/ladder_view.h"
#include "model/target/address.h"

#include <QDate>
#include <QFile>
#include <QImage>
#include <QLocale>
#include <QProcess>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QUndoStack>

#include "tests/editor/window_fixture.h"

#include <gtest/gtest.h>

using namespace rung;

namespace {

struct ExportFixture : test::WindowFixture {
    QTemporaryDir dir;
    void SetUp() override {
        WindowFixture::SetUp();
        QString listing;
        for (int i = 0; i < 60; ++i) // several printed pages
            listing += QStringLiteral("LD X%1\nOUT Y%1\n").arg(QString::number(i % 8, 8));
        load(listing + QStringLiteral("END\n"));
    }
    bool exportLadder(const QString &path, QString *error) {
        return app::ProgramExport(*window.document(), view->namesFirst()).ladder(path, error);
    }
    QByteArray read(const QString &name) {
        QFile f(dir.filePath(name));
        return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
    }
};

} // namespace

TEST_F(ExportFixture, PngShowsTheWholeLadder) {
    QString error;
    ASSERT_TRUE(exportLadder(dir.filePath(QStringLiteral("ladder.png")), &error))
        << error.toStdString();
    const QImage image(dir.filePath(QStringLiteral("ladder.png")));
    ASSERT_FALSE(image.isNull());
    EXPECT_GT(image.height(), 60 * 50); // every rung, one below the other
    int ink = 0;
    for (int y = 0; y < image.height(); y += 7)
        for (int x = 0; x < image.width(); x += 7)
            ink += qGray(image.pixel(x, y)) < 128;
    EXPECT_GT(ink, 100);
}

TEST_F(ExportFixture, SvgIsVectorTextWithTheDevices) {
    QString error;
    ASSERT_TRUE(exportLadder(dir.filePath(QStringLiteral("ladder.svg")), &error))
        << error.toStdString();
    const QByteArray svg = read(QStringLiteral("ladder.svg"));
    EXPECT_TRUE(svg.contains("<svg"));
    // The devices are text elements of their own, not paths: a reader can search them.
    EXPECT_TRUE(svg.contains(">X0<")) << svg.left(400).toStdString();
    EXPECT_TRUE(svg.contains(">Y7<"));
}

TEST_F(ExportFixture, PdfIsThePrintoutOnSeveralPages) {
    QString error;
    ASSERT_TRUE(exportLadder(dir.filePath(QStringLiteral("ladder.pdf")), &error))
        << error.toStdString();
    const QByteArray pdf = read(QStringLiteral("ladder.pdf"));
    ASSERT_TRUE(pdf.startsWith("%PDF"));
    EXPECT_GE(pdf.count("/Type /Page\n") + pdf.count("/Type /Page\r") + pdf.count("/Type /Page>") +
                  pdf.count("/Type /Page "),
              3)
        << "60 rungs do not fit one A4 page";
}

// Every printed page carries its header: the project, the PLC, the date and "page N of M".
// pdftotext (poppler-utils, installed by scripts/install-deps.sh) reads the text back.
TEST_F(ExportFixture, EveryPrintedPageHasTheHeader) {
    ASSERT_TRUE(window.saveTo(dir.filePath(QStringLiteral("pump-station.rung"))));
    QString error;
    const QString pdf = dir.filePath(QStringLiteral("ladder.pdf"));
    ASSERT_TRUE(exportLadder(pdf, &error)) << error.toStdString();
    QProcess pdftotext;
    pdftotext.start(QStringLiteral("pdftotext"),
                    {QStringLiteral("-layout"), pdf, QStringLiteral("-")});
    ASSERT_TRUE(pdftotext.waitForFinished(30000)) << "pdftotext is missing";
    ASSERT_EQ(pdftotext.exitCode(), 0);
    const QStringList pages = QString::fromUtf8(pdftotext.readAllStandardOutput())
                                  .split(QLatin1Char('\f'), Qt::SkipEmptyParts);
    ASSERT_GE(pages.size(), 3);
    const QString date = QLocale().toString(QDate::currentDate(), QLocale::ShortFormat);
    for (int i = 0; i < pages.size(); ++i) {
        const QString header = pages[i].trimmed().section(QLatin1Char('\n'), 0, 0);
        EXPECT_TRUE(header.contains(QStringLiteral("pump-station.rung"))) << header.toStdString();
        EXPECT_TRUE(header.contains(QStringLiteral("Vigor VB"))) << header.toStdString();
        EXPECT_TRUE(header.contains(date)) << header.toStdString();
        EXPECT_TRUE(header.contains(QStringLiteral("page %1 of %2").arg(i + 1).arg(pages.size())))
            << header.toStdString();
    }
    EXPECT_TRUE(pages.front().contains(QStringLiteral("X0")));
    EXPECT_TRUE(pages.back().contains(QStringLiteral("END")));
}

TEST_F(ExportFixture, AnUnwritablePlaceOrAnUnknownFormatSaysWhy) {
    QString error;
    EXPECT_FALSE(exportLadder(QStringLiteral("/nonexistent-dir/ladder.png"), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("could not be written"))) << error.toStdString();
    EXPECT_FALSE(exportLadder(QStringLiteral("/nonexistent-dir/ladder.svg"), &error));
    EXPECT_FALSE(exportLadder(dir.filePath(QStringLiteral("ladder.bmp")), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("PDF, SVG or PNG"))) << error.toStdString();
}

TEST_F(ExportFixture, NamesInPlaceOfAddressesReachTheExport) {
    window.document()->setSymbols(
        {model::Symbol{std::get<model::Address>(
                           model::parseAddress(window.document()->target(), QStringLiteral("X0"))),
                       QStringLiteral("Start"), QString()}});
    QString error;
    ASSERT_TRUE(exportLadder(dir.filePath(QStringLiteral("plain.svg")), &error));
    window.ladderView()->setNamesFirst(true);
    ASSERT_TRUE(exportLadder(dir.filePath(QStringLiteral("names.svg")), &error));
    const QByteArray plain = read(QStringLiteral("plain.svg"));
    const QByteArray names = read(QStringLiteral("names.svg"));
    // Both show the name and the address; with names first the name is the large label,
    // so the two drawings differ.
    EXPECT_TRUE(plain.contains("Start"));
    EXPECT_TRUE(names.contains("Start"));
    EXPECT_NE(plain, names);
}

TEST_F(ExportFixture, RungCommentIsOneUndoStepAndGoesIntoTheListing) {
    window.ladderView()->setCursor({0, 0, 0});
    const int before = window.document()->undoStack()->count();
    window.ladderView()->setRungComment(QStringLiteral("Pump start"));
    EXPECT_EQ(window.document()->undoStack()->count(), before + 1);
    EXPECT_EQ(window.document()->undoStack()->undoText(), QStringLiteral("Edit rung comment"));
    EXPECT_TRUE(window.document()->listingText().startsWith(QStringLiteral("; Pump start\nLD X0")))
        << window.document()->listingText().left(60).toStdString();
    window.ladderView()->setRungComment(QStringLiteral("Pump start")); // unchanged: no step
    EXPECT_EQ(window.document()->undoStack()->count(), before + 1);
    window.document()->undoStack()->undo();
    EXPECT_TRUE(window.document()->listingText().startsWith(QStringLiteral("LD X0")));
}

// A compare contact shows both operands in its narrow cell: the first above the box, the
// comparison with the second in it; the tooltip has the whole comparison.
TEST_F(ExportFixture, CompareContactsShowBothOperands) {
    std::vector<model::Diagnostic> errors;
    ASSERT_TRUE(window.document()->setListing(
        QStringLiteral("LD X0\nAND>= D100 K1000\nOUT Y0\nEND\n"), &errors));
    QString error;
    ASSERT_TRUE(exportLadder(dir.filePath(QStringLiteral("compare.svg")), &error))
        << error.toStdString();
    const QByteArray svg = read(QStringLiteral("compare.svg"));
    EXPECT_TRUE(svg.contains(">D100<")) << svg.toStdString();
    EXPECT_TRUE(svg.contains("&gt;= K1000<")) << svg.toStdString();
    EXPECT_EQ(window.ladderView()->elementHelp({0, 0, 1}), QStringLiteral("D100 >= K1000"));
}

// A box's tooltip lists every device it uses, each with its name where it has one.
TEST_F(ExportFixture, ABoxsTooltipListsEveryDevice) {
    std::vector<model::Diagnostic> errors;
    ASSERT_TRUE(window.document()->setListing(QStringLiteral("LD X0\nMOV D0 D1\nEND\n"), &errors));
    const int output = window.ladderView()->metrics().gridColumns;
    EXPECT_EQ(window.ladderView()->elementHelp({0, 0, output}), QStringLiteral("D0\nD1"));
}

// The letter inside a coil tells SET from RST and PLS from PLF at a glance: it is drawn bold,
// not in the small font of the comments.
TEST_F(ExportFixture, CoilLettersAreBold) {
    std::vector<model::Diagnostic> errors;
    ASSERT_TRUE(window.document()->setListing(
        QStringLiteral("LD X0\nSET Y0\nLD X1\nRST Y0\nLD X2\nPLS M0\nLD X3\nPLF M1\nEND\n"),
        &errors));
    QString error;
    ASSERT_TRUE(exportLadder(dir.filePath(QStringLiteral("coils.svg")), &error))
        << error.toStdString();
    const QString svg = QString::fromUtf8(read(QStringLiteral("coils.svg")));
    for (const char *mark : {"S", "R", "P", "F"}) {
        // QSvgGenerator writes each text into a group that carries its font.
        const QRegularExpression bold(
            QStringLiteral("<g [^>]*font-weight=\"(700|bold)\"[^>]*>\\s*<text[^>]*>%1</text>")
                .arg(QLatin1String(mark)));
        EXPECT_TRUE(bold.match(svg).hasMatch()) << mark;
    }
}
