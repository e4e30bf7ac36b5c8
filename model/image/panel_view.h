#pragma once

// What a PLC's front panel shows (Target::panel, model/target/front_panel.h) for a snapshot,
// a run state and a moment: the digits of the Vigor's display by its mode, the PL110-2A's
// page as lines of characters with its numeric fields, the VPC console's I/O window, each
// lamp lit or dark (blinking ones by `nowMs`), the knobs' and keys' values. A pure function:
// the editor's FrontPanel draws the result, the tests check it without a display.

#include "model/image/monitor_source.h"
#include "model/image/panel_keys.h"
#include "model/target/front_panel.h"
#include "model/target/target.h"

#include <QJsonObject>
#include <QString>
#include <QStringList>
#include <map>
#include <optional>
#include <vector>

namespace rung::model {

struct PanelLampView {
    QString label;
    LampColour colour = LampColour::Green;
    bool lit = false;
    int blinkMs = 0; // > 0: blinking, this many ms on and as many off (`lit` is now's phase)
    const char *meaning = nullptr; // QT_TRANSLATE_NOOP("rung::model::Target", ...)
};

struct PanelKnobView {
    QString label;
    Address address;
    int value = 0; // decoded (a BCD word as its number)
    int lowest = 0;
    int highest = 0;
    bool bcd = false;
    const char *meaning = nullptr;
};

struct PanelKeyView {
    QString label;
    Address address;
    bool pressed = false;
    QString shortcut;
    const char *meaning = nullptr;
    PanelKeyRole role = PanelKeyRole::Other;
};

// A numeric field drawn over a page's text (PL110 SM118..): where it is, for the reverse
// video of a field being edited.
struct PanelFieldView {
    int row = 0;    // 0-based
    int column = 0; // 0-based
    int length = 0;
    bool editable = false; // state 2, "Modifica"
    bool editing = false;  // the keys edit it now: shown in reverse (PL110 manual 5.2)
    int cursor = -1;       // the character of the digit UP / DOWN change, -1: the value
};

struct PanelView {
    std::vector<PanelLampView> lamps;
    std::vector<PanelKnobView> knobs;
    std::vector<PanelKeyView> keys;

    DisplayKind display = DisplayKind::None;
    // Digits: what the display shows, right-aligned in `digits` characters (spaces blank), or
    // the value plainly when it does not fit (`fits` false; the manual does not say how the
    // PLC shows it). Empty in a mode the manual does not describe.
    QString digitsText;
    int digits = 0;
    bool fits = true;
    int mode = 0;
    // Text and IoLines: the lines of characters (Text: rows x columns exactly).
    QStringList lines;
    QStringList lineLabels; // IoLines: the first device of each line ("o00")
    std::vector<PanelFieldView> fields;
    int page = 0; // Text: the page shown (SM105), 0 none; the password page while it is open
    int brightness = 100; // Text: % (the standby dims it, model/image/panel_keys.h)
    // Translated, empty when there is nothing to say: why the display shows nothing or what
    // the manual leaves open ("display mode 7: the manual describes modes 3 and 4").
    QString note;
    // Every device the view read, in reading order (repeats possible): what an online source
    // is to poll for the panel.
    std::vector<Address> devices;
};

// A port of the PLC and the application its settings give it (the project's "ports", a network
// station's over them; the table's first application where they name none).
struct PanelPort {
    QString port;                                 // PortSpec::name ("COM1")
    const PortApplication *application = nullptr; // null: the settings do not read
};

// What the PLC holds beside its memory that a page shows (PL110 manual 5.3, page 3: "il nome
// dell'applicazione ladder caricata, i protocolli associati alle porte seriali"): the name of
// the program loaded and each port's application, as the project or the network station that
// runs the simulated PLC says.
struct PanelContext {
    QString application;          // the ladder application's name ("pump", the project's file)
    std::vector<PanelPort> ports; // every port of the model, in the table's order
};

// The context of a PLC running `application` whose ports are set as `chosen` says (PortSpec::
// name -> application; a port it does not name runs its first application, as readPortConfig
// gives it).
PanelContext panelContext(const Target &target, const ModelVariant *model, QString application,
                          const std::map<QString, const PortApplication *> &chosen);
// The same from a project's "ports" object (model::Project::ports): a port whose settings do not
// read has no application (shown as not known).
PanelContext panelContext(const Target &target, const ModelVariant *model, QString application,
                          const QJsonObject &ports);

struct PanelInput {
    const Snapshot *snapshot = nullptr; // null: nothing runs
    MonitorSource::RunState runState = MonitorSource::RunState::Offline;
    bool fault = false; // the source reports an error
    qint64 nowMs = 0;   // wall-clock ms for the blinking lamps
    // The terminal's keys (a field being edited, the password page, the standby); null: none.
    const TerminalState *terminal = nullptr;
    // The program's name and the ports' protocols (PL110 system page 3); null: not known (the
    // page shows dashes there and its note says so).
    const PanelContext *context = nullptr;
};

// True when the target (on this model, null: the default) has a panel to show.
bool hasFrontPanel(const Target &target, const ModelVariant *model);

PanelView panelView(const Target &target, const ModelVariant *model, const PanelInput &input);

// A number formatted as a PL110 field (2.1.2: SM129 total digits, SM130 decimals, SM131 fill
// 0 spaces / 1 zeros): the digits right-aligned in `total` places, the decimal point before
// the last `decimals` digits; a value with more digits is shown whole.
QString formatPanelField(qint64 value, int total, int decimals, bool zeros);

// The value a knob's word holds for `value` (BCD encoded where the knob is BCD).
qint64 panelKnobWord(const PanelKnobView &knob, int value);

} // namespace rung::model
