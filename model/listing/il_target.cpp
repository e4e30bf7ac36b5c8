#include "model/listing/il.h"

#include <QRegularExpression>

// Which PLC a listing is for, when nobody says: its first line, else its own syntax.

namespace rung::model {

QString declaredTarget(const QString &text) {
    static const QRegularExpression re(QStringLiteral("^\\s*(?:;|//)\\s*target\\s*:\\s*(\\w+)"),
                                       QRegularExpression::CaseInsensitiveOption);
    const auto m = re.match(text.section(QLatin1Char('\n'), 0, 0));
    return m.hasMatch() ? m.captured(1) : QString();
}

QString listingTarget(const QString &text, const QString &fallback) {
    const QString declared = declaredTarget(text);
    if (!declared.isEmpty())
        return declared;
    // The families' syntaxes hardly overlap (X0 / i00 / 000.00 / I1): a listing that only
    // one of them reads is that family's. The fallback goes first, so it wins a tie.
    const Target *preferred = Target::byId(fallback);
    if (preferred && parseInstructionList(*preferred, text).ok())
        return fallback;
    for (Family family : Target::families()) {
        const Target &t = Target::get(family);
        if (&t != preferred && parseInstructionList(t, text).ok())
            return t.id;
    }
    return fallback;
}

} // namespace rung::model
