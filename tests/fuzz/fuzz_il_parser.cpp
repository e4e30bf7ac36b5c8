// Any bytes as a listing of any target: parse, and when it parses, draw it as a ladder and
// write it back. Nothing may crash, hang or trip a sanitizer.
#include "model/convert/convert.h"
#include "model/listing/il.h"

#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    if (size < 1)
        return 0;
    using namespace rung::model;
    const Family family = static_cast<Family>(data[0] % 4);
    const QString text = QString::fromUtf8(reinterpret_cast<const char *>(data + 1),
                                           static_cast<qsizetype>(size - 1));
    const ParseResult parsed = parseInstructionList(Target::get(family), text);
    if (parsed.ok()) {
        const ToLadderResult ladder = listToLadder(parsed.list);
        const ToListingResult back = ladderToList(ladder.ladder);
        (void)printInstructionList(back.list);
    }
    return 0;
}
