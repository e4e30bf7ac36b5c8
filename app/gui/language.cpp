#include "language.h"

#include "app/languages.h"

#include <QCoreApplication>
#include <QLibraryInfo>
#include <QLocale>
#include <QSettings>
#include <QTranslator>

#include <memory>

namespace rung::app {

namespace {

const auto kSetting = QStringLiteral("ui/language");

struct Installed {
    QString code;
    std::unique_ptr<QTranslator> ours;
    std::unique_ptr<QTranslator> qt;
};

Installed &installed() {
    static Installed languages;
    return languages;
}

} // namespace

QStringList availableLanguages() {
    return languageCodes();
}

QString languageFor(const QLocale &locale, const QString &remembered) {
    if (availableLanguages().contains(remembered))
        return remembered;
    const QString spoken = QLocale::languageToCode(locale.language());
    return availableLanguages().contains(spoken) ? spoken : QStringLiteral("en");
}

QString startLanguage() {
    return languageFor(QLocale::system(), QSettings().value(kSetting).toString());
}

QString currentLanguage() {
    return installed().code.isEmpty() ? QStringLiteral("en") : installed().code;
}

bool setLanguage(const QString &code, bool remember) {
    if (!availableLanguages().contains(code))
        return false;
    Installed &now = installed();
    // English has a catalogue too: its plural forms ("1 rung", "2 rungs").
    auto ours = std::make_unique<QTranslator>();
    if (!ours->load(QStringLiteral(":/i18n/rungstudio_%1").arg(code)))
        ours.reset();
    auto qt = std::make_unique<QTranslator>();
    if (!qt->load(QStringLiteral("qtbase_%1").arg(code),
                  QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        qt.reset(); // English, or the package qt6-translations-l10n is not installed
    // Each install and removal makes Qt post LanguageChange; widgets retranslate once the
    // events arrive, with the new catalogues in place.
    if (now.ours)
        QCoreApplication::removeTranslator(now.ours.get());
    if (now.qt)
        QCoreApplication::removeTranslator(now.qt.get());
    now.ours = std::move(ours);
    now.qt = std::move(qt);
    if (now.qt)
        QCoreApplication::installTranslator(now.qt.get());
    if (now.ours)
        QCoreApplication::installTranslator(now.ours.get());
    now.code = code;
    if (remember)
        QSettings().setValue(kSetting, code);
    return true;
}

} // namespace rung::app
