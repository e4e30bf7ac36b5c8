// The Hungarian and Italian catalogues: complete, faithful to the placeholders, embedded in the
// program, and reaching every room (menus, diagnostics of the model, QScintilla's own menu).
#include "app/gui/main_window.h"
#include "app/gui/network_window.h"
#include "editor/il_editor.h"
#include "model/checks/checks.h"
#include "model/listing/il.h"
#include "model/target/target.h"

#include <QApplication>
#include <QFile>
#include <QMenu>
#include <QMenuBar>
#include <QRegularExpression>
#include <QTranslator>
#include <QXmlStreamReader>

#include "tests/editor/catalogue.h"

#include <gtest/gtest.h>

#include <map>
#include <memory>
#include <set>

using namespace rung;
using test::Message;
using test::readCatalogue;

namespace {

std::multiset<QString> placeholders(const QString &text, bool numerus) {
    static const QRegularExpression re(QStringLiteral("%(?:n|L?[1-9])"));
    std::multiset<QString> found;
    for (const auto &m : re.globalMatch(text)) {
        // A plural form may say "one" instead of "%n" (Italian "un segmento").
        if (!(numerus && m.captured() == QLatin1String("%n")))
            found.insert(m.captured());
    }
    return found;
}

// Installs a catalogue for one test and takes it away again.
class Language {
public:
    explicit Language(const QString &code) {
        m_loaded = m_translator.load(QStringLiteral(":/i18n/rungstudio_%1").arg(code));
        if (m_loaded)
            QCoreApplication::installTranslator(&m_translator);
    }
    ~Language() { QCoreApplication::removeTranslator(&m_translator); }
    bool loaded() const { return m_loaded; }

private:
    QTranslator m_translator;
    bool m_loaded = false;
};

QStringList menuTitles(const QMainWindow &window) {
    QStringList titles;
    for (QAction *a : window.menuBar()->actions())
        titles << a->text();
    return titles;
}

// The access keys (the letter after '&') that two entries of one menu share, as
// "menu: key (first, second)"; the menu bar counts as a menu too.
QStringList clashingAccessKeys(const QString &where, const QList<QAction *> &actions) {
    QStringList clashes;
    std::map<QChar, QString> seen;
    static const QRegularExpression key(QStringLiteral("&([^& ])"));
    for (QAction *a : actions) {
        if (a->isSeparator())
            continue;
        const QRegularExpressionMatch m = key.match(a->text());
        if (m.hasMatch()) {
            const QChar letter = m.captured(1).at(0).toLower();
            const auto [it, fresh] = seen.emplace(letter, a->text());
            if (!fresh)
                clashes
                    << QStringLiteral("%1: %2 (%3, %4)").arg(where, letter, it->second, a->text());
        }
        if (a->menu())
            clashes << clashingAccessKeys(a->text(), a->menu()->actions());
    }
    return clashes;
}

struct Finding {
    QString code;
    QString message;
};

std::vector<Finding> vigorFindings() {
    const auto &vigor = model::Target::get(model::Family::Vigor);
    // An octal slip, a coil written twice and no END.
    const auto parsed =
        parseInstructionList(vigor, QStringLiteral("LD X8\nLD X0\nOUT Y0\nLD X1\nOUT Y0\n"));
    std::vector<Finding> findings;
    for (const auto &e : parsed.errors)
        findings.push_back({QStringLiteral("parse"), e.message});
    for (const auto &d : model::checkList(parsed.list))
        findings.push_back({d.code, d.message});
    return findings;
}

} // namespace

class Catalogue : public ::testing::TestWithParam<const char *> {};

TEST_P(Catalogue, EveryTextIsTranslatedAndKeepsItsPlaceholders) {
    const QString path =
        QStringLiteral(RUNG_SOURCE_DIR "/translations/rungstudio_%1.ts").arg(GetParam());
    const auto messages = readCatalogue(path);
    ASSERT_GT(messages.size(), 500u);
    for (const auto &m : messages) {
        const std::string where = (m.context + QLatin1String(": ") + m.source).toStdString();
        EXPECT_TRUE(m.finished) << "unfinished: " << where;
        ASSERT_FALSE(m.forms.isEmpty()) << where;
        for (const QString &form : m.forms) {
            EXPECT_FALSE(form.trimmed().isEmpty()) << "empty: " << where;
            EXPECT_EQ(placeholders(form, m.numerus), placeholders(m.source, m.numerus))
                << where << " -> " << form.toStdString();
            // A menu accelerator stays an accelerator.
            if (m.source.contains(QRegularExpression(QStringLiteral("&[^& ]")))) {
                EXPECT_TRUE(form.contains(QRegularExpression(QStringLiteral("&[^& ]"))))
                    << where << " -> " << form.toStdString();
            }
        }
    }
}

TEST_P(Catalogue, IsEmbeddedAndTranslatesTheMenusTheDiagnosticsAndTheEditorsOwnMenu) {
    const auto english = vigorFindings();
    ASSERT_GE(english.size(), 3u); // the octal error, the duplicate coil, the missing END
    QStringList englishMenus;
    {
        app::MainWindow window;
        englishMenus = menuTitles(window);
    }

    Language language(QString::fromLatin1(GetParam()));
    ASSERT_TRUE(language.loaded());

    app::MainWindow window;
    const QStringList menus = menuTitles(window);
    ASSERT_EQ(menus.size(), englishMenus.size());
    // Every title comes from the catalogue; a word may stay as it is ("&File" in Italian).
    int changed = 0;
    for (int i = 0; i < menus.size(); ++i) {
        // The Simulation and Online menus are their controllers' (simulation_menu.h,
        // online_controller.h), the others the window's.
        const char *context =
            englishMenus[i] == QLatin1String("&Online")       ? "rung::app::OnlineController"
            : englishMenus[i] == QLatin1String("&Simulation") ? "rung::app::SimulationMenu"
                                                              : "rung::app::MainWindow";
        EXPECT_EQ(menus[i].toStdString(),
                  QCoreApplication::translate(context, englishMenus[i].toUtf8().constData())
                      .toStdString());
        changed += menus[i] != englishMenus[i] ? 1 : 0;
    }
    EXPECT_GE(changed, menus.size() - 1);

    const auto translated = vigorFindings();
    ASSERT_EQ(translated.size(), english.size());
    int devicesNamed = 0;
    for (size_t i = 0; i < english.size(); ++i) {
        EXPECT_EQ(translated[i].code, english[i].code);
        EXPECT_NE(translated[i].message, english[i].message) << english[i].message.toStdString();
        // Every device the English message names, the translation names too.
        static const QRegularExpression device(QStringLiteral("\\b[XY][0-9]+\\b"));
        for (const QRegularExpressionMatch &m : device.globalMatch(english[i].message)) {
            ++devicesNamed;
            EXPECT_TRUE(translated[i].message.contains(m.captured()))
                << m.captured().toStdString() << " is not named in "
                << translated[i].message.toStdString();
        }
    }
    // The octal slip names X8, the coil written twice Y0: both were looked for.
    EXPECT_GE(devicesNamed, 2);

    // QScintilla ships no catalogue of its own; ours answers its context menu.
    editor::IlEditor il(model::Target::get(model::Family::Vigor));
    std::unique_ptr<QMenu> menu(il.createStandardContextMenu());
    ASSERT_TRUE(menu);
    const auto actions = menu->actions();
    ASSERT_FALSE(actions.isEmpty());
    EXPECT_NE(actions.first()->text(), QStringLiteral("&Undo"));
    EXPECT_EQ(actions.first()->text(), QCoreApplication::translate("QsciScintilla", "&Undo"));
}

INSTANTIATE_TEST_SUITE_P(Translations, Catalogue, ::testing::Values("hu", "it"),
                         [](const auto &info) { return std::string(info.param); });

// Alt+letter reaches one entry only, in every language.
TEST(Translations, NoTwoEntriesOfAMenuShareAnAccessKey) {
    for (const char *code : {"en", "hu", "it"}) {
        Language language(QString::fromLatin1(code));
        ASSERT_TRUE(language.loaded()) << code;
        app::MainWindow window;
        const QStringList clashes =
            clashingAccessKeys(QStringLiteral("menu bar"), window.menuBar()->actions());
        EXPECT_TRUE(clashes.isEmpty())
            << code << ": " << clashes.join(QStringLiteral("; ")).toStdString();
        // The network window's menus too (Hungarian Speed and Run For shared "e" once).
        app::NetworkWindow network;
        const QStringList networkClashes =
            clashingAccessKeys(QStringLiteral("network menu bar"), network.menuBar()->actions());
        EXPECT_TRUE(networkClashes.isEmpty())
            << code << ": " << networkClashes.join(QStringLiteral("; ")).toStdString();
    }
}

TEST(Translations, EnglishSaysOneRungAndTwoRungs) {
    Language language(QStringLiteral("en"));
    ASSERT_TRUE(language.loaded());
    EXPECT_EQ(QCoreApplication::translate("rung::editor::Document", "Delete %n rungs", nullptr, 1),
              QStringLiteral("Delete 1 rung"));
    EXPECT_EQ(QCoreApplication::translate("rung::editor::Document", "Delete %n rungs", nullptr, 2),
              QStringLiteral("Delete 2 rungs"));
}

// The source texts are English: the English catalogue holds exactly the plural texts, each
// with its singular and plural form, and none is missing beside the other catalogues.
TEST(Translations, TheEnglishCatalogueHoldsEveryPluralTextAndNothingElse) {
    const auto english =
        readCatalogue(QStringLiteral(RUNG_SOURCE_DIR "/translations/rungstudio_en.ts"));
    std::set<std::pair<QString, QString>> plurals;
    for (const auto &m : english) {
        const std::string where = (m.context + QLatin1String(": ") + m.source).toStdString();
        EXPECT_TRUE(m.numerus) << "not a plural text: " << where;
        EXPECT_TRUE(m.finished) << "unfinished: " << where;
        ASSERT_EQ(m.forms.size(), 2) << where;
        for (const QString &form : m.forms) // "1 MPS", "2 MPS": the forms may be alike
            EXPECT_EQ(placeholders(form, true), placeholders(m.source, true)) << where;
        EXPECT_TRUE(m.forms[1].contains(QLatin1String("%n"))) << where;
        plurals.emplace(m.context, m.source);
    }
    std::set<std::pair<QString, QString>> expected;
    for (const auto &m :
         readCatalogue(QStringLiteral(RUNG_SOURCE_DIR "/translations/rungstudio_hu.ts")))
        if (m.numerus)
            expected.emplace(m.context, m.source);
    EXPECT_FALSE(expected.empty());
    EXPECT_EQ(plurals, expected);
}
