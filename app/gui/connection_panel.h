#pragma once

// The connection panel (issue 13): where a real PLC is and how to speak to it, the link's
// state and figures, and the bytes both ways. The target family and model come from the
// project; the protocol is chosen where the family has a choice; the line settings start
// from each protocol's defaults (comms::defaultSettings). Connect makes a comms::OnlineSession
// (owned here) and announces it with sessionChanged(): the main window hands it to the views
// (main_window_online.cpp). A VPC is listed and says what to do instead: its link protocol is
// not published.
//
// The first write, force or preset of a connection asks before it goes to the PLC (naming
// the device and the PLC); later ones go at once. Every command's answer from the PLC is
// shown in the panel.

#include "comms/driver/online_session.h"

#include <QPointer>
#include <QWidget>

#include <functional>
#include <memory>

class QCheckBox;
class QComboBox;
class QGroupBox;
class QLabel;
class QLineEdit;
class QPlainTextEdit;
class QPushButton;
class QToolButton;
class QRadioButton;
class QSpinBox;
class QTimer;

namespace rung::model {
class Target;
}

namespace rung::app {

class ConnectionPanel : public QWidget {
    Q_OBJECT

public:
    explicit ConnectionPanel(QWidget *parent = nullptr);
    ~ConnectionPanel() override;

    // The project's target and model; a change of family ends a connection and refills the
    // protocol choice with its defaults.
    void setTarget(const model::Target &target, const QString &modelName);
    const model::Target *target() const { return m_target; }
    // True when the family has a protocol the IDE speaks (not a VPC).
    bool canConnect() const;
    // Why not, and what to do instead (empty when it can).
    QString cannotConnectReason() const;

    // The settings as the fields say; setSettings fills the fields.
    comms::ConnectionSettings settings() const;
    void setSettings(const comms::ConnectionSettings &settings);

    // Null while offline.
    comms::OnlineSession *session() const { return m_session.get(); }
    // Connects with the fields' settings; false (with message()) when it cannot start.
    bool connectToPlc();
    void disconnectFromPlc();
    // Opens a second, short-lived session that reads the identity (or the run state) and
    // says what it found in the panel and in testFinished(); false when it cannot start.
    bool testConnection();
    bool testing() const { return m_test != nullptr; }
    // RUN / STOP / MONITOR through the session (its answer shows as the last command); 0
    // while offline.
    model::MonitorSource::CommandId setPlcMode(comms::PlcMode mode);
    // The same after asking (naming the PLC and what the mode does); false when declined.
    // STOP is PROGRAM over Host Link, the RUN bit's off state over the others.
    bool requestPlcMode(comms::PlcMode mode);

    // Questions to the user (tests answer them directly): true to go on.
    using Confirmer = std::function<bool(const QString &title, const QString &text)>;
    void setConfirmer(Confirmer confirmer) { m_confirmer = std::move(confirmer); }
    bool confirm(const QString &title, const QString &text);
    // Asked before connecting (the window: the simulation); false: do not connect.
    void setConnectGuard(std::function<bool()> guard) { m_guard = std::move(guard); }

    // "Online: Vigor station 0 on /dev/pts/3", "Link lost: ...", as the panel shows it.
    QString stateText() const;
    // Online: what the PLC cannot answer ("TR 0 has no address in ..."), shown apart from the
    // state as a warning; empty otherwise.
    QString warningText() const;
    QString statisticsText() const;
    QString lastCommandText() const;
    QPlainTextEdit *trafficLog() const { return m_traffic; }
    // Writes the traffic log as shown (one record a line); false with the reason.
    bool saveTraffic(const QString &path, QString *error) const;
    // Serial ports again (Refresh).
    void refreshPorts();
    // Another project: what the panel said of the last test, command and connection is not
    // this project's (offline; online the panel keeps speaking of the PLC it is connected to).
    void forgetResults();

signals:
    void sessionChanged(rung::comms::OnlineSession *session); // null: offline again
    void testFinished(bool ok, const QString &text);
    void message(const QString &text);
    void saveTrafficRequested(); // Save... (the window asks where)

protected:
    void changeEvent(QEvent *event) override;

private:
    void build();
    void retranslate();
    void fillProtocols();
    void protocolChosen();
    void updateState();
    QString onlineText() const; // "Online: Vigor station 0 on /dev/pts/3, RUN (VB-14)"
    void updateStatistics();
    void pullTraffic();
    // A text the panel shows, made again in the language installed on a language change.
    using Text = std::function<QString()>;
    void finishTest(bool ok, const Text &text);
    void setTestResult(Text text, const QString &colour);
    void setCommandResult(Text text, bool ok);
    void setNotice(Text text);
    void retranslateResults();
    // No port chosen: says so in the panel as well as the status bar, and puts the cursor in
    // the port's field; false.
    bool askForPort();
    void showVia(int page); // 0: the serial settings, 1: TCP
    void remember() const;
    std::unique_ptr<comms::OnlineSession> makeSession() const;
    comms::ProtocolKind protocol() const;

    const model::Target *m_target = nullptr;
    QString m_modelName;
    std::unique_ptr<comms::OnlineSession> m_session;
    std::unique_ptr<comms::OnlineSession> m_test;
    QTimer *m_testDeadline = nullptr;
    Confirmer m_confirmer;
    std::function<bool()> m_guard;
    quint64 m_trafficNext = 0;
    Text m_testText;
    QString m_testColour;
    Text m_commandText;
    bool m_commandOk = true;
    Text m_noticeText;

    QLabel *m_targetLabel = nullptr;
    QLabel *m_vpcNote = nullptr;
    QGroupBox *m_settingsBox = nullptr;
    QLabel *m_protocolLabel = nullptr;
    QComboBox *m_protocol = nullptr;
    QRadioButton *m_viaSerial = nullptr;
    QRadioButton *m_viaTcp = nullptr;
    class LineSettingsForm *m_line = nullptr; // the port or host and the line
    QSpinBox *m_station = nullptr;
    QSpinBox *m_timeout = nullptr;
    QSpinBox *m_retries = nullptr;
    QLabel *m_stationLabel = nullptr;
    QLabel *m_timeoutLabel = nullptr;
    QLabel *m_retriesLabel = nullptr;
    QPushButton *m_testButton = nullptr;
    QPushButton *m_connect = nullptr;
    QLabel *m_state = nullptr;
    QLabel *m_warning = nullptr;
    QLabel *m_testResult = nullptr;
    QLabel *m_statistics = nullptr;
    QLabel *m_command = nullptr;
    QLabel *m_notice = nullptr;
    QGroupBox *m_trafficBox = nullptr;
    QCheckBox *m_record = nullptr;
    QPushButton *m_clear = nullptr;
    QPushButton *m_save = nullptr;
    QPlainTextEdit *m_traffic = nullptr;
};

} // namespace rung::app
