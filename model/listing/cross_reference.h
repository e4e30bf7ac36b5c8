#pragma once

// The cross reference of a program: for each device its uses, the rung and step of each and
// whether it is read as a contact, driven as a coil or an operand of a box. The IDE's Cross
// Reference panel shows it (editor/cross_reference_model.h); here it needs no display.

#include "model/listing/il.h"
#include "model/target/address.h"

#include <vector>

namespace rung::model {

enum class DeviceUse { Contact, Coil, Box };

// How an instruction uses its devices: LD/AND/OR (and their inverses) read a contact, OUT,
// SET, RST, PLS and PLF drive a coil, any other instruction uses them in a box.
DeviceUse deviceUse(Op op);

struct CrossReference {
    struct Use {
        int rung = 0; // 0-based
        int step = 0;
        DeviceUse use = DeviceUse::Contact;
        QString instruction; // as the target prints it: "TMR T0 K10"
    };
    struct Device {
        Address address;
        std::vector<Use> uses; // in program order, one per step
    };
    std::vector<Device> devices; // in address order
    int uses = 0;                // the uses listed, at most the limit given
    // More uses matched than the limit: the list ends at the limit.
    bool capped = false;
    // The filter named one device (only its uses are listed), not a prefix.
    bool exact = false;
};

// The uses of the devices `filter` names, rung by rung in `instructions` (rungFirst[r] is the
// index of rung r's first instruction, rungFirst.back() their number, as ToListingResult
// has it). The filter is a device ("X0": its uses only), else a prefix of the devices as the
// target writes them ("X", any case: every input), or empty (every device). An instruction
// that names a device twice (MOV D0 D0) is one use. At most maxUses uses.
CrossReference crossReference(const Target &target, const ModelVariant *model,
                              const std::vector<Instruction> &instructions,
                              const std::vector<int> &rungFirst, const QString &filter,
                              int maxUses);

} // namespace rung::model
