#pragma once

// Comparing two programs of one target rung by rung (docs/version-control.md): what the
// command-line tool's `diff` prints and what the IDE's Compare With... draws. The matching is
// structural: a rung is known by its logic (its instructions in the canonical form the
// converter writes), so a rung drawn another way, typed in a fuzzy spelling or laid out with
// other whitespace is the same rung, and one moved ten places and changed in one contact is
// found as "moved and changed", not as a deletion and an insertion.

#include "model/convert/convert.h"
#include "model/project/project.h"

#include <QString>

#include <vector>

namespace rung::model {

enum class RungStatus : std::uint8_t {
    Same,         // the same logic and comment, in the same order
    Moved,        // the same logic and comment elsewhere in the order
    Changed,      // in its place, with changes
    MovedChanged, // elsewhere, with changes
    Inserted,     // only in B
    Deleted,      // only in A
};

// One element of a rung that differs: a contact, an output (coil or box), or the branches
// that join them (ANB, ORB, MPS, MRD, MPP: "the connections changed").
struct ElementChange {
    enum class Element : std::uint8_t { Contact, Output, Branches } element = Element::Contact;
    enum class Kind : std::uint8_t { Changed, Added, Removed } kind = Kind::Changed;
    QString before; // the instruction as the target's listing writes it ("AND X1"); "" if added
    QString after;  // "" if removed
    struct Operand {
        int index = 0; // 0-based among the instruction's operands
        QString before, after;
    };
    std::vector<Operand> operands; // Changed, the same instruction: the operands that differ
    // Where the element is drawn in A's and B's rung (row and column; an output: its row and
    // the output column; the branches: -1), for the side-by-side view.
    CellOrigin cellA, cellB;
};

struct RungDifference {
    RungStatus status = RungStatus::Same;
    int a = -1; // rung index in A (-1: inserted)
    int b = -1; // rung index in B (-1: deleted)
    std::vector<ElementChange> elements;
    bool commentChanged = false;
    QString commentA, commentB; // the comments as written, when they differ
    // The rung's canonical listing, one instruction a line (a deleted rung's from A, else B's):
    // what a report shows of an inserted or deleted rung.
    QStringList instructions;
};

// A named item around the program: a symbol, a set value, a watch list.
struct ItemDifference {
    enum class Kind : std::uint8_t { Added, Removed, Changed } kind = Kind::Changed;
    QString key;    // the device (symbols, set values) or the list's name (watch lists)
    QString field;  // what changed: "name", "comment", "value", "devices", "format", ...
    QString before; // as the file writes it
    QString after;
    QString subject; // watch lists: the device a "device" or "format" item is about
};

struct Comparison {
    const Target *target = nullptr;
    QString modelA, modelB;
    std::vector<RungDifference> rungs; // every rung of both, in B's order, deleted ones
                                       // where they stood in A
    std::vector<ItemDifference> symbols;
    std::vector<ItemDifference> setValues;
    std::vector<ItemDifference> watchLists;
    // The instruction list as typed with errors (project files' pendingListing) and the symbol
    // rows that are no symbol yet: compared as text.
    std::vector<ItemDifference> pending;
    bool equal() const;
    int count(RungStatus status) const;
};

// A program's rungs as the comparison knows them: its logic and its comment.
struct ComparedRung {
    QString signature; // the canonical instructions, one a line (or the drawing)
    QString comment;   // whitespace collapsed
    std::vector<Instruction> instructions; // canonical; empty when the rung does not list
    std::vector<CellOrigin> origin;        // per instruction: its cell in the rung
};
std::vector<ComparedRung> comparedRungs(const LadderProgram &program);

// Both projects must be of one target (the caller says so otherwise). Listings are compared
// through their ladder (Project::program), with a listing's comments written after an
// instruction counted as its rung's comment (see rungCommentsOfListing).
Comparison compareProjects(const Project &a, const Project &b);

// A listing's ladder with the comments written after its instructions ("LD X0 ; start") added
// to their rung's comment, so that where a comment is written does not make a difference.
// `ladder` is listToLadder(list).ladder; rungs that did not convert are left as they are.
void addInstructionComments(const InstructionList &list, LadderProgram *ladder);

// The two instruction lists side by side, rung by rung as the comparison pairs them: a heading
// row per rung, then its instructions aligned (the same on both sides, one changed into the
// other, only in A, only in B). For the IDE's Compare With... list.
struct ListingRow {
    enum class Kind : std::uint8_t { Rung, Same, Changed, Removed, Added } kind = Kind::Same;
    int difference = -1; // the rung's entry in Comparison::rungs
    QString a, b;        // the instructions as the target writes them ("" where none)
};
std::vector<ListingRow> comparisonListing(const Comparison &comparison, const LadderProgram &a,
                                          const LadderProgram &b);

// The report: translated text (only what differs, then a summary line) or JSON (every rung
// with its status; keys and statuses are not translated: docs/version-control.md).
QString comparisonText(const Comparison &comparison, const QString &nameA, const QString &nameB);
QByteArray comparisonJson(const Comparison &comparison, const QString &nameA, const QString &nameB);
// The stable word of a status in JSON: "same", "moved", "changed", "moved-changed",
// "inserted", "deleted".
QString rungStatusKey(RungStatus status);

} // namespace rung::model
