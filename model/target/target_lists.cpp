#include "model/target/target_lists.h"

#include "model/target/address.h"

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

} // namespace rung::model
