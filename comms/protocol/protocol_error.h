#pragma once

// What went wrong with a frame, shared by the three codecs. The message is translated and
// names what was received, where and why; the kind lets a driver decide to retry.

#include <QCoreApplication>
#include <QString>

#include <cstdint>

namespace rung::comms {

// Every comms message is translated in the context "rung::comms::Protocol", spelled out in
// QCoreApplication::translate() calls: lupdate's parser loses a class's tr() context inside
// lambdas in nested namespaces and would file the texts where the program never looks.

enum class FrameStatus : std::uint8_t {
    NeedMore, // a frame has started (or not yet) and is not complete
    Complete, // a whole frame was decoded
    Failed,   // the bytes cannot become a valid frame; error() says why
};

struct ProtocolError {
    enum class Kind : std::uint8_t {
        None,
        Garbage,      // bytes that are not the protocol's framing or characters
        BadChecksum,  // sum (Vigor), CRC-16 (Modbus RTU), FCS (Host Link) mismatch
        Truncated,    // the frame stopped before its end (the caller's deadline passed)
        WrongStation, // a valid frame from another station / unit
        WrongReply,   // a valid frame that does not answer the request sent
        Malformed,    // framing fine, content impossible (lengths, counts, values)
        DeviceError,  // the PLC answered with an error / exception / end code
    };
    Kind kind = Kind::None;
    int code = 0; // the PLC's error, exception or end code for DeviceError
    QString message;

    bool ok() const { return kind == Kind::None; }
    // Worth sending the request again: line noise, not a refusal by the PLC.
    bool retryable() const {
        return kind == Kind::Garbage || kind == Kind::BadChecksum || kind == Kind::Truncated;
    }
};

// The bytes as a reader would quote them in a message: "06 30 41 ..." (at most 32 bytes).
QString hexDump(QByteArrayView bytes);

// What the three master-side reply decoders share: the status, the error, and the one way to
// fail (the error is kept, later bytes are ignored). Each decoder's deadlinePassed() says in
// its protocol's words whether nothing came or the reply stopped; truncated() makes it.
class ReplyDecoderBase {
public:
    FrameStatus status() const { return m_status; }
    const ProtocolError &error() const { return m_error; }

protected:
    FrameStatus fail(ProtocolError::Kind kind, QString message, int code = 0) {
        m_error = ProtocolError{kind, code, std::move(message)};
        m_status = FrameStatus::Failed;
        return m_status;
    }
    FrameStatus complete() {
        m_status = FrameStatus::Complete;
        return m_status;
    }
    // The caller's deadline passed: silence when nothing arrived, else what did.
    static ProtocolError truncated(bool nothingArrived, QString silence, QString stopped) {
        return {ProtocolError::Kind::Truncated, 0,
                nothingArrived ? std::move(silence) : std::move(stopped)};
    }

    FrameStatus m_status = FrameStatus::NeedMore;
    ProtocolError m_error;
};

} // namespace rung::comms
