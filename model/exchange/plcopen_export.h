#pragma once

// The writer of PLCopen TC6 XML (model/exchange/plcopen.h), in two files: each rung's grid as a
// graph of elements (plcopen_export.cpp) and the graph written as XML (plcopen_write.cpp).
// Internal to model/exchange.

#include "model/exchange/plcopen.h"
#include "model/exchange/plcopen_counters.h"

#include <QXmlStreamWriter>

#include <map>
#include <numeric>
#include <set>

namespace rung::model::plcopen {

struct Conn {
    int ref = 0;
    QString formal; // the source's output; empty: its only one
    int row = -1;   // where the source stands in the rung: parallel branches top to bottom
    int column = -1;
};

struct Elem {
    enum class Kind : std::uint8_t {
        LeftRail,
        RightRail,
        Contact,
        Coil,
        Block,
        InVar,
        OutVar,
        Comment,
        Connector,   // a counter's RST: its power, to the counter's R through a continuation
        Continuation // variable: the connector's name
    };
    Kind kind = Kind::Contact;
    int id = 0;
    int x = 0, y = 0, width = 0, height = 0;
    QString variable; // contact / coil variable; in/out variable expression; comment text
    bool negated = false;
    QString edge, storage;
    QString typeName, instanceName;
    std::vector<std::pair<QString, std::vector<Conn>>> inputs; // formal (contact, coil: "")
    QStringList outputs;                                       // block outputs
    QString instruction;                                       // addData
    QString contact;                                           // addData: a contact block's text
    int inputGroup = -1;      // contact / coil / block's first power input: its node group
    std::vector<int> boxRows; // a box's power inputs: node groups, in order
};

// Node groups of one rung: the left rail and the nodes of each row, joined by wires and links.
class Nodes {
public:
    Nodes(const Rung &rung)
        : m_columns(rung.columns)
        , m_parent(static_cast<std::size_t>(rung.rows * (rung.columns + 1) + 1)) {
        std::iota(m_parent.begin(), m_parent.end(), 0);
        for (int r = 0; r < rung.rows; ++r) {
            join(node(r, 0), rail());
            for (int c = 0; c < rung.columns; ++c)
                if (rung.cell(r, c).kind == CellKind::Wire)
                    join(node(r, c), node(r, c + 1));
            if (r + 1 < rung.rows)
                for (int c = 0; c <= rung.columns; ++c)
                    if (rung.link(r, c))
                        join(node(r, c), node(r + 1, c));
        }
    }
    int node(int row, int column) const { return row * (m_columns + 1) + column; }
    int rail() const { return static_cast<int>(m_parent.size()) - 1; }
    int find(int n) {
        while (m_parent[static_cast<std::size_t>(n)] != n)
            n = m_parent[static_cast<std::size_t>(n)] =
                m_parent[static_cast<std::size_t>(m_parent[static_cast<std::size_t>(n)])];
        return n;
    }
    void join(int a, int b) { m_parent[static_cast<std::size_t>(find(a))] = find(b); }

private:
    int m_columns;
    std::vector<int> m_parent;
};

struct Variable {
    Address address;
    QString type; // BOOL, INT, DINT, TON, TOF, CTU, CTD, CTUD, R_TRIG, F_TRIG
    bool instance = false;
    QString done;         // an instance's output that is its bit: Q, QU, QD
    bool counter = false; // a counter instance: its value is CV
};

constexpr int kCell = 60;
constexpr int kRow = 40;

class Exporter {
public:
    Exporter(const Project &p)
        : m_p(p)
        , m_t(*p.target) {}

    PlcopenExport run(const QString &name, const QDateTime &created);

private:
    static bool isEnd(const Rung &rung);

    bool bitDevice(const Address &a) const;

    // An on- or off-delay timer with a constant set value (or the VPC's, kept in setValues).
    bool standardTimer(const Instruction &ins) const;
    static QString timerType(const Instruction &ins);
    std::optional<qint64> presetMs(const Instruction &ins) const;

    // A counter that an IEC counter does alike (plcopen_counters.h), with a constant set value,
    // a word's (where the word holds the number, not BCD digits) or the VPC's, kept in
    // setValues: its form, PV's expression in *pv; *why when the target's counter is none.
    std::optional<CounterForm> standardCounter(const Instruction &ins, QString *pv,
                                               QString *why = nullptr);

    bool standardMove(const Instruction &ins) const;

    void declare(const Address &a, const QString &type, bool instance, const QString &done = {});

    // A device as a contact or coil names it: a timer declared as TON is its output Q, a counter
    // its Q, QU or QD.
    QString variableOf(const Address &a);

    // An operand as an IEC expression: a device's name, a constant as a literal; with `value`,
    // a counter instance's present value, CV.
    QString expression(const Operand &o, bool value = false);

    // An RST of a counter written as CTU with R from its RSTs: a connector at the RST's place.
    bool counterReset(const Instruction &ins) const;

    // Every RST of a one-input counter, wired to the counter's R through a continuation.
    void wireResets();

    Elem &add(Elem::Kind kind, int x, int y);

    int inVariable(const QString &expression, int x, int y);

    void planRung(const Rung &rung, int *y0);

    static QString blockName(const InstructionSpec &spec);

    PlcopenExport write(const QString &name, const QDateTime &created);

    static void beginData(QXmlStreamWriter &xml, const char *what);
    static void endData(QXmlStreamWriter &xml);
    static void writeText(QXmlStreamWriter &xml, const char *element, const QString &text);

    void writeInterface(QXmlStreamWriter &xml);

    void writeProjectData(QXmlStreamWriter &xml);

    static void writePosition(QXmlStreamWriter &xml, const char *element, int x, int y);

    static void writeConnections(QXmlStreamWriter &xml, const std::vector<Conn> &conns, int relY);

    // The instruction list beside the ladder (docs/plcopen.md "The instruction list"), in the
    // POU's addData; empty when the ladder does not convert whole.
    void writeListing(QXmlStreamWriter &xml, QStringList *notes);

    void writeInstruction(QXmlStreamWriter &xml, const Elem &e);

    // An element's start tag with its localId and size (and a connector's name).
    static void startElement(QXmlStreamWriter &xml, const QString &tag, const Elem &e,
                             bool named = false);

    void writeElem(QXmlStreamWriter &xml, const Elem &e);

    const Project &m_p;
    const Target &m_t;
    std::vector<Elem> m_elems;
    std::map<Address, Variable> m_vars;
    std::vector<std::pair<QString, QString>> m_edgeInstances;
    std::set<QString> m_vendor;
    std::map<QString, QString> m_vendorWhy; // a vendor block's reason to be one
    std::set<QString> m_counterNotes;
    std::set<Address> m_resetByRst;               // counters whose R is their RSTs
    std::map<Address, std::vector<int>> m_resets; // their RSTs: connector element ids
    std::map<Address, std::vector<std::size_t>> m_counterBlocks; // their blocks: element indexes
    int m_nextId = 1;
    int m_edges = 0;
};

} // namespace rung::model::plcopen
