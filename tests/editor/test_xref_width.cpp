// The cross reference in the project dock's width (about 300 px at the first start) in the
// longest of the languages, Hungarian: the filter's hint is not cut off and the uses do not
// scroll sideways.

#include "app/gui/language.h"
#include "editor/cross_reference_view.h"
#include "editor/document.h"

#include <QCoreApplication>
#include <QLineEdit>
#include <QScrollBar>
#include <QTest>
#include <QTreeView>

#include <gtest/gtest.h>

using namespace rung;

namespace {

struct CrossReferenceWidth : ::testing::Test {
    void TearDown() override { // English for the tests that follow, whatever happened here
        app::setLanguage(QStringLiteral("en"), false);
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
    }
};

} // namespace

TEST_F(CrossReferenceWidth, HungarianFitsTheDocksWidth) {
    ASSERT_TRUE(app::setLanguage(QStringLiteral("hu"), false));
    QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
    editor::Document document;
    document.reset(model::Target::get(model::Family::Vigor), QStringLiteral("VB"));
    std::vector<model::Diagnostic> errors;
    ASSERT_TRUE(document.setListing(QStringLiteral("LD X0\nANI X1\nOUT Y0\nLD Y0\nSET M100\nEND\n"),
                                    &errors));
    editor::CrossReferenceView view(&document);
    view.resize(300, 400);
    view.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&view));
    view.setOnScreen(true);
    view.tree()->expandAll();
    QCoreApplication::processEvents();
    ASSERT_GT(view.tree()->model()->rowCount(), 0);
    QLineEdit *filter = view.filter();
    const QString hint = filter->placeholderText();
    EXPECT_NE(hint, QStringLiteral("Device or prefix (X0, X)")); // in Hungarian
    EXPECT_LE(filter->fontMetrics().horizontalAdvance(hint), filter->width() - 12)
        << hint.toStdString();
    EXPECT_FALSE(filter->toolTip().isEmpty()); // the whole explanation
    EXPECT_EQ(view.tree()->horizontalScrollBar()->maximum(), 0)
        << view.tree()->columnWidth(0) << " " << view.tree()->columnWidth(1) << " "
        << view.tree()->columnWidth(2) << " " << view.tree()->columnWidth(3) << " "
        << view.tree()->viewport()->width() << " "
        << view.tree()->model()->headerData(0, Qt::Horizontal).toString().toStdString();
}
