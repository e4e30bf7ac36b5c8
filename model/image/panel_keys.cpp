#include "model/image/panel_keys.h"

#include "model/target/address.h"

#include <algorithm>

namespace rung::model {

namespace {

std::optional<Address> terminalDevice(const Target &target, const QString &text) {
    if (text.isEmpty())
        return std::nullopt;
    const auto parsed = parseAddress(target, text);
    if (const auto *a = std::get_if<Address>(&parsed))
        return *a;
    return std::nullopt;
}

qint64 terminalWord(const Target &target, const Snapshot &snapshot, const QString &device) {
    const auto a = terminalDevice(target, device);
    return a ? snapshot.value(*a) : 0;
}

// The variable a field names by its area in SM107's list and its number.
std::optional<Address> listedVariable(const Target &target, int code, qint64 number) {
    const PanelDisplay &d = target.panel.display;
    const auto entry = std::find_if(d.areaCodes.begin(), d.areaCodes.end(),
                                    [code](const PanelAreaCode &c) { return c.code == code; });
    if (entry == d.areaCodes.end())
        return std::nullopt;
    for (const Area &a : target.areas)
        if (a.key == entry->area)
            return terminalDevice(target, a.prefix + QString::number(number));
    return std::nullopt;
}

// The range a field's format holds (2.1.2 SM128: 16 bit signed, unsigned, 32 bit signed).
std::pair<qint64, qint64> formatRange(int format) {
    if (format == 1)
        return {0, 65535};
    if (format == 2)
        return {-2147483648LL, 2147483647LL};
    return {-32768, 32767};
}

// The fields of the page shown that SET may edit now, in the table's order: a user page's
// four, or the numbers of the system page shown (PanelDisplay::systemFields, after the four).
std::vector<int> editableFields(const Target &target, const Snapshot &snapshot) {
    const PanelDisplay &d = target.panel.display;
    std::vector<int> out;
    const qint64 page = terminalWord(target, snapshot, d.pageShownDevice);
    const bool user = page >= d.firstUserPage && page < d.firstUserPage + d.userPages;
    const bool system = page >= 1 && page <= d.systemPages;
    if (!user && !system)
        return out;
    const qint64 entered = terminalWord(target, snapshot, d.passwordDevice);
    const int userFields = static_cast<int>(d.fields.size());
    const int count = userFields + static_cast<int>(d.systemFields.size());
    for (int k = 0; k < count; ++k) {
        if (k < userFields
                ? !user
                : !system || d.systemFields[static_cast<std::size_t>(k - userFields)].page != page)
            continue;
        const auto f = terminalField(target, snapshot, k);
        if (f && f->state == 2 && f->variable &&
            (f->access == 0 || (f->password != 0 && entered == f->password)))
            out.push_back(k);
    }
    return out;
}

// A system page's number as a field (PanelSystemField): its word named by SM107's list as a
// user field's variable is, so that SET leaves the same note *(choice: 2.1.2 says "l'ultima
// area di memoria salvata tramite il terminale" without telling the system pages apart)*.
TerminalField systemField(const Target &target, const PanelSystemField &s) {
    const PanelDisplay &d = target.panel.display;
    TerminalField f;
    f.state = s.editable ? 2 : 1;
    f.variable = terminalDevice(target, s.device);
    if (f.variable) {
        const QString &key = target.areas[static_cast<std::size_t>(f.variable->area)].key;
        for (const PanelAreaCode &c : d.areaCodes)
            if (c.area == key && !c.doubles)
                f.area = c.code;
        f.number = f.variable->index;
    }
    f.lowest = s.lowest;
    f.highest = s.highest;
    f.digits = s.digits;
    f.zeros = s.zeros;
    f.row = s.row;
    f.column = s.column;
    f.access = s.password != 0 ? 1 : 0;
    f.password = s.password;
    return f;
}

qint64 power10(int n) {
    qint64 p = 1;
    for (int k = 0; k < n; ++k)
        p *= 10;
    return p;
}

void startField(const Target &target, const Snapshot &snapshot, TerminalState &s, int field) {
    const auto f = terminalField(target, snapshot, field);
    s.mode = TerminalState::Mode::Field;
    s.field = field;
    s.page = static_cast<int>(terminalWord(target, snapshot, target.panel.display.pageShownDevice));
    s.value = f && f->variable ? snapshot.value(*f->variable) : 0;
    if (f && f->format == 1)
        s.value &= 0xffff;
    s.digit = -1;
}

void endEditing(TerminalState &s) {
    s.mode = TerminalState::Mode::Pages;
    s.field = -1;
    s.digit = -1;
}

} // namespace

std::optional<TerminalField> terminalField(const Target &target, const Snapshot &snapshot,
                                           int index) {
    const PanelDisplay &d = target.panel.display;
    const int userFields = static_cast<int>(d.fields.size());
    if (index >= userFields && index < userFields + static_cast<int>(d.systemFields.size()))
        return systemField(target, d.systemFields[static_cast<std::size_t>(index - userFields)]);
    if (index < 0 || index >= userFields)
        return std::nullopt;
    const auto base = terminalDevice(target, d.fields[static_cast<std::size_t>(index)].first);
    if (!base)
        return std::nullopt;
    const auto at = [&](int offset) {
        Address a = *base;
        a.index += offset;
        return static_cast<qint64>(snapshot.value(a));
    };
    const auto number = [&](int offset) {
        return ((at(offset) & 0xffff) << 16) | (at(offset + 1) & 0xffff);
    };
    TerminalField f;
    // 2.1.2, from SM118: state, area, number (high, low), minimum's area and number, maximum's
    // area and number, format, total digits, decimals, fill, row, column, access.
    f.state = static_cast<int>(at(0));
    f.area = static_cast<int>(at(1));
    f.number = number(2);
    f.variable = listedVariable(target, f.area, f.number);
    f.format = static_cast<int>(at(10));
    f.digits = static_cast<int>(std::clamp<qint64>(at(11), 1, 12));
    f.decimals = static_cast<int>(std::clamp<qint64>(at(12), 0, 10));
    f.zeros = at(13) == 1;
    f.row = static_cast<int>(at(14));
    f.column = static_cast<int>(at(15));
    f.access = static_cast<int>(at(16));
    f.password = d.userPassword;
    // A limit is a variable named as the field's own is ("Numero area minimo parametro");
    // area 0 names none, and then its number is the limit itself *(choice: the manual's
    // SetPAR writes "Min= #0, Max = #1400" without saying how a constant is coded)*.
    const auto limit = [&](int offset) {
        const qint64 n = number(offset + 1);
        const int code = static_cast<int>(at(offset));
        if (code == 0)
            return static_cast<qint64>(static_cast<std::int32_t>(n));
        const auto v = listedVariable(target, code, n);
        return v ? static_cast<qint64>(snapshot.value(*v)) : 0;
    };
    const auto [low, high] = formatRange(f.format);
    f.lowest = std::clamp(limit(4), low, high);
    f.highest = std::clamp(limit(7), low, high);
    // A maximum below the minimum limits nothing but the format *(choice)*.
    if (f.highest < f.lowest) {
        f.lowest = low;
        f.highest = high;
    }
    return f;
}

bool terminalPassesKey(const TerminalState &state, PanelKeyRole role) {
    return role != PanelKeyRole::Swap || state.mode == TerminalState::Mode::Pages;
}

std::vector<TerminalWrite> terminalKey(const Target &target, const Snapshot &snapshot,
                                       TerminalState &s, PanelKeyRole role, bool down,
                                       qint64 wallMs) {
    std::vector<TerminalWrite> writes;
    const PanelDisplay &d = target.panel.display;
    if (d.kind != DisplayKind::Text)
        return writes;
    s.lastActivityMs = snapshot.statistics.timeMs;
    using Mode = TerminalState::Mode;
    if (role == PanelKeyRole::Set) {
        if (down) {
            s.setDownMs = wallMs;
            s.setHeldLong = false;
            return writes;
        }
        const bool held = s.setHeldLong;
        s.setDownMs = -1;
        s.setHeldLong = false;
        if (held)
            return writes; // the hold opened the password page
        if (s.mode == Mode::Password) {
            if (const auto a = terminalDevice(target, d.passwordDevice))
                writes.push_back({*a, s.value});
            endEditing(s);
            return writes;
        }
        const std::vector<int> fields = editableFields(target, snapshot);
        if (s.mode == Mode::Field) {
            const auto f = terminalField(target, snapshot, s.field);
            if (f && f->variable) {
                writes.push_back({*f->variable, std::clamp(s.value, f->lowest, f->highest)});
                // The note for the program's next scan (the engine clears it after that scan).
                if (const auto a = terminalDevice(target, d.lastAreaDevice))
                    writes.push_back({*a, f->area});
                if (const auto n = terminalDevice(target, d.lastNumberDevice))
                    writes.push_back({*n, f->number});
            }
            const auto next = std::upper_bound(fields.begin(), fields.end(), s.field);
            if (next == fields.end())
                endEditing(s);
            else
                startField(target, snapshot, s, *next);
            return writes;
        }
        if (!fields.empty())
            startField(target, snapshot, s, fields.front());
        return writes;
    }
    if (!down || s.mode == Mode::Pages)
        return writes;
    if (s.mode == Mode::Password) {
        const int digits = std::max(1, d.passwordDigits);
        if (s.digit < 0 || s.digit >= digits)
            s.digit = digits - 1;
        const qint64 unit = power10(s.digit);
        const qint64 current = s.value / unit % 10;
        if (role == PanelKeyRole::Swap)
            s.digit = s.digit == 0 ? digits - 1 : s.digit - 1; // the next digit to the right
        else if (role == PanelKeyRole::Up)
            s.value += (current == 9 ? -9 : 1) * unit; // a digit turns round, 9 -> 0
        else if (role == PanelKeyRole::Down)
            s.value += (current == 0 ? 9 : -1) * unit;
        return writes;
    }
    const auto f = terminalField(target, snapshot, s.field);
    if (!f)
        return writes;
    if (role == PanelKeyRole::Swap) {
        // Step by one -> the units digit -> the tens ... -> the field's last digit -> by one.
        s.digit = s.digit + 1 >= f->digits ? -1 : s.digit + 1;
        return writes;
    }
    const qint64 step = s.digit < 0 ? 1 : power10(s.digit);
    if (role == PanelKeyRole::Up)
        s.value = std::min(s.value + step, f->highest);
    else if (role == PanelKeyRole::Down)
        s.value = std::max(s.value - step, f->lowest);
    return writes;
}

PanelKeyAction panelKeyAction(const Target &target, const Snapshot *snapshot, TerminalState &state,
                              PanelKeyRole role, bool down, qint64 wallMs) {
    PanelKeyAction action;
    action.writeBit = !down || terminalPassesKey(state, role);
    if (role != PanelKeyRole::Other && snapshot)
        action.words = terminalKey(target, *snapshot, state, role, down, wallMs);
    return action;
}

void terminalTick(const Target &target, const Snapshot &snapshot, TerminalState &s, qint64 wallMs) {
    const PanelDisplay &d = target.panel.display;
    if (d.kind != DisplayKind::Text)
        return;
    const int page = static_cast<int>(terminalWord(target, snapshot, d.pageShownDevice));
    if (snapshot.statistics.timeMs < s.lastActivityMs) // a new run started from time 0
        s.lastActivityMs = snapshot.statistics.timeMs;
    if (page != s.lastPage) {
        // "Il cambio pagina da programma, tramite scrittura di SMW106, equivale alla pressione
        // di un tasto" (2.1.2, SM101).
        if (s.lastPage >= 0)
            s.lastActivityMs = snapshot.statistics.timeMs;
        s.lastPage = page;
    }
    if (s.mode == TerminalState::Mode::Field && page != s.page)
        endEditing(s); // the program changed the page: the value entered is not stored
    if (s.setDownMs >= 0 && !s.setHeldLong && d.passwordPage > 0 &&
        wallMs - s.setDownMs >= d.passwordHoldMs) {
        s.setHeldLong = true;
        s.mode = TerminalState::Mode::Password;
        s.field = -1;
        s.value = 0;
        s.digit = std::max(1, d.passwordDigits) - 1;
    }
}

int terminalBrightness(const Target &target, const Snapshot &snapshot, const TerminalState &state) {
    const PanelDisplay &d = target.panel.display;
    if (d.standbyDelayDevice.isEmpty())
        return 100;
    const qint64 minutes = terminalWord(target, snapshot, d.standbyDelayDevice);
    if (minutes <= 0 || snapshot.statistics.timeMs - state.lastActivityMs < minutes * 60000)
        return 100;
    return static_cast<int>(
        std::clamp<qint64>(terminalWord(target, snapshot, d.standbyBrightnessDevice), 0, 100));
}

} // namespace rung::model
