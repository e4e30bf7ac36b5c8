#pragma once

// Shared by the comms fuzzers: the first bytes of the input pick the request, the rest is
// the peer's bytes, fed in chunks whose sizes the input also picks (a reply split into many
// reads). A decoder must end Complete, Failed or NeedMore; never crash, never grow without
// bound, and a Failed one must say why.

#include "comms/protocol/protocol_error.h"

#include <QByteArray>
#include <QByteArrayList>

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

// The slave side (a responder of comms/slave, the virtual PLC's): the whole input is the peer's
// bytes, fed in chunks; with `silences`, a byte after each chunk says whether the line then
// goes quiet (silence() when it is a multiple of 4: Modbus RTU's end of a frame). Every frame
// the slave sends must pass `valid` (framed, its checksum right, from its own station), and
// what it holds stays within `bound` after every feed.
template <typename Responder, typename Valid>
void serveAll(Input &in, Responder &responder, qsizetype bound, bool silences, Valid valid) {
    while (!in.done()) {
        QByteArrayList out = responder.feed(in.chunk());
        if (silences && in.byte() % 4 == 0)
            out += responder.silence();
        for (const QByteArray &frame : out) {
            if (!valid(frame)) {
                std::fprintf(stderr, "the slave sent a frame that is not one: %s\n",
                             frame.toHex(' ').constData());
                std::abort();
            }
        }
        if (responder.buffered() > bound) {
            std::fprintf(stderr, "the slave holds %lld bytes, its bound is %lld\n",
                         static_cast<long long>(responder.buffered()),
                         static_cast<long long>(bound));
            std::abort();
        }
    }
}

// Upper-case hexadecimal digits only (the ASCII protocols' payload).
inline bool isUpperHex(QByteArrayView bytes) {
    return std::all_of(bytes.begin(), bytes.end(),
                       [](char c) { return (c >= '0' && c <= '9') || (c >= 'A' && c <= 'F'); });
}

} // namespace rung::comms::fuzz
