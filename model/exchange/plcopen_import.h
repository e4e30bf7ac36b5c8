#pragma once

// The reader of PLCopen TC6 XML LD bodies (model/exchange/plcopen.h), in five files: the file,
// its variables and elements (plcopen_import.cpp); the power flow (plcopen_power.cpp); the
// outputs (plcopen_outputs.cpp) and the counters among them (plcopen_import_counters.cpp); the
// rungs, symbols and what is left over (plcopen_rungs.cpp).
// Internal to model/exchange.

#include "model/exchange/plcopen.h"
#include "model/exchange/plcopen_counters.h"
#include "model/exchange/plcopen_xml.h"
#include "model/ladder/network.h"

#include <QHash>

#include <map>
#include <memory>
#include <set>
#include <tuple>

namespace rung::model::plcopen {

using detail::Branch;
using detail::Expr;
using detail::RungLogic;

struct Connection {
    int ref = 0;
    QString formal;
};

struct Pin {
    QString formal;
    std::vector<Connection> connections;
    QString expression; // connectionPointIn/expression (a value without an element)
    bool negated = false;
    QString edge; // an input on an edge (CU edge="rising")
};

struct Element {
    QString kind; // the XML element's name
    int id = 0;
    int line = 0;
    double x = 0, y = 0;
    int index = 0;    // document order
    QString variable; // contact / coil variable; in/out variable expression
    bool negated = false;
    QString edge, storage;
    QString typeName, instanceName, name;
    std::vector<Pin> inputs;
    QString instruction; // Rung Studio's addData
    QString contact;
    QString comment;
    long order = 0; // executionOrderId
};

struct VariableInfo {
    QString name;
    int line = 0;
    QString type;
    QString location;
    QString documentation;
    QString device; // Rung Studio's addData
    QString symbol, symbolComment;
    std::optional<qint64> setValue;
    bool used = false;
    // A CONSTANT's value (a constant="true" list's initialValue, Beremiz writes its global
    // constants so): a literal wherever the ladder names it.
    QString constant;
};

struct Factor {
    QString key;
    Expr expr; // empty: a left rail
};
using Chain = std::vector<Factor>;

struct Output {
    const Element *element = nullptr;
    Instruction instruction;
    Chain chain;               // one power input
    std::vector<Chain> inputs; // a box with several
    bool multi = false;
    std::optional<qint64> setValue; // a VPC timer's, kept in the project
};

// "block TON", "contact start", "coil pump", "jump": how an issue names an element.
QString describe(const Element &e);
bool isTimerType(const QString &type);
bool isCounterType(const QString &type); // CTU, CTD, CTUD and their typed forms (CTU_DINT)
// TRUE / FALSE (or 1 / 0) as an IEC literal, nullopt for anything else.
std::optional<bool> boolLiteral(const QString &text);
std::optional<CompareOp> compareOf(const QString &type);
// An IEC TIME literal in milliseconds: T#1s, TIME#1m30s, t#1.5s, T#250ms.
std::optional<qint64> timeLiteral(const QString &text);
// An IEC integer literal: 10, -5, 16#1F, 2#1010, 8#17, INT#5, TRUE, FALSE.
std::optional<qint64> integerLiteral(const QString &text);

class Importer {
public:
    Importer(const Target &target, const ModelVariant *model, const DeviceMapping &mapping)
        : m_t(target)
        , m_model(model)
        , m_mapping(mapping) {}

    PlcopenImport run(const QByteArray &bytes);

private:
    void issue(int line, const QString &element, const QString &message);

    PlcopenImport finish();

    // ---- the file's header, variables and our addData ------------------------------------

    static const XmlNode *ourData(const XmlNode &node, const char *what);

    void readHeader(const XmlNode &root);

    // The POUs the configurations' resources run (pouInstance, in a task or not), by type.
    static QStringList runningPous(const XmlNode &root);

    void readVarList(const XmlNode &list);

    void readVariables(const XmlNode &pou);

    void readGlobals(const XmlNode &instances);

    void readProjectData(const XmlNode &add);

    // ---- variables to devices --------------------------------------------------------------

    // The device a variable names: the mapping file, Rung Studio's own note of it, its
    // located address, a name that is a device of the target. nullopt: none (it is listed as
    // unmapped, with a free device proposed, once).
    std::optional<Address> resolve(const QString &name, int line, const QString &wantedType = {});

    // An operand written as an expression: a variable (a device) or a literal.
    std::optional<Operand> operandOf(const QString &expression, int line, bool timeAllowed = false);

    // ---- the LD body's elements --------------------------------------------------------------

    static std::vector<Connection> connectionsOf(const XmlNode &point);

    void readElements(const XmlNode &ld);

    const Element *element(int id) const;

    const Pin *pin(const Element &e, const char *formal) const;

    // The expression an operand pin carries: an inVariable connected to it, or its own; a
    // constant's value for its name.
    std::optional<QString> pinExpression(const Pin &p, int line);

    // The value of a CONSTANT the expression names, else the expression.
    QString constantValue(const QString &expression);

    // ---- power flow as chains -------------------------------------------------------------

    Factor leaf(const Element &e, const Contact &c) const;

    std::optional<Contact> contactOfVariable(const QString &variable, int line);

    std::optional<Chain> chainIn(const Pin *p, const Element &owner);

    struct Grouped {
        Expr expr;
        QString key;
        bool always = false; // a way through with nothing on it: the OR is always ON
    };

    // The OR of chains that share their first k factors: grouped by factor k in the order the
    // groups first appear, each group its factor and the OR of what follows it.
    static Grouped groupChains(const std::vector<const Chain *> &chains, std::size_t k);

    std::optional<Chain> chainOf(int id, const QString &formal, const Element &from);

    std::optional<Chain> computeChain(const Element &e, const QString &formal);

    // A block's output as power: a comparison, NOT, an edge (R_TRIG / F_TRIG), a timer's or a
    // counter's Q (its done bit), ENO (the power at EN).
    std::optional<Chain> blockChain(const Element &e, const QString &formal);

    // An output straight from the rail: the target's always-ON contact (W353's 253.13, Vigor's
    // M9000, PL110's RUN bit SM0.0) stands in for the rail, as the PLC needs a condition.
    Chain railChain();

    // An input that is never ON, for a box input the IEC block leaves FALSE (a CTU's R on a
    // counter with a reset input): the always-ON (or RUN) contact negated. nullopt: the target
    // has none.
    std::optional<Chain> neverChain(const Element &owner);

    // An IEC block's EN: absent, or ON whenever the rail is. Otherwise listed (while EN is OFF
    // an IEC block stops where it stands, which no target's timer or counter does).
    bool enAlwaysOn(const Element &e);

    // A power input of a block: its chain; TRUE the rail's, FALSE nullopt in *never.
    std::optional<Chain> powerPin(const Pin *p, const Element &owner, bool *never);

    // ---- outputs ------------------------------------------------------------------------

    std::optional<Instruction> parseInstruction(const QString &text, const Element &e);

    // The instruction with these operands, checked as the target's listing reads it.
    std::optional<Instruction> build(const InstructionSpec *spec, std::vector<Operand> operands,
                                     const Element &e);

    std::optional<Output> coilOutput(const Element &e);

    // An IEC timer (TON, TOF) as the target's timer of that kind: its instance a timer device,
    // PT in the timer's units.
    std::optional<Output> timerOutput(const Element &e);

    // A set value as the target writes one: K10 (Vigor), #0010 (CPM1: BCD digits), 10.
    std::variant<Constant, AddressError> setValueConstant(qint64 value) const;

    std::optional<Instruction> timerInstruction(const InstructionSpec &spec, const Address &timer,
                                                qint64 ms, std::optional<qint64> *kept);

    // The target's instruction that copies `source` to `dest` (from BCD digits to binary with
    // `fromBcd`), checked as its listing reads it; nullopt, listed, when it has none.
    std::optional<Instruction> copyInstruction(const Operand &source, const Operand &dest,
                                               bool fromBcd, const Element &e);

    std::optional<Output> moveOutput(const Element &e);

    // A block of Rung Studio's own file: its instruction; its power inputs EN (IN for a timer)
    // or IN1..INk; its operands are the instruction's.
    std::optional<Output> ownBlockOutput(const Element &e);

    std::optional<Output> outputOf(const Element &e);

    // ---- counters (plcopen_import_counters.cpp) ---------------------------------------------

    // An IEC counter (CTU, CTD, CTUD) as the target's counter (plcopen_counters.h): the counter
    // instruction, and on a one-input counter an RST after it for R.
    bool counterOutputs(const Element &e, std::vector<Output> *outs);

    // A counter's CV (or a timer's ET) to an output variable: the present value moved there.
    std::optional<Output> valueOutput(const Element &e);

    // A counter this file's block was imported as, by instance name.
    struct ImportedCounter {
        Address device;
        CounterChoice choice;
    };
    const ImportedCounter *importedCounter(const QString &instance) const;

    // A counter's present value (CTU0.CV): its device as a word, where the target's counter
    // counts as the IEC one does and keeps the value binary.
    std::optional<Operand> counterValue(const QString &instance, int line,
                                        const QString &element = {});

    void note(const QString &text);
    // The notes of the counters imported (counterOutputs), one a kind.
    void noteCounters();

    bool consumesPower(const Element &e) const;
    // A timer or counter block: built first, so that what reads its Q knows whether it is there.
    static bool isInstanceBlock(const Element &e);
    // The block whose output this element's (first) input takes, and that output's name.
    const Element *valueSource(const Element &e, QString *formal) const;

    // ---- rungs --------------------------------------------------------------------------

    struct Node;
    struct Item {
        bool output = false;
        int outputIndex = -1;
        Factor factor;
        std::unique_ptr<Node> child;
    };
    struct Node {
        std::vector<Item> items;
    };

    void insert(Node &node, const Chain &chain, std::size_t k, int outputIndex);

    Branch branchOf(const Item &edge);

    void buildProgram();

    static bool endsWithEnd(const Rung &r);

    void attachComments(Project &p, const std::vector<double> &rungTop);

    // The device of a variable the ladder did not name through resolve(): Rung Studio's note
    // of it, its location, a name that is a device. Nothing is listed as unmapped for it.
    std::optional<Address> quietDevice(const QString &name, const VariableInfo &v) const;

    // The symbols, in the order of the file's variables: Rung Studio's own (its note of the
    // symbol), or another tool's variable named otherwise than its device (the name, its
    // documentation the comment). A variable the ladder does not use and no rule maps to a
    // device is listed.
    void collectSymbols(Project &p);

    // An element, not imported, whose output this element's inputs take.
    const Element *sourceNotImported(const Element &e) const;

    // A block, not imported, that this element's output feeds.
    const Element *blockFedBy(const Element &e) const;

    void reportUnused();

    // A free device for each variable without one: of the kind its type needs.
    void proposeDevices();

    void checkListing(const Project &p);

    const Target &m_t;
    const ModelVariant *m_model;
    const DeviceMapping &m_mapping;
    PlcopenImport m_result;
    bool m_own = false;
    QString m_fileModel;
    QHash<QString, VariableInfo> m_vars;
    QStringList m_varOrder;
    std::map<QString, std::optional<Address>> m_resolved;
    std::set<Address> m_usedDevices;
    std::vector<Element> m_elements;
    std::map<int, std::size_t> m_byId;
    std::map<QString, std::optional<Chain>> m_chains;
    std::set<QString> m_visiting;
    std::set<int> m_used;
    std::vector<Output> m_outputs;
    std::vector<int> m_rungLine;  // the line of each rung's first output
    std::set<int> m_failedBlocks; // timer and counter blocks not imported
    std::map<QString, ImportedCounter> m_counters;
    struct CounterNote {
        QStringList instances;
        QString difference;
    };
    // By the file's kind, the target's mnemonic, whether it counts alike.
    std::map<std::tuple<QString, QString, bool>, CounterNote> m_counterNotes;
    QString m_listing; // the instruction list of Rung Studio's file, beside its ladder
};

} // namespace rung::model::plcopen
