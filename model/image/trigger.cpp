#include "model/image/trigger.h"

#include "model/target/address.h"
#include "model/target/target_lists.h"
#include "model/tr.h"

#include <QCoreApplication>
#include <QRegularExpression>

namespace rung::model {

namespace {

bool isBitDevice(const Target &target, const Address &a) {
    return a.bit >= 0 || target.area(a.area).kind == AreaKind::Bit;
}

} // namespace

bool Trigger::holds(qint64 v) const {
    switch (kind) {
    case Kind::Rises:
        return v != 0;
    case Kind::Falls:
        return v == 0;
    case Kind::Compare:
        break;
    }
    return compareHolds(op, v, value);
}

std::variant<Trigger, QString> parseTrigger(const Target &target, const QString &text,
                                            const ModelVariant *model) {
    // The device is everything before the condition: CPM1 writes "TIM 000" with a space.
    static const QRegularExpression edge(QStringLiteral("^(.+?)\\s*(rises|falls|↑|↓)$"),
                                         QRegularExpression::CaseInsensitiveOption);
    const QString typed = text.trimmed();
    if (typed.isEmpty())
        return TriggerTr::tr("Type a condition: \"%1 rises\", \"%1 falls\" or \"%2 > 100\"")
            .arg(exampleDevice(target, true), exampleWord(target, 10));
    Trigger trigger;
    QString device;
    if (const auto m = edge.match(typed); m.hasMatch()) {
        device = m.captured(1);
        const QString word = m.captured(2).toLower();
        trigger.kind = word == QLatin1String("rises") || word == QStringLiteral("↑")
                           ? Trigger::Kind::Rises
                           : Trigger::Kind::Falls;
    } else if (const std::optional<CompareAt> c = findCompare(typed);
               c && !typed.sliced(c->at + c->length).trimmed().isEmpty()) {
        device = typed.first(c->at);
        trigger.kind = Trigger::Kind::Compare;
        trigger.op = c->op;
        const QString number = typed.sliced(c->at + c->length).trimmed();
        bool ok = false;
        trigger.value = number.startsWith(QLatin1String("0x"), Qt::CaseInsensitive)
                            ? number.mid(2).toLongLong(&ok, 16)
                            : number.toLongLong(&ok, 10);
        if (!ok)
            return TriggerTr::tr("\"%1\" is not a whole number (0x before a hexadecimal one)")
                .arg(number);
    } else {
        return TriggerTr::tr("\"%1\" is no condition: write \"%2 rises\", \"%2 falls\" or "
                             "\"%3 > 100\"")
            .arg(typed, exampleDevice(target, true), exampleWord(target, 10));
    }
    const auto parsed = parseAddress(target, device.trimmed(), model);
    if (const auto *error = std::get_if<AddressError>(&parsed))
        return error->message;
    trigger.device = std::get<Address>(parsed);
    const bool bit = isBitDevice(target, trigger.device);
    if (trigger.kind != Trigger::Kind::Compare && !bit)
        return TriggerTr::tr("%1 is a word: compare it with a value (\"%1 > 100\")")
            .arg(formatAddress(target, trigger.device));
    return trigger;
}

QString formatTrigger(const Target &target, const Trigger &trigger) {
    const QString device = formatAddress(target, trigger.device);
    switch (trigger.kind) {
    case Trigger::Kind::Rises:
        return device + QLatin1String(" rises");
    case Trigger::Kind::Falls:
        return device + QLatin1String(" falls");
    case Trigger::Kind::Compare:
        break;
    }
    return QStringLiteral("%1 %2 %3")
        .arg(device, QString::fromLatin1(compareSymbol(trigger.op)))
        .arg(trigger.value);
}

} // namespace rung::model
