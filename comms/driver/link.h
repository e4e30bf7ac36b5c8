#pragma once

// One request, one reply, over a Transport: the part every protocol driver shares. A request
// is sent, the reply is fed to the protocol's incremental decoder as bytes arrive, until it is
// whole, broken or late. Noise (a garbled reply, a bad sum / CRC / FCS) and silence are tried
// again, at most LinkSettings::retries times; a reply that refuses (the PLC's error code) or
// answers for another station is never sent again. Everything is counted in LinkStatistics
// and every byte, both ways, goes to the TrafficTap.
//
// Threads: a Link lives on the driver's worker thread, as its transport does; cancel() is the
// one call for other threads (it ends the exchange that waits, see Transport::cancel()).

#include "comms/driver/traffic.h"
#include "comms/protocol/protocol_error.h"
#include "comms/transport/transport.h"

#include <QElapsedTimer>
#include <QList>

#include <functional>
#include <memory>
#include <mutex>
#include <optional>

namespace rung::comms {

struct LinkSettings {
    int timeoutMs = 1000; // for each attempt: request sent -> reply complete
    int retries = 2;      // attempts after the first, for noise and silence only
    // How long the line must stay quiet after a broken reply before the request goes again,
    // so that the rest of the broken reply is not taken for the next one.
    int drainMs = 20;
    // A serial line's time per character (0: a pseudo-terminal or TCP, no baud rate). The
    // first byte of a reply is awaited timeoutMs after the request has left the wire, and
    // each next byte timeoutMs after the one before, so a long reply at a slow baud rate is
    // not cut off by a timeout sized for a short one.
    int characterUs = 0;
    // The least silence between the end of one frame on the line and the next request
    // (Modbus RTU: 3.5 characters, serial line V1.02 2.5.1.1); 0: none.
    int gapUs = 0;
};

// Why an exchange, a read or a write did not succeed. The message is translated and complete:
// it names the device (where there is one), the PLC and the cause.
struct DriverError {
    enum class Kind : std::uint8_t {
        None,
        LinkDown,    // the port or connection failed or is closed
        NoReply,     // silence (or a reply that stopped) on every attempt
        Garbled,     // noise, bad sums, garbage on every attempt
        Refused,     // the PLC answered with an error / exception / end code
        WrongPeer,   // another station answered, or an answer to another request
        Unsupported, // the protocol cannot do it (force over Modbus, RUN/STOP over Vigor link)
        BadDevice,   // the device has no place in this protocol's map, or is read-only there
        Cancelled,   // the session is stopping
    };
    Kind kind = Kind::None;
    int code = 0; // the PLC's code for Refused
    QString message;

    bool ok() const { return kind == Kind::None; }
    // The PLC cannot be reached: a session shows the link lost and tries again in the
    // background.
    bool linkLost() const { return kind == Kind::LinkDown || kind == Kind::NoReply; }
};

// The decoder of one reply, behind one face for the three protocols (DecoderSink below).
class ReplySink {
public:
    virtual ~ReplySink() = default;
    virtual void restart() = 0; // a fresh decoder for the next attempt
    virtual FrameStatus feed(QByteArrayView bytes) = 0;
    virtual bool takeDelimiterRequest() { return false; } // Host Link: send a lone CR
    virtual ProtocolError deadlinePassed(int waitedMs) const = 0;
    virtual ProtocolError error() const = 0;
};

template <typename Decoder> class DecoderSink final : public ReplySink {
public:
    explicit DecoderSink(std::function<Decoder()> make)
        : m_make(std::move(make)) {
        restart();
    }
    void restart() override { m_decoder.emplace(m_make()); }
    FrameStatus feed(QByteArrayView bytes) override { return m_decoder->feed(bytes); }
    bool takeDelimiterRequest() override {
        if constexpr (requires(Decoder d) { d.takeDelimiterRequest(); })
            return m_decoder->takeDelimiterRequest();
        return false;
    }
    ProtocolError deadlinePassed(int waitedMs) const override {
        return m_decoder->deadlinePassed(waitedMs);
    }
    ProtocolError error() const override { return m_decoder->error(); }
    const Decoder &decoder() const { return *m_decoder; }

private:
    std::function<Decoder()> m_make;
    std::optional<Decoder> m_decoder;
};

class Link {
public:
    Link(std::unique_ptr<Transport> transport, LinkSettings settings);
    ~Link();

    Transport &transport() { return *m_transport; }
    const LinkSettings &settings() const { return m_settings; }
    void setSettings(const LinkSettings &settings) { m_settings = settings; }

    bool open(QString *error);
    void close();
    bool isOpen() const { return m_transport->isOpen(); }

    // Sends the request and decodes the reply into sink. expectReply false: a broadcast,
    // done once it is sent. `what` names the operation for messages: "reading D100 from
    // Vigor station 0". The error, when there is one, starts with it.
    DriverError exchange(QByteArrayView request, ReplySink &sink, const QString &what,
                         bool expectReply = true);

    void cancel(); // any thread

    LinkStatistics statistics() const;
    void countRefresh(double ms, int frames, int bytes);
    void countReconnect();
    TrafficTap &tap() { return *m_tap; }
    // Sends the traffic to another tap (the session's, which outlives the link); nullptr:
    // back to the link's own.
    void setTap(TrafficTap *tap) { m_tap = tap ? tap : &m_ownTap; }

private:
    bool send(QByteArrayView bytes, QString *error);
    void drain();

    std::unique_ptr<Transport> m_transport;
    LinkSettings m_settings;
    TrafficTap m_ownTap;
    TrafficTap *m_tap = &m_ownTap;
    mutable std::mutex m_statsMutex;
    LinkStatistics m_stats;
    quint64 m_goodExchanges = 0;
    QElapsedTimer m_lastTraffic; // the last byte sent or received, for gapUs
};

} // namespace rung::comms
