#pragma once

// The traffic of a network, decoded (docs/network.md, "The Traffic view"): for each
// transmission the protocol it speaks, who it is for, the station, request or reply, the
// command or function, the address as the addressed PLC's device (through its target's
// protocol map) beside the address on the wire, the count, the data, the PLC's error or
// exception code, and what is wrong with the frame when something is (a wrong sum or CRC, a
// frame cut short, bytes that are no frame). The comms codecs read the frames; nothing here
// parses a protocol a second time.
//
// A decoder learns the network's wiring once (which ends are on each wire, what each port
// runs, its station, its target) and keeps no pointer to the network afterwards, so it may
// decode on another thread than the one running the network. It is fed the records in the
// order the network made them: a reply is read against the last request on its wire.

#include "network/network.h"

#include <map>
#include <memory>
#include <optional>

namespace rung::model {
class Target;
}

namespace rung::network {

struct DecodedFrame {
    enum class Kind : std::uint8_t {
        Request,  // a master asks
        Reply,    // a slave answers
        Raw,      // bytes of no protocol (RS, free-port, a line device), shown as text and hex
        Exchange, // CPU Link, Parallel Link: no frame, only what was exchanged (the note)
    };
    Kind kind = Kind::Raw;
    QString protocol; // translated: "Computer Link", "MODBUS RTU", "MODBUS ASCII", "Host Link"
    QString receiver; // the end the frame is for ("s5/CP2", "tc"); a reply's: the master
    int station = -1; // the station number the frame names; -1: none
    // Computer Link command, MODBUS function, Host Link header (its two characters, the first
    // in the high byte: RD is 5244h); -1: none.
    int command = -1;
    QString commandText;
    int rawAddress = -1; // as on the wire; -1: none
    QString address;     // "D1 (1C02h)", "D100 (100)", "DM 0000 (0000)", "100" where no map applies
    // bytes (Computer Link), registers or bits (MODBUS), words, present values or flags (Host
    // Link); -1: none
    int count = -1;
    QString data;       // the values carried, or the frame as text for a raw frame
    int errorCode = -1; // the PLC's error / exception / end code; -1: none
    QString errorText;  // translated: "illegal data address (exception 02h)"
    QString problem;    // translated: what is wrong with the frame; empty when it reads
    // A request that comes while the last request on its wire is still unanswered: that one
    // got no reply (a time-out, a silent or absent slave). The request itself is fine.
    bool previousUnanswered = false;

    bool failed() const { return errorCode >= 0 || !problem.isEmpty(); }
};

class TrafficDecoder {
public:
    // Learns the wiring of the network; the network may go on running elsewhere after this.
    explicit TrafficDecoder(const Network &network);
    ~TrafficDecoder();
    TrafficDecoder(const TrafficDecoder &) = delete;
    TrafficDecoder &operator=(const TrafficDecoder &) = delete;

    // The record decoded; records of a wire must come in the order the network made them.
    DecodedFrame decode(const TrafficRecord &record);
    // Forgets the requests in flight (the traffic starts over: the network was rebuilt).
    void reset();

    // The problem of a request whose reply never came (DecodedFrame::previousUnanswered).
    static QString noReplyText();

    // The station or device an end belongs to ("master" for "master/CP2").
    QString ownerOf(const QString &end) const;

    // What the decoder knows of an end of a wire.
    struct End {
        QString name;  // "master/CP2", "tc"
        QString owner; // "master", "tc"
        QString wire;
        enum class Speaks : std::uint8_t {
            Nothing,
            VigorLink,
            Modbus,
            HostLink
        } speaks = Speaks::Nothing;
        bool answers = false;       // a slave of its protocol (it answers `station`)
        bool master = false;        // its program is the master of its protocol
        bool programDriven = false; // RS, VB-1COM; a PL110 port its program may switch to free-port
        bool modbusAscii = false;
        bool sharedLink = false; // CPU Link, Parallel Link: no frames
        QString application;     // translated name of what it runs
        int station = -1;
        int anyStation = -1;                   // a unit every slave of its map answers (PL110: FFh)
        const model::Target *target = nullptr; // null for a device
    };

private:
    struct Pending; // the last request on a wire
    // Learns an end on `wire`; returns its name.
    QString learn(const Network &network, const Endpoint &endpoint, const QString &wire);
    const End *end(const QString &name) const;
    // Forgets the wire's last request; true when it was waiting for a slave's reply.
    bool takeUnanswered(const QString &wire);
    DecodedFrame decodeVigorRequest(const End &from, const QByteArray &bytes, const QString &wire);
    DecodedFrame decodeVigorReply(const End &from, const QByteArray &bytes, const QString &wire);
    DecodedFrame decodeModbusRequest(const End &from, const QByteArray &bytes, bool ascii,
                                     const QString &wire);
    DecodedFrame decodeModbusReply(const End &from, const QByteArray &bytes, bool ascii,
                                   const QString &wire);
    DecodedFrame decodeHostLinkRequest(const End &from, const QByteArray &bytes,
                                       const QString &wire);
    DecodedFrame decodeHostLinkReply(const End &from, const QByteArray &bytes, const QString &wire);
    // True when the bytes go on a Host Link exchange of the wire: a command ("@..."), the
    // next part of a command in parts, the host's CR for the next part of a reply.
    bool continuesHostLink(const End &from, const QByteArray &bytes, const QString &wire) const;
    DecodedFrame raw(const End *from, const QByteArray &bytes, const QString &wire) const;
    // The end on the wire that answers `station` with the protocol; null: none.
    const End *slaveOn(const QString &wire, End::Speaks speaks, int station) const;
    QString receiversOf(const QString &wire, const QString &sender) const;

    std::map<QString, End> m_ends;                         // by name
    std::map<QString, QStringList> m_wires;                // wire -> its ends
    std::map<QString, std::unique_ptr<Pending>> m_pending; // wire -> its last request
};

} // namespace rung::network
