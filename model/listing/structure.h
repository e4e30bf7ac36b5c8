#pragma once

// The structure of a listing, defined once for every room that reads one: where its rungs
// begin and end, which IL / ILC, JMP / JPE (JME) and STL / RET belong together, and how deep
// its stacks may grow. The converter (IL -> ladder), the checks and the simulator's compiler
// all call these; none keeps a copy of its own (docs/listings.md "Structure").

#include "model/listing/il.h"

#include <QString>

#include <vector>

namespace rung::model {

// ---- rungs -----------------------------------------------------------------------------

// Instructions [first, last) of one rung.
struct RungSpan {
    int first = 0;
    int last = 0;
    friend bool operator==(const RungSpan &, const RungSpan &) = default;
};

// The rungs of a listing, in order, covering every instruction. A rung starts
// - at the first instruction,
// - at a load right after an output, unless an MPS is still pending (`MPP LD X1 ANB`
//   continues the branch) or a later ANB / ORB joins the block it opens to the accumulator
//   (`OUT Y0 LD X1 OR X2 ANB OUT Y1`: the branch point's condition and that block in series,
//   as the PLC runs it),
// - and an instruction that takes no condition (isUnconditional: END, ILC, JPE / JME, RET,
//   STL, NOP) is a rung of its own.
// The load that starts a rung also starts the PLC's block stack afresh.
std::vector<RungSpan> rungSpans(const std::vector<Instruction> &instructions);

// Whether instruction `index` is a load right after an output that no later ANB / ORB joins to
// the accumulator: it starts a new rung, or, with an MPS still pending, shows that the rung
// before it left its MPS open (ST003).
bool loadsAfterOutput(const std::vector<Instruction> &instructions, int index);

// The span holding instruction `index` (spans as rungSpans gives them).
RungSpan spanOf(const std::vector<RungSpan> &spans, int index);

// ---- blocks: IL / ILC, JMP / JPE (JME), STL / RET --------------------------------------

struct BlockProblem {
    const char *code = nullptr; // NE001..NE007, SL001 (docs/diagnostics.md)
    int instruction = -1;       // where it is reported
    int related = -1;           // another instruction the message is about, or -1
    QString message;            // translated
    bool aboutJump = false;     // the jump targets are wrong: a program cannot run
    bool warning = false;       // a warning, not an error (SB004)
};

struct BlockPairs {
    // Per instruction: an IL's ILC and back, a JMP's JPE / JME (the one with its number), a
    // JPE's JMP (a JME's first JMP), an SBN(92)'s RET(93) and back, an SBS(91)'s SBN(92); -1
    // when it has none or is no block instruction.
    std::vector<int> partner;
    std::vector<BlockProblem> problems; // in the order of the listing's walk
    int end = -1;                       // the first END, or -1 (nothing after it is paired)
};

// Pairs the blocks of a listing up to its first END. Targets with jump numbers
// (Limits::jumpLabels, CPM1 JMP(04) 00..49) pair a JMP with the JME of its number after it;
// several JMP may share a number, one JME ends it. The others nest JMP .. JPE and allow no
// jump inside a jump. IL inside IL, and an IL and a JMP that close out of order, are errors.
// CPM1 subroutines and steps (W353) are paired too: SBN(92) N .. RET(93) after the main
// program (SB001-SB004), STEP(08) B .. STEP(08) (SP001-SP003).
BlockPairs pairBlocks(const InstructionList &list);

// ---- stacks ------------------------------------------------------------------------------

// MPS levels are a PLC fact (Limits::stackDepth, 8 on every target: ST001). The simulator
// keeps a branch stack of this size, which no target's table may exceed (a test holds the
// tables to it).
inline constexpr int kMaxStackDepthOfAnyTarget = 32;

// Blocks a rung may hold open at once (each LD before its ANB / ORB, the first one included).
// Not a PLC fact: the manuals limit consecutive ANB / ORB (Limits::maxBlocksInRow, FZ003) or
// nothing (CPM1); this is the size of the simulator's block stack, and the compiler refuses a
// rung that needs more.
inline constexpr int kMaxOpenBlocks = 64;

} // namespace rung::model
