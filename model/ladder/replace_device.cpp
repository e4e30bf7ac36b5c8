#include "model/ladder/replace_device.h"

namespace rung::model {

int replaceDevice(std::vector<Rung> &rungs, const Address &from, const Address &to) {
    int count = 0;
    auto replace = [&](std::vector<Operand> &operands) {
        for (Operand &o : operands)
            if (o.kind == Operand::Kind::Device && o.address == from) {
                o.address = to;
                ++count;
            }
    };
    for (Rung &r : rungs) {
        for (Cell &c : r.cells)
            replace(c.contact.operands);
        for (auto &out : r.outputs)
            if (out)
                replace(out->operands);
    }
    return count;
}

} // namespace rung::model
