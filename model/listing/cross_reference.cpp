#include "cross_reference.h"

#include <map>
#include <optional>

namespace rung::model {

DeviceUse deviceUse(Op op) {
    switch (op) {
    case Op::Load:
    case Op::And:
    case Op::Or:
        return DeviceUse::Contact;
    case Op::Out:
    case Op::Set:
    case Op::Reset:
    case Op::PulseRise:
    case Op::PulseFall:
        return DeviceUse::Coil;
    default:
        return DeviceUse::Box;
    }
}

CrossReference crossReference(const Target &target, const ModelVariant *model,
                              const std::vector<Instruction> &instructions,
                              const std::vector<int> &rungFirst, const QString &text, int maxUses) {
    CrossReference out;
    const QString filter = text.trimmed();
    // A whole device shows only its uses; otherwise the text is a prefix of the names.
    std::optional<Address> exact;
    if (!filter.isEmpty()) {
        auto parsed = parseAddress(target, filter, model);
        if (auto *a = std::get_if<Address>(&parsed))
            exact = *a;
    }
    out.exact = exact.has_value();
    std::map<Address, std::vector<CrossReference::Use>> uses;
    const int last = static_cast<int>(instructions.size());
    for (std::size_t r = 0; r + 1 < rungFirst.size() && !out.capped; ++r) {
        const int end = std::min(rungFirst[r + 1], last);
        for (int i = rungFirst[r]; i < end && !out.capped; ++i) {
            const Instruction &ins = instructions[static_cast<std::size_t>(i)];
            for (const Operand &o : ins.operands) {
                if (o.kind != Operand::Kind::Device)
                    continue;
                if (exact ? !(o.address == *exact)
                          : !filter.isEmpty() && !formatAddress(target, o.address)
                                                      .startsWith(filter, Qt::CaseInsensitive))
                    continue;
                auto &places = uses[o.address];
                if (!places.empty() && places.back().step == ins.step)
                    continue;
                if (out.uses == maxUses) {
                    out.capped = true; // one more than the list holds
                    if (places.empty())
                        uses.erase(o.address);
                    break;
                }
                places.push_back({static_cast<int>(r), ins.step, deviceUse(ins.op()),
                                  printInstruction(target, ins)});
                ++out.uses;
            }
        }
    }
    out.devices.reserve(uses.size());
    for (auto &[address, places] : uses)
        out.devices.push_back({address, std::move(places)});
    return out;
}

} // namespace rung::model
