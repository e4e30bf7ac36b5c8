#pragma once

// A listing finding with the instructions it is about, so the ladder checks can place it on
// the rung those instructions came from. Internal to model/.

#include "model/checks/checks.h"

#include <optional>
#include <utility>
#include <vector>

namespace rung::model::detail {

struct Finding {
    Diagnostic diagnostic;
    int instruction = -1;     // index in the listing
    std::vector<int> related; // indexes of the related instructions
    // The message for the ladder, where listing lines mean nothing: %1 is the rung (1-based)
    // of the first related instruction. Empty: the message serves both.
    QString ladderMessage;
};

// A finding on instruction `index` of `list` (its line and column), appended to `found`.
Finding &addFinding(std::vector<Finding> &found, const InstructionList &list, const char *code,
                    Severity severity, int index, const QString &message);
// END missing or not last, IL/ILC, JMP/JPE (JME) and STL/RET nesting.
void endAndNesting(const InstructionList &list, std::vector<Finding> &found);
// OP006: timers / counters a system bit switches (Area::enabledBy) left off by the program.
void switchedElements(const InstructionList &list, std::vector<Finding> &found);

// A rung of a listing as the converter writes it back. A form is fuzzy only where its text
// differs from that: the canonical listing never gets a fuzzy-form warning.
struct RungForm {
    bool known = false;     // the rung converts on its own
    bool canonical = false; // its instructions are the converter's
    std::vector<Instruction> rewrite;
};
RungForm canonicalForm(const InstructionList &list, int first, int last);

// Whether [first, last] holds MPS, MRD or MPP.
bool stackBetween(const InstructionList &list, int first, int last);
// FZ004: the AND form of the load right after the single contact at `single` when the block
// it opens, up to the ANB at `join`, is contacts in series only; nullopt otherwise.
std::optional<const InstructionSpec *> inSeries(const InstructionList &list, int single, int join);
// FZ004/FZ005: the rung `span` with the single contact `single` (a load) moved behind the
// block it is joined with at `join`, as `as` (And/Or), and the ANB/ORB dropped. A block of
// contacts in series joined by ANB stays behind the single contact instead (inSeries).
std::optional<std::vector<Instruction>>
moveBehind(const InstructionList &list, std::pair<int, int> span, int single, int join, Op as);
// FZ006: the rung `span` with the output after the MRD/MPP at `read` put before its MPS, and
// the stack instructions it needed dropped. Only where that output is its branch's whole
// content.
std::optional<std::vector<Instruction>> liftOutput(const InstructionList &list,
                                                   std::pair<int, int> span, int read);

// forms == false: no fuzzy-form findings (the ladder's own listing), and none of their work.
std::vector<Finding> checkListFindings(const InstructionList &list, const CheckOptions &options,
                                       bool forms = true);

} // namespace rung::model::detail
