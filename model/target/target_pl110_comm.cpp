#include "model/target/target_data.h"

#include <QCoreApplication>

#include <algorithm>

// The PL110's serial ports as its program drives them (PL110 manual, Italian: 2.1.2, 2.1.14,
// 2.1.15, 4.2.19 SEND and free-port, 4.2.21 COM / EXP): the ports and their protocols, the byte
// buffers of free-port and the three instructions. What they do: docs/network.md.

namespace rung::model::detail {

namespace {

using K = OperandKind;

constexpr int kPl110SerialBuffer = 256;

} // namespace

// The serial ports (1.3, 1.5.4, 3.1, 4.2.19, 4.2.21): COM1 (RS-485) and EXP1 answer MODBUS RTU
// or run a master protocol for COM / EXP; COM2 is the USB programming port, MODBUS RTU at
// 57600 8N1 only. Any port may be switched to free-port by the program (SM78 / SM88 / SM98),
// whatever its protocol. Of the master protocols, MODBUS RTU is the protocol of chapter 3,
// whose frames the product's codec writes; NAIS MATSUSHITA-MASTER (4.2.21) has no published
// frames, so a port set to it puts none on a wire (docs/network.md).
std::vector<PortSpec> pl110Ports() {
    // The baud codes of SM71 and SM78 (2.1.2): code k is bauds[k].
    const std::vector<int> codeBauds = {110,  150,  300,   600,   1200,  2400,
                                        4800, 9600, 19200, 28800, 38400, 57600};
    // The format codes of SM72 and SM78 (2.1.2).
    const std::vector<const char *> codeFormats = {"8N1", "8O1", "8E1", "7N1", "7O1", "7E1",
                                                   "8N2", "8O2", "8E2", "7N2", "7O2", "7E2"};
    std::vector<int> bauds = codeBauds; // 19200 first: the default of COM1 and EXP1
    std::rotate(bauds.begin(), bauds.begin() + 8, bauds.begin() + 9);
    PortApplication slave;
    slave.id = "modbus";
    slave.name = QT_TRANSLATE_NOOP("rung::model::Target", "MODBUS RTU slave");
    // On the display's system page 3 (5.3: "i protocolli associati alle porte seriali"), whose
    // words the manual does not give: the protocol and the port's part in it, in the display's
    // capitals, within a 21-column row beside the port's name (target_pl110_panel.cpp).
    slave.displayName = "MODBUS SLAVE";
    slave.bauds = bauds;
    slave.frame = "8N1";
    slave.stationMin = 1;
    slave.stationMax = 255;
    slave.station = 1;
    slave.answers = ProtocolId::Modbus;
    PortApplication master = slave;
    master.id = "modbus-master";
    master.name = QT_TRANSLATE_NOOP("rung::model::Target", "MODBUS RTU master (COM / EXP)");
    master.answers.reset();
    master.master = true;
    master.displayName = "MODBUS MASTER";
    // 4.2.21: "generalmente" RS-232 at 9600,8,O,1; the frames are not in the manual.
    PortApplication nais = master;
    nais.id = "nais-master";
    nais.name =
        QT_TRANSLATE_NOOP("rung::model::Target", "NAIS MATSUSHITA-MASTER (COM / EXP, no frames)");
    nais.bauds = {9600, 110, 150, 300, 600, 1200, 2400, 4800, 19200, 28800, 38400, 57600};
    nais.frame = "8O1";
    nais.displayName = "NAIS MASTER";
    nais.published = false;
    auto markers = [&](const char *status, const char *timeout, const char *gap, const char *limit,
                       const char *timeouts, const char *errors, const char *freePort,
                       const char *received, const char *sending, const char *transmit,
                       const char *receive) {
        PortMarkers m;
        m.status = status;
        m.replyTimeout = timeout;
        m.requestGap = gap;
        m.errorLimit = limit;
        m.timeouts = timeouts;
        m.errors = errors;
        m.freePort = freePort;
        m.received = received;
        m.sending = sending;
        m.transmit = transmit;
        m.receive = receive;
        m.bauds = codeBauds;
        m.formats = codeFormats;
        return m;
    };
    PortSpec com1;
    com1.name = QStringLiteral("COM1");
    com1.description = QT_TRANSLATE_NOOP("rung::model::Target", "COM1, the RS-485 port");
    com1.applications = {slave, master, nais};
    com1.markers = markers("SM70", "SM73", "SM74", "SM75", "SM76", "SM77", "SM78", "SM79", "SM0.6",
                           "COM1_TX0", "COM1_RX0");
    PortSpec exp1 = com1;
    exp1.name = QStringLiteral("EXP1");
    exp1.description = QT_TRANSLATE_NOOP("rung::model::Target", "EXP1, the expansion port");
    exp1.markers = markers("SM80", "SM83", "SM84", "SM85", "SM86", "SM87", "SM88", "SM89", "SM0.7",
                           "EXP1_TX0", "EXP1_RX0");
    PortSpec com2;
    com2.name = QStringLiteral("COM2");
    com2.description =
        QT_TRANSLATE_NOOP("rung::model::Target", "COM2, the USB programming port (57600 8N1)");
    PortApplication usb = slave;
    usb.bauds = {57600};
    usb.fixedFrame = true;
    com2.applications = {usb};
    // SM93..SM97 describe a COM2 master too, but no instruction serves COM2 (4.2.21): only
    // its free-port markers mean something here.
    com2.markers = markers("SM90", "SM93", "SM94", "SM95", "SM96", "SM97", "SM98", "SM99", "SM0.8",
                           "COM2_TX0", "COM2_RX0");
    com2.markers.replyTimeoutMs = 0;
    return {com1, exp1, com2};
}

void addPl110SerialBuffers(Target &t) {
    // The serial buffers of free-port (2.1.14, 2.1.15): "organizzate a byte", spelled as 2.1's
    // table writes them (COM1_TX, EXP1_RX). The manual gives no size: 256 bytes each, a whole
    // MODBUS RTU frame, is the product's choice (docs/targets.md).
    const std::pair<const char *, const char *> buffers[] = {
        {"COM1_TX", QT_TRANSLATE_NOOP("rung::model::Target", "COM1 transmit buffer (bytes)")},
        {"COM1_RX", QT_TRANSLATE_NOOP("rung::model::Target", "COM1 receive buffer (bytes)")},
        {"EXP1_TX", QT_TRANSLATE_NOOP("rung::model::Target", "EXP1 transmit buffer (bytes)")},
        {"EXP1_RX", QT_TRANSLATE_NOOP("rung::model::Target", "EXP1 receive buffer (bytes)")},
        {"COM2_TX", QT_TRANSLATE_NOOP("rung::model::Target", "COM2 transmit buffer (bytes)")},
        {"COM2_RX", QT_TRANSLATE_NOOP("rung::model::Target", "COM2 receive buffer (bytes)")},
    };
    for (const auto &[name, description] : buffers)
        addArea(t, name, name, AreaKind::Word, 0, kPl110SerialBuffer - 1, description).wordBits = 8;
}

void addPl110Communication(Target &t) {
    auto addBox = [&t](const char *mnemonic, ApplyFunction function,
                       std::vector<OperandSpec> operands, const char *summary,
                       const char *help) -> InstructionSpec & {
        InstructionSpec &s = addSpec(t, mnemonic, Op::Apply, std::move(operands), summary, help);
        s.function = function;
        return s;
    };
    // SEND port n (4.2.19): "ha come parametri la porta seriale e il numero di caratteri da
    // trasmettere". The port is written as the manual names it; n is a constant or a word,
    // 1..256, the transmit buffer's size (the product's choice).
    OperandSpec port{K::Constant};
    port.allowedTexts = {"COM1", "EXP1", "COM2"};
    port.name = QT_TRANSLATE_NOOP("rung::model::Target", "serial port");
    OperandSpec characters{K::WordSource};
    characters.lowest = 1;
    characters.highest = kPl110SerialBuffer;
    characters.wholeWords = true;
    characters.name = QT_TRANSLATE_NOOP("rung::model::Target", "number of characters");
    InstructionSpec &send = addBox(
        "SEND", ApplyFunction::FreePortSend, {port, characters},
        QT_TRANSLATE_NOOP("rung::model::Target",
                          "Send n characters of the port's transmit buffer (free-port mode)"),
        "COM1|EXP1|COM2 n");
    send.portOperand = 0;

    // COM / EXP index operation slave type number area count (4.2.21): the fields of PLProg's
    // dialog in its order ("Numero bobina", "Azione e indirizzo slave", "Indirizzo Word\Bit",
    // "Area", "Numero Word/Bit letti/scritti consecutivi"); its limits 0..255, 0..65535, 0..16
    // are the slave, the data number and the count, and the index is COM_1..COM_16.
    OperandSpec index{K::Constant};
    index.lowest = 1;
    index.highest = 16;
    index.name = QT_TRANSLATE_NOOP("rung::model::Target", "index");
    OperandSpec operation{K::Constant};
    operation.allowedTexts = {"READ", "WRITE", "READWRITE"};
    operation.name = QT_TRANSLATE_NOOP("rung::model::Target", "operation");
    OperandSpec slave{K::Constant};
    slave.lowest = 0;
    slave.highest = 255;
    slave.name = QT_TRANSLATE_NOOP("rung::model::Target", "slave");
    OperandSpec type{K::Constant};
    type.allowedTexts = {"WORD", "BIT"};
    type.name = QT_TRANSLATE_NOOP("rung::model::Target", "data type");
    OperandSpec number{K::Constant};
    number.lowest = 0;
    number.highest = 65535;
    number.name = QT_TRANSLATE_NOOP("rung::model::Target", "data number");
    OperandSpec area{K::WordSource};
    area.deviceOnly = true;
    area.wholeWords = true;
    area.name = QT_TRANSLATE_NOOP("rung::model::Target", "PL110 area");
    OperandSpec count{K::Constant};
    count.lowest = 1;
    count.highest = 16;
    count.name = QT_TRANSLATE_NOOP("rung::model::Target", "number of words or bits");
    const char *help = "1..16 READ|WRITE|READWRITE SLAVE WORD|BIT NUMBER AREA COUNT";
    InstructionSpec &com = addBox(
        "COM", ApplyFunction::MasterQuery, {index, operation, slave, type, number, area, count},
        QT_TRANSLATE_NOOP("rung::model::Target",
                          "COM1 master query COM_1..COM_16: read or write a slave's words or bits "
                          "while ON"),
        help);
    com.port = "COM1";
    com.portApplications = {"modbus-master", "nais-master"};
    InstructionSpec &exp = addBox(
        "EXP", ApplyFunction::MasterQuery, {index, operation, slave, type, number, area, count},
        QT_TRANSLATE_NOOP("rung::model::Target",
                          "EXP1 master query EXP_1..EXP_16: read or write a slave's words or bits "
                          "while ON"),
        help);
    exp.port = "EXP1";
    exp.portApplications = {"modbus-master", "nais-master"};
}

} // namespace rung::model::detail
