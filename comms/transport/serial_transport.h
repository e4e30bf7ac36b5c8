#pragma once

// Real serial ports through libserialport: the port list (with description and USB VID:PID)
// and the port itself. Pseudo-terminals are PtyTransport's: libserialport cannot open them.
// Reads wait on the port's descriptor with the FdWaiter, so cancel() wakes them at once.

#include "comms/transport/fd_waiter.h"
#include "comms/transport/serial_settings.h"
#include "comms/transport/transport.h"

#include <QList>

struct sp_port;

namespace rung::comms {

struct SerialPortInfo {
    QString name;        // "/dev/ttyUSB0"
    QString description; // "FT232R USB UART"
    int usbVendor = -1;  // -1 when the port is not on USB
    int usbProduct = -1;
    // "0403:6001", or empty for a port that is not on USB.
    QString usbId() const;
};

QList<SerialPortInfo> availableSerialPorts();

class SerialTransport final : public Transport {
public:
    SerialTransport(QString port, SerialSettings settings);
    ~SerialTransport() override;

    QString name() const override { return m_name; }
    bool open(QString *error) override;
    void close() override;
    bool isOpen() const override { return m_port != nullptr; }
    bool write(QByteArrayView bytes, QDeadlineTimer deadline, QString *error) override;
    ReadResult read(QDeadlineTimer deadline) override;
    void discardInput() override;
    void cancel() override { m_waiter.wake(); }

private:
    QString failure(int spResult) const; // names the port and the cause
    QString m_name;
    SerialSettings m_settings;
    sp_port *m_port = nullptr;
    int m_fd = -1;
    detail::FdWaiter m_waiter;
};

} // namespace rung::comms
