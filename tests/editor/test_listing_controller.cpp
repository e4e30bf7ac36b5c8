// The list pane in step with the program (app/gui/listing_controller.h), without a window: a
// document, the two views, the problems panel and a status bar, as the window hands them.

#include "app/gui/listing_controller.h"
#include "editor/document.h"
#include "editor/il_editor.h"
#include "editor/ladder_view.h"
#include "editor/problems_view.h"

#include "model/target/target.h"

#include <QAction>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTest>
#include <QUndoStack>

#include <gtest/gtest.h>

using namespace rung;

namespace {

// X is octal on a Vigor: X8 is no device.
const auto kListingAloneProgram = QStringLiteral("LD X0\nOUT Y0\nEND\n");
const auto kListingAloneWithError = QStringLiteral("LD X0\nOUT X8\nEND\n");

struct ListingAlone : ::testing::Test {
    editor::Document document;
    editor::LadderView ladder{&document};
    editor::IlEditor il{model::Target::get(model::Family::Vigor)};
    editor::ProblemsView problems;
    QStatusBar status;
    app::ListingController listing{&document, &ladder, &il, &problems, &status, nullptr};

    void SetUp() override {
        document.reset(model::Target::get(model::Family::Vigor), QStringLiteral("VB"));
        il.setTarget(document.target());
    }
    // Text typed into the list as a user types it: the pause's timer starts.
    void type(const QString &text) {
        il.setText(text);
        emit il.listingEdited();
    }
};

} // namespace

TEST_F(ListingAlone, TextTypedBecomesTheProgramAfterThePauseOrAtOnce) {
    QSignalSpy refreshed(&listing, &app::ListingController::refreshed);
    type(kListingAloneProgram);
    EXPECT_TRUE(listing.editPending());
    listing.flush(); // what a save or a run does first
    EXPECT_FALSE(listing.editPending());
    EXPECT_EQ(document.listingText(), kListingAloneProgram);
    EXPECT_GT(refreshed.count(), 0);
    EXPECT_FALSE(listing.hasErrors());
    EXPECT_TRUE(listing.pendingListing().isEmpty()); // the program holds what is typed
    // The pause applies it too.
    type(QStringLiteral("LD X1\nOUT Y1\nEND\n"));
    ASSERT_TRUE(QTest::qWaitFor([this] { return !listing.editPending(); }, 5000));
    EXPECT_EQ(document.listingText(), QStringLiteral("LD X1\nOUT Y1\nEND\n"));
}

TEST_F(ListingAlone, AListWithErrorsStaysAsTypedAndTheLadderKeepsTheLastProgram) {
    ASSERT_TRUE(document.setListing(kListingAloneProgram, nullptr));
    type(kListingAloneWithError);
    listing.applyListing();
    EXPECT_TRUE(listing.hasErrors());
    EXPECT_EQ(listing.pendingListing(),
              kListingAloneWithError);                       // what a save keeps beside the program
    EXPECT_EQ(document.listingText(), kListingAloneProgram); // the last valid program
    EXPECT_EQ(il.text(), kListingAloneWithError);
    EXPECT_TRUE(ladder.notice().contains(QStringLiteral("line 2")))
        << ladder.notice().toStdString();
    EXPECT_GT(problems.count(model::Severity::Error), 0);
    // Undo takes the typed text back in the list itself.
    QAction *undo = listing.undoAction(false, &listing);
    EXPECT_TRUE(undo->isEnabled());
    // Another program: the findings of the old list go, the pane shows the new listing.
    listing.forget();
    document.reset(model::Target::get(model::Family::Vigor), QStringLiteral("VB"));
    EXPECT_FALSE(listing.hasErrors());
    EXPECT_EQ(il.text(), document.listingText());
}

TEST_F(ListingAlone, AnEditOfTheRungsIsFreeWhenNothingTypedWouldBeLost) {
    ASSERT_TRUE(document.setListing(kListingAloneProgram, nullptr));
    EXPECT_TRUE(listing.mayReplaceTypedList(0, 1));
    // A valid text typed within the pause is taken first, as its own undo step.
    const int steps = document.undoStack()->count();
    type(QStringLiteral("LD X0\nOUT Y0\nLD X1\nOUT Y1\nEND\n"));
    EXPECT_TRUE(listing.mayReplaceTypedList(0, 1)); // rung 1 is as it was
    EXPECT_EQ(document.undoStack()->count(), steps + 1);
    EXPECT_EQ(document.ladder().rungs.size(), 3u); // two rungs and END
    // When the text taken changed the rung the edit was made on, the edit is not made.
    type(QStringLiteral("LD X2\nOUT Y0\nLD X1\nOUT Y1\nEND\n"));
    EXPECT_FALSE(listing.mayReplaceTypedList(0, 1));
    EXPECT_TRUE(status.currentMessage().contains(QStringLiteral("rung 1")))
        << status.currentMessage().toStdString();
}

TEST_F(ListingAlone, TheErrorsMessageGoesOnceTheListAppliesWithoutThem) {
    type(kListingAloneWithError);
    listing.applyListing();
    listing.sayErrors(QStringLiteral("prog.il has errors"));
    EXPECT_EQ(status.currentMessage(), QStringLiteral("prog.il has errors"));
    type(kListingAloneProgram);
    listing.applyListing();
    EXPECT_TRUE(status.currentMessage().isEmpty());
    EXPECT_TRUE(ladder.notice().isEmpty());
}
