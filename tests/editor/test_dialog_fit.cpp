// Nothing cut off in English, Hungarian or Italian: every dialog the window opens is wide
// enough for its title in a window manager's title bar, and every label, button and combo box
// of it, and of the window at 1366x768 and at 1024x600, is at least as large as its text needs.

#include "app/gui/language.h"
#include "app/gui/main_window.h"

#include <QAbstractButton>
#include <QApplication>
#include <QComboBox>
#include <QDialog>
#include <QDockWidget>
#include <QFontMetrics>
#include <QHeaderView>
#include <QLabel>
#include <QMessageBox>
#include <QSettings>
#include <QStatusBar>
#include <QTabBar>
#include <QTemporaryDir>
#include <QTimer>

#include "tests/editor/window_fixture.h"

#include <gtest/gtest.h>

#include <functional>

using namespace rung;

namespace {

QString tr(const char *context, const char *text) {
    return QCoreApplication::translate(context, text);
}

QString nameOf(const QWidget *w) {
    return QString::fromLatin1(w->metaObject()->className()) + QLatin1Char('#') + w->objectName();
}

// The texts of `root` (and its children) that do not fit their widget, as "widget: text".
QStringList cutTexts(QWidget *root) {
    QStringList cut;
    QList<QWidget *> widgets = root->findChildren<QWidget *>();
    widgets.prepend(root);
    for (QWidget *w : widgets) {
        if (!w->isVisible() || w->window() != root->window())
            continue;
        if (auto *label = qobject_cast<QLabel *>(w)) {
            if (label->text().isEmpty() || label->pixmap().isNull() == false)
                continue;
            const bool fits = label->wordWrap()
                                  ? label->height() >= label->heightForWidth(label->width())
                                  : label->width() >= label->sizeHint().width();
            if (!fits)
                cut << QStringLiteral("%1 (%2 px of %3): %4")
                           .arg(nameOf(w))
                           .arg(label->width())
                           .arg(label->sizeHint().width())
                           .arg(label->text());
        } else if (auto *button = qobject_cast<QAbstractButton *>(w)) {
            if (!button->text().isEmpty() && button->width() < button->sizeHint().width())
                cut << QStringLiteral("%1 (%2 px of %3): %4")
                           .arg(nameOf(w))
                           .arg(button->width())
                           .arg(button->sizeHint().width())
                           .arg(button->text());
        } else if (auto *combo = qobject_cast<QComboBox *>(w)) {
            if (combo->width() < combo->minimumSizeHint().width())
                cut << QStringLiteral("%1: %2").arg(nameOf(w), combo->currentText());
        } else if (auto *tabs = qobject_cast<QTabBar *>(w)) {
            for (int i = 0; i < tabs->count(); ++i)
                if (tabs->tabRect(i).width() <
                    tabs->fontMetrics().horizontalAdvance(tabs->tabText(i)))
                    cut << QStringLiteral("%1 tab: %2").arg(nameOf(w), tabs->tabText(i));
        } else if (auto *header = qobject_cast<QHeaderView *>(w)) {
            // Every column but a stretched last one is as wide as its title.
            if (header->orientation() != Qt::Horizontal || !header->model())
                continue;
            for (int i = 0; i < header->count(); ++i) {
                if (header->isSectionHidden(i) ||
                    (i == header->count() - 1 && header->stretchLastSection()))
                    continue;
                const QString title = header->model()->headerData(i, Qt::Horizontal).toString();
                if (header->sectionSize(i) < header->fontMetrics().horizontalAdvance(title) + 8)
                    cut << QStringLiteral("%1 column %2 (%3 px): %4")
                               .arg(nameOf(header->parentWidget()))
                               .arg(i)
                               .arg(header->sectionSize(i))
                               .arg(title);
            }
        }
    }
    return cut;
}

// The width a title bar needs: the title in bold and, beside it, the icon and buttons of a
// title bar; under openbox seven text heights of them still cut "Nuovo progetto", eight did not.
int titleNeeds(const QWidget *dialog) {
    QFont bold = dialog->font();
    bold.setBold(true);
    return QFontMetrics(bold).horizontalAdvance(dialog->windowTitle()) +
           8 * QFontMetrics(bold).height();
}

struct Seen {
    QString title;
    QStringList problems;
};

// Runs `open`, which shows a modal dialog; looks at the dialog once it is on screen, then
// closes it (and any dialog that follows it).
Seen inspectDialog(const std::function<void()> &open) {
    Seen seen;
    std::function<void()> look = [&seen] {
        auto *dialog = qobject_cast<QDialog *>(QApplication::activeModalWidget());
        if (!dialog) {
            seen.problems << QStringLiteral("no dialog");
            return;
        }
        seen.title = dialog->windowTitle();
        if (dialog->width() < titleNeeds(dialog))
            seen.problems << QStringLiteral("title \"%1\": %2 px of %3")
                                 .arg(dialog->windowTitle())
                                 .arg(dialog->width())
                                 .arg(titleNeeds(dialog));
        seen.problems << cutTexts(dialog);
        dialog->reject();
    };
    QTimer::singleShot(0, look);
    open();
    QCoreApplication::processEvents(); // the look, had no dialog come
    // A dialog the first one led to (Replace Device asks twice) goes too.
    while (auto *next = qobject_cast<QDialog *>(QApplication::activeModalWidget()))
        next->reject();
    return seen;
}

struct DialogFit : test::WindowFixture, ::testing::WithParamInterface<const char *> {
    QTemporaryDir dir;
    void SetUp() override {
        WindowFixture::SetUp();
        ASSERT_TRUE(app::setLanguage(QString::fromLatin1(GetParam()), false));
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
        QCoreApplication::processEvents();
        load("LD X0\nOUT Y0\nEND\n");
        window.document()->markSaved();
        window.resize(1366, 768);
        window.show();
        QCoreApplication::processEvents();
    }
    void TearDown() override {
        app::setLanguage(QStringLiteral("en"), false);
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
    }
    QAction *entry(const char *context, const char *text) {
        QAction *a = test::menuAction(window, tr(context, text).remove(QLatin1Char('&')));
        EXPECT_NE(a, nullptr) << text;
        return a;
    }
    void expectFits(const char *what, const std::function<void()> &open) {
        const Seen seen = inspectDialog(open);
        EXPECT_FALSE(seen.title.isEmpty()) << what;
        EXPECT_TRUE(seen.problems.isEmpty())
            << GetParam() << ": " << what << ": "
            << seen.problems.join(QStringLiteral("; ")).toStdString();
    }
};

} // namespace

TEST_P(DialogFit, EveryDialogFitsItsTitleAndTexts) {
    const char *mw = "rung::app::MainWindow";
    expectFits("New Project", [&] { entry(mw, "&New Project...")->trigger(); });
    expectFits("Find Device", [&] { entry(mw, "&Find Device...")->trigger(); });
    expectFits("Replace Device", [&] { entry(mw, "Replace &Device...")->trigger(); });
    expectFits("Rung Comment", [&] { window.editRungComment(); });
    expectFits("Keyboard", [&] { entry(mw, "&Keyboard...")->trigger(); });
    expectFits("About", [&] { entry(mw, "&About Rung Studio")->trigger(); });
    // Save the changes? (New Project on a changed program asks first.)
    window.document()->insertRung(0, window.document()->ladder().rungs.front());
    expectFits("Unsaved changes", [&] { entry(mw, "&New Project...")->trigger(); });
    window.document()->markSaved();
    // Qt's own file dialogs, as under a desktop without one of its own: the size and date
    // columns' titles whole ("Dimensione" was cut).
    QCoreApplication::setAttribute(Qt::AA_DontUseNativeDialogs, true);
    expectFits("Open", [&] { entry(mw, "&Open...")->trigger(); });
    expectFits("Export Instruction List",
               [&] { entry(mw, "&Export Instruction List...")->trigger(); });
    QCoreApplication::setAttribute(Qt::AA_DontUseNativeDialogs, false);
    // A file that cannot be opened.
    expectFits("Cannot open the file",
               [&] { window.openFile(dir.filePath(QStringLiteral("none.rung"))); });
    // An export name that names a file that exists.
    const QString existing = dir.filePath(QStringLiteral("latch.pdf"));
    QFile(existing).open(QIODevice::WriteOnly);
    expectFits("Replace File", [&] {
        window.completeSavePath(dir.filePath(QStringLiteral("latch")), {QStringLiteral("pdf")});
    });
}

// The window at 1366x768 and at 1024x600: the docks, the tabs, the tables' headers and the
// status bar show their texts whole.
TEST_P(DialogFit, TheWindowShowsItsTextsWholeOnSmallScreens) {
    auto *project = window.findChild<QDockWidget *>(QStringLiteral("projectDock"));
    auto *crossReference = window.findChild<QDockWidget *>(QStringLiteral("crossReferenceDock"));
    ASSERT_NE(project, nullptr);
    ASSERT_NE(crossReference, nullptr);
    for (const QSize size : {QSize(1366, 768), QSize(1024, 600)}) {
        window.resize(size);
        // The project and the cross reference share a place: each in turn in front.
        for (QDockWidget *front : {project, crossReference}) {
            front->raise();
            QCoreApplication::processEvents();
            const QStringList cut = cutTexts(&window);
            EXPECT_TRUE(cut.isEmpty())
                << GetParam() << " at " << size.width() << ", " << front->objectName().toStdString()
                << " in front: " << cut.join(QStringLiteral("; ")).toStdString();
        }
    }
    project->raise();
}

INSTANTIATE_TEST_SUITE_P(Languages, DialogFit, ::testing::Values("en", "hu", "it"),
                         [](const auto &info) { return std::string(info.param); });
