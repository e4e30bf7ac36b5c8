// Language > Magyar / Italiano / English switches the whole interface at once, no restart:
// menus, docks, the problems list, the status bar and Qt's own texts (standard buttons), and
// the next start keeps the choice.

#include "app/gui/language.h"
#include "app/gui/main_window.h"
#include "editor/il_editor.h"
#include "editor/problems_view.h"

#include <QApplication>
#include <QCoreApplication>
#include <QDialog>
#include <QDockWidget>
#include <QFontMetrics>
#include <QLocale>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QTimer>

#include "tests/editor/window_fixture.h"

#include <gtest/gtest.h>

using namespace rung;

namespace {

QString tr(const char *context, const char *text) {
    return QCoreApplication::translate(context, text);
}

struct LanguageSwitch : test::WindowFixture {
    void SetUp() override {
        WindowFixture::SetUp();
        // Y0 driven twice: a finding in the problems list.
        load("LD X0\nOUT Y0\nLD X1\nOUT Y0\nEND\n");
        window.show();
    }
    void TearDown() override {
        app::setLanguage(QStringLiteral("en"), false);
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
        QSettings().remove(QStringLiteral("ui/language"));
    }
    QString dockTitle(const char *name) {
        auto *dock = window.findChild<QDockWidget *>(QString::fromLatin1(name));
        return dock ? dock->windowTitle() : QString();
    }
};

} // namespace

TEST_F(LanguageSwitch, EverythingChangesAtOnceWithoutARestart) {
    ASSERT_EQ(window.menuBar()->actions().first()->text(), QStringLiteral("&File"));
    ASSERT_EQ(dockTitle("projectDock"), QStringLiteral("Project"));
    ASSERT_NE(window.problemsView()->diagnosticAt(0), nullptr);
    const model::Diagnostic english = *window.problemsView()->diagnosticAt(0);
    const QString englishStatus = test::statusText(window);
    ASSERT_TRUE(englishStatus.contains(QStringLiteral("steps"))) << englishStatus.toStdString();

    test::pickMenuEntry(window, "Magyar");
    EXPECT_EQ(app::currentLanguage(), QStringLiteral("hu"));
    const QString file = tr("rung::app::MainWindow", "&File");
    ASSERT_NE(file, QStringLiteral("&File")); // the catalogue is there
    EXPECT_EQ(window.menuBar()->actions().first()->text(), file);
    EXPECT_EQ(dockTitle("projectDock"), tr("rung::app::MainWindow", "Project"));
    EXPECT_NE(dockTitle("projectDock"), QStringLiteral("Project"));
    EXPECT_EQ(dockTitle("crossReferenceDock"), tr("rung::app::MainWindow", "Cross Reference"));
    // The problems list: the same finding, its message found again in Hungarian.
    ASSERT_NE(window.problemsView()->diagnosticAt(0), nullptr);
    const model::Diagnostic hungarian = *window.problemsView()->diagnosticAt(0);
    EXPECT_EQ(hungarian.code, english.code);
    EXPECT_NE(hungarian.message, english.message);
    EXPECT_EQ(dockTitle("problemsDock"), window.problemsView()->summary());
    EXPECT_FALSE(dockTitle("problemsDock").startsWith(QStringLiteral("Problems")));
    // The status bar.
    EXPECT_NE(test::statusText(window), englishStatus);
    EXPECT_FALSE(test::statusText(window).contains(QStringLiteral("steps")));
    // The menu shows the choice, and the rest of the menus work on.
    EXPECT_TRUE(test::menuAction(window, "Magyar")->isChecked());
    EXPECT_FALSE(test::menuAction(window, "English")->isChecked());
    // Qt's own texts: the buttons of Save / Discard / Cancel and Yes / No.
    QMessageBox box(QMessageBox::Warning, QStringLiteral("t"), QStringLiteral("t"),
                    QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel |
                        QMessageBox::Yes);
    EXPECT_EQ(box.button(QMessageBox::Save)->text(), QStringLiteral("Mentés"));
    EXPECT_EQ(box.button(QMessageBox::Yes)->text(), QStringLiteral("&Igen"));

    test::pickMenuEntry(window, "Italiano");
    EXPECT_EQ(window.menuBar()->actions().first()->text(), tr("rung::app::MainWindow", "&File"));
    EXPECT_NE(window.problemsView()->diagnosticAt(0)->message, hungarian.message);
    QMessageBox italian(QMessageBox::Warning, QStringLiteral("t"), QStringLiteral("t"),
                        QMessageBox::Save);
    EXPECT_EQ(italian.button(QMessageBox::Save)->text(), QStringLiteral("Salva"));

    test::pickMenuEntry(window, "English");
    EXPECT_EQ(window.menuBar()->actions().first()->text(), QStringLiteral("&File"));
    EXPECT_EQ(window.problemsView()->diagnosticAt(0)->message, english.message);
    EXPECT_EQ(test::statusText(window), englishStatus);
}

TEST_F(LanguageSwitch, TheListAsTypedStaysAndItsErrorsAreTranslatedToo) {
    const QString typed = QStringLiteral("LD X8\nOUT Y1\nEND\n");
    window.ilEditor()->setText(typed);
    window.applyListing();
    const QString before = window.problemsView()->diagnosticAt(0)->message;
    test::pickMenuEntry(window, "Magyar");
    EXPECT_EQ(window.ilEditor()->text(), typed);
    EXPECT_NE(window.problemsView()->diagnosticAt(0)->message, before);
    EXPECT_TRUE(window.isModified()); // still unsaved work
}

TEST_F(LanguageSwitch, TheChoiceIsRememberedForTheNextStart) {
    QSettings().remove(QStringLiteral("ui/language"));
    test::pickMenuEntry(window, "Italiano");
    EXPECT_EQ(QSettings().value(QStringLiteral("ui/language")).toString(), QStringLiteral("it"));
    EXPECT_EQ(app::startLanguage(), QStringLiteral("it"));
    app::MainWindow next;
    EXPECT_TRUE(test::menuAction(next, "Italiano")->isChecked());
    // No choice made: the system's language when we have it, else English.
    QSettings().remove(QStringLiteral("ui/language"));
    EXPECT_EQ(app::startLanguage(), app::languageFor(QLocale::system()));
}

// The first start speaks the system's language where we have it, English elsewhere.
TEST(StartLanguage, TheFirstStartFollowsTheSystemLocale) {
    EXPECT_EQ(app::languageFor(QLocale(QStringLiteral("hu_HU"))), QStringLiteral("hu"));
    EXPECT_EQ(app::languageFor(QLocale(QStringLiteral("it_IT"))), QStringLiteral("it"));
    EXPECT_EQ(app::languageFor(QLocale(QStringLiteral("it_CH"))), QStringLiteral("it"));
    EXPECT_EQ(app::languageFor(QLocale(QStringLiteral("de_DE"))), QStringLiteral("en"));
    EXPECT_EQ(app::languageFor(QLocale(QStringLiteral("en_US"))), QStringLiteral("en"));
    EXPECT_EQ(app::languageFor(QLocale::c()), QStringLiteral("en"));
}

// A language chosen in the menu wins over the locale at every later start; a remembered value
// we have no catalogue for (an older version's, edited by hand) falls back to the locale.
TEST(StartLanguage, TheRememberedChoiceWinsOverTheLocale) {
    EXPECT_EQ(app::languageFor(QLocale(QStringLiteral("hu_HU")), QStringLiteral("it")),
              QStringLiteral("it"));
    EXPECT_EQ(app::languageFor(QLocale(QStringLiteral("it_IT")), QStringLiteral("en")),
              QStringLiteral("en"));
    EXPECT_EQ(app::languageFor(QLocale(QStringLiteral("de_DE")), QStringLiteral("hu")),
              QStringLiteral("hu"));
    EXPECT_EQ(app::languageFor(QLocale(QStringLiteral("hu_HU")), QStringLiteral("xx")),
              QStringLiteral("hu"));
    // startLanguage() reads the remembered choice.
    QSettings().setValue(QStringLiteral("ui/language"), QStringLiteral("hu"));
    EXPECT_EQ(app::startLanguage(), QStringLiteral("hu"));
    QSettings().remove(QStringLiteral("ui/language"));
}

// The New Project dialog leaves its title room in a title bar: in Italian it read
// "Nuovo... getto" under a window manager, the dialog only as wide as its combo boxes.
TEST_F(LanguageSwitch, TheNewProjectDialogIsWideEnoughForItsTitle) {
    test::pickMenuEntry(window, "Italiano");
    window.document()->markSaved(); // no "save the changes?" before the dialog
    QAction *entry = test::menuAction(
        window, tr("rung::app::FileController", "&New Project...").remove(QLatin1Char('&')));
    ASSERT_NE(entry, nullptr);
    QString title;
    int width = 0;
    int needed = 0;
    QTimer::singleShot(0, [&] {
        if (auto *dialog = qobject_cast<QDialog *>(QApplication::activeModalWidget())) {
            title = dialog->windowTitle();
            width = dialog->width();
            QFont bold = dialog->font();
            bold.setBold(true);
            // The title and a title bar's icon, minimise, maximise and close buttons: under
            // openbox seven text heights beside the title still cut it, eight did not.
            needed = QFontMetrics(bold).horizontalAdvance(title) + 8 * QFontMetrics(bold).height();
            dialog->reject();
        }
    });
    entry->trigger();
    EXPECT_EQ(title, QStringLiteral("Nuovo progetto"));
    EXPECT_GE(width, needed) << title.toStdString();
}
