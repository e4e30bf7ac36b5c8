#pragma once

// What a text terminal's keys do beyond the pages (PL110 manual 5.2, 5.5, 2.1.2): SET edits
// the fields of the page shown that the program made editable (state 2, "Modifica") in turn,
// the field being edited shown in reverse; UP / DOWN change its value by one, or SWAP switches
// to changing it digit by digit (1*10^n); SET stores it into the field's variable and goes to
// the next field, after the last back to the page. SET held for about 2 s opens the password
// page (253), where UP / DOWN change the digit SWAP chooses and SET enters the number into
// the password word (SM109); a field of access 1 is edited only while that word holds the user
// password (1234). The system pages' numbers (5.3) are edited the same way: the slave address
// only while that word holds the system password (1357). And the standby: after SM101 minutes
// without a key or a page change the display dims to SM100 %.
//
// The terminal's state is the front panel's (TerminalState): the keys still reach the program
// through their bits (SM110) and the engine steps the pages on SWAP, but which field is edited
// and the value being entered live in the terminal until SET stores them, as on the PLC. A
// pure function of the target, a snapshot and the time: the editor's FrontPanel calls it and
// writes what it returns through its source; the tests call it without a display.

#include "model/image/snapshot.h"
#include "model/target/front_panel.h"
#include "model/target/target.h"

#include <vector>

namespace rung::model {

struct TerminalState {
    enum class Mode : std::uint8_t { Pages, Field, Password };
    Mode mode = Mode::Pages;
    int field = -1;           // Mode::Field: the index in PanelDisplay::fields
    int page = 0;             // Mode::Field: the page it started on; another page ends the editing
    qint64 value = 0;         // Mode::Field / Password: the value being entered
    int digit = -1;           // -1: UP / DOWN step by one; n: they change digit n (10^n)
    qint64 setDownMs = -1;    // SET held since (wall ms); -1: not held
    bool setHeldLong = false; // this hold has opened the password page
    // The standby: the virtual time of the last key or page change, and the page then.
    qint64 lastActivityMs = 0;
    int lastPage = -1;
};

// A word the terminal writes: the value SET stores into a field's variable, the password.
struct TerminalWrite {
    Address device;
    qint64 value = 0;
    friend bool operator==(const TerminalWrite &, const TerminalWrite &) = default;
};

// A key of the table pressed (down) or released at wall time `wallMs` (SET's hold is timed in
// the user's time, a paused simulation included). Returns the words to write.
std::vector<TerminalWrite> terminalKey(const Target &target, const Snapshot &snapshot,
                                       TerminalState &state, PanelKeyRole role, bool down,
                                       qint64 wallMs);

// A key of the table pressed or released as the IDE's front panel and a scenario's `press` do
// it: whether its bit is written (a release always; a press unless the terminal keeps the key,
// terminalPassesKey), and then the words the terminal writes (terminalKey; none for a key of
// no terminal role or without a snapshot).
struct PanelKeyAction {
    bool writeBit = false;
    std::vector<TerminalWrite> words;
};
PanelKeyAction panelKeyAction(const Target &target, const Snapshot *snapshot, TerminalState &state,
                              PanelKeyRole role, bool down, qint64 wallMs);

// Time passing and a new snapshot: SET held long enough opens the password page; a page
// change ends the editing of a field and, as a key does, wakes the display.
void terminalTick(const Target &target, const Snapshot &snapshot, TerminalState &state,
                  qint64 wallMs);

// Whether the key's bit reaches the program and the engine: SWAP does not while a value is
// entered (it chooses the digit there, and the engine would step the page).
bool terminalPassesKey(const TerminalState &state, PanelKeyRole role);

// A field of the page as its words say (PL110 manual 2.1.2, from SM118 for the first); from
// index PanelDisplay::fields.size() on, the system pages' numbers (PanelDisplay::systemFields:
// the slave address, the clock, the display setup) as the table gives them.
struct TerminalField {
    int state = 0; // 0 disabled, 1 shown, 2 editable ("Modifica")
    std::optional<Address> variable;
    int area = 0;      // the variable's area as SM107's list codes it
    qint64 number = 0; // and its number
    qint64 lowest = 0;
    qint64 highest = 0;
    int format = 0; // 0 16 bit signed, 1 16 bit unsigned, 2 32 bit signed
    int digits = 1;
    int decimals = 0;
    bool zeros = false;
    int row = 0;      // 1-based, as the word holds it
    int column = 0;   // 1-based
    int access = 0;   // 0 free, 1 protected by the password
    int password = 0; // access 1: the value the password word must hold (1234, 1357)
};
std::optional<TerminalField> terminalField(const Target &target, const Snapshot &snapshot,
                                           int index);

// The display's brightness in % now (100, or SM100's in standby).
int terminalBrightness(const Target &target, const Snapshot &snapshot, const TerminalState &state);

} // namespace rung::model
