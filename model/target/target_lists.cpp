#include "model/target/target_lists.h"

#include "model/target/address.h"

#include <algorithm>

namespace rung::model {

QStringList targetIds() {
    QStringList out;
    for (const Family f : Target::families())
        out << Target::get(f).id;
    return out;
}

QStringList targetDisplayNames() {
    QStringList out;
    for (const Family f : Target::families())
        out << Target::get(f).displayName;
    return out;
}

QString exampleDevice(const Target &target, bool output) {
    for (std::size_t i = 0; i < target.areas.size(); ++i) {
        const Area &a = target.areas[i];
        if (!a.physical || a.writable != output ||
            (a.kind != AreaKind::Bit && a.kind != AreaKind::Channel))
            continue;
        return formatAddress(
            target, Address{static_cast<int>(i), a.first, a.kind == AreaKind::Channel ? 0 : -1});
    }
    return QString();
}

QString exampleWord(const Target &target, int offset) {
    // The plain data memory: a word area the program writes freely (not a system area, not an
    // index register, not presets); a channel area with a prefix (CPM1 DM) where the target
    // has no word area of that kind.
    const auto plain = [](const Area &a) {
        return a.writable && !a.system && !a.physical && !a.indexRegister && !a.presetsOf;
    };
    for (const AreaKind kind : {AreaKind::Word, AreaKind::Channel})
        for (std::size_t i = 0; i < target.areas.size(); ++i) {
            const Area &a = target.areas[i];
            if (a.kind != kind || !plain(a) || (kind == AreaKind::Channel && a.prefix.isEmpty()))
                continue;
            return formatAddress(
                target, Address{static_cast<int>(i), std::min(a.first + offset, a.last), -1});
        }
    return QString();
}

QString exampleWordRange(const Target &target, int count) {
    return QStringLiteral("%1..%2").arg(exampleWord(target, 0), exampleWord(target, count - 1));
}

} // namespace rung::model
