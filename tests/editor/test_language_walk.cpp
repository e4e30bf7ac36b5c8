// After a switch of language no text of the old one is left anywhere in the window: every
// widget (labels, buttons, tooltips, headers, tabs, dock titles, the problems list, the list's
// annotations and marked lines, the ladder's notice, the status bar) and every action. The
// texts of a language are those of our catalogues, with a placeholder matching anything.

#include "app/gui/language.h"
#include "app/gui/main_window.h"
#include "editor/document.h"
#include "editor/il_editor.h"
#include "model/convert/convert.h"
#include "model/ladder/ladder_text.h"
#include "model/listing/il.h"
#include "tests/targets.h"

#include <QAbstractButton>
#include <QAbstractItemView>
#include <QApplication>
#include <QComboBox>
#include <QDockWidget>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QRegularExpression>
#include <QSettings>
#include <QStatusBar>
#include <QTabBar>
#include <QTabWidget>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTreeWidget>

#include "tests/editor/catalogue.h"
#include "tests/editor/window_fixture.h"

#include <gtest/gtest.h>

#include <map>

using namespace rung;

namespace {

std::vector<test::Message> catalogue(const QString &code) {
    return test::readCatalogue(
        QStringLiteral(RUNG_SOURCE_DIR "/translations/rungstudio_%1.ts").arg(code));
}

// The texts language `old` shows where language `now` shows another text, as patterns.
class OldTexts {
public:
    OldTexts(const QString &old, const QString &now) {
        // English is the source text, its plural forms are in the English catalogue.
        std::map<std::pair<QString, QString>, QStringList> english;
        for (const test::Message &m : catalogue(QStringLiteral("en")))
            english[{m.context, m.source}] = m.forms;
        const auto formsIn = [&](const QString &code, const test::Message &m,
                                 const std::map<std::pair<QString, QString>, QStringList> &of) {
            if (code != QLatin1String("en"))
                return of.at({m.context, m.source});
            const auto plural = english.find({m.context, m.source});
            return plural != english.end() ? plural->second : QStringList{m.source};
        };
        // Every message of the hu catalogue, by context and source (all catalogues hold the
        // same messages).
        const QString any = old == QLatin1String("en") ? now : old;
        std::map<std::pair<QString, QString>, QStringList> oldForms, nowForms;
        const auto messages = catalogue(any);
        for (const test::Message &m : catalogue(old == QLatin1String("en") ? any : old))
            oldForms[{m.context, m.source}] = m.forms;
        for (const test::Message &m : catalogue(now == QLatin1String("en") ? any : now))
            nowForms[{m.context, m.source}] = m.forms;
        for (const test::Message &m : messages) {
            const QStringList was = formsIn(old, m, oldForms);
            const QStringList is = formsIn(now, m, nowForms);
            for (const QString &form : was)
                if (!is.contains(form))
                    add(form);
        }
    }

    // The old-language text that `text` is or contains, empty if none.
    QString foundIn(const QString &text) const {
        const QString plain = QString(text).remove(QLatin1Char('&')).simplified();
        for (const auto &[source, re] : m_patterns)
            if (re.match(plain).hasMatch())
                return source;
        for (const QString &phrase : m_phrases)
            if (plain.contains(phrase))
                return phrase;
        return QString();
    }
    bool empty() const { return m_patterns.empty(); }

private:
    void add(const QString &form) {
        static const QRegularExpression placeholder(QStringLiteral("%(?:n|L?[1-9])"));
        const QString plain = QString(form).remove(QLatin1Char('&')).simplified();
        const QStringList parts = plain.split(placeholder);
        QString literal = parts.join(QString());
        literal.remove(QRegularExpression(QStringLiteral("<[^>]*>"))); // markup is no word
        if (literal.count(QRegularExpression(QStringLiteral("\\p{L}"))) < 3)
            return; // "%1 ms", "%1: %2": nothing of a language in it
        QStringList escaped;
        for (const QString &p : parts)
            escaped << QRegularExpression::escape(p);
        m_patterns.emplace_back(form, QRegularExpression(QLatin1Char('^') +
                                                         escaped.join(QStringLiteral("(.*?)")) +
                                                         QLatin1Char('$')));
        // A phrase of two words or more is found inside a longer text too ("Rung Studio" is
        // the name, not a phrase).
        if (parts.size() == 1 && plain.count(QLatin1Char(' ')) >= 2 && plain.size() >= 12)
            m_phrases << plain;
    }

    std::vector<std::pair<QString, QRegularExpression>> m_patterns;
    QStringList m_phrases;
};

struct Text {
    QString where;
    QString text;
};

void addItem(std::vector<Text> &out, const QString &where, QTreeWidgetItem *item, int columns) {
    for (int c = 0; c < columns; ++c) {
        out.push_back({where + QStringLiteral(" item"), item->text(c)});
        out.push_back({where + QStringLiteral(" item tooltip"), item->toolTip(c)});
    }
    for (int i = 0; i < item->childCount(); ++i)
        addItem(out, where, item->child(i), columns);
}

// The rows of a model under `parent` and theirs (the watch lists' devices), as drawn.
void addRows(std::vector<Text> &out, const QString &where, const QAbstractItemModel &m,
             const QModelIndex &parent) {
    for (int r = 0; r < m.rowCount(parent); ++r) {
        for (int c = 0; c < m.columnCount(parent); ++c) {
            const QModelIndex index = m.index(r, c, parent);
            out.push_back({where + QStringLiteral(" item"), index.data().toString()});
            out.push_back(
                {where + QStringLiteral(" item tooltip"), index.data(Qt::ToolTipRole).toString()});
        }
        addRows(out, where, m, m.index(r, 0, parent));
    }
}

// Every text the window holds for the user to read.
std::vector<Text> windowTexts(QMainWindow &window) {
    std::vector<Text> out;
    QList<QWidget *> widgets = window.findChildren<QWidget *>();
    widgets.prepend(&window);
    for (QWidget *w : widgets) {
        const QString where =
            QString::fromLatin1(w->metaObject()->className()) + QLatin1Char('#') + w->objectName();
        if (w->isWindow() || qobject_cast<QDockWidget *>(w))
            out.push_back({where + QStringLiteral(" title"), w->windowTitle()});
        out.push_back({where + QStringLiteral(" tooltip"), w->toolTip()});
        out.push_back({where + QStringLiteral(" status tip"), w->statusTip()});
        out.push_back({where + QStringLiteral(" what's this"), w->whatsThis()});
        out.push_back({where + QStringLiteral(" accessible name"), w->accessibleName()});
        if (auto *label = qobject_cast<QLabel *>(w))
            out.push_back({where, label->text()});
        if (auto *button = qobject_cast<QAbstractButton *>(w))
            out.push_back({where, button->text()});
        if (auto *edit = qobject_cast<QLineEdit *>(w))
            out.push_back({where + QStringLiteral(" placeholder"), edit->placeholderText()});
        if (auto *combo = qobject_cast<QComboBox *>(w))
            for (int i = 0; i < combo->count(); ++i)
                out.push_back({where + QStringLiteral(" item"), combo->itemText(i)});
        if (auto *tabs = qobject_cast<QTabBar *>(w))
            for (int i = 0; i < tabs->count(); ++i) {
                out.push_back({where + QStringLiteral(" tab"), tabs->tabText(i)});
                out.push_back({where + QStringLiteral(" tab tooltip"), tabs->tabToolTip(i)});
            }
        if (auto *menu = qobject_cast<QMenu *>(w))
            out.push_back({where + QStringLiteral(" menu title"), menu->title()});
        if (auto *tree = qobject_cast<QTreeWidget *>(w)) {
            addItem(out, where + QStringLiteral(" header"), tree->headerItem(),
                    tree->columnCount());
            // A list out of sight (the cross reference behind the project tab) is filled
            // anew when it comes into view.
            for (int i = 0; tree->isVisible() && i < tree->topLevelItemCount(); ++i)
                addItem(out, where, tree->topLevelItem(i), tree->columnCount());
        }
        // A view over a model of its own (the problems list): its headers and rows as drawn.
        if (auto *view = qobject_cast<QAbstractItemView *>(w);
            view && view->model() && !qobject_cast<QTreeWidget *>(w) &&
            !qobject_cast<QTableWidget *>(w) && !qobject_cast<QHeaderView *>(w)) {
            const QAbstractItemModel *m = view->model();
            for (int c = 0; c < m->columnCount(); ++c) {
                out.push_back({where + QStringLiteral(" header"),
                               m->headerData(c, Qt::Horizontal).toString()});
                out.push_back({where + QStringLiteral(" header tooltip"),
                               m->headerData(c, Qt::Horizontal, Qt::ToolTipRole).toString()});
            }
            if (view->isVisible())
                addRows(out, where, *m, {});
        }
        if (auto *table = qobject_cast<QTableWidget *>(w))
            for (int c = 0; c < table->columnCount(); ++c) {
                if (QTableWidgetItem *h = table->horizontalHeaderItem(c))
                    out.push_back({where + QStringLiteral(" header"), h->text()});
                for (int r = 0; r < table->rowCount(); ++r)
                    if (QTableWidgetItem *item = table->item(r, c)) {
                        out.push_back({where + QStringLiteral(" cell"), item->text()});
                        out.push_back({where + QStringLiteral(" cell tooltip"), item->toolTip()});
                    }
            }
        if (auto *sci = qobject_cast<QsciScintilla *>(w))
            for (int line = 0; line < sci->lines(); ++line) {
                out.push_back(
                    {where + QStringLiteral(" line %1").arg(line + 1), sci->text(line).trimmed()});
                out.push_back(
                    {where + QStringLiteral(" note %1").arg(line + 1), sci->annotation(line)});
            }
        if (auto *status = qobject_cast<QStatusBar *>(w))
            out.push_back({where + QStringLiteral(" message"), status->currentMessage()});
    }
    for (QAction *a : window.findChildren<QAction *>()) {
        const QString where = QStringLiteral("action ") + a->objectName();
        out.push_back({where, a->text()});
        out.push_back({where + QStringLiteral(" tooltip"), a->toolTip()});
        out.push_back({where + QStringLiteral(" status tip"), a->statusTip()});
    }
    std::erase_if(out, [](const Text &t) { return t.text.trimmed().isEmpty(); });
    return out;
}

// "where: text (the old text)" for each text of the old language left in the window.
QStringList leftOver(QMainWindow &window, const OldTexts &old) {
    QStringList found;
    for (const Text &t : windowTexts(window))
        for (const QString &line : t.text.split(QLatin1Char('\n')))
            if (const QString was = old.foundIn(line); !was.isEmpty())
                found << QStringLiteral("%1: \"%2\" (%3)").arg(t.where, line, was);
    found.removeDuplicates();
    return found;
}

QStringList linesOf(const QString &text) {
    QStringList lines = text.split(QLatin1Char('\n'));
    for (QString &line : lines)
        line = line.trimmed();
    return lines;
}

using rung::testing::vigor;

// Something of everything: a coil driven twice (a finding), a bridge the list cannot express
// (a placeholder line), a contact on no path (a marked line), a symbol, a symbol row that is
// no symbol yet (its tooltip says why), a watch list.
model::Project busyProject() {
    const model::ParseResult parsed = model::parseInstructionList(
        vigor(), QStringLiteral("LD X0\nOUT Y0\nLD X1\nOUT Y0\nLD X2\nOUT Y2\nEND\n"));
    model::Project p;
    p.target = &vigor();
    p.model = vigor().defaultModel().name;
    p.program = model::listToLadder(parsed.list).ladder;
    const char *bridge = "LADDER vigor WIDTH 8\n"
                         "RUNG 1 ROWS 3 COLUMNS 3\n"
                         "|-[ X0 ]-+----------[ X1 ]-+(OUT Y0)\n"
                         "|        |                 |\n"
                         "|        +-[ X2 ]-+        +\n"
                         "|                 |        |\n"
                         "|-[ X3 ]----------+-[ X4 ]-+\n";
    p.program.rungs.insert(
        p.program.rungs.begin() + 2,
        model::parseLadderText(vigor(), QString::fromLatin1(bridge)).ladder.rungs.at(0));
    model::Rung &third = p.program.rungs.at(3);
    third.resize(2, third.columns);
    QString why;
    third.cell(1, 0).kind = model::CellKind::Contact;
    third.cell(1, 0).contact = *model::contactFromText(vigor(), QStringLiteral("X5"), &why);
    const auto x0 = model::parseAddress(vigor(), QStringLiteral("X0"));
    p.symbols.push_back({std::get<model::Address>(x0), QStringLiteral("Start"), {}});
    p.pendingSymbols.push_back({QStringLiteral("X9"), QStringLiteral("Spare"), {}});
    p.watchLists.push_back({QStringLiteral("Lamps"), {QStringLiteral("X0"), QStringLiteral("Y0")}});
    return p;
}

struct LanguageWalk : test::WindowFixture {
    QTemporaryDir dir;
    void SetUp() override {
        WindowFixture::SetUp();
        const QString path = dir.filePath(QStringLiteral("busy.rung"));
        ASSERT_TRUE(model::saveProject(busyProject(), path, nullptr));
        ASSERT_TRUE(window.openFile(path, QString(), true));
        window.show();
        QApplication::processEvents();
    }
    void TearDown() override {
        app::setLanguage(QStringLiteral("en"), false);
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
        QSettings().remove(QStringLiteral("ui/language"));
    }
};

} // namespace

TEST(LanguageWalkTexts, FindsTheOldLanguageAndNothingElse) {
    const OldTexts english(QStringLiteral("en"), QStringLiteral("hu"));
    ASSERT_FALSE(english.empty());
    EXPECT_FALSE(english.foundIn(QStringLiteral("&File")).isEmpty());
    EXPECT_FALSE(english.foundIn(QStringLiteral("Rung 3, row 1, column 2")).isEmpty());
    EXPECT_FALSE(english.foundIn(QStringLiteral("4 rungs")).isEmpty()); // a plural form
    EXPECT_TRUE(english.foundIn(QStringLiteral("LD X0")).isEmpty());
    EXPECT_TRUE(english.foundIn(QStringLiteral("Rung Studio")).isEmpty());
    const OldTexts hungarian(QStringLiteral("hu"), QStringLiteral("it"));
    EXPECT_FALSE(hungarian.foundIn(QStringLiteral("&Fájl")).isEmpty());
    EXPECT_TRUE(hungarian.foundIn(QStringLiteral("&File")).isEmpty());
}

TEST_F(LanguageWalk, NoTextOfTheOldLanguageIsLeft) {
    ASSERT_TRUE(window.isVisible());
    ASSERT_GT(window.document()->diagnostics().size(), 2u);
    window.statusBar()->showMessage(QStringLiteral("Saved /tmp/busy.rung"), 60000);
    // The list's caret on an instruction: its tooltip tells what the instruction does.
    if (auto *tabs = window.findChild<QTabWidget *>())
        tabs->setCurrentWidget(window.ilEditor());
    QApplication::processEvents();
    const int out = linesOf(window.ilEditor()->text()).indexOf(QStringLiteral("OUT Y2"));
    ASSERT_GE(out, 0);
    window.ilEditor()->setCursorPosition(out, 1);
    QApplication::processEvents(); // QScintilla tells of the move when it updates
    ASSERT_FALSE(window.ilEditor()->toolTip().isEmpty());
    test::pickMenuEntry(window, "Magyar");
    QStringList left = leftOver(window, OldTexts(QStringLiteral("en"), QStringLiteral("hu")));
    EXPECT_TRUE(left.isEmpty()) << left.join(QLatin1Char('\n')).toStdString();
    test::pickMenuEntry(window, "Italiano");
    left = leftOver(window, OldTexts(QStringLiteral("hu"), QStringLiteral("it")));
    EXPECT_TRUE(left.isEmpty()) << left.join(QLatin1Char('\n')).toStdString();
    test::pickMenuEntry(window, "English");
    left = leftOver(window, OldTexts(QStringLiteral("it"), QStringLiteral("en")));
    EXPECT_TRUE(left.isEmpty()) << left.join(QLatin1Char('\n')).toStdString();
}

// The list as typed with an error: the ladder's notice and the list's findings follow the
// language; the typed text stays as it is.
TEST_F(LanguageWalk, TheNoticeOfAListWithErrorsFollows) {
    const QString typed = QStringLiteral("LD X8\nOUT Y1\nEND\n");
    window.ilEditor()->setText(typed);
    window.applyListing();
    auto *notice = window.findChild<QLabel *>(QStringLiteral("ladderNotice"));
    ASSERT_NE(notice, nullptr);
    const QString english = notice->text();
    ASSERT_FALSE(english.isEmpty());
    test::pickMenuEntry(window, "Italiano");
    EXPECT_EQ(window.ilEditor()->text(), typed);
    EXPECT_NE(notice->text(), english);
    const QStringList left = leftOver(window, OldTexts(QStringLiteral("en"), QStringLiteral("it")));
    EXPECT_TRUE(left.isEmpty()) << left.join(QLatin1Char('\n')).toStdString();
}
