#include "breakpoint_dialog.h"

#include "dialogs.h"

#include "model/target/address.h"
#include "model/target/target_lists.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

#include <limits>

namespace rung::app {

namespace {

using When = simulator::Breakpoint::When;

constexpr model::CompareOp kOps[] = {model::CompareOp::Eq, model::CompareOp::Ne,
                                     model::CompareOp::Lt, model::CompareOp::Le,
                                     model::CompareOp::Gt, model::CompareOp::Ge};

bool isWordArea(model::AreaKind k) {
    return k == model::AreaKind::Word || k == model::AreaKind::Channel ||
           k == model::AreaKind::Timer || k == model::AreaKind::Counter;
}

} // namespace

BreakpointDialog::BreakpointDialog(const model::Target &target, const QString &place,
                                   const SimulationController::BreakpointSpec &initial,
                                   QWidget *parent)
    : QDialog(parent)
    , m_target(target) {
    setWindowTitle(tr("Breakpoint Condition"));
    auto *layout = new QVBoxLayout(this);
    auto *where = new QLabel(place);
    where->setWordWrap(true);
    layout->addWidget(where);
    auto *form = new QFormLayout;
    m_kind = new QComboBox;
    m_kind->addItem(tr("Always"), static_cast<int>(When::Always));
    m_kind->addItem(tr("When the bit rises"), static_cast<int>(When::Rises));
    m_kind->addItem(tr("When the bit falls"), static_cast<int>(When::Falls));
    m_kind->addItem(tr("While the bit is ON"), static_cast<int>(When::IsOn));
    m_kind->addItem(tr("While the bit is OFF"), static_cast<int>(When::IsOff));
    m_kind->addItem(tr("When the word compares"), static_cast<int>(When::Compare));
    form->addRow(tr("&Stop"), m_kind);
    m_device = new QLineEdit;
    m_device->setPlaceholderText(
        tr("a device, e.g. %1 or %2")
            .arg(model::exampleDevice(target, true), model::exampleWord(target, 10)));
    form->addRow(tr("&Device"), m_device);
    m_op = new QComboBox;
    for (const model::CompareOp op : kOps)
        m_op->addItem(QString::fromLatin1(model::compareSymbol(op)), static_cast<int>(op));
    m_value = new QSpinBox;
    m_value->setRange(std::numeric_limits<int>::min(), std::numeric_limits<int>::max());
    auto *compare = new QHBoxLayout;
    compare->addWidget(m_op);
    compare->addWidget(m_value, 1);
    // A row of a layout gets no buddy from the form: its "&Compare" would show the '&'.
    auto *compareLabel = new QLabel(tr("&Compare"));
    compareLabel->setBuddy(m_op);
    form->addRow(compareLabel, compare);
    layout->addLayout(form);
    m_problem = new QLabel;
    m_problem->setObjectName(QStringLiteral("breakpointProblem"));
    m_problem->setWordWrap(true);
    m_problem->setStyleSheet(QStringLiteral("color: #b00020"));
    layout->addWidget(m_problem);
    m_buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
    layout->addWidget(m_buttons);
    connect(m_buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    m_kind->setCurrentIndex(std::max(0, m_kind->findData(static_cast<int>(initial.when))));
    if (initial.device.valid())
        m_device->setText(model::formatAddress(target, initial.device));
    m_op->setCurrentIndex(std::max(0, m_op->findData(static_cast<int>(initial.op))));
    m_value->setValue(static_cast<int>(initial.value));
    connect(m_kind, &QComboBox::currentIndexChanged, this, &BreakpointDialog::validate);
    connect(m_device, &QLineEdit::textChanged, this, &BreakpointDialog::validate);
    validate();
    fitTitle(this);
}

QString BreakpointDialog::problem() const {
    return m_problem->text();
}

void BreakpointDialog::validate() {
    const auto when = static_cast<When>(m_kind->currentData().toInt());
    const bool needsDevice = when != When::Always;
    m_device->setEnabled(needsDevice);
    m_op->setEnabled(when == When::Compare);
    m_value->setEnabled(when == When::Compare);
    QString why;
    if (needsDevice) {
        const QString text = m_device->text().trimmed();
        const auto parsed = model::parseAddress(m_target, text);
        if (text.isEmpty()) {
            why = tr("Type the device the condition watches");
        } else if (const auto *e = std::get_if<model::AddressError>(&parsed)) {
            why = tr("%1 is no device of this PLC: %2").arg(text, e->message);
        } else {
            const model::Address a = std::get<model::Address>(parsed);
            const bool word = a.bit < 0 && isWordArea(m_target.area(a.area).kind);
            if (when == When::Compare && !word)
                why = tr("%1 is a bit: compare a word (D, a timer's or counter's value)").arg(text);
            else if (when != When::Compare && word &&
                     m_target.area(a.area).kind != model::AreaKind::Timer &&
                     m_target.area(a.area).kind != model::AreaKind::Counter)
                why = tr("%1 is a word: watch a bit, or compare the word").arg(text);
        }
    }
    m_problem->setText(why);
    m_problem->setVisible(!why.isEmpty());
    m_buttons->button(QDialogButtonBox::Ok)->setEnabled(why.isEmpty());
}

SimulationController::BreakpointSpec BreakpointDialog::breakpoint() const {
    SimulationController::BreakpointSpec b;
    b.when = static_cast<When>(m_kind->currentData().toInt());
    if (b.when != When::Always) {
        const auto parsed = model::parseAddress(m_target, m_device->text().trimmed());
        if (const auto *a = std::get_if<model::Address>(&parsed))
            b.device = *a;
    }
    b.op = static_cast<model::CompareOp>(m_op->currentData().toInt());
    b.value = m_value->value();
    return b;
}

} // namespace rung::app
