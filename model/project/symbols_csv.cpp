#include "model/project/symbols_csv.h"

#include "model/target/address.h"

#include <QCoreApplication>

#include <algorithm>

namespace rung::model {

namespace {

QString field(const QString &s) {
    static const QString special = QStringLiteral(",;\"\n\r");
    bool quote = s.startsWith(QLatin1Char(' ')) || s.endsWith(QLatin1Char(' '));
    for (QChar c : s)
        quote = quote || special.contains(c);
    if (!quote)
        return s;
    QString q = s;
    q.replace(QLatin1String("\""), QLatin1String("\"\""));
    return QLatin1Char('"') + q + QLatin1Char('"');
}

struct Record {
    int line = 0; // where it starts
    QStringList fields;
};

// Splits the whole text, so a quoted field may run over several lines.
std::vector<Record> records(const QString &text) {
    std::vector<Record> out;
    Record current;
    QString value;
    bool quoted = false;
    bool any = false; // the record has a character or a separator
    int line = 1;
    current.line = 1;
    auto endRecord = [&] {
        if (any || !value.isEmpty()) {
            current.fields << value;
            out.push_back(current);
        }
        current = Record{};
        value.clear();
        any = false;
    };
    for (qsizetype i = 0; i < text.size(); ++i) {
        const QChar c = text[i];
        if (quoted) {
            if (c == QLatin1Char('"') && i + 1 < text.size() && text[i + 1] == QLatin1Char('"')) {
                value += c;
                ++i;
            } else if (c == QLatin1Char('"')) {
                quoted = false;
            } else {
                if (c == QLatin1Char('\n'))
                    ++line;
                value += c;
            }
            continue;
        }
        if (c == QLatin1Char('"')) {
            quoted = true;
            any = true;
        } else if (c == QLatin1Char(',') || c == QLatin1Char(';')) {
            current.fields << value;
            value.clear();
            any = true;
        } else if (c == QLatin1Char('\n')) {
            endRecord();
            ++line;
            current.line = line;
        } else if (c != QLatin1Char('\r')) {
            if (!c.isSpace() || !value.isEmpty())
                value += c;
            any = any || !c.isSpace();
        }
    }
    endRecord();
    return out;
}

} // namespace

QString symbolsToCsv(const Target &target, const std::vector<Symbol> &symbols) {
    QString text = QStringLiteral("device,name,comment\n");
    for (const Symbol &s : symbols)
        text += field(formatAddress(target, s.address)) + QLatin1Char(',') + field(s.name) +
                QLatin1Char(',') + field(s.comment) + QLatin1Char('\n');
    return text;
}

SymbolsCsv symbolsFromCsv(const Target &target, const ModelVariant *modelVariant,
                          const QString &text) {
    SymbolsCsv result;
    QString body = text;
    if (body.startsWith(QChar(0xfeff)))
        body.remove(0, 1);
    bool first = true;
    for (const Record &r : records(body)) {
        const QString device = r.fields.value(0).trimmed();
        if (first && device.compare(QLatin1String("device"), Qt::CaseInsensitive) == 0) {
            first = false;
            continue; // the header row
        }
        first = false;
        if (device.isEmpty() && r.fields.join(QString()).trimmed().isEmpty())
            continue;
        auto parsed = parseAddress(target, device, modelVariant);
        if (auto *e = std::get_if<AddressError>(&parsed)) {
            result.error = device.isEmpty()
                               ? QCoreApplication::translate("rung::model::SymbolsCsv",
                                                             "a symbol without a device")
                               : e->message;
            result.errorLine = r.line;
            result.symbols.clear();
            return result;
        }
        Symbol s{std::get<Address>(parsed), r.fields.value(1).trimmed(),
                 r.fields.value(2).trimmed()};
        auto same = std::find_if(result.symbols.begin(), result.symbols.end(),
                                 [&](const Symbol &o) { return o.address == s.address; });
        if (same != result.symbols.end())
            *same = s;
        else
            result.symbols.push_back(s);
    }
    return result;
}

} // namespace rung::model
