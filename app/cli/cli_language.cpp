#include "cli_language.h"

#include "app/languages.h"
#include "app/tr.h"

#include <QCoreApplication>

namespace rung::app {

bool takeLanguageOption(QStringList *arguments, QString *language, QString *error) {
    language->clear();
    for (qsizetype i = 1; i < arguments->size(); ++i) {
        const QString arg = arguments->at(i);
        QString code;
        if (arg == QLatin1String("--lang")) {
            code = arguments->value(i + 1);
            arguments->remove(i, std::min<qsizetype>(2, arguments->size() - i));
        } else if (arg.startsWith(QLatin1String("--lang="))) {
            code = arg.mid(7);
            arguments->remove(i);
        } else {
            continue;
        }
        if (!languageCodes().contains(code)) {
            *error = CliTr::tr("--lang must be one of %1")
                         .arg(languageCodes().join(QLatin1String(", ")));
            return false;
        }
        *language = code;
        --i;
    }
    return true;
}

} // namespace rung::app
