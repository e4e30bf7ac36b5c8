#pragma once

// The PLC's front panel as the manuals describe it, as table data (Target::panel): its lamps
// and what lights them, its display and the devices it shows, the knobs and keys and the
// devices they write. model/image/panel_view.h turns a target and a snapshot into what the
// panel shows; the editor's FrontPanel draws that. A family whose manual describes no panel
// leaves the table empty.

#include <QString>
#include <QStringList>
#include <cstdint>
#include <utility>
#include <vector>

namespace rung::model {

// Unstated: the manual gives the lamp no colour (VPC user's manual, II: "LEDs to show which
// inputs/outputs are driven ON"); it is drawn plainly, filled when ON, empty when OFF.
enum class LampColour : std::uint8_t { Green, Red, Yellow, Orange, Unstated };

// What lights a lamp.
enum class LampSignal : std::uint8_t {
    Power,   // the PLC has power: the source is not Offline
    Running, // the program runs (a paused simulation is a PLC in RUN frozen in time)
    Fault,   // the source reports an error that stopped the program
    // Lit on an error that stopped the CPU; blinks (PanelLamp::alarmBlinkMs) on a non-fatal
    // error the program goes on after (Omron CPM1 guide 2.1, ERROR/ALARM "Villog: Nem lényegi
    // hiba, a CPU tovább dolgozik"): while the word `device` has a bit of `deviceMask` ON (the
    // FAL number in 253.00..253.07, W353 FAL(06)), and, where FrontPanel::errorsGoOn, while the
    // source reports an error and the program runs on.
    Alarm,
    Device, // a bit device of the table (PL110 COM1: its port's "transmitting" marker)
    // Lit while a port of the PLC sent or received a byte within the last PanelLamp::holdMs of
    // simulated time (Snapshot::communicatedUs: a network station's ports); dark where nothing
    // is known of its ports (a PLC simulated alone has none).
    Communication,
    Never, // what lights it is not simulated; the lamp is shown dark with its meaning
};

struct PanelLamp {
    QString label; // as printed on the PLC ("RUN", "COM1", "ERROR/ALARM"): not translated
    LampColour colour = LampColour::Green;
    LampSignal signal = LampSignal::Running;
    QString device; // LampSignal::Device: the bit; LampSignal::Alarm: the word
    // LampSignal::Running: while a program is loaded but does not run, the lamp blinks this
    // many ms on and as many off (PL110 manual 1.2: "Lampeggio lento - (0,5s on /0,5 s off)");
    // 0: it is dark then.
    int stoppedBlinkMs = 0;
    // QT_TRANSLATE_NOOP("rung::model::Target", ...): what the manual's table says it means.
    const char *meaning = nullptr;
    // LampSignal::Alarm: the bits of `device` that hold the non-fatal error, and the blink
    // (this many ms on and as many off).
    int deviceMask = 0xffff;
    int alarmBlinkMs = 0;
    // LampSignal::Communication: how long after a port's last byte the lamp stays lit.
    int holdMs = 0;
};

// A lamp for each element of an area the model has, labelled by its address and lit while its
// bit is ON (VPC user's manual, II: "LEDs to show which inputs/outputs are driven ON (VPC2416
// and higher)"). Shown after FrontPanel::lamps, in the order of the table.
struct PanelPointLamps {
    QString area;       // Area::key
    QStringList models; // the models that have them; empty: every model
    LampColour colour = LampColour::Unstated;
    const char *meaning = nullptr; // QT_TRANSLATE_NOOP("rung::model::Target", ...)
};

enum class DisplayKind : std::uint8_t {
    None,
    // Vigor VB: a 4-digit display whose mode word says what it shows and whose register word
    // names the D register (Vigor M/VB/VH communication manual, B-3: mode 3 one 4-digit value,
    // mode 4 two 2-digit values).
    Digits,
    // PL110-2A: the OLED terminal, rows x columns of characters from a byte area, system and
    // user pages, four parameter fields (PL110 manual 2.1.2, 2.1.16, 5).
    Text,
    // VPC: the console's LCD in its first RUN & MONITOR window: the outputs, then the inputs,
    // 16 to a line, a filled field ON (VPC user's manual, V.a).
    IoLines,
};

// One numeric field of a user page (PL110 manual 2.1.2, SM118..SM134 for the first): the
// words from `first` on, in the manual's order.
struct PanelField {
    QString first; // "SM118": state, area, number (high, low), min and max, format, digits,
                   // decimals, fill, row, column, access
};

// SM107's list of areas (PL110 manual 2.1.2): the number a field names its variable's area by.
struct PanelAreaCode {
    int code = 0;
    QString area;         // Area::key
    bool doubles = false; // the area's double words (VD, SMD)
};

// A number a system page shows (PL110 manual 5.3: the slave address, the clock, the display
// setup): its word, where it stands (1-based, as a user field's row and column), how many
// places. Editable ones the keys edit as they edit a user page's fields (model/image/
// panel_keys.h), within `lowest`..`highest`, while the password word holds `password` (0:
// free).
struct PanelSystemField {
    int page = 0;
    QString device;
    int row = 0;
    int column = 0;
    int digits = 1;
    bool zeros = false; // fill with zeros (the clock's "09")
    bool editable = false;
    int lowest = 0;
    int highest = 0;
    int password = 0;
    QString zeroText; // shown for 0 instead of the number, right-aligned ("OFF"); empty: none
};

// A system page's fixed text, row by row from the first (the device's own English words).
struct PanelSystemPage {
    int page = 0;
    QStringList lines;
    // Translated (QT_TRANSLATE_NOOP("rung::model::PanelView", ...)): what the page shows that
    // the simulation does not have or does not do; null: nothing to say.
    const char *note = nullptr;
};

struct PanelDisplay {
    DisplayKind kind = DisplayKind::None;
    // Digits: the mode word and the word naming the register shown; the register area.
    QString modeDevice;
    QString registerDevice;
    QString registerArea;
    int digits = 4;
    int singleValueMode = 0; // the mode that shows one value on all digits
    int pairMode = 0;        // the mode that shows two values, the register's on the right
    // Text: the character area (absent on a model without the terminal), its rows and columns.
    QString charArea;
    int rows = 0;
    int columns = 0;
    QString systemPagesDevice; // a bit a page, system page 1 at bit 0
    QString userPagesDevice;   // a bit a user page, the first user page at bit 0
    QString startPageDevice;
    QString pageShownDevice;
    QString pageRequestDevice;
    int systemPages = 0;   // 1..systemPages
    int firstUserPage = 0; // firstUserPage..firstUserPage + userPages - 1
    int userPages = 0;
    std::vector<PanelField> fields;
    std::vector<PanelAreaCode> areaCodes;
    // Text: the character codes the display draws as characters, ranges inclusive; any other
    // byte is drawn as a space. A text stored in the character area with another character
    // is warned by `check` (OP007).
    std::vector<std::pair<int, int>> shownCodes;
    bool shows(int code) const {
        for (const auto &[low, high] : shownCodes)
            if (code >= low && code <= high)
                return true;
        return false;
    }
    // Text: the keys editing the fields and the password page (model/image/panel_keys.h):
    // SET held this long opens the page `passwordPage`, where a number of `passwordDigits`
    // is entered into `passwordDevice`; a field of access 1 is edited only while that word
    // holds `userPassword`. 0 / empty: the terminal edits nothing.
    int passwordPage = 0;
    QString passwordDevice;
    // The note of the last variable stored from the keys, for the scan after the store only:
    // its area's code (areaCodes) and its number (PL110 manual 2.1.2 SM107, SM108).
    QString lastAreaDevice;
    QString lastNumberDevice;
    int passwordDigits = 0;
    int userPassword = 0;
    int passwordHoldMs = 0;
    // Text: the standby (the brightness in % after `standbyDelayDevice` minutes without a
    // key; a delay of 0 turns it off); empty: the display is never dimmed.
    QString standbyBrightnessDevice;
    QString standbyDelayDevice;
    // Text: the system pages' contents beyond the terminal strip's pages 1 and 2, and their
    // numbers (PanelSystemField).
    std::vector<PanelSystemPage> systemTexts;
    std::vector<PanelSystemField> systemFields;
    // Text: the system page that shows what the PLC holds beside its memory
    // (model::PanelContext: PL110 manual 5.3, page 3), 0 none; the row (1-based) of the ladder
    // application's name, from column 1, cut at the row's end; the first row of the ports, one
    // a row in the table's order, the port's name at the left and its application at the right
    // (PortApplication::displayName), cut at the row's end. What is not known: a dash at the
    // row's end.
    int contextPage = 0;
    int applicationRow = 0;
    int portsRow = 0;
    // IoLines: the areas shown, in order, and how many to a line.
    std::vector<QString> lineAreas;
    int perLine = 16;
};

// A knob with a number box (Vigor VR1, CPM1 analog setting 0): writes its word.
struct PanelKnob {
    QString label; // as the manual names it ("VR1"); a number on the CPM1 ("0")
    QString device;
    int lowest = 0;
    int highest = 0;
    bool bcd = false;              // the word holds the value as BCD digits (CPM1 0..200)
    const char *meaning = nullptr; // QT_TRANSLATE_NOOP("rung::model::Target", ...)
};

// What a key does on a text display's terminal (model/image/panel_keys.h): SWAP steps the
// pages (the engine) and, while a field is edited, the digit; UP / DOWN change the value; SET
// edits the fields in turn and, held, opens the password page.
enum class PanelKeyRole : std::uint8_t { Other, Swap, Up, Down, Set };

// A key: held down, its bit is 1 (PL110 SM110: "Il bit a 1 indica che il rispettivo pulsante
// è attualmente premuto").
struct PanelKey {
    QString label;    // as printed ("SWAP", "UP", "DOWN", "SET")
    QString device;   // its bit
    QString shortcut; // the keyboard key that presses it in the IDE (a QKeySequence text)
    const char *meaning = nullptr; // QT_TRANSLATE_NOOP("rung::model::Target", ...)
    PanelKeyRole role = PanelKeyRole::Other;
};

// A word's value at power-on (PL110 SM102 31: every system page enabled).
struct PowerOnValue {
    QString device;
    int value = 0;
};

struct FrontPanel {
    std::vector<PanelLamp> lamps;
    std::vector<PanelPointLamps> pointLamps;
    PanelDisplay display;
    std::vector<PanelKnob> knobs;
    std::vector<PanelKey> keys; // the display's terminal: absent when the display is
    std::vector<PowerOnValue> powerOn;
    // The manual tells an error that stops the CPU from one it goes on after (Omron CPM1 guide
    // 2.1: ERROR/ALARM lit or blinking, RUN dark "vagy hiba" only in the first case). Then an
    // error the source reports while the program runs on (the simulator skips the instruction
    // and goes on) is one of the second kind: ERROR/ALARM blinks and RUN stays lit; one it
    // reports while the program does not run stopped it. False: any error the source reports
    // is shown as one that stopped the PLC (RUN dark, the Fault lamp lit).
    bool errorsGoOn = false;
    bool empty() const {
        return lamps.empty() && pointLamps.empty() && display.kind == DisplayKind::None &&
               knobs.empty();
    }
};

} // namespace rung::model
