#pragma once

// Simulated devices on a wire (docs/network-format.md, "devices"): a MODBUS slave with a
// register map from the network file (a temperature controller, an inverter), and a line
// device that records what it receives and answers from a script (a bar-code reader, a
// display, anything a program drives with RS).

#include "network/network.h"

#include "comms/protocol/modbus_slave.h"

#include <map>

namespace rung::network {

std::unique_ptr<Endpoint> makeDevice(Network *network, const DeviceDescription &description,
                                     QString *error);

class ModbusSlaveDevice final : public Endpoint, public Actor {
public:
    ModbusSlaveDevice(Network *network, const QString &name)
        : m_network(network) {
        this->name = name;
        owner = name;
    }
    bool read(const DeviceDescription &d, QString *error);

    const model::SerialSettings &lineSettings() const override { return m_line; }
    void deliver(const QByteArray &bytes, int errors, qint64 atUs) override;
    qint64 nextUs() const override;
    void run(qint64 nowUs) override;

    // The tables: holding registers, input registers, coils, discrete inputs.
    std::map<int, std::uint16_t> holding, input;
    std::map<int, bool> coils, discrete;
    int station = 1;

private:
    QByteArray respond(const comms::modbus::ParsedRequest &parsed);
    Network *m_network;
    model::SerialSettings m_line;
    comms::modbus::Framing m_framing = comms::modbus::Framing::Rtu;
    std::unique_ptr<comms::modbus::RequestDecoder> m_decoder;
    qint64 m_delayUs = 2000;
    qint64 m_lastUs = -1;
    std::vector<std::pair<qint64, QByteArray>> m_replies; // due time, frame
};

class LineDevice final : public Endpoint, public Actor {
public:
    LineDevice(Network *network, const QString &name)
        : m_network(network) {
        this->name = name;
        owner = name;
    }
    bool read(const DeviceDescription &d, QString *error);

    const model::SerialSettings &lineSettings() const override { return m_line; }
    void deliver(const QByteArray &bytes, int errors, qint64 atUs) override;
    qint64 nextUs() const override;
    void run(qint64 nowUs) override;

    const QByteArray &received() const { return m_all; } // everything, as it came

private:
    struct Answer {
        QByteArray expect;
        QByteArray reply;
    };
    Network *m_network;
    model::SerialSettings m_line;
    qint64 m_delayUs = 2000;
    std::vector<Answer> m_answers;
    QByteArray m_buffer;
    QByteArray m_all;
    std::vector<std::pair<qint64, QByteArray>> m_replies;
};

// "02 30 31" as bytes; false for anything else.
bool hexBytes(const QString &text, QByteArray *bytes);
// A text with C escapes (\x02, \r, \n, \t, \\, \") as bytes.
QByteArray escapedBytes(const QString &text);

} // namespace rung::network
