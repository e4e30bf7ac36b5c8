#include "line_settings_form.h"

#include "comms/transport/serial_transport.h"

#include <QComboBox>
#include <QEvent>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QSpinBox>
#include <QStyle>
#include <QToolButton>
#include <QVBoxLayout>

namespace rung::app {

namespace {

// The frame formats the manuals name (data bits, parity, stop bits).
constexpr const char *kLineFrames[] = {"7E1", "7E2", "7O1", "7O2", "8N1", "8N2", "8E1", "8O1"};
constexpr int kLineBauds[] = {1200, 2400, 4800, 9600, 19200, 38400, 57600, 115200};

} // namespace

LineSettingsForm::LineSettingsForm(const QString &prefix, QWidget *parent)
    : QWidget(parent) {
    setObjectName(prefix + QStringLiteral("Via"));
    const auto named = [&prefix](QWidget *w, const char *name) {
        w->setObjectName(prefix + QString::fromLatin1(name));
    };
    auto *pages = new QVBoxLayout(this);
    pages->setContentsMargins(0, 0, 0, 0);
    auto *serial = new QWidget;
    auto *serialForm = new QFormLayout(serial);
    serialForm->setContentsMargins(0, 0, 0, 0);
    serialForm->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    // A narrow dock (a long Hungarian label) puts the label above its field.
    serialForm->setRowWrapPolicy(QFormLayout::WrapLongRows);
    auto *portRow = new QHBoxLayout;
    m_port = new QComboBox;
    named(m_port, "Port");
    m_port->setEditable(true); // a pseudo-terminal or a port the list does not show
    m_port->setInsertPolicy(QComboBox::NoInsert);
    m_port->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_port->setMinimumContentsLength(12);
    // An icon beside the port, as the vendors' port lists have it: a button's word here made
    // the panel wider than its column and pushed the settings behind a sideways scroll bar.
    m_refresh = new QToolButton;
    named(m_refresh, "Refresh");
    m_refresh->setToolButtonStyle(Qt::ToolButtonIconOnly);
    m_refresh->setIcon(QIcon::fromTheme(QStringLiteral("view-refresh"),
                                        style()->standardIcon(QStyle::SP_BrowserReload)));
    portRow->addWidget(m_port, 1);
    portRow->addWidget(m_refresh);
    m_portLabel = new QLabel;
    m_portLabel->setBuddy(m_port);
    serialForm->addRow(m_portLabel, portRow);
    m_baud = new QComboBox;
    named(m_baud, "Baud");
    m_frame = new QComboBox;
    named(m_frame, "Frame");
    setBauds({});
    setFrames({});
    m_baudLabel = new QLabel;
    m_baudLabel->setBuddy(m_baud);
    m_frameLabel = new QLabel;
    m_frameLabel->setBuddy(m_frame);
    serialForm->addRow(m_baudLabel, m_baud);
    serialForm->addRow(m_frameLabel, m_frame);
    pages->addWidget(serial);
    m_pages[0] = serial;

    auto *tcp = new QWidget;
    auto *tcpForm = new QFormLayout(tcp);
    tcpForm->setContentsMargins(0, 0, 0, 0);
    tcpForm->setRowWrapPolicy(QFormLayout::WrapLongRows);
    m_host = new QLineEdit(QStringLiteral("127.0.0.1"));
    named(m_host, "Host");
    m_tcpPort = new QSpinBox;
    named(m_tcpPort, "TcpPort");
    m_tcpPort->setRange(1, 65535);
    m_tcpPort->setValue(502);
    m_hostLabel = new QLabel;
    m_hostLabel->setBuddy(m_host);
    m_tcpPortLabel = new QLabel;
    m_tcpPortLabel->setBuddy(m_tcpPort);
    tcpForm->addRow(m_hostLabel, m_host);
    tcpForm->addRow(m_tcpPortLabel, m_tcpPort);
    pages->addWidget(tcp);
    m_pages[1] = tcp;
    showPage(Page::Serial);

    connect(m_refresh, &QToolButton::clicked, this, &LineSettingsForm::refreshPorts);
    connect(m_port, &QComboBox::currentTextChanged, this, &LineSettingsForm::edited);
    connect(m_baud, &QComboBox::activated, this, &LineSettingsForm::edited);
    connect(m_frame, &QComboBox::activated, this, &LineSettingsForm::edited);
    connect(m_host, &QLineEdit::textEdited, this, &LineSettingsForm::edited);
    connect(m_tcpPort, &QSpinBox::valueChanged, this, &LineSettingsForm::edited);
    retranslate();
    refreshPorts();
}

void LineSettingsForm::retranslate() {
    m_portLabel->setText(tr("Port:"));
    m_refresh->setText(tr("Refresh")); // its accessible name
    m_refresh->setToolTip(tr("Look for serial ports again"));
    updatePortHint();
    m_baudLabel->setText(tr("Baud rate:"));
    m_frameLabel->setText(tr("Format:"));
    m_frame->setToolTip(tr("Data bits, parity (N none, E even, O odd) and stop bits"));
    m_hostLabel->setText(m_hostText.isEmpty() ? tr("Host:") : m_hostText);
    m_tcpPortLabel->setText(tr("TCP port:"));
}

void LineSettingsForm::changeEvent(QEvent *event) {
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void LineSettingsForm::setHostLabel(const QString &text) {
    m_hostText = text;
    m_hostLabel->setText(m_hostText.isEmpty() ? tr("Host:") : m_hostText);
}

void LineSettingsForm::showPage(Page page) {
    // Only the page shown takes room (a stack would be as tall as its tallest page, and leave
    // the serial settings' room empty under the TCP ones).
    m_page = page;
    const int shown = page == Page::Serial ? 0 : 1;
    m_pages[1 - shown]->hide();
    m_pages[shown]->show();
}

void LineSettingsForm::refreshPorts() {
    const QString typed = m_port->currentText();
    const QString current = m_port->currentData().toString();
    m_port->clear();
    for (const comms::SerialPortInfo &p : comms::availableSerialPorts()) {
        QString text = p.name;
        if (!p.description.isEmpty())
            text += QStringLiteral(" - ") + p.description;
        if (!p.usbId().isEmpty())
            text += QStringLiteral(" [%1]").arg(p.usbId());
        m_port->addItem(text, p.name);
    }
    const QString keep = current.isEmpty() ? typed : current;
    if (const int i = m_port->findData(keep); i >= 0)
        m_port->setCurrentIndex(i);
    else
        m_port->setEditText(keep);
    updatePortHint();
}

void LineSettingsForm::updatePortHint() {
    // An empty field says whether the list has anything to choose from.
    m_port->lineEdit()->setPlaceholderText(m_port->count() == 0 ? tr("No port found")
                                                                : tr("Choose or type a port"));
}

QString LineSettingsForm::port() const {
    const int i = m_port->currentIndex();
    return i >= 0 && m_port->itemText(i) == m_port->currentText() ? m_port->itemData(i).toString()
                                                                  : m_port->currentText().trimmed();
}

void LineSettingsForm::setPort(const QString &port) {
    if (const int i = m_port->findData(port); i >= 0)
        m_port->setCurrentIndex(i);
    else
        m_port->setEditText(port);
}

model::SerialSettings LineSettingsForm::line() const {
    model::SerialSettings s;
    s.baud = m_baud->currentData().toInt();
    model::parseFrameFormat(m_frame->currentText(), &s);
    return s;
}

void LineSettingsForm::setLine(const model::SerialSettings &line) {
    if (int i = m_baud->findData(line.baud); i >= 0) {
        m_baud->setCurrentIndex(i);
    } else {
        m_baud->addItem(QString::number(line.baud), line.baud);
        m_baud->setCurrentIndex(m_baud->count() - 1);
    }
    const QString frame = model::frameFormatText(line);
    if (m_frame->findText(frame) < 0)
        m_frame->addItem(frame);
    m_frame->setCurrentText(frame);
}

void LineSettingsForm::setBauds(const std::vector<int> &bauds) {
    const int was = m_baud->currentData().toInt();
    m_baud->clear();
    const std::vector<int> all(std::begin(kLineBauds), std::end(kLineBauds));
    for (int b : bauds.empty() ? all : bauds)
        m_baud->addItem(QString::number(b), b);
    if (const int i = m_baud->findData(was); i >= 0)
        m_baud->setCurrentIndex(i);
}

void LineSettingsForm::setFrames(const QStringList &frames) {
    const QString was = m_frame->currentText();
    m_frame->clear();
    if (frames.isEmpty()) {
        for (const char *f : kLineFrames)
            m_frame->addItem(QString::fromLatin1(f));
    } else {
        m_frame->addItems(frames);
    }
    if (const int i = m_frame->findText(was); i >= 0)
        m_frame->setCurrentIndex(i);
}

QString LineSettingsForm::host() const {
    return m_host->text().trimmed();
}

void LineSettingsForm::setHost(const QString &host) {
    m_host->setText(host);
}

int LineSettingsForm::tcpPort() const {
    return m_tcpPort->value();
}

void LineSettingsForm::setTcpPort(int port) {
    m_tcpPort->setValue(port);
}

void LineSettingsForm::setTcpPortRange(int lowest, int highest) {
    m_tcpPort->setRange(lowest, highest);
}

} // namespace rung::app
