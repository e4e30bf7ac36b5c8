#include "network/station.h"

#include "network/engine_image.h"
#include "network/uart.h"

#include "comms/protocol/plc_master.h"
#include "comms/slave/responder.h"

namespace rung::network {

namespace {

void keep(QByteArray &into, const QByteArray &bytes) {
    into += bytes;
    trimReceived(into);
}

} // namespace

StationPort::StationPort(Network *network, Station *station, model::PortConfig config)
    : m_network(network)
    , m_station(station)
    , m_config(std::move(config))
    , m_line(m_config.line) {
    name = station->name() + QLatin1Char('/') + m_config.port;
    owner = station->name();
    const model::PortApplication &app = *m_config.application;
    // The master a program's instruction drives on this port speaks the application's
    // protocol: Computer Link for LINK, MODBUS for MBUS and COM / EXP. A master whose frames
    // the manual does not publish (the PL110's NAIS MATSUSHITA-MASTER) has none: its queries
    // put nothing on the wire and time out (docs/network.md).
    if (app.answers == model::ProtocolId::VigorLink)
        m_master = std::make_unique<comms::VigorLinkMaster>();
    else if (app.answers == model::ProtocolId::Modbus || (app.master && app.published))
        m_master = std::make_unique<comms::ModbusMaster>(
            m_config.modbusAscii ? comms::modbus::Framing::Ascii : comms::modbus::Framing::Rtu);
}

StationPort::~StationPort() = default;

void StationPort::makeResponder(const std::shared_ptr<EngineImage> &image) {
    // The slaves' rule (model::answersAt: MODBUS station 0 answers nothing) and the responder
    // of the protocol (comms::slave::makeResponder), as the virtual PLC answers it.
    const model::PortApplication &app = *m_config.application;
    const model::Target &target = m_station->target();
    if (!model::answersAt(app, m_config.station))
        return;
    if (const auto *map = model::findProtocolMap(target, *app.answers))
        m_responder = comms::slave::makeResponder(
            target, *map, m_config.station, image,
            m_config.modbusAscii ? comms::modbus::Framing::Ascii : comms::modbus::Framing::Rtu,
            m_line);
}

qint64 StationPort::nowUs() const {
    return m_network->nowUs();
}

qint64 StationPort::send(QByteArrayView bytes) {
    m_sentUs = m_network->transmit(this, bytes.toByteArray());
    return m_sentUs;
}

QByteArray StationPort::receive() {
    return std::exchange(m_forProgram, QByteArray());
}

int StationPort::takeCharacterErrors() {
    return std::exchange(m_errors, 0);
}

void StationPort::setProgramDriven(bool on) {
    if (on == m_programDriven)
        return;
    m_programDriven = on;
    // What the protocol had half read is not the program's, nor a request once it is back.
    m_forResponder.clear();
    m_replies.clear();
    if (m_responder && m_responder->buffered() > 0)
        m_responder->silence();
}

void StationPort::deliver(const QByteArray &bytes, int errors, qint64 atUs) {
    if (m_responder && !m_programDriven) {
        // A MODBUS RTU frame ends at 3.5 characters of silence: when these bytes began after
        // such a gap, what came before them is a frame of its own (another slave's reply on
        // the bus, a request cut short), decided now, as the PLC's UART would, though its
        // answer waits for the station's next END.
        const int gap = m_responder->silenceMicroseconds();
        const qint64 start = atUs - wireTimeUs(bytes.size(), m_line);
        if (gap > 0 && m_lastUs >= 0 && start - m_lastUs >= gap) {
            const qsizetype before = m_replies.size();
            m_replies += feedResponder(std::exchange(m_forResponder, QByteArray()), true);
            if (m_replies.size() > before)
                m_lastAnsweredUs = m_lastUs; // the request ended with the bytes before these
        }
        keep(m_forResponder, bytes);
    }
    m_lastUs = atUs;
    m_errors += errors;
    if (m_used)
        keep(m_forProgram, bytes);
}

// The bytes to the slave's side, and the frame ended by a silence when `silence`: a frame the
// responder drops (a wrong CRC or length) whose first byte is this station's address is a
// request for it that came wrong; another slave's reply on the bus is not.
QByteArrayList StationPort::feedResponder(QByteArray bytes, bool silence) {
    const quint64 dropped = m_responder->statistics().dropped;
    if (m_responder->buffered() == 0 && !bytes.isEmpty())
        m_frameAddress = quint8(bytes.front()); // a frame begins: its address
    const bool ours = m_frameAddress == m_config.station;
    QByteArrayList frames;
    if (!bytes.isEmpty())
        frames += m_responder->feed(bytes);
    if (silence && m_responder->buffered() > 0)
        frames += m_responder->silence();
    if (ours && m_responder->statistics().dropped > dropped)
        ++m_requestErrors;
    return frames;
}

void StationPort::answer(qint64 nowUs) {
    if (!m_responder || m_programDriven)
        return;
    QByteArrayList frames = std::exchange(m_replies, QByteArrayList());
    const qsizetype decided = frames.size(); // answers to requests ended before, timed then
    const int gap = m_responder->silenceMicroseconds();
    frames += feedResponder(std::exchange(m_forResponder, QByteArray()),
                            gap > 0 && m_lastUs >= 0 && nowUs - m_lastUs >= gap);
    if (frames.size() > decided)
        m_lastAnsweredUs = m_lastUs; // the request's last byte
    for (const QByteArray &frame : frames)
        m_sentUs = m_network->transmit(this, frame);
}

Station::Station(Network *network, QString name, const LoadedStation &loaded, qint64 periodMs)
    : m_network(network)
    , m_name(std::move(name))
    , m_target(loaded.target)
    , m_model(loaded.model)
    , m_periodMs(periodMs)
    , m_engine(std::make_unique<simulator::Engine>(loaded.program)) {
    m_engine->setPeriodMs(periodMs);
    // A scan's END, where its communication work happens, is at the end of its period: scan 1
    // ends at one period, as a program's trace counts its scans (docs/network.md).
    m_nextUs = periodMs * 1000;
    m_image = std::make_shared<EngineImage>(m_engine.get(), &m_written);
}

Station::~Station() = default;

model::Snapshot Station::snapshot() const {
    model::Snapshot s = m_engine->snapshot();
    s.communicatedUs = communicatedUs();
    return s;
}

qint64 Station::communicatedUs() const {
    qint64 us = -1;
    for (const auto &[key, port] : m_ports)
        us = std::max(us, port->communicatedUs());
    return us;
}

StationPort *Station::findPort(const QString &name) const {
    for (const auto &[key, port] : m_ports)
        if (key.compare(name, Qt::CaseInsensitive) == 0)
            return port.get();
    return nullptr;
}

StationPort *Station::addPort(model::PortConfig config) {
    const QString key = config.port;
    auto port = std::make_unique<StationPort>(m_network, this, std::move(config));
    StationPort *p = port.get();
    m_ports[key] = std::move(port);
    return p;
}

void Station::start() {
    for (auto &[key, port] : m_ports)
        port->makeResponder(m_image);
    m_engine->attachPorts(this);
}

model::PlcPort *Station::port(const QString &name) {
    StationPort *p = findPort(name);
    if (p)
        p->setUsedByProgram();
    return p;
}

void Station::run(qint64 nowUs) {
    if (m_holdAtStart) {
        m_holdAtStart = false;
        m_engine->stepInstruction(); // the scan starts: inputs read, before its first instruction
        return;
    }
    // Without breakpoints this is the plain scan.
    if (m_engine->scanToBreakpoint() == simulator::ScanStop::Breakpoint)
        return;
    scanEnded(nowUs);
}

void Station::scanEnded(qint64 nowUs) {
    for (auto &[key, port] : m_ports)
        port->answer(nowUs);
    m_nextUs += m_periodMs * 1000;
    if (m_scanHook)
        m_scanHook(*this);
}

simulator::ScanStop Station::stepInstruction() {
    const simulator::ScanStop stop = m_engine->stepInstruction();
    if (stop == simulator::ScanStop::Completed)
        scanEnded(m_network->nowUs());
    return stop;
}

void Station::finishScan() {
    if (!m_engine->insideScan())
        return;
    m_engine->scan();
    scanEnded(m_network->nowUs());
}

simulator::ScanStop Station::continueScan() {
    const simulator::ScanStop stop = m_engine->scanToBreakpoint();
    if (stop == simulator::ScanStop::Completed)
        scanEnded(m_network->nowUs());
    return stop;
}

} // namespace rung::network
