#pragma once

// A port's settings (what Ladder Master calls the "2nd COM Port Setting", Vigor M/VB/VH
// communication manual, B-3-1; the PL110's port protocols, PL110 manual 3.1 and 4.2.21): the
// application, station number, baud rate and format, and each application's own panel (CPU
// Link's slaves, transfer range, retries and time-out; Parallel Link's role and speed; MODBUS
// RTU / ASCII; Non Protocol's start and end characters). Every choice, range and default comes
// from the target's table (Target::ports); the settings are checked as the network and the
// project read them (model::readPortConfig), and OK stays off with the reason shown while they
// would be refused. The result holds the keys the user set and those the settings had, not the
// defaults (a project saves what the user set).

#include <QDialog>
#include <QJsonObject>
#include <QStringList>

#include <optional>

class QComboBox;
class QDialogButtonBox;
class QGroupBox;
class QLabel;
class QSpinBox;

namespace rung::model {
class Target;
struct PortApplication;
struct PortSpec;
} // namespace rung::model

namespace rung::app {

class NetworkPortDialog : public QDialog {
    Q_OBJECT
public:
    // `lower`: the settings under the ones edited (a project's, under a network's); their
    // values are the defaults shown. `title` names the port ("master/CP2").
    NetworkPortDialog(const model::Target &target, const QString &model, const QString &port,
                      const QJsonObject &settings, const QJsonObject &lower, const QString &title,
                      QWidget *parent = nullptr);

    QJsonObject settings() const; // the keys as a file writes them
    QString problem() const;      // why the settings would be refused; "" when they would not

    // The widgets, for tests and for the keyboard.
    QComboBox *applicationBox() const { return m_application; }
    QSpinBox *stationBox() const { return m_station; }
    QComboBox *baudBox() const { return m_baud; }
    QComboBox *frameBox() const { return m_frame; }
    QSpinBox *slavesBox() const { return m_slaves; }
    QSpinBox *rangeBox() const { return m_range; }
    QSpinBox *retryBox() const { return m_retry; }
    QSpinBox *timeoutBox() const { return m_timeout; }
    QGroupBox *cpuLinkGroup() const { return m_cpuLink; }
    QGroupBox *parallelGroup() const { return m_parallel; }
    QGroupBox *modbusGroup() const { return m_modbus; }
    QGroupBox *charactersGroup() const { return m_characters; }
    QLabel *problemLabel() const { return m_problem; }
    QDialogButtonBox *buttons() const { return m_buttons; }

private:
    const model::PortApplication *application() const;
    void fill(const QJsonObject &settings); // the widgets for the chosen application
    void check();                           // the problem label and OK
    QJsonObject defaultsFor(const model::PortApplication &application) const;

    const model::Target &m_target;
    QString m_model;
    const model::PortSpec *m_spec;
    QJsonObject m_original;
    QJsonObject m_lower;
    QComboBox *m_application;
    QLabel *m_applicationNote;
    QSpinBox *m_station;
    QLabel *m_stationNote;
    QComboBox *m_baud;
    QComboBox *m_frame;
    QLabel *m_frameNote;
    QGroupBox *m_cpuLink;
    QSpinBox *m_slaves;
    QSpinBox *m_range;
    QSpinBox *m_retry;
    QSpinBox *m_timeout;
    QGroupBox *m_parallel;
    QComboBox *m_role;
    QComboBox *m_speed;
    QGroupBox *m_modbus;
    QComboBox *m_mode;
    QGroupBox *m_characters;
    QSpinBox *m_start;
    QSpinBox *m_end;
    QLabel *m_problem;
    QDialogButtonBox *m_buttons;
    bool m_filling = false;
};

// The character formats a UART takes, as the port dialogs offer them: 8N1 .. 7O2
// (model::parseFrameFormat reads each).
QStringList portFrameChoices();

// Edits one port of a network's station or of a single project: the settings after OK, nullopt
// when cancelled. `lower` as above (empty for a project's own ports).
std::optional<QJsonObject> editPortSettings(QWidget *parent, const model::Target &target,
                                            const QString &model, const QString &port,
                                            const QJsonObject &settings,
                                            const QJsonObject &lower = {},
                                            const QString &title = {});

// A project's "ports" object edited port by port: asks which of the model's ports, then its
// settings; the whole object after OK (a port without settings is left out), nullopt when
// cancelled. The caller makes it one undo step of the project.
std::optional<QJsonObject> editProjectPorts(QWidget *parent, const model::Target &target,
                                            const QString &model, const QJsonObject &ports);

} // namespace rung::app
