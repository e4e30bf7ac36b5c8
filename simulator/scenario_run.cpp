#include "scenario.h"
#include "simulator/tr.h"

#include "model/image/panel_keys.h"
#include "model/target/address.h"

#include <map>

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QRegularExpression>

// Running a scenario on the scan engine (docs/scenario-tests.md "How a scenario runs"): the
// statements' devices and conditions are read with the program's target, then the engine
// scans on virtual time, the statements applied and checked in the file's order.

namespace rung::simulator {

namespace {

// A value a condition reads: a device (a bit; a word; a timer's or counter's current or set
// value) or a constant.
struct Value {
    enum class Kind : std::uint8_t { Bit, Word, Current, SetValue, Constant } kind = Kind::Constant;
    model::Address address;
    Engine *engine = nullptr; // the device's (a network's station's)
    bool inStation = false;   // written STATION/DEVICE
    qint64 constant = 0;
    QString text; // as written

    bool isDevice() const { return kind != Kind::Constant; }
    qint64 read() const { // a constant has no engine
        switch (kind) {
        case Kind::Bit:
            return engine->bit(address) ? 1 : 0;
        case Kind::Word:
        case Kind::Current:
            return engine->value(address);
        case Kind::SetValue:
            return engine->setValue(address);
        case Kind::Constant:
            break;
        }
        return constant;
    }
};

struct Condition {
    enum class Kind : std::uint8_t { And, Or, Not, Compare, Truth } kind = Kind::Truth;
    std::vector<Condition> items;
    Value left, right;
    model::CompareOp op = model::CompareOp::Eq;

    bool holds() const {
        switch (kind) {
        case Kind::And:
            return std::all_of(items.begin(), items.end(),
                               [&](const Condition &c) { return c.holds(); });
        case Kind::Or:
            return std::any_of(items.begin(), items.end(),
                               [&](const Condition &c) { return c.holds(); });
        case Kind::Not:
            return !items.front().holds();
        case Kind::Truth:
            return left.read() != 0;
        case Kind::Compare:
            break;
        }
        return model::compareHolds(op, left.read(), right.read());
    }
    void devices(std::vector<const Value *> *out) const {
        for (const Condition &c : items)
            c.devices(out);
        for (const Value *v : {&left, &right})
            if (v->isDevice() && std::none_of(out->begin(), out->end(),
                                              [v](const Value *w) { return w->text == v->text; }))
                out->push_back(v);
    }
};

struct Assignment {
    Value device;
    qint64 value = 0;
};

// Reads the devices, values and conditions of one statement with the target's spelling of
// devices ("DM 0010", "000.01", "TIM 000", "V10"; "st1/D0" in a network: the subject says
// which engine and target). A device may hold one space (the CPM1's "DM 0010"): a word that
// is no device is tried with the word after it.
class StatementReader {
public:
    StatementReader(ScenarioSubject &subject, const QString &text)
        : m_subject(subject)
        , m_text(text) {}

    QString error() const { return m_error; }

    std::optional<Condition> condition() {
        auto c = readOr();
        if (c && !atEnd())
            return fail(
                ScenarioTr::tr("\"%1\" is not understood here").arg(m_text.mid(m_pos).trimmed()));
        return c;
    }

    std::optional<std::vector<Assignment>> assignments(bool bitsOnly) {
        std::vector<Assignment> out;
        while (!atEnd()) {
            auto device = readValue(true);
            if (!device)
                return std::nullopt;
            if (!device->isDevice())
                return fail(ScenarioTr::tr("%1 is no device").arg(device->text));
            if (bitsOnly && device->kind != Value::Kind::Bit)
                return fail(ScenarioTr::tr("%1: only bits are forced").arg(device->text));
            skipSpaces();
            if (!take(QStringLiteral("=")))
                return fail(ScenarioTr::tr("%1 needs =VALUE").arg(device->text));
            auto value = readValue(false);
            if (!value)
                return std::nullopt;
            if (value->isDevice())
                return fail(ScenarioTr::tr("%1 is no value (a number, ON or OFF, #hex digits)")
                                .arg(value->text));
            out.push_back({*device, value->constant});
            skipSpaces();
            take(QStringLiteral(","));
        }
        if (out.empty())
            return fail(ScenarioTr::tr("DEVICE=VALUE is expected"));
        return out;
    }

    std::optional<std::vector<Value>> devices() {
        std::vector<Value> out;
        while (!atEnd()) {
            auto device = readValue(true);
            if (!device)
                return std::nullopt;
            if (device->kind != Value::Kind::Bit)
                return fail(
                    ScenarioTr::tr("%1: only bits are forced and released").arg(device->text));
            out.push_back(*device);
            skipSpaces();
            take(QStringLiteral(","));
        }
        return out;
    }

private:
    std::nullopt_t fail(const QString &message) {
        if (m_error.isEmpty())
            m_error = message;
        return std::nullopt;
    }
    void skipSpaces() {
        while (m_pos < m_text.size() && m_text[m_pos].isSpace())
            ++m_pos;
    }
    bool atEnd() {
        skipSpaces();
        return m_pos >= m_text.size();
    }
    bool take(const QString &s) {
        skipSpaces();
        if (m_text.mid(m_pos, s.size()) != s)
            return false;
        m_pos += s.size();
        return true;
    }
    static bool wordChar(QChar c) { return !c.isSpace() && !QStringLiteral("()=<>!,").contains(c); }
    // The word at `from` (no spaces, no operators); its end in *end.
    QString wordAt(qsizetype from, qsizetype *end) const {
        qsizetype p = from;
        while (p < m_text.size() && m_text[p].isSpace())
            ++p;
        qsizetype q = p;
        while (q < m_text.size() && wordChar(m_text[q]))
            ++q;
        *end = q;
        return m_text.mid(p, q - p);
    }
    bool keyword(const char *word) {
        qsizetype end = 0;
        if (wordAt(m_pos, &end).compare(QLatin1String(word), Qt::CaseInsensitive) != 0)
            return false;
        m_pos = end;
        return true;
    }
    bool peekKeyword(const char *word) const {
        qsizetype end = 0;
        return wordAt(m_pos, &end).compare(QLatin1String(word), Qt::CaseInsensitive) == 0;
    }

    static std::optional<qint64> constant(const QString &w) {
        static const QRegularExpression decimal(QStringLiteral("^-?\\d+$"));
        bool ok = false;
        if (decimal.match(w).hasMatch()) {
            const qint64 v = w.toLongLong(&ok);
            return ok ? std::optional<qint64>(v) : std::nullopt;
        }
        const QString upper = w.toUpper();
        if (upper == QLatin1String("ON") || upper == QLatin1String("TRUE"))
            return 1;
        if (upper == QLatin1String("OFF") || upper == QLatin1String("FALSE"))
            return 0;
        // A word in hexadecimal digits: #0150 (as CPM1 listings write BCD words), 0x96, 16#96.
        QString digits;
        if (w.startsWith(QLatin1Char('#')))
            digits = w.mid(1);
        else if (upper.startsWith(QLatin1String("0X")))
            digits = w.mid(2);
        else if (w.startsWith(QLatin1String("16#")))
            digits = w.mid(3);
        if (digits.isEmpty() || digits.size() > 8)
            return std::nullopt;
        const qint64 v = digits.toLongLong(&ok, 16);
        return ok ? std::optional<qint64>(v) : std::nullopt;
    }

    // A device or a constant. With preferDevice a word that reads as both (the CPM1's channel
    // "200") is the device: left of a comparison and in an assignment a device is expected.
    std::optional<Value> readValue(bool preferDevice) {
        qsizetype end = 0;
        const QString word = wordAt(m_pos, &end);
        if (word.isEmpty())
            return fail(m_pos >= m_text.size()
                            ? ScenarioTr::tr("a device or a value is missing at the end")
                            : ScenarioTr::tr("a device or a value is expected at \"%1\"")
                                  .arg(m_text.mid(m_pos).trimmed()));
        if (!preferDevice) {
            if (const auto c = constant(word)) {
                m_pos = end;
                Value v;
                v.constant = *c;
                v.text = word;
                return v;
            }
        }
        QString prefix;
        QString name = word;
        for (const char *p : {"cv:", "sv:"})
            if (name.startsWith(QLatin1String(p), Qt::CaseInsensitive)) {
                prefix = name.left(3).toLower();
                name = name.mid(3);
            }
        const bool inStation = name.contains(QLatin1Char('/'));
        QString device;
        QString why;
        Engine *engine = m_subject.engineFor(name, &device, &why);
        if (!engine)
            return fail(why);
        name = device;
        const model::Target &target = engine->program().layout->target();
        auto parsed = model::parseAddress(target, name);
        qsizetype used = end;
        QString written = word;
        if (std::holds_alternative<model::AddressError>(parsed)) {
            qsizetype end2 = 0;
            const QString next = wordAt(end, &end2);
            if (!next.isEmpty() && next.compare(QLatin1String("and"), Qt::CaseInsensitive) != 0 &&
                next.compare(QLatin1String("or"), Qt::CaseInsensitive) != 0 &&
                next.compare(QLatin1String("not"), Qt::CaseInsensitive) != 0) {
                auto two = model::parseAddress(target, name + QLatin1Char(' ') + next);
                if (std::holds_alternative<model::Address>(two)) {
                    parsed = two;
                    used = end2;
                    written = word + QLatin1Char(' ') + next;
                }
            }
        }
        if (const auto *e = std::get_if<model::AddressError>(&parsed)) {
            if (preferDevice)
                if (const auto c = constant(word)) {
                    m_pos = end;
                    Value v;
                    v.constant = *c;
                    v.text = word;
                    return v;
                }
            return fail(ScenarioTr::tr("%1 is no device of %2: %3")
                            .arg(word, target.displayName, e->message));
        }
        m_pos = used;
        Value v;
        v.text = written;
        v.address = std::get<model::Address>(parsed);
        v.engine = engine;
        v.inStation = inStation;
        const model::AreaKind kind = target.area(v.address.area).kind;
        const bool element = kind == model::AreaKind::Timer || kind == model::AreaKind::Counter;
        if (!prefix.isEmpty() && (!element || v.address.bit >= 0))
            return fail(
                ScenarioTr::tr("%1: cv: and sv: name a timer's or a counter's current and set "
                               "value")
                    .arg(written));
        if (prefix == QLatin1String("cv:"))
            v.kind = Value::Kind::Current;
        else if (prefix == QLatin1String("sv:"))
            v.kind = Value::Kind::SetValue;
        else if (element || kind == model::AreaKind::Bit || v.address.bit >= 0)
            v.kind = Value::Kind::Bit; // a timer's or counter's done bit
        else
            v.kind = Value::Kind::Word;
        return v;
    }

    std::optional<Condition> readOr() {
        auto first = readAnd();
        if (!first)
            return std::nullopt;
        Condition c;
        c.kind = Condition::Kind::Or;
        c.items.push_back(*first);
        while (keyword("or")) {
            auto next = readAnd();
            if (!next)
                return std::nullopt;
            c.items.push_back(*next);
        }
        return c.items.size() == 1 ? c.items.front() : c;
    }
    // Conditions side by side hold together: "Y0=0 Y1=1" is "Y0=0 and Y1=1".
    std::optional<Condition> readAnd() {
        Condition c;
        c.kind = Condition::Kind::And;
        while (true) {
            auto next = readUnary();
            if (!next)
                return std::nullopt;
            c.items.push_back(*next);
            if (keyword("and"))
                continue;
            if (atEnd() || m_text[m_pos] == QLatin1Char(')') || peekKeyword("or"))
                break;
        }
        return c.items.size() == 1 ? c.items.front() : c;
    }
    std::optional<Condition> readUnary() {
        if (keyword("not")) {
            auto inner = readUnary();
            if (!inner)
                return std::nullopt;
            Condition c;
            c.kind = Condition::Kind::Not;
            c.items.push_back(*inner);
            return c;
        }
        if (take(QStringLiteral("("))) {
            auto inner = readOr();
            if (!inner)
                return std::nullopt;
            if (!take(QStringLiteral(")")))
                return fail(ScenarioTr::tr("a \")\" is missing"));
            return inner;
        }
        auto left = readValue(true);
        if (!left)
            return std::nullopt;
        skipSpaces();
        static const std::pair<const char *, model::CompareOp> ops[] = {
            {"<>", model::CompareOp::Ne}, {"!=", model::CompareOp::Ne},
            {"<=", model::CompareOp::Le}, {">=", model::CompareOp::Ge},
            {"==", model::CompareOp::Eq}, {"=", model::CompareOp::Eq},
            {"<", model::CompareOp::Lt},  {">", model::CompareOp::Gt}};
        for (const auto &[text, op] : ops) {
            if (!take(QLatin1String(text)))
                continue;
            auto right = readValue(false);
            if (!right)
                return std::nullopt;
            Condition c;
            c.kind = Condition::Kind::Compare;
            c.left = *left;
            c.right = *right;
            c.op = op;
            return c;
        }
        if (left->kind != Value::Kind::Bit)
            return fail(
                left->isDevice()
                    ? ScenarioTr::tr("%1 is a word: compare it (%1=5, %1>100)").arg(left->text)
                    : ScenarioTr::tr("%1 alone is no condition").arg(left->text));
        Condition c;
        c.kind = Condition::Kind::Truth;
        c.left = *left;
        return c;
    }

    ScenarioSubject &m_subject;
    QString m_text;
    qsizetype m_pos = 0;
    QString m_error;
};

struct PreparedStatement {
    const ScenarioStatement *statement = nullptr;
    std::vector<Assignment> assignments; // set, force
    std::vector<Value> devices;          // release
    bool releaseAll = false;
    Condition condition; // expect, within, always
    // press: the key's engine, bit and role, and how long it is held
    Engine *keyEngine = nullptr;
    model::Address key;
    model::PanelKeyRole keyRole = model::PanelKeyRole::Other;
    qint64 holdMs = 0;
};

// A key of the engine's front panel by its label (PL110 manual 5.2: SWAP, UP, DOWN, SET),
// into `step`; false with the reason in `error`.
bool readKey(ScenarioSubject &subject, const QString &written, PreparedStatement &step,
             QString *error) {
    QString label;
    Engine *engine = subject.engineFor(written, &label, error);
    if (!engine)
        return false;
    const model::Target &target = engine->program().layout->target();
    QStringList labels;
    for (const model::PanelKey &k : target.panel.keys) {
        labels << k.label;
        if (k.label.compare(label, Qt::CaseInsensitive) != 0)
            continue;
        const auto parsed = model::parseAddress(target, k.device);
        const auto *a = std::get_if<model::Address>(&parsed);
        if (!a)
            break;
        step.keyEngine = engine;
        step.key = *a;
        step.keyRole = k.role;
        return true;
    }
    *error = labels.isEmpty()
                 ? ScenarioTr::tr("%1: the %2 has no keys on its front panel to press")
                       .arg(written, target.displayName)
                 : ScenarioTr::tr("%1 is no key of the %2's front panel (its keys: %3)")
                       .arg(written, target.displayName, labels.join(QStringLiteral(", ")));
    return false;
}

QString seenText(const Condition &c) {
    std::vector<const Value *> devices;
    c.devices(&devices);
    QStringList parts;
    for (const Value *v : devices)
        parts << QStringLiteral("%1=%2").arg(v->text).arg(v->read());
    return parts.join(QLatin1Char(' '));
}

// The devices for a timing chart of the program; a network's (STATION/DEVICE) have no place
// in one program's chart.
std::vector<model::Address> addressesOf(const Condition &c) {
    std::vector<const Value *> devices;
    c.devices(&devices);
    std::vector<model::Address> out;
    for (const Value *v : devices)
        if (!v->inStation)
            out.push_back(v->address);
    return out;
}

// One program on one engine: a device is the program's, written as its target writes it.
class ProgramSubject final : public ScenarioSubject {
public:
    explicit ProgramSubject(const std::shared_ptr<const Program> &program,
                            const std::function<void(const Engine &)> &afterScan)
        : m_engine(program)
        , m_afterScan(afterScan) {}
    Engine *engineFor(const QString &written, QString *device, QString *error) override {
        if (written.contains(QLatin1Char('/'))) {
            *error = ScenarioTr::tr("%1: STATION/DEVICE names a device of a network's station; "
                                    "this scenario's program is one PLC")
                         .arg(written);
            return nullptr;
        }
        *device = written;
        return &m_engine;
    }
    qint64 defaultPeriodMs() const override { return 10; }
    void start(qint64 periodMs) override { m_engine.setPeriodMs(periodMs); }
    void releaseAll() override { m_engine.releaseAll(); }
    void step() override {
        m_engine.scan();
        if (m_afterScan)
            m_afterScan(m_engine);
    }
    QStringList runtimeErrors() const override {
        QStringList out;
        for (const RuntimeError &e : m_engine.runtimeErrors())
            out << ScenarioTr::tr("runtime error at step %1: %2").arg(e.instruction).arg(e.message);
        return out;
    }

private:
    Engine m_engine;
    std::function<void(const Engine &)> m_afterScan;
};

} // namespace

ScenarioResult runScenario(const Scenario &s, const std::shared_ptr<const Program> &program,
                           const std::function<void(const Engine &)> &afterScan) {
    ProgramSubject subject(program, afterScan);
    return runScenario(s, subject);
}

ScenarioResult runScenario(const Scenario &s, ScenarioSubject &subject) {
    ScenarioResult result;
    result.file = s.file;
    const qint64 period =
        s.period ? s.period->resolve(subject.defaultPeriodMs()) : subject.defaultPeriodMs();
    std::vector<PreparedStatement> steps;
    std::vector<std::size_t> always;
    qint64 lastAt = 0;
    int lastAtLine = 0;
    for (const ScenarioStatement &st : s.statements) {
        PreparedStatement step;
        step.statement = &st;
        StatementReader reader(subject, st.text);
        bool ok = true;
        using K = ScenarioStatement::Kind;
        if (st.kind != K::Within && st.kind != K::Always && st.kind != K::Run) {
            const qint64 t = st.time.resolve(period);
            if (t < lastAt) {
                result.errors.push_back(
                    {st.line,
                     ScenarioTr::tr("at %1 comes before line %2's %3: statements stand in the "
                                    "order of their times")
                         .arg(st.time.text)
                         .arg(lastAtLine)
                         .arg(formatScenarioTime(lastAt))});
                continue;
            }
            lastAt = t;
            lastAtLine = st.line;
        }
        switch (st.kind) {
        case K::Set:
        case K::Force:
            if (auto a = reader.assignments(st.kind == K::Force))
                step.assignments = *a;
            else
                ok = false;
            break;
        case K::Release:
            if (st.text.compare(QLatin1String("all"), Qt::CaseInsensitive) == 0) {
                step.releaseAll = true;
            } else if (auto d = reader.devices()) {
                step.devices = *d;
            } else {
                ok = false;
            }
            break;
        case K::Expect:
        case K::Within:
        case K::Always:
            if (auto c = reader.condition())
                step.condition = *c;
            else
                ok = false;
            break;
        case K::Run:
            break;
        case K::Press: {
            QString error;
            ok = readKey(subject, st.text, step, &error);
            if (!ok)
                result.errors.push_back({st.line, error});
            // A tap: 100 ms, and at least the one scan that sees the key.
            step.holdMs = std::max(st.hold ? st.hold->resolve(period) : 100, period);
            break;
        }
        }
        if (!ok) {
            if (st.kind == K::Press)
                continue;
            result.errors.push_back({st.line, reader.error()});
            continue;
        }
        if (st.kind == K::Expect || st.kind == K::Within || st.kind == K::Always)
            result.expectations.push_back({st.line, st.source});
        if (st.kind == K::Always)
            always.push_back(steps.size());
        steps.push_back(std::move(step));
    }
    if (!result.errors.empty())
        return result;

    result.ran = true;
    subject.start(period);
    quint64 done = 0;
    // `always`: the first failing scan is reported, with how many failed.
    std::vector<std::optional<ScenarioFailure>> alwaysFailure(always.size());
    // The front panels' terminals (model/image/panel_keys.h) of the engines whose keys are
    // pressed, on virtual time, and the keys held until a time.
    struct HeldKey {
        const PreparedStatement *press;
        qint64 untilMs;
    };
    std::map<Engine *, model::TerminalState> terminals;
    std::vector<HeldKey> held;
    // The terminal sees the memory as each key comes (what the IDE's panel does at every
    // refresh): SET held long enough opens the password page, a page the program changed ends
    // a field's editing; between keys nothing it keeps shows in the memory.
    auto pressKey = [&](const PreparedStatement &st, bool down, qint64 ms) {
        Engine &engine = *st.keyEngine;
        const model::Target &target = engine.program().layout->target();
        model::TerminalState &terminal = terminals[&engine];
        const model::Snapshot snapshot = engine.snapshot();
        model::terminalTick(target, snapshot, terminal, ms);
        const model::PanelKeyAction action =
            model::panelKeyAction(target, &snapshot, terminal, st.keyRole, down, ms);
        if (action.writeBit)
            engine.setBit(st.key, down);
        for (const model::TerminalWrite &w : action.words)
            engine.writeWord(w.device, w.value);
    };
    // The keys held until `ms` or before come up (in the order they were pressed).
    auto releaseUntil = [&](qint64 ms) {
        for (auto k = held.begin(); k != held.end();) {
            if (k->untilMs > ms) {
                ++k;
                continue;
            }
            pressKey(*k->press, false, k->untilMs);
            k = held.erase(k);
        }
    };
    auto scan = [&] {
        releaseUntil(static_cast<qint64>(done) * period);
        subject.step();
        ++done;
        for (std::size_t k = 0; k < always.size(); ++k) {
            const PreparedStatement &st = steps[always[k]];
            if (st.condition.holds())
                continue;
            if (alwaysFailure[k]) {
                ++alwaysFailure[k]->failingScans;
                continue;
            }
            ScenarioFailure f;
            f.line = st.statement->line;
            f.timeMs = static_cast<qint64>(done - 1) * period;
            f.statement = st.statement->source;
            f.seen = seenText(st.condition);
            f.devices = addressesOf(st.condition);
            alwaysFailure[k] = f;
        }
    };
    // Scans until `count` scans have run (scan k starts at k x period).
    auto runTo = [&](quint64 count) {
        while (done < count)
            scan();
    };
    auto scanOf = [period](qint64 ms) { return static_cast<quint64>(ms / period); };
    auto fail = [&](const PreparedStatement &st, qint64 time, const QString &message) {
        ScenarioFailure f;
        f.line = st.statement->line;
        f.timeMs = time;
        f.statement = st.statement->source;
        f.seen = seenText(st.condition);
        f.devices = addressesOf(st.condition);
        f.message = message;
        result.failures.push_back(f);
    };
    qint64 previous = 0;                 // the previous statement's time (within counts from it)
    std::optional<quint64> expectedScan; // the scan of the last `at T expect`
    for (const PreparedStatement &st : steps) {
        using K = ScenarioStatement::Kind;
        const ScenarioStatement &statement = *st.statement;
        switch (statement.kind) {
        case K::Set:
        case K::Force:
        case K::Release:
        case K::Press: {
            const qint64 t = statement.time.resolve(period);
            // A `within` before it may have run past t: applied late it would change what the
            // rest of the run shows without a word, so the scenario fails here, saying so.
            // (`at T expect` then `at T set` is the one scan the expectation needed, as
            // written: the set follows it.)
            const bool afterExpectSameScan =
                expectedScan && *expectedScan == scanOf(t) && done == scanOf(t) + 1;
            if (done > scanOf(t) && !afterExpectSameScan)
                fail(st, t,
                     ScenarioTr::tr("%1: the run was already at %2 (the statement before waited "
                                    "until then), so it applied then, not at %3")
                         .arg(statement.source,
                              formatScenarioTime(static_cast<qint64>(done) * period),
                              statement.time.text));
            runTo(scanOf(t));
            for (const Assignment &a : st.assignments) {
                Engine &engine = *a.device.engine;
                const model::Target &target = engine.program().layout->target();
                if (statement.kind == K::Force)
                    engine.force(a.device.address, a.value != 0);
                else if (a.device.kind == Value::Kind::SetValue ||
                         (a.device.kind == Value::Kind::Bit &&
                          target.area(a.device.address.area).kind != model::AreaKind::Bit &&
                          a.device.address.bit < 0))
                    engine.writeSetValue(a.device.address, a.value); // a timer or counter
                else if (a.device.kind == Value::Kind::Bit)
                    engine.setBit(a.device.address, a.value != 0);
                else
                    engine.writeWord(a.device.address, a.value);
            }
            if (st.releaseAll)
                subject.releaseAll();
            for (const Value &d : st.devices)
                d.engine->release(d.address);
            if (statement.kind == K::Press) {
                releaseUntil(t); // a key held until t is up before the next goes down at t
                pressKey(st, true, t);
                held.push_back({&st, t + st.holdMs});
            }
            previous = t;
            break;
        }
        case K::Expect: {
            const qint64 t = statement.time.resolve(period);
            const quint64 k = scanOf(t);
            if (done > k + 1) {
                fail(st, t,
                     ScenarioTr::tr(
                         "%1: the run was already at %2 (the statement before waited until "
                         "then), so at %3 could not be checked")
                         .arg(statement.source,
                              formatScenarioTime(static_cast<qint64>(done - 1) * period),
                              statement.time.text));
                previous = t;
                break;
            }
            runTo(k + 1);
            expectedScan = k;
            if (!st.condition.holds())
                fail(st, t,
                     //: A failed expectation: %1 the time, %2 what was expected, %3 the devices'
                     //: values then ("Y0=1 Y1=0").
                     ScenarioTr::tr("at %1: expected %2, seen %3")
                         .arg(formatScenarioTime(t), statement.text, seenText(st.condition)));
            previous = t;
            break;
        }
        case K::Within: {
            const qint64 deadline = previous + statement.time.resolve(period);
            const quint64 first = scanOf(previous);
            const quint64 last = scanOf(deadline);
            bool met = false;
            while (true) {
                if (done > first && st.condition.holds()) {
                    met = true;
                    break;
                }
                if (done > last)
                    break;
                scan();
            }
            const qint64 at = static_cast<qint64>(done - 1) * period;
            if (!met)
                fail(st, at,
                     //: %1 the time allowed ("2s"), %2 the time it counted from, %3 until when,
                     //: %4 what was expected, %5 the values seen at the end.
                     ScenarioTr::tr("within %1 of %2 (until %3): expected %4, seen %5")
                         .arg(statement.time.text, formatScenarioTime(previous),
                              formatScenarioTime(deadline), statement.text,
                              seenText(st.condition)));
            previous = met ? at : deadline;
            break;
        }
        case K::Run: {
            const qint64 t = statement.time.resolve(period);
            runTo(static_cast<quint64>((t + period - 1) / period));
            previous = std::max(previous, t);
            break;
        }
        case K::Always:
            break;
        }
    }
    for (std::size_t k = 0; k < always.size(); ++k) {
        if (!alwaysFailure[k])
            continue;
        ScenarioFailure f = *alwaysFailure[k];
        const ScenarioStatement &statement = *steps[always[k]].statement;
        //: An `always` expectation that failed: %1 the first time, %2 what was expected, %3
        //: the values then, %4 the scans it failed in, %5 the scans run.
        f.message = ScenarioTr::tr("at %1: expected always %2, seen %3 (failed in %4 of %5 scans)")
                        .arg(formatScenarioTime(f.timeMs), statement.text, f.seen)
                        .arg(f.failingScans)
                        .arg(done);
        result.failures.push_back(f);
    }
    std::stable_sort(
        result.failures.begin(), result.failures.end(),
        [](const ScenarioFailure &x, const ScenarioFailure &y) { return x.line < y.line; });
    result.scans = done;
    result.durationMs = static_cast<qint64>(done) * period;
    result.runtimeErrors = subject.runtimeErrors();
    return result;
}

ScenarioResult runScenario(const QString &text, const QString &file,
                           const ScenarioProgramLoader &loader,
                           const ScenarioNetworkLoader &networkLoader) {
    std::vector<ScenarioError> errors;
    const Scenario scenario = parseScenario(text, file, &errors);
    ScenarioResult result;
    result.file = file;
    if (!errors.empty()) {
        result.errors = errors;
        return result;
    }
    const QString path = QFileInfo(scenario.program).isAbsolute()
                             ? scenario.program
                             : QFileInfo(file).dir().filePath(scenario.program);
    if (path.endsWith(QLatin1String(".rungnet"), Qt::CaseInsensitive)) {
        if (!scenario.target.isEmpty() || !scenario.model.isEmpty()) {
            result.errors.push_back({scenario.programLine,
                                     ScenarioTr::tr("a network's stations bring their own targets "
                                                    "and models: --target and --model are for "
                                                    "one program")});
            return result;
        }
        QStringList errors;
        std::unique_ptr<ScenarioSubject> network =
            networkLoader ? networkLoader(QDir::cleanPath(path), &errors) : nullptr;
        if (!network) {
            for (const QString &e : errors)
                result.errors.push_back({scenario.programLine, e});
            if (result.errors.empty())
                result.errors.push_back(
                    {scenario.programLine,
                     ScenarioTr::tr("%1 is a network: rungstudio-cli test runs it").arg(path)});
            return result;
        }
        return runScenario(scenario, *network);
    }
    const ScenarioProgram loaded = loader(QDir::cleanPath(path), scenario.target, scenario.model);
    if (!loaded.program) {
        for (const QString &e : loaded.errors)
            result.errors.push_back({scenario.programLine, e});
        if (result.errors.empty())
            result.errors.push_back(
                {scenario.programLine, ScenarioTr::tr("the program does not start")});
        return result;
    }
    return runScenario(scenario, loaded.program);
}

} // namespace rung::simulator
