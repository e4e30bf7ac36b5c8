#include "model/image/panel_view.h"

#include "model/comm/port_config.h"
#include "model/image/bcd.h"
#include "model/target/address.h"

#include <QCoreApplication>
#include <algorithm>

namespace rung::model {

namespace {

std::optional<Address> panelDevice(const Target &target, const QString &text) {
    if (text.isEmpty())
        return std::nullopt;
    const auto parsed = parseAddress(target, text);
    if (const auto *a = std::get_if<Address>(&parsed))
        return *a;
    return std::nullopt;
}

const Area *areaByKey(const Target &target, const QString &key) {
    for (const Area &a : target.areas)
        if (a.key == key)
            return &a;
    return nullptr;
}

bool modelHasArea(const Target &target, const ModelVariant *model, const QString &key) {
    for (std::size_t k = 0; k < target.areas.size(); ++k)
        if (target.areas[k].key == key)
            return target.range(static_cast<int>(k), model).has_value();
    return false;
}

// Every read goes through these, so the view lists the devices it showed (PanelView::devices:
// an online source polls those).
qint64 readValue(const PanelInput &in, PanelView &v, const Address &a) {
    v.devices.push_back(a);
    return in.snapshot ? in.snapshot->value(a) : 0;
}
bool readBit(const PanelInput &in, PanelView &v, const Address &a) {
    v.devices.push_back(a);
    return in.snapshot && in.snapshot->bit(a);
}
qint64 wordOf(const PanelInput &in, PanelView &v, const std::optional<Address> &a) {
    return a ? readValue(in, v, *a) : 0;
}

bool running(MonitorSource::RunState state) {
    using R = MonitorSource::RunState;
    return state == R::Running || state == R::Stepping || state == R::Paused;
}

// The source reports an error that stopped the CPU: any error, unless the target's manual
// tells errors the CPU goes on after (FrontPanel::errorsGoOn) and the program runs on.
bool faultStopped(const Target &target, const PanelInput &in) {
    return in.fault && (!target.panel.errorsGoOn || !running(in.runState));
}

PanelLampView lampView(const Target &target, const PanelLamp &lamp, const PanelInput &in,
                       PanelView &view) {
    PanelLampView v{lamp.label, lamp.colour, false, 0, lamp.meaning};
    using R = MonitorSource::RunState;
    switch (lamp.signal) {
    case LampSignal::Power:
        v.lit = in.runState != R::Offline;
        break;
    case LampSignal::Running:
        if (faultStopped(target, in) || in.runState == R::Offline)
            break;
        if (running(in.runState)) {
            v.lit = true;
        } else if (lamp.stoppedBlinkMs > 0) {
            v.blinkMs = lamp.stoppedBlinkMs;
            v.lit = (in.nowMs % (2 * lamp.stoppedBlinkMs)) < lamp.stoppedBlinkMs;
        }
        break;
    case LampSignal::Fault:
        v.lit = in.fault;
        break;
    case LampSignal::Alarm: {
        // A fatal error: lit. A non-fatal one (the source's error while the program runs on,
        // or its bits in the word ON): blinking. Neither: dark.
        if (faultStopped(target, in)) {
            v.lit = true;
            break;
        }
        const auto a = panelDevice(target, lamp.device);
        const bool alarm = in.fault || (a && (readValue(in, view, *a) & lamp.deviceMask) != 0);
        if (alarm && in.runState != R::Offline && lamp.alarmBlinkMs > 0) {
            v.blinkMs = lamp.alarmBlinkMs;
            v.lit = (in.nowMs % (2 * lamp.alarmBlinkMs)) < lamp.alarmBlinkMs;
        }
        break;
    }
    case LampSignal::Device:
        if (const auto a = panelDevice(target, lamp.device))
            v.lit = readBit(in, view, *a);
        break;
    case LampSignal::Communication:
        // On the PLC's clock: a paused PLC keeps the lamp as it was at its last scan.
        if (in.snapshot && in.snapshot->communicatedUs >= 0 && in.runState != R::Offline)
            v.lit = in.snapshot->statistics.timeMs * 1000 - in.snapshot->communicatedUs <
                    qint64(lamp.holdMs) * 1000;
        break;
    case LampSignal::Never:
        break;
    }
    return v;
}

void digitsView(const Target &target, const PanelDisplay &d, const PanelInput &in, PanelView &v) {
    v.digits = d.digits;
    if (!in.snapshot)
        return;
    const qint64 mode = wordOf(in, v, panelDevice(target, d.modeDevice));
    const qint64 reg = wordOf(in, v, panelDevice(target, d.registerDevice));
    v.mode = static_cast<int>(mode);
    const Area *area = areaByKey(target, d.registerArea);
    const auto registerValue = [&](qint64 n) -> std::optional<qint64> {
        if (!area || n < 0)
            return std::nullopt;
        const auto a = panelDevice(target, area->prefix + QString::number(n));
        if (!a)
            return std::nullopt;
        return readValue(in, v, *a);
    };
    if (mode != d.singleValueMode && mode != d.pairMode) {
        v.note = QCoreApplication::translate(
                     "rung::model::PanelView",
                     "Display mode %1: the manual describes mode %2 (one %3-digit value) and "
                     "mode %4 (two %5-digit values)")
                     .arg(mode)
                     .arg(d.singleValueMode)
                     .arg(d.digits)
                     .arg(d.pairMode)
                     .arg(d.digits / 2);
        return;
    }
    const auto first = registerValue(reg);
    const auto second = mode == d.pairMode ? registerValue(reg + 1) : std::optional<qint64>(0);
    if (!first || !second) {
        v.note = QCoreApplication::translate("rung::model::PanelView",
                                             "The register named by %1 (%2) does not exist")
                     .arg(d.registerDevice)
                     .arg(reg);
        return;
    }
    const auto fitsIn = [](qint64 value, int places) {
        return value >= 0 && QString::number(value).size() <= places;
    };
    if (mode == d.singleValueMode) {
        v.fits = fitsIn(*first, d.digits);
        v.digitsText = v.fits ? QString::number(*first).rightJustified(d.digits, QLatin1Char(' '))
                              : QString::number(*first);
        return;
    }
    // Mode 4: "Show the value of D10 on the right side of the screen, and show the value of
    // D11 on the left side" (D9081 = 10).
    const int half = d.digits / 2;
    v.fits = fitsIn(*first, half) && fitsIn(*second, half);
    v.digitsText = v.fits ? QString::number(*second).rightJustified(half, QLatin1Char(' ')) +
                                QString::number(*first).rightJustified(half, QLatin1Char(' '))
                          : QString::number(*second) + QLatin1Char(' ') + QString::number(*first);
}

// A byte of the character area as the display draws it: the codes the table says it shows
// as their Latin-1 characters, the rest (0 included, which a cleared area that was never
// filled holds) as a space.
QChar displayChar(const PanelDisplay &d, qint64 byte) {
    const int c = static_cast<int>(byte & 0xff);
    return d.shows(c) ? QChar(c) : QChar(' ');
}

void putText(QString &line, int column, const QString &text) {
    for (int k = 0; k < text.size() && column + k < line.size(); ++k)
        if (column + k >= 0)
            line[column + k] = text[k];
}

// Where digit n (0: the units) of a formatted field stands in it, the decimal point skipped.
int digitColumn(const QString &text, int n, int decimals) {
    const int at = static_cast<int>(text.size()) - 1 - n - (decimals > 0 && n >= decimals ? 1 : 0);
    return std::max(at, -1);
}

// The numbers of system page `page` (PanelDisplay::systemFields) at their places; the one the
// keys edit shows the value being entered (model/image/panel_keys.h: their index follows the
// user fields').
void systemFieldsView(const Target &target, const PanelDisplay &d, const PanelInput &in, int page,
                      PanelView &v) {
    const TerminalState *keys = in.terminal;
    for (std::size_t k = 0; k < d.systemFields.size(); ++k) {
        const PanelSystemField &f = d.systemFields[k];
        const auto device = panelDevice(target, f.device);
        const int row = f.row - 1, column = f.column - 1;
        if (f.page != page || !device || row < 0 || row >= v.lines.size() || column < 0 ||
            column >= d.columns)
            continue;
        const int index = static_cast<int>(d.fields.size() + k);
        const bool editing = keys && keys->mode == TerminalState::Mode::Field &&
                             keys->field == index && keys->page == page;
        const qint64 value = editing ? keys->value : readValue(in, v, *device);
        const QString text = value == 0 && !f.zeroText.isEmpty()
                                 ? f.zeroText.rightJustified(f.digits, QLatin1Char(' '))
                                 : formatPanelField(value, f.digits, 0, f.zeros);
        putText(v.lines[row], column, text);
        const int length = static_cast<int>(std::min<qsizetype>(text.size(), d.columns - column));
        const int cursor = editing && keys->digit >= 0 ? digitColumn(text, keys->digit, 0) : -1;
        v.fields.push_back(
            {row, column, length, f.editable, editing, cursor < length ? cursor : -1});
    }
}

// A row of the display: `left` from column 1 and `right` ending at the last column, cut at the
// row's end as the display cuts what does not fit (a space between them at least).
QString displayRow(const QString &left, const QString &right, int columns) {
    const int gap = std::max<int>(right.isEmpty() ? 0 : 1,
                                  columns - static_cast<int>(left.size() + right.size()));
    return (left + QString(gap, QLatin1Char(' ')) + right).left(columns);
}

// What the PLC holds beside its memory (PanelDisplay::contextPage: PL110 manual 5.3, page 3,
// "il nome dell'applicazione ladder caricata, i protocolli associati alle porte seriali"): the
// program's name and each port's application as the context says, or, without one, a dash
// where each would stand, the note saying why.
void contextView(const Target &target, const ModelVariant &model, const PanelDisplay &d,
                 const PanelInput &in, PanelView &v) {
    const QString dash(QChar(0x2014));
    const auto put = [&](int row, const QString &text) {
        if (row >= 1 && row <= v.lines.size())
            v.lines[row - 1] = text.leftJustified(d.columns, QLatin1Char(' '));
    };
    const PanelContext *c = in.context;
    if (d.applicationRow > 0)
        put(d.applicationRow, c && !c->application.isEmpty()
                                  ? c->application.left(d.columns)
                                  : displayRow(QString(), dash, d.columns));
    int row = d.portsRow;
    for (const PortSpec &spec : target.ports) {
        if (row <= 0 || !spec.on(model.name))
            continue;
        QString words = dash;
        if (c)
            for (const PanelPort &p : c->ports)
                if (p.port == spec.name && p.application)
                    words =
                        QString::fromLatin1(p.application->displayName ? p.application->displayName
                                                                       : p.application->name);
        put(row++, displayRow(spec.name, words, d.columns));
    }
    const QString note =
        c ? QCoreApplication::translate("rung::model::PanelView",
                                        "Application \"%1\"; the ports' protocols as their "
                                        "settings give them")
                .arg(c->application)
          : QCoreApplication::translate(
                "rung::model::PanelView",
                "The application's name and the ports' protocols are not known here: shown as "
                "dashes");
    v.note = v.note.isEmpty() ? note : v.note + QLatin1Char('\n') + note;
}

// The system pages (PL110 manual 5.3). Pages 1 and 2: the digital inputs and outputs, "attive ...
// con un quadratino pieno", and the analog inputs' values, from the model's terminal strip.
void systemPage(const Target &target, const ModelVariant *model, const PanelInput &in, int page,
                PanelView &v) {
    const QString filled = QStringLiteral("\u25a0"), empty = QStringLiteral("\u25a1");
    int row = 0;
    const auto put = [&](const QString &text) {
        if (row < v.lines.size())
            putText(v.lines[row++], 0, text);
    };
    const ModelVariant &m = model ? *model : target.defaultModel();
    if (page == 1 || page == 2) {
        for (const TerminalBlock &b : m.terminals) {
            const Area *area = areaByKey(target, b.area);
            if (!area || b.words() != (page == 2))
                continue;
            if (page == 2 && area->writable)
                continue;
            if (!b.words()) {
                QString text = area->prefix.leftJustified(4, QLatin1Char(' '));
                for (int k = 0; k < b.count; ++k) {
                    const auto a = panelDevice(target, area->prefix + QString::number(b.first + k));
                    text += a && readBit(in, v, *a) ? filled : empty;
                }
                put(text);
                continue;
            }
            for (int k = 0; k < b.count; ++k) {
                const QString name = area->prefix + QString::number(b.first + k);
                put(name.leftJustified(6, QLatin1Char(' ')) +
                    QString::number(wordOf(in, v, panelDevice(target, name)))
                        .rightJustified(6, QLatin1Char(' ')));
            }
        }
        return;
    }
    // Pages 3..5 (5.3): the table's text and numbers (PanelDisplay::systemTexts, systemFields).
    const PanelDisplay &d = target.panel.display;
    for (const PanelSystemPage &text : d.systemTexts) {
        if (text.page != page)
            continue;
        for (const QString &line : text.lines)
            put(line);
        if (text.note)
            v.note = QCoreApplication::translate("rung::model::PanelView", text.note);
    }
    if (page == d.contextPage)
        contextView(target, m, d, in, v);
    systemFieldsView(target, d, in, page, v);
}

void fieldsView(const Target &target, const PanelDisplay &d, const PanelInput &in, PanelView &v) {
    const TerminalState *keys = in.terminal;
    for (std::size_t index = 0; index < d.fields.size(); ++index) {
        const PanelField &f = d.fields[index];
        // The field the keys edit shows the value being entered, not yet stored (5.2).
        const bool editing = keys && keys->mode == TerminalState::Mode::Field &&
                             keys->field == static_cast<int>(index) && keys->page == v.page;
        const auto base = panelDevice(target, f.first);
        if (!base)
            continue;
        const auto at = [&](int offset) {
            Address a = *base;
            a.index += offset;
            return static_cast<int>(readValue(in, v, a));
        };
        // 2.1.2: state 0 disabled, 1 shown, 2 editable; area (SM107's list); number, high and
        // low word; ...; format 0 16 bit signed, 1 unsigned, 2 32 bit signed; total digits;
        // decimals; fill; row 1..8; column 1..21.
        const int state = at(0);
        if (state != 1 && state != 2)
            continue;
        const int code = at(1);
        const qint64 number = (static_cast<qint64>(at(2) & 0xffff) << 16) | (at(3) & 0xffff);
        const auto entry = std::find_if(d.areaCodes.begin(), d.areaCodes.end(),
                                        [code](const PanelAreaCode &c) { return c.code == code; });
        const Area *area = entry == d.areaCodes.end() ? nullptr : areaByKey(target, entry->area);
        const int row = at(14) - 1, column = at(15) - 1;
        if (row < 0 || row >= v.lines.size() || column < 0 || column >= d.columns)
            continue;
        QString text;
        const auto device =
            area ? panelDevice(target, area->prefix + QString::number(number)) : std::nullopt;
        if (!device) {
            text = QStringLiteral("?");
        } else {
            qint64 value = editing ? keys->value : readValue(in, v, *device);
            if (at(10) == 1)
                value &= 0xffff;
            else if (at(10) == 0)
                value = static_cast<qint16>(value & 0xffff);
            text = formatPanelField(value, std::clamp(at(11), 1, 12), std::clamp(at(12), 0, 10),
                                    at(13) == 1);
        }
        putText(v.lines[row], column, text);
        const int length = static_cast<int>(std::min<qsizetype>(text.size(), d.columns - column));
        const int cursor = editing && keys->digit >= 0
                               ? digitColumn(text, keys->digit, std::clamp(at(12), 0, 10))
                               : -1;
        v.fields.push_back(
            {row, column, length, state == 2, editing, cursor < length ? cursor : -1});
    }
}

// The password page (PL110 manual 5.5, page 253: "*** PASSWORD ***" over the number entered),
// the digit SWAP chose marked.
void passwordView(const PanelDisplay &d, const TerminalState &keys, PanelView &v) {
    v.page = d.passwordPage;
    const auto centred = [&](int row, const QString &text) {
        const int column = std::max(0, (d.columns - static_cast<int>(text.size())) / 2);
        putText(v.lines[row], column, text);
        return column;
    };
    centred(1, QStringLiteral("*** PASSWORD ***"));
    const int digits = std::max(1, d.passwordDigits);
    const QString number =
        QStringLiteral("%1").arg(keys.value, digits, 10, QLatin1Char('0')).right(digits);
    const int column = centred(4, number);
    v.fields.push_back({4, column, digits, true, true,
                        keys.digit >= 0 && keys.digit < digits ? digits - 1 - keys.digit : -1});
}

void textView(const Target &target, const ModelVariant *model, const PanelDisplay &d,
              const PanelInput &in, PanelView &v) {
    for (int r = 0; r < d.rows; ++r)
        v.lines << QString(d.columns, QLatin1Char(' '));
    if (!in.snapshot)
        return;
    v.page = static_cast<int>(wordOf(in, v, panelDevice(target, d.pageShownDevice)));
    if (in.terminal) {
        v.brightness = terminalBrightness(target, *in.snapshot, *in.terminal);
        if (in.terminal->mode == TerminalState::Mode::Password && d.passwordPage > 0) {
            passwordView(d, *in.terminal, v);
            return;
        }
    }
    if (v.page >= d.firstUserPage && v.page < d.firstUserPage + d.userPages) {
        const Area *chars = areaByKey(target, d.charArea);
        for (int r = 0; chars && r < d.rows; ++r)
            for (int c = 0; c < d.columns; ++c)
                if (const auto a =
                        panelDevice(target, chars->prefix + QString::number(r * d.columns + c)))
                    v.lines[r][c] = displayChar(d, readValue(in, v, *a));
        fieldsView(target, d, in, v);
    } else if (v.page >= 1 && v.page <= d.systemPages) {
        systemPage(target, model, in, v.page, v);
    } else {
        v.note = QCoreApplication::translate("rung::model::PanelView",
                                             "No page is shown: the program enables none");
    }
}

void ioLinesView(const Target &target, const ModelVariant *model, const PanelDisplay &d,
                 const PanelInput &in, PanelView &v) {
    const QString filled = QStringLiteral("\u25a0"), empty = QStringLiteral("\u25a1");
    for (const QString &key : d.lineAreas) {
        for (std::size_t k = 0; k < target.areas.size(); ++k) {
            const Area &area = target.areas[k];
            if (area.key != key)
                continue;
            const auto range = target.range(static_cast<int>(k), model);
            if (!range)
                continue;
            for (int first = range->first; first <= range->second; first += d.perLine) {
                QString line;
                const int last = std::min(range->second, first + d.perLine - 1);
                for (int n = first; n <= last; ++n) {
                    const Address a{static_cast<int>(k), n, -1};
                    line += readBit(in, v, a) ? filled : empty;
                }
                v.lines << line;
                v.lineLabels << formatAddress(target, Address{static_cast<int>(k), first, -1});
            }
        }
    }
}

// A lamp for each element of the areas the model has them for (VPC: the I/O LEDs).
void pointLampsView(const Target &target, const ModelVariant *model, const FrontPanel &p,
                    const PanelInput &in, PanelView &v) {
    const QString modelName = model ? model->name : target.defaultModel().name;
    for (const PanelPointLamps &points : p.pointLamps) {
        if (!points.models.isEmpty() && !points.models.contains(modelName))
            continue;
        for (std::size_t k = 0; k < target.areas.size(); ++k) {
            if (target.areas[k].key != points.area)
                continue;
            const auto range = target.range(static_cast<int>(k), model);
            for (int n = range ? range->first : 0; range && n <= range->second; ++n) {
                const Address a{static_cast<int>(k), n, -1};
                v.lamps.push_back({formatAddress(target, a), points.colour, readBit(in, v, a), 0,
                                   points.meaning});
            }
        }
    }
}

} // namespace

PanelContext panelContext(const Target &target, const ModelVariant *model, QString application,
                          const std::map<QString, const PortApplication *> &chosen) {
    PanelContext c;
    c.application = std::move(application);
    const ModelVariant &m = model ? *model : target.defaultModel();
    for (const PortSpec &spec : target.ports) {
        if (!spec.on(m.name))
            continue;
        PanelPort p{spec.name, nullptr};
        // A port the settings do not name: its first application, as readPortConfig gives it.
        if (const auto it = chosen.find(spec.name); it != chosen.end())
            p.application = it->second;
        else if (!spec.applications.empty())
            p.application = &spec.applications.front();
        c.ports.push_back(p);
    }
    return c;
}

PanelContext panelContext(const Target &target, const ModelVariant *model, QString application,
                          const QJsonObject &ports) {
    std::map<QString, const PortApplication *> chosen;
    for (auto it = ports.begin(); it != ports.end(); ++it) {
        PortConfig config;
        QString why;
        if (readPortConfig(target, model, it.key(), {{it.value().toObject(), it.key()}}, &config,
                           &why))
            chosen[config.port] = config.application;
        else
            for (const PortSpec &spec : target.ports)
                if (spec.name.compare(it.key(), Qt::CaseInsensitive) == 0)
                    chosen[spec.name] = nullptr;
    }
    return panelContext(target, model, std::move(application), chosen);
}

bool hasFrontPanel(const Target &target, const ModelVariant *model) {
    const FrontPanel &p = target.panel;
    if (!p.lamps.empty() || !p.pointLamps.empty() || !p.knobs.empty())
        return true;
    if (p.display.kind == DisplayKind::Text)
        return modelHasArea(target, model, p.display.charArea);
    return p.display.kind != DisplayKind::None;
}

PanelView panelView(const Target &target, const ModelVariant *model, const PanelInput &input) {
    PanelView v;
    const FrontPanel &p = target.panel;
    for (const PanelLamp &lamp : p.lamps)
        v.lamps.push_back(lampView(target, lamp, input, v));
    pointLampsView(target, model, p, input, v);
    for (const PanelKnob &k : p.knobs) {
        const auto a = panelDevice(target, k.device);
        if (!a)
            continue;
        const qint64 word = wordOf(input, v, a);
        const qint64 value = k.bcd ? fromBcd(word).value_or(0) : word;
        v.knobs.push_back(
            {k.label, *a, static_cast<int>(value), k.lowest, k.highest, k.bcd, k.meaning});
    }
    v.display = p.display.kind;
    // The terminal (display and keys) exists on the models that have its character area
    // (PL110 manual 1.2: "Terminale con display OLED e tasti. (solo modello PL110-2A)").
    if (v.display == DisplayKind::Text && !modelHasArea(target, model, p.display.charArea))
        v.display = DisplayKind::None;
    if (v.display != DisplayKind::None || p.display.kind != DisplayKind::Text)
        for (const PanelKey &k : p.keys)
            if (const auto a = panelDevice(target, k.device))
                v.keys.push_back(
                    {k.label, *a, readBit(input, v, *a), k.shortcut, k.meaning, k.role});
    switch (v.display) {
    case DisplayKind::Digits:
        digitsView(target, p.display, input, v);
        break;
    case DisplayKind::Text:
        textView(target, model, p.display, input, v);
        break;
    case DisplayKind::IoLines:
        ioLinesView(target, model, p.display, input, v);
        break;
    case DisplayKind::None:
        break;
    }
    return v;
}

QString formatPanelField(qint64 value, int total, int decimals, bool zeros) {
    const bool negative = value < 0;
    QString digits = QString::number(negative ? -value : value);
    if (decimals > 0) {
        digits = digits.rightJustified(decimals + 1, QLatin1Char('0'));
        digits.insert(digits.size() - decimals, QLatin1Char('.'));
    }
    const int width = total + (decimals > 0 ? 1 : 0);
    if (zeros) {
        digits = digits.rightJustified(width - (negative ? 1 : 0), QLatin1Char('0'));
        return (negative ? QStringLiteral("-") : QString()) + digits;
    }
    return ((negative ? QStringLiteral("-") : QString()) + digits)
        .rightJustified(width, QLatin1Char(' '));
}

qint64 panelKnobWord(const PanelKnobView &knob, int value) {
    const int v = std::clamp(value, knob.lowest, knob.highest);
    return knob.bcd ? toBcd(v) : v;
}

} // namespace rung::model
