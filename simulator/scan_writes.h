#pragma once

// The words of the memory image a scan of a program can change: every destination of its
// steps (coils, word results, a timer's or counter's current value, bit and set value, a
// block's words), the system devices the engine drives at the start of a scan, the inputs it
// reads from the stimulus, the flags it clears at END and the terminal's pages. What a scan
// does not write keeps its value from one scan to the next, so the network's history compares
// only these words after a slice (network/network_history.h; docs/network.md, "History across
// the network"), not the whole image.
//
// Exact as a superset: a word outside it is never written by a scan of the program. Where the
// words written are found only at run time (an operand resolved at run time: an index
// register or a digit group, kResolve; communication instructions and the ports the program
// drives, whose replies land where a table in the image says), the answer is "any word".
// What is written between scans (a command, a network's exchange, a slave's write) is not a
// scan's and is not here.

#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

namespace rung::simulator {

struct Program;

// [first, end) word ranges of the layout's image, rising, apart from each other by at least
// `gap` words (closer ones are joined: comparing a few words more is cheaper than a range
// more); empty optional: any word of the image.
using WordRanges = std::vector<std::pair<std::size_t, std::size_t>>;
std::optional<WordRanges> scanWrites(const Program &program, std::size_t gap = 8);

} // namespace rung::simulator
