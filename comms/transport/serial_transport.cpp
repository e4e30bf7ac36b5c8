#include "comms/transport/serial_transport.h"

#include <libserialport.h>

#include <cerrno>
#include <cstring>

namespace rung::comms {

namespace {

// The cause of an open failure as the user can act on it (errno after sp_open).
QString openCause(const QString &port, int error) {
    switch (error) {
    case EACCES:
    case EPERM:
        return QCoreApplication::translate(
                   "rung::comms::Protocol",
                   "permission denied: add your user to the group that owns %1 (usually "
                   "\"dialout\": sudo usermod -aG dialout $USER, then log in again)")
            .arg(port);
    case EBUSY:
        return QCoreApplication::translate("rung::comms::Protocol",
                                           "the port is busy: another program has it open");
    case ENOENT:
    case ENODEV:
    case ENXIO:
        return QCoreApplication::translate("rung::comms::Protocol", "no such port (unplugged?)");
    default:
        return QString::fromLocal8Bit(std::strerror(error));
    }
}

} // namespace

QString SerialPortInfo::usbId() const {
    if (usbVendor < 0)
        return {};
    return QStringLiteral("%1:%2")
        .arg(usbVendor, 4, 16, QLatin1Char('0'))
        .arg(usbProduct, 4, 16, QLatin1Char('0'));
}

QList<SerialPortInfo> availableSerialPorts() {
    QList<SerialPortInfo> ports;
    sp_port **list = nullptr;
    if (sp_list_ports(&list) != SP_OK)
        return ports;
    for (int i = 0; list[i]; ++i) {
        SerialPortInfo info;
        info.name = QString::fromUtf8(sp_get_port_name(list[i]));
        if (const char *d = sp_get_port_description(list[i]))
            info.description = QString::fromUtf8(d);
        int vid = 0, pid = 0;
        if (sp_get_port_transport(list[i]) == SP_TRANSPORT_USB &&
            sp_get_port_usb_vid_pid(list[i], &vid, &pid) == SP_OK) {
            info.usbVendor = vid;
            info.usbProduct = pid;
        }
        ports << info;
    }
    sp_free_port_list(list);
    return ports;
}

SerialTransport::SerialTransport(QString port, SerialSettings settings)
    : m_name(std::move(port))
    , m_settings(settings) {}

SerialTransport::~SerialTransport() {
    close();
}

QString SerialTransport::failure(int spResult) const {
    if (spResult == SP_ERR_FAIL)
        return openCause(m_name, sp_last_error_code());
    return QString::fromUtf8(sp_last_error_message());
}

bool SerialTransport::open(QString *error) {
    if (m_port)
        return true;
    if (!m_waiter.ok()) {
        if (error)
            *error = QCoreApplication::translate("rung::comms::Protocol", "Cannot open %1: %2")
                         .arg(m_name, m_waiter.error());
        return false;
    }
    const int errnoBefore = errno;
    if (sp_get_port_by_name(m_name.toUtf8().constData(), &m_port) != SP_OK) {
        m_port = nullptr;
        if (error)
            *error = QCoreApplication::translate("rung::comms::Protocol", "Cannot open %1: %2")
                         .arg(m_name, openCause(m_name, ENOENT));
        return false;
    }
    errno = errnoBefore;
    const int opened = sp_open(m_port, SP_MODE_READ_WRITE);
    if (opened != SP_OK) {
        const QString cause = opened == SP_ERR_FAIL ? openCause(m_name, errno)
                                                    : QString::fromUtf8(sp_last_error_message());
        sp_free_port(m_port);
        m_port = nullptr;
        if (error)
            *error = QCoreApplication::translate("rung::comms::Protocol", "Cannot open %1: %2")
                         .arg(m_name, cause);
        return false;
    }
    const auto parity = m_settings.parity == SerialSettings::Parity::Even  ? SP_PARITY_EVEN
                        : m_settings.parity == SerialSettings::Parity::Odd ? SP_PARITY_ODD
                                                                           : SP_PARITY_NONE;
    const auto flow = m_settings.flow == SerialSettings::Flow::RtsCts    ? SP_FLOWCONTROL_RTSCTS
                      : m_settings.flow == SerialSettings::Flow::XonXoff ? SP_FLOWCONTROL_XONXOFF
                                                                         : SP_FLOWCONTROL_NONE;
    if (sp_set_baudrate(m_port, m_settings.baud) != SP_OK ||
        sp_set_bits(m_port, m_settings.dataBits) != SP_OK ||
        sp_set_parity(m_port, parity) != SP_OK ||
        sp_set_stopbits(m_port, m_settings.stopBits) != SP_OK ||
        sp_set_flowcontrol(m_port, flow) != SP_OK || sp_get_port_handle(m_port, &m_fd) != SP_OK) {
        if (error)
            *error = QCoreApplication::translate("rung::comms::Protocol",
                                                 "%1 does not accept the line settings: %2")
                         .arg(m_name, QString::fromUtf8(sp_last_error_message()));
        close();
        return false;
    }
    return true;
}

void SerialTransport::close() {
    if (m_port) {
        sp_close(m_port);
        sp_free_port(m_port);
        m_port = nullptr;
        m_fd = -1;
    }
}

bool SerialTransport::write(QByteArrayView bytes, QDeadlineTimer deadline, QString *error) {
    if (!m_port) {
        if (error)
            *error =
                QCoreApplication::translate("rung::comms::Protocol", "%1 is not open").arg(m_name);
        return false;
    }
    const qint64 left = deadline.remainingTime();
    const unsigned ms = left < 0 ? 0 : unsigned(std::max<qint64>(1, left)); // 0: no time-out
    const int n = sp_blocking_write(m_port, bytes.data(), size_t(bytes.size()), ms);
    if (n == bytes.size())
        return true;
    if (error)
        *error =
            n < 0 ? QCoreApplication::translate("rung::comms::Protocol", "Writing to %1 failed: %2")
                        .arg(m_name, failure(n))
                  : QCoreApplication::translate("rung::comms::Protocol",
                                                "Writing to %1 did not finish in time")
                        .arg(m_name);
    return false;
}

ReadResult SerialTransport::read(QDeadlineTimer deadline) {
    using R = ReadResult::Status;
    if (!m_port)
        return {R::Failed,
                {},
                QCoreApplication::translate("rung::comms::Protocol", "%1 is not open").arg(m_name)};
    while (true) {
        char buffer[512];
        const int n = sp_nonblocking_read(m_port, buffer, sizeof buffer);
        if (n > 0)
            return {R::Data, QByteArray(buffer, n), {}};
        if (n < 0)
            return {R::Failed,
                    {},
                    QCoreApplication::translate("rung::comms::Protocol",
                                                "%1 failed while reading (unplugged?): %2")
                        .arg(m_name, failure(n))};
        switch (m_waiter.wait(m_fd, deadline)) {
        case detail::FdWaiter::Result::Ready: {
            // Readable but nothing to read: the device went away (a USB adapter unplugged).
            const int again = sp_nonblocking_read(m_port, buffer, sizeof buffer);
            if (again > 0)
                return {R::Data, QByteArray(buffer, again), {}};
            return {R::Failed,
                    {},
                    QCoreApplication::translate("rung::comms::Protocol", "%1 is gone (unplugged?)")
                        .arg(m_name)};
        }
        case detail::FdWaiter::Result::Timeout:
            return {R::Timeout, {}, {}};
        case detail::FdWaiter::Result::Cancelled:
            return {R::Cancelled, {}, {}};
        case detail::FdWaiter::Result::Hangup:
        case detail::FdWaiter::Result::Error:
            return {R::Failed,
                    {},
                    QCoreApplication::translate("rung::comms::Protocol", "%1 is gone (unplugged?)")
                        .arg(m_name)};
        }
    }
}

void SerialTransport::discardInput() {
    if (m_port)
        sp_flush(m_port, SP_BUF_INPUT);
}

} // namespace rung::comms
