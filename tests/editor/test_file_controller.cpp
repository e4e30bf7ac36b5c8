// The window's files (app/gui/file_controller.h) without a window: the document, the two
// views, the list as typed and the symbol table, a plain widget for the dialogs' parent.

#include "app/gui/file_controller.h"
#include "app/gui/listing_controller.h"
#include "app/gui/symbol_table.h"
#include "editor/document.h"
#include "editor/il_editor.h"
#include "editor/ladder_view.h"
#include "editor/problems_view.h"

#include "model/project/project.h"
#include "model/target/target.h"

#include <QFile>
#include <QFileInfo>
#include <QMenu>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QToolBar>

#include "tests/editor/window_fixture.h"

#include <gtest/gtest.h>

#include <memory>

using namespace rung;

namespace {

// What the window hands its file controller, and the controller.
struct FilesAlone {
    QWidget window; // the dialogs' parent: no MainWindow
    editor::Document document;
    editor::LadderView ladder{&document};
    editor::IlEditor il{model::Target::get(model::Family::Vigor)};
    editor::ProblemsView problems;
    QStatusBar status;
    app::ListingController listing{&document, &ladder, &il, &problems, &status, &window};
    app::SymbolTable symbols{&document};
    app::FileController files{&document, &ladder, &il, &listing, &symbols, &status, &window};

    FilesAlone() {
        files.newProject(model::Target::get(model::Family::Vigor), QStringLiteral("VB"));
    }
};

struct FileControllerAlone : ::testing::Test {
    test::OwnRecoveryFolder recoveryFolder;
    QTemporaryDir dir;
    QString path(const char *name) const { return dir.filePath(QString::fromLatin1(name)); }
};

} // namespace

TEST_F(FileControllerAlone, SavesAndOpensAProject) {
    const QString file = path("plant.rung");
    {
        FilesAlone f;
        ASSERT_TRUE(f.document.setListing(QStringLiteral("LD X1\nOUT Y1\nEND\n"), nullptr));
        EXPECT_TRUE(f.files.isModified());
        QSignalSpy saved(&f.files, &app::FileController::saved);
        ASSERT_TRUE(f.files.saveTo(file));
        EXPECT_EQ(saved.count(), 1);
        EXPECT_FALSE(f.files.isModified());
        EXPECT_EQ(f.document.path(), file);
        EXPECT_TRUE(f.status.currentMessage().contains(QStringLiteral("Saved")))
            << f.status.currentMessage().toStdString();
    }
    FilesAlone other;
    ASSERT_TRUE(other.files.openFile(file, QString(), true));
    EXPECT_EQ(other.document.listingText(), QStringLiteral("LD X1\nOUT Y1\nEND\n"));
    EXPECT_EQ(other.il.text(), other.document.listingText());
    EXPECT_FALSE(other.files.isModified());
}

TEST_F(FileControllerAlone, AListingWithErrorsOpensAsTypedAndIsSavedSo) {
    const QString listing = path("broken.il");
    QFile out(listing);
    ASSERT_TRUE(out.open(QIODevice::WriteOnly));
    out.write("LD X0\nOUT X8\nEND\n"); // X is octal on a Vigor
    out.close();
    FilesAlone f;
    ASSERT_TRUE(f.files.openFile(listing, QStringLiteral("vigor"), true));
    EXPECT_TRUE(f.listing.hasErrors());
    EXPECT_EQ(f.il.text(), QStringLiteral("LD X0\nOUT X8\nEND\n"));
    EXPECT_TRUE(f.status.currentMessage().contains(QStringLiteral("broken.il has errors")));
    // Saved beside the listing, as a project, with the list as typed.
    const QString saved = path("broken.rung");
    ASSERT_TRUE(f.files.saveTo(saved));
    const auto project = model::loadProject(saved, nullptr);
    ASSERT_TRUE(project.has_value());
    EXPECT_EQ(project->pendingListing, QStringLiteral("LD X0\nOUT X8\nEND\n"));
    EXPECT_FALSE(f.files.isModified());
}

TEST_F(FileControllerAlone, AFileThatCannotBeReadOpensNothingAndSaysWhy) {
    FilesAlone f;
    const QString before = f.document.listingText();
    EXPECT_FALSE(f.files.openFile(path("missing.rung"), QString(), true));
    EXPECT_FALSE(f.status.currentMessage().isEmpty());
    EXPECT_EQ(f.document.listingText(), before);
}

TEST_F(FileControllerAlone, AddsTheFileMenusEntriesAndTheToolbarsButtons) {
    FilesAlone f;
    QMenu file;
    QToolBar bar;
    f.files.addActions(&file, &bar);
    QStringList entries;
    for (QAction *a : file.actions())
        if (!a->isSeparator())
            entries << a->text();
    EXPECT_EQ(entries, QStringList({QStringLiteral("&New Project..."),
                                    QStringLiteral("New Net&work"), QStringLiteral("&Open..."),
                                    QStringLiteral("Open &Recent"), QStringLiteral("E&xamples"),
                                    QStringLiteral("&Save"), QStringLiteral("Save &As..."),
                                    QStringLiteral("Co&mpare With..."),
                                    QStringLiteral("&Import Instruction List..."),
                                    QStringLiteral("&Export Instruction List..."),
                                    QStringLiteral("Import &PLCopen XML..."),
                                    QStringLiteral("Expor&t PLCopen XML..."),
                                    QStringLiteral("Export &Ladder"),
                                    QStringLiteral("Print Pre&view..."), QStringLiteral("&Quit")}));
    ASSERT_EQ(bar.actions().size(), 3);
    EXPECT_EQ(bar.actions().front()->toolTip(),
              QStringLiteral("New Project (%1)")
                  .arg(QKeySequence(QKeySequence::New).toString(QKeySequence::NativeText)));
}

TEST_F(FileControllerAlone, RecoveryOfAnInstanceThatIsGone) {
    auto crashed = std::make_unique<FilesAlone>();
    ASSERT_TRUE(crashed->document.setListing(QStringLiteral("LD X5\nOUT Y5\nEND\n"), nullptr));
    crashed->files.writeRecovery();
    const QString kept = crashed->files.recoveryPath();
    ASSERT_TRUE(QFileInfo::exists(kept));
    crashed.reset(); // as a crash leaves it: the file stays, orphaned
    ASSERT_TRUE(QFileInfo::exists(kept));
    FilesAlone other;
    ASSERT_TRUE(other.files.offerRecovery(false));
    EXPECT_EQ(other.document.listingText(), QStringLiteral("LD X5\nOUT Y5\nEND\n"));
    EXPECT_TRUE(other.files.isModified());
    other.files.closing(); // a close that saved or discarded: no recovery file is left
    EXPECT_FALSE(QFileInfo::exists(other.files.recoveryPath()));
}
