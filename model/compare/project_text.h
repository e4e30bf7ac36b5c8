#pragma once

// A project as a text to read and to compare line by line (git's textconv, docs/
// version-control.md): the canonical listing, a blank line between rungs, the rungs' comments
// as "; " lines; a rung the listing cannot hold (reverse current, an open branch) as its
// drawing in comment lines; then the symbols, set values, watch lists and what is kept as
// typed, as comment lines. Not translated: it is data a user keeps and compares. No rung
// numbers, so that a rung inserted does not change every line after it.

#include "model/project/project.h"

#include <QString>

namespace rung::model {

QString projectText(const Project &project);

} // namespace rung::model
