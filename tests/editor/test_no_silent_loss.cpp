// Never a shorter program than the user made without saying so: Save and the recovery file keep
// the instruction list as typed when it has errors, and Export Instruction List writes the
// whole program or nothing.

#include "app/gui/ladder_export.h"
#include "app/gui/main_window.h"
#include "editor/il_editor.h"
#include "editor/problems_view.h"

#include "model/ladder/ladder_text.h"

#include <QApplication>
#include <QFile>
#include <QFileInfo>
#include <QMessageBox>
#include <QPushButton>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTimer>

#include "tests/editor/window_fixture.h"

#include <gtest/gtest.h>

using namespace rung;

namespace {

// The example of the report: X is octal on a Vigor, so X8 is no device.
const auto kTyped = QStringLiteral("LD X0\nOUT Y0\nLD X8\nOUT Y1\nEND\n");

struct NoSilentLoss : test::WindowFixture {
    QTemporaryDir dir;
    void SetUp() override {
        WindowFixture::SetUp();
        load("LD X0\nOUT Y0\nEND\n");
        window.document()->markSaved();
    }
    void type(const QString &text) {
        window.ilEditor()->setText(text);
        window.applyListing();
    }
    QByteArray read(const QString &path) {
        QFile f(path);
        return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
    }
};

} // namespace

TEST_F(NoSilentLoss, SaveKeepsTheListAsTypedAndReopensItAsItWas) {
    type(kTyped);
    // Typed errors are unsaved work even though the program did not change.
    EXPECT_FALSE(window.document()->isModified());
    EXPECT_TRUE(window.isModified());
    EXPECT_TRUE(window.isWindowModified());
    const QString path = dir.filePath(QStringLiteral("typed.rung"));
    ASSERT_TRUE(window.saveTo(path));
    EXPECT_FALSE(window.isModified());
    EXPECT_FALSE(window.isWindowModified());
    EXPECT_TRUE(window.statusBar()->currentMessage().contains(QStringLiteral("as typed")))
        << window.statusBar()->currentMessage().toStdString();
    const auto saved = model::loadProject(path, nullptr);
    ASSERT_TRUE(saved);
    EXPECT_EQ(saved->pendingListing, kTyped);

    app::MainWindow reopened;
    ASSERT_TRUE(reopened.openFile(path, QString(), true));
    EXPECT_EQ(reopened.ilEditor()->text(), kTyped);
    // The ladder holds the last valid program; the error is on the list's line 3.
    EXPECT_EQ(reopened.document()->listingText(), QStringLiteral("LD X0\nOUT Y0\nEND\n"));
    EXPECT_GT(reopened.problemsView()->count(model::Severity::Error), 0);
    EXPECT_FALSE(reopened.isModified()); // as saved
    // Fixed, the list and the program agree again, and the next save leaves the key out.
    reopened.ilEditor()->setText(QStringLiteral("LD X0\nOUT Y0\nLD X7\nOUT Y1\nEND\n"));
    reopened.applyListing();
    EXPECT_TRUE(reopened.isModified());
    ASSERT_TRUE(reopened.saveTo(path));
    EXPECT_FALSE(read(path).contains("pendingListing"));
    EXPECT_TRUE(read(path).contains("X7"));
}

TEST_F(NoSilentLoss, ClosingWithTypedErrorsAsksToSave) {
    type(kTyped);
    bool asked = false;
    QTimer::singleShot(0, &window, [&asked] {
        if (auto *box = qobject_cast<QMessageBox *>(QApplication::activeModalWidget())) {
            asked = true;
            box->button(QMessageBox::Cancel)->click();
        }
    });
    window.show();
    EXPECT_FALSE(window.close());
    EXPECT_TRUE(asked);
}

TEST_F(NoSilentLoss, TheRecoveryFileKeepsTheListAsTyped) {
    {
        app::MainWindow crashed;
        crashed.newProject(model::Target::get(model::Family::Vigor), QStringLiteral("VB"));
        crashed.ilEditor()->setText(kTyped);
        crashed.applyListing();
        crashed.writeRecovery();
        ASSERT_TRUE(QFileInfo::exists(crashed.recoveryPath()));
        const auto kept = model::loadProject(crashed.recoveryPath(), nullptr);
        ASSERT_TRUE(kept);
        EXPECT_EQ(kept->pendingListing, kTyped);
    }
    app::MainWindow other;
    ASSERT_TRUE(other.offerRecovery(false));
    EXPECT_EQ(other.ilEditor()->text(), kTyped);
    EXPECT_TRUE(other.isModified());
}

TEST_F(NoSilentLoss, ExportRefusesWhileTheListAsTypedHasErrorsNamingThem) {
    type(kTyped);
    const QString path = dir.filePath(QStringLiteral("out.il"));
    std::vector<model::Diagnostic> errors;
    ASSERT_FALSE(window.document()->setListing(kTyped, &errors));
    QString error;
    EXPECT_FALSE(app::ProgramExport(*window.document(), false).listing(path, &error, errors));
    EXPECT_FALSE(QFileInfo::exists(path));
    EXPECT_TRUE(error.contains(QStringLiteral("line 3"))) << error.toStdString();
    EXPECT_TRUE(error.contains(QStringLiteral("X8"))) << error.toStdString();
}

// The refusal comes before the file dialog: the user does not pick a file for nothing.
TEST_F(NoSilentLoss, ExportFromTheMenuRefusesBeforeAskingForAFile) {
    type(kTyped);
    QString seen;
    QTimer::singleShot(0, [&seen] {
        QWidget *modal = QApplication::activeModalWidget();
        seen = modal ? QString::fromLatin1(modal->metaObject()->className()) : QString();
        if (auto *box = qobject_cast<QMessageBox *>(modal)) {
            seen += u' ' + box->text();
            box->accept();
        } else if (modal) {
            modal->close();
        }
    });
    QAction *entry = test::menuAction(window, QStringLiteral("Export Instruction List..."));
    ASSERT_NE(entry, nullptr);
    entry->trigger();
    EXPECT_TRUE(seen.startsWith(QStringLiteral("QMessageBox"))) << seen.toStdString();
    EXPECT_TRUE(seen.contains(QStringLiteral("X8"))) << seen.toStdString();
}

TEST_F(NoSilentLoss, ExportRefusesARungThatCannotBeListedNamingIt) {
    QFile bridge(QStringLiteral(RUNG_TEST_DATA_DIR "/ladder/bridge.ladder"));
    ASSERT_TRUE(bridge.open(QIODevice::ReadOnly));
    const model::LadderTextResult drawn =
        model::parseLadderText(window.document()->target(), QString::fromUtf8(bridge.readAll()));
    ASSERT_TRUE(drawn.ok());
    window.document()->replaceRungs(1, 0, drawn.ladder.rungs, QStringLiteral("bridge"));
    ASSERT_FALSE(window.document()->listing().ok());
    const QString path = dir.filePath(QStringLiteral("out.il"));
    QString error;
    EXPECT_FALSE(app::ProgramExport(*window.document(), false).listing(path, &error));
    EXPECT_FALSE(QFileInfo::exists(path)); // never a file with only part of the program
    EXPECT_TRUE(error.contains(QStringLiteral("Rung 2"))) << error.toStdString();
}

TEST_F(NoSilentLoss, ExportOfAValidProgramIsTheWholeListing) {
    const QString path = dir.filePath(QStringLiteral("out.il"));
    QString error;
    ASSERT_TRUE(app::ProgramExport(*window.document(), false).listing(path, &error))
        << error.toStdString();
    EXPECT_EQ(QString::fromUtf8(read(path)), window.document()->listingText());
    EXPECT_TRUE(read(path).contains("LD X0\nOUT Y0\n"));
}

// A rung of contacts with no output lists nothing: the list pane shows a placeholder line for
// it, and neither that line nor a listing without the rung may reach the file.
TEST_F(NoSilentLoss, ExportRefusesARungOfContactsWithoutAnOutput) {
    model::Rung contacts(1, 2);
    for (int c = 0; c < 2; ++c) {
        QString why;
        const auto contact =
            model::contactFromText(window.document()->target(),
                                   c == 0 ? QStringLiteral("X1") : QStringLiteral("X2"), &why);
        ASSERT_TRUE(contact) << why.toStdString();
        contacts.cell(0, c).kind = model::CellKind::Contact;
        contacts.cell(0, c).contact = *contact;
    }
    window.document()->replaceRungs(1, 0, {contacts}, QStringLiteral("contacts"));
    ASSERT_EQ(window.document()->unlistedRungs().size(), 1u);
    ASSERT_FALSE(window.document()->listingText().contains(QStringLiteral("LD X1")));
    const QString path = dir.filePath(QStringLiteral("out.il"));
    QString error;
    const app::ProgramExport exporter(*window.document(), false);
    EXPECT_FALSE(exporter.listingBlockers().isEmpty());
    EXPECT_FALSE(exporter.listing(path, &error));
    EXPECT_FALSE(QFileInfo::exists(path));
    EXPECT_TRUE(error.contains(QStringLiteral("Rung 2"))) << error.toStdString();
    EXPECT_TRUE(error.contains(QStringLiteral("X1"))) << error.toStdString();
}

// A contact beside the path to the output is left out of the list (LD002): the rung is
// listed, but not whole.
TEST_F(NoSilentLoss, ExportRefusesARungListedOnlyInPart) {
    model::Rung rung = window.document()->ladder().rungs.front();
    ASSERT_GE(rung.columns, 1);
    QString why;
    const auto stray =
        model::contactFromText(window.document()->target(), QStringLiteral("X5"), &why);
    ASSERT_TRUE(stray) << why.toStdString();
    rung.resize(2, rung.columns);
    rung.cell(1, 0).kind = model::CellKind::Contact;
    rung.cell(1, 0).contact = *stray;
    window.document()->setRung(0, rung, QStringLiteral("stray"));
    ASSERT_TRUE(window.document()->unlistedRungs().empty()); // the rung itself is listed
    const QString path = dir.filePath(QStringLiteral("out.il"));
    QString error;
    EXPECT_FALSE(app::ProgramExport(*window.document(), false).listing(path, &error));
    EXPECT_FALSE(QFileInfo::exists(path));
    EXPECT_TRUE(error.contains(QStringLiteral("Rung 1"))) << error.toStdString();
    EXPECT_TRUE(error.contains(QStringLiteral("X5"))) << error.toStdString();
}

// A symbol or a watch list edited while the list as typed has errors: the list stays as typed
// (the rungs did not change), and Save keeps it.
TEST_F(NoSilentLoss, EditingSymbolsOrWatchListsKeepsTheListAsTyped) {
    type(kTyped);
    ASSERT_EQ(window.ilEditor()->text(), kTyped);
    const auto x0 = model::parseAddress(window.document()->target(), QStringLiteral("X0"));
    ASSERT_TRUE(std::holds_alternative<model::Address>(x0));
    window.document()->setSymbols({{std::get<model::Address>(x0), QStringLiteral("Start"), {}}});
    EXPECT_EQ(window.ilEditor()->text(), kTyped);
    EXPECT_GT(window.problemsView()->count(model::Severity::Error), 0);
    window.document()->setWatchLists({{QStringLiteral("Main"), {QStringLiteral("X0")}}},
                                     QStringLiteral("watch"));
    EXPECT_EQ(window.ilEditor()->text(), kTyped);
    window.document()->undoStack()->undo(); // the watch list
    window.document()->undoStack()->undo(); // the symbol
    EXPECT_EQ(window.ilEditor()->text(), kTyped);
    const QString path = dir.filePath(QStringLiteral("typed.rung"));
    ASSERT_TRUE(window.saveTo(path));
    const auto saved = model::loadProject(path, nullptr);
    ASSERT_TRUE(saved);
    EXPECT_EQ(saved->pendingListing, kTyped);
    // An edit of the rungs still brings the ladder's listing into the list, once the user
    // agreed to it.
    QTimer::singleShot(0, &window, [] {
        if (auto *box = qobject_cast<QMessageBox *>(QApplication::activeModalWidget()))
            box->buttons().front()->click(); // "Replace the List"
    });
    window.document()->insertRung(0, window.document()->ladder().rungs.front());
    EXPECT_EQ(window.ilEditor()->text(), window.document()->listingText());
}

// recheck() converts and checks again without a change of the rungs: no undo step, the same
// revision, programChanged once.
TEST_F(NoSilentLoss, RecheckChangesNothing) {
    const quint64 revision = window.document()->rungsRevision();
    const int steps = window.document()->undoStack()->count();
    QSignalSpy changed(window.document(), &editor::Document::programChanged);
    window.document()->recheck();
    EXPECT_EQ(changed.count(), 1);
    EXPECT_EQ(window.document()->rungsRevision(), revision);
    EXPECT_EQ(window.document()->undoStack()->count(), steps);
    EXPECT_FALSE(window.document()->isModified());
}
