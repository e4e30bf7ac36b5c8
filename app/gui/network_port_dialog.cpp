#include "app/gui/network_port_dialog.h"

#include "model/comm/port_config.h"
#include "model/target/target.h"

#include <QComboBox>
#include <QCoreApplication>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QInputDialog>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

#include <algorithm>
#include <tuple>

namespace rung::app {

namespace {

QString applicationText(const model::PortApplication &a) {
    return QCoreApplication::translate("rung::model::Target", a.name);
}

QSpinBox *portSpin(model::SettingRange range, QWidget *parent) {
    auto *box = new QSpinBox(parent);
    box->setRange(range.lowest, range.highest);
    return box;
}

// "Total slaves (1..7):": the range as the table gives it, in the label.
QString withRange(const QString &label, model::SettingRange range) {
    return label.arg(range.lowest).arg(range.highest);
}

// A value outside the range stays as it is (and the problem says why), never clamped away.
void setSpin(QSpinBox *box, int lowest, int highest, int value) {
    box->setRange(std::min(lowest, value), std::max(highest, value));
    box->setValue(value);
}

QJsonValue codeValue(int code) {
    return code < 0 ? QJsonValue(QJsonValue::Null) : QJsonValue(code);
}

} // namespace

NetworkPortDialog::NetworkPortDialog(const model::Target &target, const QString &model,
                                     const QString &port, const QJsonObject &settings,
                                     const QJsonObject &lower, const QString &title,
                                     QWidget *parent)
    : QDialog(parent)
    , m_target(target)
    , m_model(model)
    , m_spec(target.port(port))
    , m_original(settings)
    , m_lower(lower) {
    setWindowTitle(tr("Port Settings: %1").arg(title.isEmpty() ? port : title));
    auto *layout = new QVBoxLayout(this);
    // The table's description names the port ("CP2, the second communication port ...").
    auto *head = new QLabel(
        m_spec && m_spec->description
            ? tr("%1 %2: %3")
                  .arg(target.displayName, model,
                       QCoreApplication::translate("rung::model::Target", m_spec->description))
            : tr("%1 %2, port %3").arg(target.displayName, model, m_spec ? m_spec->name : port),
        this);
    head->setWordWrap(true);
    layout->addWidget(head);

    auto *form = new QFormLayout;
    m_application = new QComboBox(this);
    m_applicationNote = new QLabel(this);
    m_station = portSpin({0, 255}, this);
    m_stationNote = new QLabel(this);
    m_baud = new QComboBox(this);
    m_frame = new QComboBox(this);
    m_frameNote = new QLabel(this);
    const auto withNote = [this](QWidget *field, QLabel *note) {
        auto *row = new QWidget(this);
        auto *h = new QHBoxLayout(row);
        h->setContentsMargins(0, 0, 0, 0);
        h->addWidget(field);
        h->addWidget(note, 1);
        return row;
    };
    form->addRow(tr("&Application:"), withNote(m_application, m_applicationNote));
    form->addRow(tr("&Station number:"), withNote(m_station, m_stationNote));
    form->addRow(tr("&Baud rate:"), m_baud);
    form->addRow(tr("&Format:"), withNote(m_frame, m_frameNote));
    layout->addLayout(form);

    // CPU Link's master panel (B-3-4): "Total Slaves", "Transfer Range Mode", "Retry",
    // "Timeout unit (10mS)"; the ranges are those readPortConfig takes.
    m_cpuLink = new QGroupBox(tr("CPU Link master (station 0)"), this);
    auto *cpu = new QFormLayout(m_cpuLink);
    m_slaves = portSpin(model::kCpuLinkSlaves, this);
    m_range = portSpin(model::kCpuLinkRange, this);
    m_retry = portSpin(model::kCpuLinkRetries, this);
    m_timeout = portSpin(model::kCpuLinkTimeout, this);
    m_timeout->setSuffix(tr(" x 10 ms"));
    cpu->addRow(withRange(tr("Total s&laves (%1..%2):"), model::kCpuLinkSlaves), m_slaves);
    cpu->addRow(withRange(tr("&Transfer range mode (%1..%2):"), model::kCpuLinkRange), m_range);
    cpu->addRow(withRange(tr("&Retries (%1..%2):"), model::kCpuLinkRetries), m_retry);
    cpu->addRow(withRange(tr("T&ime-out (%1..%2):"), model::kCpuLinkTimeout), m_timeout);
    layout->addWidget(m_cpuLink);

    m_parallel = new QGroupBox(tr("Parallel Link"), this);
    auto *par = new QFormLayout(m_parallel);
    m_role = new QComboBox(this);
    m_role->addItem(tr("Master"), QStringLiteral("master"));
    m_role->addItem(tr("Slave"), QStringLiteral("slave"));
    m_speed = new QComboBox(this);
    m_speed->addItem(tr("Low speed"), QStringLiteral("low"));
    m_speed->addItem(tr("High speed"), QStringLiteral("high"));
    par->addRow(tr("R&ole:"), m_role);
    par->addRow(tr("S&peed (the master's decides):"), m_speed);
    layout->addWidget(m_parallel);

    m_modbus = new QGroupBox(tr("MODBUS"), this);
    auto *mb = new QFormLayout(m_modbus);
    m_mode = new QComboBox(this);
    m_mode->addItem(QStringLiteral("RTU"), QStringLiteral("rtu"));
    m_mode->addItem(QStringLiteral("ASCII"), QStringLiteral("ascii"));
    mb->addRow(tr("&Mode:"), m_mode);
    layout->addWidget(m_modbus);

    m_characters = new QGroupBox(tr("Start and end characters"), this);
    auto *chars = new QFormLayout(m_characters);
    // -1 (shown as "none") below the range: no character.
    m_start = portSpin({model::kCharacterCode.lowest - 1, model::kCharacterCode.highest}, this);
    m_end = portSpin({model::kCharacterCode.lowest - 1, model::kCharacterCode.highest}, this);
    m_start->setSpecialValueText(tr("none"));
    m_end->setSpecialValueText(tr("none"));
    chars->addRow(withRange(tr("Start c&haracter (%1..%2):"), model::kCharacterCode), m_start);
    chars->addRow(withRange(tr("&End character (%1..%2):"), model::kCharacterCode), m_end);
    layout->addWidget(m_characters);

    m_problem = new QLabel(this);
    m_problem->setWordWrap(true);
    m_problem->setStyleSheet(QStringLiteral("color: #b00020"));
    layout->addWidget(m_problem);
    m_buttons = new QDialogButtonBox(
        QDialogButtonBox::Ok | QDialogButtonBox::Cancel | QDialogButtonBox::RestoreDefaults, this);
    layout->addWidget(m_buttons);
    connect(m_buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_buttons->button(QDialogButtonBox::RestoreDefaults), &QPushButton::clicked, this,
            [this] {
                m_original = {};
                fill({});
            });

    if (m_spec) {
        QString lowerApplication = lower.value(QStringLiteral("application")).toString();
        if (!m_spec->application(lowerApplication))
            lowerApplication = QLatin1String(m_spec->applications.front().id);
        for (const model::PortApplication &a : m_spec->applications)
            if (model::applicationOn(a, model)) {
                const QString text = lowerApplication == QLatin1String(a.id)
                                         ? tr("%1 (default)").arg(applicationText(a))
                                         : applicationText(a);
                m_application->addItem(text, QLatin1String(a.id));
            }
    }
    connect(m_application, &QComboBox::currentIndexChanged, this, [this] {
        if (!m_filling)
            fill(m_original);
    });
    for (QSpinBox *box : {m_station, m_slaves, m_range, m_retry, m_timeout, m_start, m_end})
        connect(box, &QSpinBox::valueChanged, this, [this] { check(); });
    for (QComboBox *box : {m_baud, m_frame, m_role, m_speed, m_mode})
        connect(box, &QComboBox::currentIndexChanged, this, [this] { check(); });

    const QString id = settings.value(QStringLiteral("application"))
                           .toString(lower.value(QStringLiteral("application")).toString());
    const int index = m_application->findData(id);
    m_filling = true;
    m_application->setCurrentIndex(index >= 0 ? index : 0);
    m_filling = false;
    fill(settings);
}

const model::PortApplication *NetworkPortDialog::application() const {
    return m_spec ? m_spec->application(m_application->currentData().toString()) : nullptr;
}

QJsonObject NetworkPortDialog::defaultsFor(const model::PortApplication &a) const {
    // What the port runs without this layer's keys: the lower layer's settings where they
    // belong to the application, else the table's defaults.
    model::PortConfig config;
    QString why;
    const QJsonObject choice{{QStringLiteral("application"), QLatin1String(a.id)}};
    const model::ModelVariant *variant = m_target.model(m_model);
    if (!model::readPortConfig(m_target, variant, m_spec->name, {{m_lower, {}}, {choice, {}}},
                               &config, &why))
        model::readPortConfig(m_target, variant, m_spec->name, {{choice, {}}}, &config, &why);
    QString lowerApplication = m_lower.value(QStringLiteral("application")).toString();
    if (!m_spec->application(lowerApplication))
        lowerApplication = QLatin1String(m_spec->applications.front().id);
    return {{QStringLiteral("application"), lowerApplication},
            {QStringLiteral("station"), config.station},
            {QStringLiteral("baud"), config.line.baud},
            {QStringLiteral("frame"), model::frameFormatText(config.line)},
            {QStringLiteral("slaves"), config.slaves},
            {QStringLiteral("range"), config.range},
            {QStringLiteral("retry"), config.retries},
            {QStringLiteral("timeout"), config.timeout},
            {QStringLiteral("role"),
             config.parallelMaster ? QStringLiteral("master") : QStringLiteral("slave")},
            {QStringLiteral("speed"),
             config.highSpeed ? QStringLiteral("high") : QStringLiteral("low")},
            {QStringLiteral("mode"),
             config.modbusAscii ? QStringLiteral("ascii") : QStringLiteral("rtu")},
            {QStringLiteral("start"), codeValue(config.startCode)},
            {QStringLiteral("end"), codeValue(config.endCode)}};
}

void NetworkPortDialog::fill(const QJsonObject &settings) {
    const model::PortApplication *a = application();
    if (!a) {
        m_problem->setText(tr("%1 %2 has no such port").arg(m_target.displayName, m_model));
        m_buttons->button(QDialogButtonBox::Ok)->setEnabled(false);
        return;
    }
    m_filling = true;
    const QJsonObject defaults = defaultsFor(*a);
    const auto value = [&settings, &defaults](const char *key) {
        const QJsonValue v = settings.value(QLatin1String(key));
        return v.isUndefined() ? defaults.value(QLatin1String(key)) : v;
    };
    const QString defaultApplication = defaults.value(QStringLiteral("application")).toString();
    m_applicationNote->clear();
    if (const model::PortApplication *d = m_spec->application(defaultApplication); d && d != a)
        m_applicationNote->setText(tr("default: %1").arg(applicationText(*d)));

    const bool stations = a->stationMax > a->stationMin;
    const int station = value("station").toInt(defaults.value(QStringLiteral("station")).toInt());
    setSpin(m_station, a->stationMin, a->stationMax, station);
    m_station->setEnabled(stations || station != a->stationMin);
    m_stationNote->setText(tr("%1..%2, default %3")
                               .arg(a->stationMin)
                               .arg(a->stationMax)
                               .arg(defaults.value(QStringLiteral("station")).toInt()));

    m_baud->clear();
    const int defaultBaud = defaults.value(QStringLiteral("baud")).toInt();
    for (int b : a->bauds)
        m_baud->addItem(b == defaultBaud ? tr("%1 (default)").arg(b) : QString::number(b), b);
    const int baud = value("baud").toInt(-1);
    if (m_baud->findData(baud) < 0)
        m_baud->addItem(tr("%1 (not a rate of %2)").arg(baud).arg(applicationText(*a)), baud);
    m_baud->setCurrentIndex(m_baud->findData(baud));
    m_baud->setEnabled(a->bauds.size() > 1 || m_baud->count() > 1);

    m_frame->clear();
    const QString defaultFrame = defaults.value(QStringLiteral("frame")).toString();
    for (const QString &f : portFrameChoices())
        m_frame->addItem(f == defaultFrame ? tr("%1 (default)").arg(f) : f, f);
    const QString frame = value("frame").toString();
    if (m_frame->findData(frame) < 0)
        m_frame->addItem(frame, frame);
    m_frame->setCurrentIndex(m_frame->findData(frame));
    m_frame->setEnabled(!a->fixedFrame || frame != defaultFrame);
    m_frameNote->setText(
        a->fixedFrame ? tr("%1 always uses %2").arg(applicationText(*a), QLatin1String(a->frame))
                      : QString());

    m_cpuLink->setVisible(a->sharedLink == 1);
    for (const auto &[box, range, key] : {std::tuple{m_slaves, model::kCpuLinkSlaves, "slaves"},
                                          std::tuple{m_range, model::kCpuLinkRange, "range"},
                                          std::tuple{m_retry, model::kCpuLinkRetries, "retry"},
                                          std::tuple{m_timeout, model::kCpuLinkTimeout, "timeout"}})
        setSpin(box, range.lowest, range.highest, value(key).toInt());
    m_parallel->setVisible(a->sharedLink == 2);
    m_role->setCurrentIndex(m_role->findData(value("role").toString()));
    m_speed->setCurrentIndex(m_speed->findData(value("speed").toString()));
    m_modbus->setVisible(QLatin1String(a->id) == QLatin1String("modbus"));
    m_mode->setCurrentIndex(m_mode->findData(value("mode").toString()));
    m_characters->setVisible(a->programDriven);
    m_start->setValue(value("start").isNull() ? -1 : value("start").toInt());
    m_end->setValue(value("end").isNull() ? -1 : value("end").toInt());
    m_filling = false;
    check();
    adjustSize();
}

QJsonObject NetworkPortDialog::settings() const {
    const model::PortApplication *a = application();
    if (!a)
        return m_original;
    const QJsonObject defaults = defaultsFor(*a);
    QJsonObject current{{QStringLiteral("application"), QLatin1String(a->id)},
                        {QStringLiteral("station"), m_station->value()},
                        {QStringLiteral("baud"), m_baud->currentData().toInt()},
                        {QStringLiteral("frame"), m_frame->currentData().toString()}};
    if (a->sharedLink == 1) {
        current.insert(QStringLiteral("slaves"), m_slaves->value());
        current.insert(QStringLiteral("range"), m_range->value());
        current.insert(QStringLiteral("retry"), m_retry->value());
        current.insert(QStringLiteral("timeout"), m_timeout->value());
    }
    if (a->sharedLink == 2) {
        current.insert(QStringLiteral("role"), m_role->currentData().toString());
        current.insert(QStringLiteral("speed"), m_speed->currentData().toString());
    }
    if (QLatin1String(a->id) == QLatin1String("modbus"))
        current.insert(QStringLiteral("mode"), m_mode->currentData().toString());
    if (a->programDriven) {
        current.insert(QStringLiteral("start"), codeValue(m_start->value()));
        current.insert(QStringLiteral("end"), codeValue(m_end->value()));
    }
    // The keys the settings had stay (the user wrote them); a default is not written.
    QJsonObject out;
    for (auto it = current.begin(); it != current.end(); ++it)
        if (m_original.contains(it.key()) || it.value() != defaults.value(it.key()))
            out.insert(it.key(), it.value());
    return out;
}

QString NetworkPortDialog::problem() const {
    if (!m_spec)
        return m_problem->text();
    model::PortConfig config;
    QString why;
    std::vector<model::PortLayer> layers;
    if (!m_lower.isEmpty())
        layers.push_back({m_lower, tr("the project's settings")});
    layers.push_back({settings(), m_spec->name});
    if (model::readPortConfig(m_target, m_target.model(m_model), m_spec->name, layers, &config,
                              &why))
        return {};
    return why;
}

void NetworkPortDialog::check() {
    if (m_filling)
        return;
    const QString why = problem();
    m_problem->setText(why);
    m_problem->setVisible(!why.isEmpty());
    m_buttons->button(QDialogButtonBox::Ok)->setEnabled(why.isEmpty());
}

// The formats a UART takes (parseFrameFormat: 7 or 8 data bits, N / E / O, 1 or 2 stop bits).
QStringList portFrameChoices() {
    QStringList out;
    for (const char *data : {"8", "7"})
        for (const char *parity : {"N", "E", "O"})
            for (const char *stop : {"1", "2"})
                out << QLatin1String(data) + QLatin1String(parity) + QLatin1String(stop);
    return out;
}

std::optional<QJsonObject> editPortSettings(QWidget *parent, const model::Target &target,
                                            const QString &model, const QString &port,
                                            const QJsonObject &settings, const QJsonObject &lower,
                                            const QString &title) {
    NetworkPortDialog dialog(target, model, port, settings, lower, title, parent);
    if (dialog.exec() != QDialog::Accepted)
        return std::nullopt;
    return dialog.settings();
}

std::optional<QJsonObject> editProjectPorts(QWidget *parent, const model::Target &target,
                                            const QString &model, const QJsonObject &ports) {
    QStringList names;
    for (const model::PortSpec &p : target.ports)
        if (p.on(model))
            names << p.name;
    if (names.isEmpty())
        return std::nullopt;
    bool ok = false;
    const QString port = QInputDialog::getItem(
        parent, NetworkPortDialog::tr("Port Settings"),
        NetworkPortDialog::tr("The %1 %2's port:").arg(target.displayName, model), names, 0, false,
        &ok);
    if (!ok)
        return std::nullopt;
    const auto edited =
        editPortSettings(parent, target, model, port, ports.value(port).toObject(), {}, port);
    if (!edited)
        return std::nullopt;
    QJsonObject out = ports;
    if (edited->isEmpty())
        out.remove(port);
    else
        out.insert(port, *edited);
    return out;
}

} // namespace rung::app
