#pragma once

// The instruction list as the user types it back: the list pane shows the canonical listing of
// the ladder, and where the list cannot say what the ladder holds, a marked comment line
// stands for it (editor::Document writes them): "; [[3:9f2c41]] ..." for a rung the list
// cannot express, "; [[3:9f2c41@2,1]] ..." for a contact of a listed rung that is on no path
// to an output (LD002). Reading a typed list puts each such rung and contact back where its
// line stands, so that editing the list never drops what the ladder holds. No widgets: the
// tests read it without a display.

#include "model/checks/diagnostic.h"
#include "model/convert/convert.h"

#include <map>
#include <optional>
#include <utility>
#include <vector>

namespace rung::model {

// The rungs marked lines have stood for, by the key a line carries ("3:9f2c41").
using HeldRungs = std::map<QString, Rung>;

// Keeps rung `index` in `held` and returns the key of the line that stands for it: its number
// and a hash of its drawing, so that text typed from an older list still finds its rung.
QString holdRung(HeldRungs &held, const Target &target, int index, const Rung &rung);

// The key a marked line carries ("3:9f2c41", or "3:9f2c41@2,1" for a contact), empty if the
// line is no marked line. The marker is the same in every language.
QString placeholderKey(const QString &line);

// The contacts of listed rung `index` that the list leaves out, being on no path to an
// output (LD002): (row, column), in reading order.
std::vector<std::pair<int, int>> leftOutContacts(const Rung &rung, int index,
                                                 const ToListingResult &listing);

// How a message names a contact: its device, else the contact as the ladder text writes it.
QString contactName(const Target &target, const Contact &contact);

struct TypedListing {
    // The program the text is, with the held rungs and the kept contacts back in place; empty
    // when the text is none (an error it has, a line that no held rung answers, a kept
    // contact that finds no place).
    std::optional<std::vector<Rung>> rungs;
    // Without rungs: why (the syntax errors, or every finding of the listing checks when the
    // text parses but cannot be drawn). With them: the fuzzy forms of the text as typed (FZ*,
    // with the canonical rewrite as a fix).
    std::vector<Diagnostic> findings;
};

TypedListing readTypedListing(const Target &target, const ModelVariant *model, const QString &text,
                              const HeldRungs &held);

} // namespace rung::model
