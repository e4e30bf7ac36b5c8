#pragma once

// One interface for the byte pipes to a PLC (docs/comms.md, "Transports"): libserialport for real
// ports, termios for pseudo-terminals (libserialport cannot open them), TCP (serial device servers
// carry RTU frames over raw TCP; Modbus TCP), a fake for unit tests of the layers above.
//
// Threading: every call but cancel() blocks, up to its deadline, so a transport lives on a
// worker thread (the driver's or the slave's), never on the UI thread. cancel() may be
// called from any thread: it ends the read that is waiting or, when none is, the next read
// that would have to wait (a cancel that comes between two reads is not lost).

#include "comms/protocol/protocol_error.h"

#include <QByteArray>
#include <QDeadlineTimer>
#include <QString>

#include <cstdint>

namespace rung::comms {

struct ReadResult {
    enum class Status : std::uint8_t {
        Data,      // bytes holds what arrived (at least one byte)
        Timeout,   // the deadline passed with nothing new
        Cancelled, // cancel() was called
        Failed,    // the port or connection is gone or broken: message says which and why
    };
    Status status = Status::Timeout;
    QByteArray bytes;
    QString message;
};

class Transport {
public:
    virtual ~Transport() = default;
    Transport() = default;
    Transport(const Transport &) = delete;
    Transport &operator=(const Transport &) = delete;

    // What the user would call it: "/dev/ttyUSB0", "/dev/pts/3", "127.0.0.1:502".
    virtual QString name() const = 0;
    // Opens the port / connects; false with a message that names the port and the cause.
    virtual bool open(QString *error) = 0;
    virtual void close() = 0;
    virtual bool isOpen() const = 0;
    // Writes every byte before the deadline or fails with a message.
    virtual bool write(QByteArrayView bytes, QDeadlineTimer deadline, QString *error) = 0;
    // Waits for bytes until the deadline, cancel() or a failure.
    virtual ReadResult read(QDeadlineTimer deadline) = 0;
    // Drops what arrived and was not read (before sending a request again).
    virtual void discardInput() = 0;
    // Thread-safe: the read that is waiting returns Cancelled; with no read waiting, the next
    // read that finds nothing to read returns Cancelled at once instead of waiting (bytes
    // already there are returned first). However many cancel() calls came before it, one
    // read returns Cancelled; the read after it waits as usual.
    virtual void cancel() = 0;
};

} // namespace rung::comms
