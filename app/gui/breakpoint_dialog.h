#pragma once

// The condition of a breakpoint: always, when a bit rises or falls, while it is ON or OFF,
// or when a word compares with a number ("when D10 > 100"). The device is checked against
// the target as it is typed; OK stays disabled until the condition is complete.

#include "simulation_controller.h"

#include <QDialog>

class QComboBox;
class QDialogButtonBox;
class QLabel;
class QLineEdit;
class QSpinBox;

namespace rung::app {

class BreakpointDialog : public QDialog {
    Q_OBJECT

public:
    BreakpointDialog(const model::Target &target, const QString &place,
                     const SimulationController::BreakpointSpec &initial,
                     QWidget *parent = nullptr);

    SimulationController::BreakpointSpec breakpoint() const;
    // For tests and keyboard users: the parts of the form.
    QComboBox *kindBox() const { return m_kind; }
    QLineEdit *deviceEdit() const { return m_device; }
    QComboBox *operatorBox() const { return m_op; }
    QSpinBox *valueBox() const { return m_value; }
    QString problem() const; // why OK is disabled; empty when it is enabled

private:
    void validate();

    const model::Target &m_target;
    QComboBox *m_kind;
    QLineEdit *m_device;
    QComboBox *m_op;
    QSpinBox *m_value;
    QLabel *m_problem;
    QDialogButtonBox *m_buttons;
};

} // namespace rung::app
