// The connection panel's live side (connection_panel.h): connecting and the first-time
// question, Test Connection, RUN / STOP / MONITOR, the state and figures shown, the traffic
// log. The settings form is connection_panel.cpp.

#include "connection_panel.h"

#include "dialogs.h"
#include "line_settings_form.h"

#include "comms/driver/relay.h"
#include "model/target/address.h"
#include "model/target/target.h"

#include <QCheckBox>
#include <QComboBox>
#include <QGroupBox>
#include <QHash>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QRadioButton>
#include <QSaveFile>
#include <QTimer>

namespace rung::app {

namespace {

using comms::ConnectionSettings;
using comms::ProtocolKind;
using State = comms::OnlineSession::ConnectionState;
using Text = std::function<QString()>; // as ConnectionPanel::Text

// The colours of a state, a test's result and a command's answer (with their words, never
// alone).
const QString kGood = QStringLiteral("#1b5e20");
const QString kBad = QStringLiteral("#b00020");

QString colourSheet(const QString &colour, bool bold = false) {
    return QStringLiteral("QLabel { %1color: %2; }")
        .arg(bold ? QStringLiteral("font-weight: bold; ") : QString(), colour);
}

// The user's words for a command, for the question and the result line.
QString describe(const model::Target &target, const model::DeviceCommand &c) {
    using Kind = model::DeviceCommand::Kind;
    const QString device = model::formatAddress(target, c.address);
    const QString onOff = c.value ? ConnectionPanel::tr("ON") : ConnectionPanel::tr("OFF");
    switch (c.kind) {
    case Kind::WriteBit:
        return ConnectionPanel::tr("Set %1 %2").arg(device, onOff);
    case Kind::WriteWord:
        return ConnectionPanel::tr("Write %1 = %2").arg(device).arg(c.value);
    case Kind::WriteSetValue:
        return ConnectionPanel::tr("Write the preset of %1 = %2").arg(device).arg(c.value);
    case Kind::Force:
        return ConnectionPanel::tr("Force %1 %2").arg(device, onOff);
    case Kind::Release:
        return ConnectionPanel::tr("Release the force on %1").arg(device);
    case Kind::ReleaseAll:
        return ConnectionPanel::tr("Release every force");
    }
    return {};
}

// The online session with the panel's first-time question: the first change of a
// connection asks before it goes to the PLC; a refusal answers the command at once, with
// nothing sent.
class ConfirmingSession final : public comms::OnlineSession {
public:
    using Ask = std::function<bool(const QString &what)>;
    ConfirmingSession(const model::Target &target, ConnectionSettings settings, Ask ask)
        : OnlineSession(target, std::move(settings))
        , m_ask(std::move(ask)) {}

    // The command's words, once: taken when its answer is shown (made again in the language
    // installed whenever the panel's texts are).
    Text takeWhat(CommandId id) { return m_what.take(id); }
    void remember(CommandId id, Text what) { m_what.insert(id, std::move(what)); }

protected:
    void startCommand(CommandId id, const model::DeviceCommand &command) override {
        const QString text = describe(target(), command);
        m_what.insert(id, [t = &target(), command] { return describe(*t, command); });
        if (!m_confirmed) {
            if (!m_ask || !m_ask(text)) {
                finishCommand(id, false,
                              ConnectionPanel::tr("Cancelled: nothing was sent to the PLC"));
                return;
            }
            m_confirmed = true;
        }
        OnlineSession::startCommand(id, command);
    }

private:
    Ask m_ask;
    bool m_confirmed = false;
    QHash<CommandId, Text> m_what;
};

} // namespace

std::unique_ptr<comms::OnlineSession> ConnectionPanel::makeSession() const {
    auto *self = const_cast<ConnectionPanel *>(this);
    ConnectionSettings s = settings();
    auto session = std::make_unique<ConfirmingSession>(
        *m_target, s, [self, where = s.where()](const QString &what) {
            const QString plc = self->m_session ? self->m_session->plcName() : where;
            return self->confirm(
                tr("Change the PLC's Memory"),
                tr("%1 on %2?\n\nThis changes the memory of a real PLC, which may be driving a "
                   "machine. You are asked once for each connection; later changes go at once.")
                    .arg(what, plc));
        });
    return session;
}

bool ConnectionPanel::connectToPlc() {
    if (m_session)
        return true;
    if (!canConnect()) {
        emit message(m_vpcNote->text());
        return false;
    }
    const ConnectionSettings s = settings();
    if (s.where().isEmpty() || (s.via == ConnectionSettings::Via::Serial && s.port.isEmpty()))
        return askForPort();
    if (m_guard && !m_guard())
        return false;
    m_test.reset();
    remember();
    m_session = makeSession();
    m_session->setTrafficTap(m_record->isChecked());
    m_trafficNext = 0;
    setTestResult({}, QString());
    setCommandResult({}, true);
    comms::OnlineSession *session = m_session.get();
    connect(session, &comms::OnlineSession::connectionStateChanged, this,
            &ConnectionPanel::updateState);
    connect(session, &comms::OnlineSession::plcModeChanged, this, &ConnectionPanel::updateState);
    connect(session, &comms::OnlineSession::identityChanged, this, &ConnectionPanel::updateState);
    connect(session, &model::MonitorSource::errorTextChanged, this, &ConnectionPanel::updateState);
    connect(session, &comms::OnlineSession::statisticsChanged, this,
            &ConnectionPanel::updateStatistics);
    connect(session, &comms::OnlineSession::trafficAvailable, this, &ConnectionPanel::pullTraffic);
    connect(session, &comms::OnlineSession::notice, this, [this](const QString &text) {
        setNotice([text] { return text; }); // the session's words, as it said them
        emit message(text);
    });
    connect(session, &model::MonitorSource::commandFinished, this,
            [this, session](model::MonitorSource::CommandId id, bool ok, const QString &error) {
                Text what = static_cast<ConfirmingSession *>(session)->takeWhat(id);
                if (!what)
                    what = [] { return tr("A command"); };
                setCommandResult(
                    [what, ok, error] {
                        return ok ? tr("%1: done, the PLC acknowledged it").arg(what())
                                  : tr("%1: not done: %2").arg(what(), error);
                    },
                    ok);
            });
    setNotice([] {
        return tr("These PLCs cannot send their program back, so the IDE cannot know whether "
                  "the PLC runs the program shown here. Compare by reading devices: watch them "
                  "in the ladder or the watch table.");
    });
    m_session->connectToPlc();
    updateState();
    emit sessionChanged(session);
    return true;
}

void ConnectionPanel::disconnectFromPlc() {
    if (!m_session)
        return;
    pullTraffic();
    // The views let go of the session before it goes; session() is null while they do.
    std::unique_ptr<comms::OnlineSession> old = std::move(m_session);
    emit sessionChanged(nullptr);
    old->disconnectFromPlc();
    old.reset();
    setNotice({});
    updateState();
}

model::MonitorSource::CommandId ConnectionPanel::setPlcMode(comms::PlcMode mode) {
    if (!m_session)
        return 0;
    const model::MonitorSource::CommandId id = m_session->setPlcMode(mode);
    static_cast<ConfirmingSession *>(m_session.get())->remember(id, [mode] {
        return tr("Switch to %1").arg(comms::modeName(mode));
    });
    return id;
}

bool ConnectionPanel::requestPlcMode(comms::PlcMode mode) {
    comms::OnlineSession *session = m_session.get();
    if (!session)
        return false;
    // Host Link has PROGRAM / MONITOR / RUN; the others RUN and STOP (their RUN bit).
    if (mode == comms::PlcMode::Program && !session->abilities().monitorMode)
        mode = comms::PlcMode::Stop;
    QString what;
    switch (mode) {
    case comms::PlcMode::Run:
        what = tr("The PLC runs its program: its outputs switch as the program says.");
        break;
    case comms::PlcMode::Monitor:
        what = tr("The PLC runs its program and takes writes from the IDE.");
        break;
    default:
        what = tr("The PLC stops running its program.");
        break;
    }
    if (!confirm(tr("PLC Mode"),
                 tr("Switch %1 to %2?\n\n%3").arg(session->plcName(), comms::modeName(mode), what)))
        return false;
    return setPlcMode(mode) != 0;
}

bool ConnectionPanel::askForPort() {
    const bool tcp = m_viaTcp->isChecked();
    setTestResult(
        [tcp] {
            return tcp ? tr("Type the host name or IP address of the PLC or its gateway")
                       : tr("Choose the serial port the PLC is on (or type its path)");
        },
        kBad);
    emit message(m_testResult->text());
    QWidget *field = m_viaTcp->isChecked() ? static_cast<QWidget *>(m_line->hostEdit())
                                           : static_cast<QWidget *>(m_line->portBox());
    field->setFocus(Qt::OtherFocusReason);
    return false;
}

bool ConnectionPanel::testConnection() {
    if (m_session || m_test) {
        emit message(m_session ? tr("Already connected: the panel shows what the PLC reports")
                               : tr("A test is under way"));
        return false;
    }
    if (!canConnect()) {
        emit message(m_vpcNote->text());
        return false;
    }
    const ConnectionSettings s = settings();
    if (s.where().isEmpty())
        return askForPort();
    remember();
    m_test = std::make_unique<comms::OnlineSession>(*m_target, s);
    setTestResult([where = s.where()] { return tr("Testing %1...").arg(where); }, QString());
    comms::OnlineSession *test = m_test.get();
    connect(test, &comms::OnlineSession::connectionStateChanged, this, [this, test](State state) {
        if (m_test.get() != test)
            return; // the test is over; the session is on its way out
        if (state == State::Online) {
            const comms::PlcIdentity id = test->identity();
            const comms::PlcMode mode = test->plcMode();
            const double roundTrip = test->statistics().lastRoundTripMs;
            finishTest(true, [id, mode, roundTrip] {
                QString found =
                    id.model.isEmpty()
                        ? tr("The PLC answers (this protocol does not report the model)")
                        : tr("The PLC answers: %1").arg(id.model);
                if (!id.version.isEmpty())
                    found += tr(", version %1").arg(id.version);
                if (mode != comms::PlcMode::Unknown)
                    found += tr("; mode %1").arg(comms::modeName(mode));
                found += tr("; round trip %1 ms").arg(roundTrip, 0, 'f', 1);
                return found + QLatin1Char('.');
            });
        } else if (state == State::Lost || state == State::Failed ||
                   (state == State::Connecting && !test->errorText().isEmpty())) {
            finishTest(false,
                       [error = test->errorText()] { return tr("No answer: %1").arg(error); });
        }
    });
    // A silent line: the session keeps trying; the test gives up after every retry's time.
    if (!m_testDeadline) {
        m_testDeadline = new QTimer(this);
        m_testDeadline->setSingleShot(true);
        connect(m_testDeadline, &QTimer::timeout, this, [this] {
            if (m_test)
                finishTest(false, [error = m_test->errorText()] {
                    return error.isEmpty() ? tr("No answer from the PLC")
                                           : tr("No answer: %1").arg(error);
                });
        });
    }
    m_testDeadline->start(s.link.timeoutMs * (s.link.retries + 1) + 1000);
    m_test->connectToPlc();
    updateState();
    return true;
}

void ConnectionPanel::finishTest(bool ok, const Text &text) {
    if (m_testDeadline)
        m_testDeadline->stop();
    // Not inside the test session's own signal: it goes on the next turn of the loop.
    if (m_test) {
        m_test->disconnectFromPlc();
        m_test.release()->deleteLater();
    }
    setTestResult(text, ok ? kGood : kBad);
    updateState();
    emit testFinished(ok, m_testResult->text());
}

QString ConnectionPanel::onlineText() const {
    QString text = tr("Online: %1").arg(m_session->plcName());
    if (m_session->plcMode() != comms::PlcMode::Unknown)
        text += QStringLiteral(", ") + comms::modeName(m_session->plcMode());
    if (!m_session->identity().model.isEmpty())
        text += QStringLiteral(" (%1)").arg(m_session->identity().model);
    return text;
}

QString ConnectionPanel::warningText() const {
    return m_session && m_session->connectionState() == State::Online ? m_session->errorText()
                                                                      : QString();
}

QString ConnectionPanel::stateText() const {
    if (!m_session)
        return canConnect() ? tr("Offline") : tr("Offline: no link to this PLC");
    const QString error = m_session->errorText();
    switch (m_session->connectionState()) {
    case State::Disconnected:
        return tr("Offline");
    case State::Connecting:
        return error.isEmpty()
                   ? tr("Connecting to %1...").arg(m_session->settings().where())
                   : tr("Connecting to %1: %2").arg(m_session->settings().where(), error);
    case State::Online:
        return error.isEmpty() ? onlineText() : onlineText() + QLatin1Char('\n') + error;
    case State::Lost:
        // The session's text says "lost", the PLC, the cause and that it tries again.
        return tr("%1\nThe values shown are the last read, marked stale.").arg(error);
    case State::Failed:
        return tr("Cannot connect: %1").arg(error);
    }
    return {};
}

void ConnectionPanel::updateState() {
    const bool online = m_session != nullptr;
    m_connect->setText(online ? tr("Disconnect") : tr("Connect"));
    m_connect->setEnabled(canConnect());
    m_testButton->setEnabled(canConnect() && !online && !m_test);
    // A test runs on the settings it started with: changed under it, its answer would stand
    // beside settings it never tried.
    m_settingsBox->setEnabled(canConnect() && !online && !m_test);
    // Online the settings cannot change: the state names the port and the PLC, and the room
    // goes to the figures and the traffic.
    m_settingsBox->setVisible(!online);
    // Online, what the PLC cannot answer (a device with no address in the protocol) is a
    // warning of its own, never in the green of the state above it.
    const QString warning = warningText();
    m_state->setText(warning.isEmpty() ? stateText() : onlineText());
    m_warning->setText(warning.isEmpty() ? QString() : QStringLiteral("\u26A0 ") + warning);
    m_warning->setVisible(!warning.isEmpty());
    QString colour;
    if (m_session) {
        switch (m_session->connectionState()) {
        case State::Online:
            colour = kGood;
            break;
        case State::Lost:
        case State::Failed:
            colour = kBad;
            break;
        case State::Connecting: // first contact failed: the session tries again
            if (!m_session->errorText().isEmpty())
                colour = kBad;
            break;
        default:
            break;
        }
    }
    m_state->setStyleSheet(colour.isEmpty() ? QStringLiteral("QLabel { font-weight: bold; }")
                                            : colourSheet(colour, true));
    updateStatistics();
}

QString ConnectionPanel::statisticsText() const {
    if (!m_session)
        return {};
    const comms::LinkStatistics s = m_session->statistics();
    return tr("Errors %1, retries %2, timeouts %3, refused %4, reconnects %5\n"
              "Round trip %6 ms (mean %7, max %8); refresh %9 ms, %10 frame(s)")
        .arg(s.errors)
        .arg(s.retries)
        .arg(s.timeouts)
        .arg(s.refusals)
        .arg(s.reconnects)
        .arg(s.lastRoundTripMs, 0, 'f', 1)
        .arg(s.meanRoundTripMs, 0, 'f', 1)
        .arg(s.maxRoundTripMs, 0, 'f', 1)
        .arg(s.lastRefreshMs, 0, 'f', 1)
        .arg(s.framesPerRefresh);
}

void ConnectionPanel::updateStatistics() {
    m_statistics->setText(statisticsText());
}

QString ConnectionPanel::lastCommandText() const {
    return m_command->text();
}

void ConnectionPanel::setTestResult(Text text, const QString &colour) {
    m_testText = std::move(text);
    m_testColour = colour;
    m_testResult->setText(m_testText ? m_testText() : QString());
    m_testResult->setStyleSheet(colour.isEmpty() ? QString() : colourSheet(colour));
}

void ConnectionPanel::setCommandResult(Text text, bool ok) {
    m_commandText = std::move(text);
    m_commandOk = ok;
    m_command->setText(m_commandText ? m_commandText() : QString());
    m_command->setStyleSheet(ok ? QString() : colourSheet(kBad));
}

void ConnectionPanel::setNotice(Text text) {
    m_noticeText = std::move(text);
    m_notice->setText(m_noticeText ? m_noticeText() : QString());
}

void ConnectionPanel::retranslateResults() {
    setTestResult(m_testText, m_testColour);
    setCommandResult(m_commandText, m_commandOk);
    setNotice(m_noticeText);
}

void ConnectionPanel::forgetResults() {
    // Offline only: online, the panel speaks of the PLC the IDE is still connected to.
    if (m_session)
        return;
    setTestResult({}, QString());
    setCommandResult({}, true);
    setNotice({}); // the traffic log stays: it is a record the user may still save
}

void ConnectionPanel::pullTraffic() {
    if (!m_session)
        return;
    quint64 next = m_trafficNext;
    const std::vector<comms::TrafficRecord> records = m_session->traffic(m_trafficNext, &next);
    m_trafficNext = next;
    if (records.empty())
        return;
    //: the direction of bytes in the traffic log: from the PC to the PLC, and back
    const QString sent = tr("PC>PLC");
    const QString received = tr("PLC>PC");
    QStringList lines;
    lines.reserve(int(records.size()));
    for (const comms::TrafficRecord &r : records)
        lines << comms::formatTrafficRecord(r, m_session->trafficStart(), sent, received);
    m_traffic->appendPlainText(lines.join(QLatin1Char('\n')));
}

bool ConnectionPanel::saveTraffic(const QString &path, QString *error) const {
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Text)) {
        *error = tr("Cannot write %1: %2").arg(path, file.errorString());
        return false;
    }
    file.write(m_traffic->toPlainText().toUtf8());
    file.write("\n");
    if (!file.commit()) {
        *error = tr("Cannot write %1: %2").arg(path, file.errorString());
        return false;
    }
    return true;
}

} // namespace rung::app
