#pragma once

// The protocol half of a slave: bytes from the line in, the frames to send back out, as the
// PLC would answer. No I/O and no threads (SlaveServer has those), so each protocol's rules
// are tested byte for byte. A responder may block in DeviceImage::apply() for a write.

#include "comms/protocol/modbus.h"
#include "comms/slave/mapped_image.h"
#include "comms/transport/serial_settings.h"

#include <QByteArrayList>

#include <memory>

namespace rung::comms::slave {

// What a slave has done so far; the counters only grow.
struct SlaveStatistics {
    quint64 answered = 0; // requests answered normally
    quint64 refused = 0;  // answered with an error / exception / end code
    quint64 ignored = 0;  // for another station, or broadcast: no answer
    quint64 dropped = 0;  // not a frame (garbage, bad CRC): no answer
    quint64 writes = 0;   // requests that changed the image
};

class Responder {
public:
    virtual ~Responder() = default;
    Responder(const Responder &) = delete;
    Responder &operator=(const Responder &) = delete;

    // Bytes as they arrive, in any split; the frames to send, in order (often none yet).
    virtual QByteArrayList feed(QByteArrayView bytes) = 0;
    // The line has been quiet for silenceMicroseconds() after bytes came (Modbus RTU: a frame
    // ends there); 0 when the protocol needs no such timer.
    virtual QByteArrayList silence() { return {}; }
    virtual int silenceMicroseconds() const { return 0; }
    // Bytes held for frames not complete yet: never more than the protocol's decoder keeps
    // (docs/comms.md, "Bounded memory"), whatever arrives.
    virtual qsizetype buffered() const = 0;

    const SlaveStatistics &statistics() const { return m_statistics; }
    // The last request not done as asked, or bytes thrown away, and why (translated).
    QString lastProblem() const { return m_lastProblem; }

    // Testing aid (SlaveServer's fault modes): answers as if it were another station.
    void setReplyStation(int station) { m_replyStation = station; }
    // Testing aid: the frame with its checksum broken (a frame with none is returned as is).
    virtual QByteArray breakChecksum(QByteArray frame) const = 0;

protected:
    Responder(const model::Target &target, const model::ProtocolMap &map, int station,
              std::shared_ptr<DeviceImage> image, int writeTimeoutMs)
        : m_mapped(target, map, station)
        , m_station(station)
        , m_replyStation(station)
        , m_image(std::move(image))
        , m_writeTimeoutMs(writeTimeoutMs) {}

    // Applies a change through the image: the commands, then the mode it asks for.
    ImageChange apply(const MappedImage::Change &change);

    MappedImage m_mapped;
    int m_station;
    int m_replyStation;
    std::shared_ptr<DeviceImage> m_image;
    int m_writeTimeoutMs;
    SlaveStatistics m_statistics;
    QString m_lastProblem;
};

// The responder of the map's protocol: which class answers which protocol is said here once,
// for the virtual PLC (SlaveServer) and a network station's ports alike. `framing` and `line`
// are Modbus's (RTU or not, and the 3.5-character silence); the others ignore them.
std::unique_ptr<Responder> makeResponder(const model::Target &target, const model::ProtocolMap &map,
                                         int station, std::shared_ptr<DeviceImage> image,
                                         modbus::Framing framing, const SerialSettings &line,
                                         int writeTimeoutMs = 2000);

} // namespace rung::comms::slave
