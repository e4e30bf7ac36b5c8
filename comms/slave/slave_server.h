#pragma once

// A slave: answers a master for one PLC over a transport, on worker threads, until stopped.
// It serves any DeviceImage (the virtual PLC in app/ puts a simulator session behind one) for
// a target, through the target's protocol map:
//
//   auto image = std::make_shared<MemoryImage>(target);
//   SlaveServer server(target, {ProtocolId::Modbus, Framing::Rtu, 1}, image);
//   server.start(PtyTransport::createPair(&error), &error);       // a pty, a serial port, ...
//   server.listen(QHostAddress::LocalHost, 502, &error);         // ... or TCP clients
//
// One byte stream (serial port, pty, a TCP connection) is served by one worker thread; a
// listening server accepts on a thread of its own and serves each client on its own thread,
// at most maxClients at once. Nothing here runs on the caller's thread: start() and listen()
// return once the stream is open / the port listens; stop() cancels every wait and joins.

#include "comms/protocol/modbus.h"
#include "comms/slave/responder.h"
#include "comms/transport/serial_settings.h"
#include "comms/transport/tcp_transport.h"
#include "comms/transport/transport.h"

#include <QHostAddress>

#include <atomic>
#include <functional>
#include <future>
#include <list>
#include <mutex>
#include <optional>
#include <thread>

namespace rung::comms::slave {

// Testing aids: a PLC that misbehaves, so that a master's handling of it can be tested.
enum class Fault : std::uint8_t {
    None,
    BadChecksum,  // every answer with a wrong sum / CRC / FCS
    Silent,       // no answer at all
    WrongStation, // answers as station + 1
    Garbage,      // bytes that are no frame instead of each answer
    Truncated,    // the first half of each answer, then nothing
    Split,        // each answer one byte at a time, a few milliseconds apart
};
// "bad-checksum", "silent", ...; nullopt for a name that is none of them.
std::optional<Fault> faultFromName(QStringView name);
QStringList faultNames();

struct SlaveOptions {
    model::ProtocolId protocol = model::ProtocolId::Modbus;
    modbus::Framing framing = modbus::Framing::Rtu; // Modbus only: RTU or TCP (MBAP)
    int station = 1;                                // Vigor station, Modbus unit, Host Link unit
    SerialSettings line;                            // the RTU 3.5-character silence
    Fault fault = Fault::None;
    int writeTimeoutMs = 2000; // a write not applied by then is answered with an error
    int maxClients = 8;        // TCP clients served at once; more are refused
    // Called on a worker thread when a served stream fails (a serial port unplugged); the
    // server has stopped serving it. Not called for stop().
    std::function<void(const QString &error)> onFailure;
};

class SlaveServer {
public:
    // The target must have a map for options.protocol (start() / listen() say when not).
    SlaveServer(const model::Target &target, SlaveOptions options,
                std::shared_ptr<DeviceImage> image);
    ~SlaveServer(); // stop()
    SlaveServer(const SlaveServer &) = delete;
    SlaveServer &operator=(const SlaveServer &) = delete;

    // Serves one byte stream, opening it when it is not open. False with the reason when the
    // stream cannot be opened or the target has no map for the protocol.
    bool start(std::unique_ptr<Transport> transport, QString *error);
    // Listens for TCP clients (Modbus TCP, or any protocol's frames over raw TCP as a serial
    // device server carries them). port 0: any free port, see port().
    bool listen(const QHostAddress &host, quint16 port, QString *error);
    quint16 port() const { return m_port.load(); }
    // Any thread but a worker's: ends every wait, closes the streams, joins. Idempotent.
    void stop();

    // Summed over every stream served so far.
    SlaveStatistics statistics() const;
    int clients() const { return m_clients.load(); } // TCP clients being served now
    // The last thing not done as asked, or thrown away, and why (translated); empty if none.
    QString lastProblem() const;

private:
    struct Stream;
    std::unique_ptr<Responder> makeResponder() const;
    void run(Stream &stream, std::promise<QString> *opened);
    void serve(Stream &stream);
    void send(Stream &stream, const QByteArrayList &frames);
    void acceptLoop(const QHostAddress &host, quint16 port, std::promise<QString> *listening);
    void record(Stream &stream);
    void reap();

    const model::Target &m_target;
    const model::ProtocolMap *m_map;
    SlaveOptions m_options;
    std::shared_ptr<DeviceImage> m_image;

    mutable std::mutex m_mutex;
    std::list<std::unique_ptr<Stream>> m_streams; // under m_mutex
    SlaveStatistics m_finished;                   // of streams that ended, under m_mutex
    QString m_lastProblem;                        // under m_mutex
    std::atomic<bool> m_quit{false};
    std::atomic<quint16> m_port{0};
    std::atomic<int> m_clients{0};
    std::thread m_acceptor;
    TcpServer *m_server = nullptr; // the acceptor's, for stop() to cancel; under m_mutex
};

} // namespace rung::comms::slave
