#pragma once

// The four families' tables by name, for the tests that read one family's table throughout.
// One definition for every test file: the test binaries compile their files in batches (a
// unity build), where a helper of the same name in two files would be defined twice.

#include "model/target/target.h"

namespace rung::testing {

inline const model::Target &target(model::Family family) {
    return model::Target::get(family);
}
inline const model::Target &vpc() {
    return model::Target::get(model::Family::Vpc);
}
inline const model::Target &vigor() {
    return model::Target::get(model::Family::Vigor);
}
inline const model::Target &cpm1() {
    return model::Target::get(model::Family::Cpm1);
}
inline const model::Target &pl110() {
    return model::Target::get(model::Family::Pl110);
}

} // namespace rung::testing
