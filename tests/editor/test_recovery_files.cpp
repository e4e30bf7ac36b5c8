// The recovery files hold the user's unsaved work: one that cannot be read is kept and named,
// never deleted; the companion naming the original file is read with a bound; a write that
// fails is said in the status bar.

#include "app/gui/main_window.h"
#include "app/gui/recovery.h"
#include "editor/il_editor.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QStatusBar>
#include <QTemporaryDir>

#include <gtest/gtest.h>

using namespace rung;

namespace {

QString recoveryFolder() {
    app::MainWindow probe; // its recovery file names the folder the tests use
    return QFileInfo(probe.recoveryPath()).absolutePath();
}

bool writeBytes(const QString &path, const QByteArray &bytes) {
    QFile f(path);
    return f.open(QIODevice::WriteOnly) && f.write(bytes) == bytes.size();
}

// A recovery folder of the test's own: other tests leave orphans behind (a window that
// recovered work keeps it in a recovery file of its own, orphaned when it goes).
struct RecoveryFiles : ::testing::Test {
    QTemporaryDir folder;
    QString before;
    void SetUp() override {
        before = recoveryFolder();
        ASSERT_TRUE(folder.isValid());
        app::RecoveryFile::setDirectory(folder.path());
    }
    void TearDown() override { app::RecoveryFile::setDirectory(before); }
};

} // namespace

TEST_F(RecoveryFiles, AnOrphanThatDoesNotLoadIsKeptAndNamed) {
    const QString broken = QDir(folder.path()).filePath(QStringLiteral("recovery-broken-1.rung"));
    ASSERT_TRUE(writeBytes(broken, "{ \"format\": \"rung-project\", truncated by the crash"));
    app::MainWindow window;
    EXPECT_FALSE(window.offerRecovery(false));
    EXPECT_TRUE(QFileInfo::exists(broken)); // never delete what could not be read
    const QString message = window.statusBar()->currentMessage();
    EXPECT_TRUE(message.contains(QDir::toNativeSeparators(broken))) << message.toStdString();
    EXPECT_TRUE(message.contains(QStringLiteral("kept"))) << message.toStdString();
}

TEST_F(RecoveryFiles, AnOversizedOriginCompanionIsNoPath) {
    QString recovery;
    {
        app::MainWindow crashed;
        crashed.newProject(model::Target::get(model::Family::Vigor), QStringLiteral("VB"));
        crashed.ilEditor()->setText(QStringLiteral("LD X3\nOUT Y3\nEND\n"));
        crashed.applyListing();
        crashed.writeRecovery();
        recovery = crashed.recoveryPath();
        ASSERT_TRUE(QFileInfo::exists(recovery));
        // A megabyte where one path should be (a disk error, another program's file).
        ASSERT_TRUE(writeBytes(recovery.chopped(5) + QStringLiteral(".path"),
                               QByteArray(1024 * 1024, 'a')));
    }
    app::MainWindow window;
    ASSERT_TRUE(window.offerRecovery(false));
    EXPECT_EQ(window.document()->listingText(), QStringLiteral("LD X3\nOUT Y3\nEND\n"));
    EXPECT_TRUE(window.document()->path().isEmpty()); // untitled: Save asks where
}

TEST_F(RecoveryFiles, AWriteThatFailsIsSaidInTheStatusBar) {
    app::MainWindow window;
    window.newProject(model::Target::get(model::Family::Vigor), QStringLiteral("VB"));
    window.ilEditor()->setText(QStringLiteral("LD X4\nOUT Y4\nEND\n"));
    window.applyListing();
    // A folder where the recovery file should go: no file can be written there.
    ASSERT_TRUE(QDir().mkpath(window.recoveryPath()));
    window.writeRecovery();
    const QString message = window.statusBar()->currentMessage();
    EXPECT_TRUE(message.contains(QStringLiteral("recovery file could not be written")))
        << message.toStdString();
    QDir(window.recoveryPath()).removeRecursively();
}
