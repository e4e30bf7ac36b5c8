#include "monitor_commands.h"

#include "model/image/bcd.h"
#include "model/target/address.h"

#include <QAction>
#include <QInputDialog>
#include <QMenu>
#include <QWidget>

namespace rung::editor {

namespace {

bool isDevice(const model::Operand &o) {
    return o.kind == model::Operand::Kind::Device && o.address.valid();
}

void addOnce(std::vector<model::Address> &list, const model::Address &a) {
    if (std::find(list.begin(), list.end(), a) == list.end())
        list.push_back(a);
}

// The BCD digits of a value 0..9999 as a word (a CPM1 channel that holds a set value).
std::optional<qint64> toBcd(qint64 value) {
    if (value < 0 || value > 9999)
        return std::nullopt;
    return model::toBcd(value);
}

} // namespace

MonitorTargets monitorTargets(const model::Target &target,
                              const std::vector<model::Operand> &operands, model::Op op) {
    MonitorTargets t;
    const bool element =
        op == model::Op::Timer || op == model::Op::Counter || op == model::Op::UpDownCounter;
    for (std::size_t k = 0; k < operands.size(); ++k) {
        const model::Operand &o = operands[k];
        if (!isDevice(o))
            continue;
        const model::AreaKind kind = target.area(o.address.area).kind;
        if (element && k == 0) {
            // The box's own element: its preset, as the instruction keeps it.
            MonitorTargets::Preset preset{o.address, std::nullopt, QString()};
            if (operands.size() > 1) {
                const model::Operand &set = operands[1];
                if (isDevice(set))
                    preset.word = set.address;
                else if (set.kind == model::Operand::Kind::Constant)
                    preset.constant = model::formatOperand(target, set);
            }
            t.presets.push_back(preset);
            addOnce(t.bits, o.address); // its done bit
            continue;
        }
        if (element && k == 1)
            continue; // the preset's word: written through Write Preset
        if (o.address.bit >= 0 || kind == model::AreaKind::Bit) {
            addOnce(t.bits, o.address);
        } else if (kind == model::AreaKind::Timer || kind == model::AreaKind::Counter) {
            // A timer's or counter's contact is its done bit; its current value follows the
            // program and cannot be written.
            if (op == model::Op::Load || op == model::Op::Out || op == model::Op::Set ||
                op == model::Op::Reset)
                addOnce(t.bits, o.address);
        } else {
            addOnce(t.words, o.address);
        }
    }
    return t;
}

MonitorTargets monitorTargets(const model::Target &target, const model::Instruction &ins) {
    model::Op op = ins.op();
    if (op == model::Op::And || op == model::Op::Or)
        op = model::Op::Load; // a contact is a contact, wherever it stands
    return monitorTargets(target, ins.operands, op);
}

MonitorCommands::MonitorCommands(const model::Target *target, QWidget *view)
    : QObject(view)
    , m_target(target)
    , m_view(view) {}

void MonitorCommands::setSource(model::MonitorSource *source) {
    if (!model::MonitorSource::switchSource(m_source, source, this))
        return;
    m_pending.clear();
    if (!source)
        return;
    connect(source, &model::MonitorSource::commandFinished, this,
            [this](model::MonitorSource::CommandId id, bool ok, const QString &error) {
                const auto it = m_pending.find(id);
                if (it == m_pending.end())
                    return; // another view's command
                const QString done = it->second;
                m_pending.erase(it);
                emit message(ok ? done : error);
            });
}

QString MonitorCommands::device(const model::Address &address) const {
    return m_target ? model::formatAddress(*m_target, address) : QString();
}

void MonitorCommands::track(model::MonitorSource::CommandId id, const QString &done) {
    m_pending[id] = done;
}

bool MonitorCommands::addActions(QMenu *menu, const MonitorTargets &devices) {
    if (devices.empty() || !m_target)
        return false;
    const bool live = m_source != nullptr;
    const auto add = [menu, live](const QString &text, auto run) {
        QAction *a = menu->addAction(text);
        a->setEnabled(live);
        connect(a, &QAction::triggered, menu, run);
        return a;
    };
    QPointer<MonitorCommands> self(this);
    const QString noForce = live ? m_source->forceRefusal() : QString();
    const auto forcing = [&noForce](QAction *a) {
        if (noForce.isEmpty())
            return;
        a->setEnabled(false);
        a->setToolTip(noForce);
    };
    for (const model::Address &bit : devices.bits) {
        const QString name = device(bit);
        forcing(add(tr("Force %1 O&N").arg(name), [self, bit] {
            if (self)
                self->force(bit, true);
        }));
        forcing(add(tr("Force %1 O&FF").arg(name), [self, bit] {
            if (self)
                self->force(bit, false);
        }));
        forcing(add(tr("&Release %1").arg(name), [self, bit] {
            if (self)
                self->release(bit);
        }));
        add(tr("Set %1 &ON").arg(name), [self, bit] {
            if (self)
                self->setBit(bit, true);
        });
        add(tr("Set %1 OFF").arg(name), [self, bit] {
            if (self)
                self->setBit(bit, false);
        });
        menu->addSeparator();
    }
    for (const model::Address &word : devices.words)
        add(tr("&Write %1...").arg(device(word)), [self, word] {
            if (self)
                self->writeValue(word);
        });
    for (const MonitorTargets::Preset &preset : devices.presets) {
        QAction *a = add(tr("Write &Preset of %1...").arg(device(preset.element)), [self, preset] {
            if (self)
                self->writePreset(preset);
        });
        if (!preset.constant.isEmpty()) {
            // Written over by the program at the next scan: only an edit changes it.
            a->setEnabled(false);
            a->setToolTip(tr("The preset of %1 is the constant %2 of the program: change it in "
                             "the program")
                              .arg(device(preset.element), preset.constant));
        }
    }
    menu->setToolTipsVisible(true);
    return true;
}

void MonitorCommands::force(const model::Address &address, bool on) {
    if (!m_source)
        return;
    track(m_source->force(address, on),
          on ? tr("%1 forced ON").arg(device(address)) : tr("%1 forced OFF").arg(device(address)));
}

void MonitorCommands::release(const model::Address &address) {
    if (!m_source)
        return;
    track(m_source->release(address), tr("%1 released").arg(device(address)));
}

void MonitorCommands::setBit(const model::Address &address, bool on) {
    if (!m_source)
        return;
    track(m_source->writeBit(address, on),
          on ? tr("%1 set ON").arg(device(address)) : tr("%1 set OFF").arg(device(address)));
}

std::optional<qint64> MonitorCommands::parseValue(const QString &text) {
    const QString typed = text.trimmed();
    bool ok = false;
    qint64 value = 0;
    if (typed.startsWith(QLatin1String("0x"), Qt::CaseInsensitive))
        value = typed.mid(2).toLongLong(&ok, 16);
    else if (typed.startsWith(QLatin1String("-0x"), Qt::CaseInsensitive))
        value = -typed.mid(3).toLongLong(&ok, 16);
    else
        value = typed.toLongLong(&ok, 10);
    return ok ? std::optional<qint64>(value) : std::nullopt;
}

std::optional<QString> MonitorCommands::askValue(const QString &title, const QString &label,
                                                 const QString &initial) {
    QInputDialog dialog(m_view);
    dialog.setObjectName(QStringLiteral("monitorValueDialog"));
    dialog.setWindowTitle(title);
    dialog.setLabelText(label);
    dialog.setTextValue(initial);
    if (dialog.exec() != QDialog::Accepted)
        return std::nullopt;
    return dialog.textValue();
}

bool MonitorCommands::writeValue(const model::Address &address) {
    if (!m_source)
        return false;
    const auto snapshot = m_source->snapshot();
    const QString now = snapshot ? QString::number(snapshot->value(address)) : QString();
    const auto typed = askValue(tr("Write %1").arg(device(address)),
                                tr("New value of %1 (a whole number, 0x before a hexadecimal "
                                   "one):")
                                    .arg(device(address)),
                                now);
    return typed && writeValueText(address, *typed);
}

bool MonitorCommands::writeValueText(const model::Address &address, const QString &text) {
    if (!m_source)
        return false;
    const auto value = parseValue(text);
    if (!value) {
        emit message(tr("\"%1\" is no value for %2: type a whole number (0x before a "
                        "hexadecimal one)")
                         .arg(text.trimmed(), device(address)));
        return false;
    }
    track(m_source->writeWord(address, *value),
          tr("%1 written: %2").arg(device(address)).arg(*value));
    return true;
}

bool MonitorCommands::writePreset(const MonitorTargets::Preset &preset) {
    if (!m_source || !preset.constant.isEmpty())
        return false;
    const auto snapshot = m_source->snapshot();
    const QString now = snapshot && snapshot->setValueKnown(preset.element)
                            ? QString::number(snapshot->setValue(preset.element))
                            : QString();
    const auto typed = askValue(tr("Write Preset of %1").arg(device(preset.element)),
                                tr("New preset of %1:").arg(device(preset.element)), now);
    return typed && writePresetText(preset, *typed);
}

bool MonitorCommands::writePresetText(const MonitorTargets::Preset &preset, const QString &text) {
    if (!m_source || !m_target)
        return false;
    const QString name = device(preset.element);
    if (!preset.constant.isEmpty()) {
        emit message(tr("The preset of %1 is the constant %2 of the program: change it in the "
                        "program")
                         .arg(name, preset.constant));
        return false;
    }
    const auto value = parseValue(text);
    if (!value || *value < 0) {
        emit message(
            tr("\"%1\" is no preset for %2: type a whole number from 0").arg(text.trimmed(), name));
        return false;
    }
    if (!preset.word) {
        // Kept in the PLC's memory (VPC), or in the word the program reads (PL110 PT1).
        track(m_source->writeSetValue(preset.element, *value),
              tr("Preset of %1 written: %2").arg(name).arg(*value));
        return true;
    }
    qint64 word = *value;
    if (m_target->constants.bcdSetValues) {
        // The channel holds the preset's BCD digits (Omron CPM1 guide).
        const auto bcd = toBcd(*value);
        if (!bcd) {
            emit message(tr("\"%1\" is no preset for %2: the preset is 0..9999 (BCD)")
                             .arg(text.trimmed(), name));
            return false;
        }
        word = *bcd;
    }
    track(m_source->writeWord(*preset.word, word),
          tr("Preset of %1 written: %2 (in %3)").arg(name).arg(*value).arg(device(*preset.word)));
    return true;
}

} // namespace rung::editor
