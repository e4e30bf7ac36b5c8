#pragma once

// What a monitoring view (the ladder, the instruction list) lets the user do to the devices
// of an element: force a bit ON or OFF, release it, set it; write a word; write a timer's or
// counter's preset where the preset can be written. The entries go into the view's context
// menu, disabled while no source is set; each command's result (from the source's
// commandFinished) comes back as message(), for the status bar. The views do not know which
// origin (simulation, online PLC) the source is.

#include "model/image/monitor_source.h"
#include "model/listing/il.h"

#include <QObject>
#include <QPointer>

#include <map>
#include <optional>
#include <vector>

class QMenu;
class QWidget;

namespace rung::editor {

struct MonitorTargets {
    std::vector<model::Address> bits;  // force ON / OFF, release, set ON / OFF
    std::vector<model::Address> words; // write a value
    struct Preset {
        model::Address element;             // the timer or counter
        std::optional<model::Address> word; // the word that holds the preset (TMR T0 D10)
        // The preset is a constant of the program (TMR T0 K50): only an edit changes it.
        QString constant;
    };
    std::vector<Preset> presets;
    bool empty() const { return bits.empty() && words.empty() && presets.empty(); }
};

// The devices of a contact, or of an output instruction (a coil, a box).
MonitorTargets monitorTargets(const model::Target &target,
                              const std::vector<model::Operand> &operands,
                              model::Op op = model::Op::Load);
MonitorTargets monitorTargets(const model::Target &target, const model::Instruction &instruction);

class MonitorCommands : public QObject {
    Q_OBJECT

public:
    // `view`: the parent of the value dialogs.
    explicit MonitorCommands(const model::Target *target, QWidget *view);

    void setTarget(const model::Target *target) { m_target = target; }
    void setSource(model::MonitorSource *source);
    model::MonitorSource *source() const { return m_source; }

    // Adds the entries for the devices to the menu (disabled without a source); false when
    // there is none to add.
    bool addActions(QMenu *menu, const MonitorTargets &devices);

    void force(const model::Address &address, bool on);
    void release(const model::Address &address);
    void setBit(const model::Address &address, bool on);
    // Ask for a value (a dialog), then write it; false when cancelled or refused.
    bool writeValue(const model::Address &address);
    bool writePreset(const MonitorTargets::Preset &preset);
    // Writes a value typed as text (a whole number; 0x before a hexadecimal one); false, with
    // message(), when it is no number.
    bool writeValueText(const model::Address &address, const QString &text);
    bool writePresetText(const MonitorTargets::Preset &preset, const QString &text);

    // A whole number as typed: decimal, or hexadecimal after 0x; nullopt when it is none.
    static std::optional<qint64> parseValue(const QString &text);

signals:
    void message(const QString &text);

private:
    QString device(const model::Address &address) const;
    void track(model::MonitorSource::CommandId id, const QString &done);
    std::optional<QString> askValue(const QString &title, const QString &label,
                                    const QString &initial);

    const model::Target *m_target;
    QWidget *m_view;
    QPointer<model::MonitorSource> m_source;
    // What each command of ours did, said once it is finished.
    std::map<model::MonitorSource::CommandId, QString> m_pending;
};

} // namespace rung::editor
