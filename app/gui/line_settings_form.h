#pragma once

// Where a line goes and how it runs, as the Connection dock asks it (issue 13): a serial port
// (one of those found, or a path typed), its baud rate and format; or a host and a TCP port.
// One form for every place that asks it: the Connection dock (connection_panel.h) and a
// network's bridges (network_bridge_dialog.h). Its owner chooses the page shown and says what
// the port and the host mean there (their tooltips).

#include "model/comm/serial_line.h"

#include <QWidget>

#include <vector>

class QComboBox;
class QLabel;
class QLineEdit;
class QSpinBox;
class QToolButton;

namespace rung::app {

class LineSettingsForm : public QWidget {
    Q_OBJECT

public:
    // `prefix` names the widgets ("connection": connectionPort, connectionRefresh,
    // connectionBaud, connectionFrame, connectionHost, connectionTcpPort, connectionVia).
    explicit LineSettingsForm(const QString &prefix, QWidget *parent = nullptr);

    enum class Page { Serial, Tcp };
    // Only the page shown takes room.
    void showPage(Page page);
    Page page() const { return m_page; }

    // A port chosen from the list stands for its name; anything else is as typed.
    QString port() const;
    void setPort(const QString &port);
    // The baud rate and format; a rate the list lacks is added to it.
    model::SerialSettings line() const;
    void setLine(const model::SerialSettings &line);
    // The rates and formats offered (default: the common ones, 1200..115200 and the formats the
    // manuals name).
    void setBauds(const std::vector<int> &bauds);
    void setFrames(const QStringList &frames);
    QString host() const;
    void setHost(const QString &host);
    int tcpPort() const;
    void setTcpPort(int port);
    void setTcpPortRange(int lowest, int highest);
    // The host's label ("Host:" unless told otherwise: "Listen on:").
    void setHostLabel(const QString &text);

    // Serial ports again (Refresh).
    void refreshPorts();

    QComboBox *portBox() const { return m_port; }
    QComboBox *baudBox() const { return m_baud; }
    QComboBox *frameBox() const { return m_frame; }
    QLineEdit *hostEdit() const { return m_host; }
    QSpinBox *tcpPortBox() const { return m_tcpPort; }

signals:
    // A field was changed by the user.
    void edited();

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();
    void updatePortHint();

    Page m_page = Page::Serial;
    QString m_hostText; // set by the owner; "" : "Host:"
    QWidget *m_pages[2] = {};
    QComboBox *m_port = nullptr;
    QToolButton *m_refresh = nullptr;
    QComboBox *m_baud = nullptr;
    QComboBox *m_frame = nullptr;
    QLineEdit *m_host = nullptr;
    QSpinBox *m_tcpPort = nullptr;
    QLabel *m_portLabel = nullptr;
    QLabel *m_baudLabel = nullptr;
    QLabel *m_frameLabel = nullptr;
    QLabel *m_hostLabel = nullptr;
    QLabel *m_tcpPortLabel = nullptr;
};

} // namespace rung::app
