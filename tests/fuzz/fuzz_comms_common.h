#pragma once

// Shared by the comms fuzzers: the first bytes of the input pick the request, the rest is
// the peer's bytes, fed in chunks whose sizes the input also picks (a reply split into many
// reads). A decoder must end Complete, Failed or NeedMore; never crash, never grow without
// bound, and a Failed one must say why.

#include "comms/protocol/protocol_error.h"

#include <QByteArray>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

namespace rung::comms::fuzz {

struct Input {
    const std::uint8_t *data;
    std::size_t size;
    std::size_t at = 0;
    int byte() { return at < size ? data[at++] : 0; }
    // Two statements: in `byte() << 8 | byte()` the order of the two reads is unspecified,
    // so a finding would not replay the same on another compiler.
    int word() {
        const int high = byte();
        return high << 8 | byte();
    }
    // The next chunk of the peer's bytes: 1..16 bytes, or the rest.
    QByteArray chunk() {
        // The size byte first, on its own: `min(size - at, byte())` may read `at` before
        // byte() moves it, and then copy one byte past the input (found by libFuzzer + ASan).
        const auto wanted = std::size_t(1 + byte() % 16);
        const std::size_t n = std::min(size - at, wanted);
        QByteArray out(reinterpret_cast<const char *>(data + at), qsizetype(n));
        at += n;
        return out;
    }
    bool done() const { return at >= size; }
};

// The decoder's memory stays within its protocol's bound after every feed (issue 12).
template <typename Decoder> void checkBound(const Decoder &decoder) {
    if (decoder.buffered() > Decoder::MaxBuffered) {
        std::fprintf(stderr, "decoder holds %lld bytes, its bound is %lld\n",
                     static_cast<long long>(decoder.buffered()),
                     static_cast<long long>(Decoder::MaxBuffered));
        std::abort();
    }
}

template <typename Decoder> void feedAll(Input &in, Decoder &decoder) {
    while (!in.done() && decoder.status() == FrameStatus::NeedMore) {
        decoder.feed(in.chunk());
        checkBound(decoder);
    }
    if (decoder.status() == FrameStatus::Failed && decoder.error().message.isEmpty())
        std::abort(); // every failure names its cause
    if (decoder.status() == FrameStatus::NeedMore && decoder.deadlinePassed(100).message.isEmpty())
        std::abort();
}

} // namespace rung::comms::fuzz
