#pragma once

// A station port's bridge to a real line (docs/network.md, "Bridges in the IDE"): a
// pseudo-terminal for a master on this computer, a serial port, a TCP connection to a serial
// device server, or a TCP port a master connects to. The port or host and the line are asked
// with the Connection dock's own form (line_settings_form.h); a serial port opens at the
// station port's rate and format, so changing them here changes the port's settings (in the
// same undo step). OK stays off, with the reason shown, while the bridge would be refused.

#include "network/network_file.h"

#include <QDialog>
#include <QJsonObject>

#include <optional>

class QDialogButtonBox;
class QLabel;
class QRadioButton;

namespace rung::model {
struct PortApplication;
struct SerialSettings;
} // namespace rung::model

namespace rung::app {

class LineSettingsForm;

class NetworkBridgeDialog : public QDialog {
    Q_OBJECT
public:
    // `bridge`: the port's bridge as it is (its end names the port: "s5/CP2"); `application`
    // and `line`: what the port runs and its rate and format; `settings`: the network's own
    // settings of the port (a changed rate is written over them).
    NetworkBridgeDialog(const network::BridgeDescription &bridge,
                        const model::PortApplication &application,
                        const model::SerialSettings &line, const QJsonObject &settings,
                        QWidget *parent = nullptr);

    network::BridgeDescription bridge() const;
    // The port's new settings when the rate or format was changed; nullopt when not.
    std::optional<QJsonObject> portSettings() const;
    QString problem() const; // why OK is off; "" when it is on

    void setKind(network::BridgeDescription::Kind kind);
    LineSettingsForm *lineForm() const { return m_line; }
    QDialogButtonBox *buttons() const { return m_buttons; }

private:
    network::BridgeDescription::Kind kind() const;
    void kindChosen();
    void check();

    network::BridgeDescription m_bridge;
    const model::PortApplication &m_application;
    QJsonObject m_settings;
    int m_baud = 0;
    QString m_frame;
    QRadioButton *m_kinds[4] = {};
    LineSettingsForm *m_line = nullptr;
    QLabel *m_note = nullptr;
    QLabel *m_problem = nullptr;
    QDialogButtonBox *m_buttons = nullptr;
};

} // namespace rung::app
