// The PL110's front panel (PL110 manual 1.2 "Descrizione generale e pannello frontale", 2.1.2
// SM100..SM185, 2.1.16 the display characters, 5 the PL110-2A's terminal).

#include "model/target/target_data.h"

namespace rung::model::detail {

void addPl110Panel(Target &t) {
    FrontPanel &p = t.panel;
    // 1.2: "Led verde RUN: Acceso fisso -> il PLC è in RUN ... Lampeggio lento - (0,5s on /0,5 s
    // off) il PL110 è usato come modulo di IN/OUT senza l'applicativo ladder caricato.
    // Lampeggio veloce - (0,2 s on /0,2 s off) ... solo il programma di boot". A simulation
    // stopped runs no ladder: the slow blink. The boot-only state does not arise.
    // "Led gialli COM1 ed EXP1: Acceso - alla trasmissione di ogni pacchetto di dati sulla
    // porta seriale corrispondente"; "Led giallo COM2: ... traffico dati in uscita": lit while
    // the port's transmitting marker (SM0.6, SM0.7, SM0.8) is.
    p.lamps = {
        {QStringLiteral("RUN"),
         LampColour::Green,
         LampSignal::Running,
         {},
         500,
         QT_TRANSLATE_NOOP("rung::model::Target",
                           "steady: the PLC is in RUN; slow blink (0.5 s on, 0.5 s off): no "
                           "ladder program runs")},
        {QStringLiteral("COM1"), LampColour::Yellow, LampSignal::Device, QStringLiteral("SM0.6"), 0,
         QT_TRANSLATE_NOOP("rung::model::Target", "lit while the port transmits a packet")},
        {QStringLiteral("EXP1"), LampColour::Yellow, LampSignal::Device, QStringLiteral("SM0.7"), 0,
         QT_TRANSLATE_NOOP("rung::model::Target", "lit while the port transmits a packet")},
        {QStringLiteral("COM2"), LampColour::Yellow, LampSignal::Device, QStringLiteral("SM0.8"), 0,
         QT_TRANSLATE_NOOP("rung::model::Target", "lit while the port transmits a packet")},
    };

    // 2.1.16: "Il display è organizzato in 8 righe, ciascuna da 21 caratteri" from DISP0;
    // 2.1.2: SM102 the system pages 1..5, SM103 the user pages 17..32, SM104 the start page,
    // SM105 the page shown, SM106 the page requested; 5.4: "fino a 16 pagine utente, a cui il
    // sistema assegna i numeri da 17 a 32".
    PanelDisplay &d = p.display;
    d.kind = DisplayKind::Text;
    d.charArea = QStringLiteral("DISP");
    d.rows = 8;
    d.columns = 21;
    d.systemPagesDevice = QStringLiteral("SM102");
    d.userPagesDevice = QStringLiteral("SM103");
    d.startPageDevice = QStringLiteral("SM104");
    d.pageShownDevice = QStringLiteral("SM105");
    d.pageRequestDevice = QStringLiteral("SM106");
    d.systemPages = 5;
    d.firstUserPage = 17;
    d.userPages = 16;
    // The manual gives no character set. It clears the area with "il carattere ascii 32
    // (spazio)" (2.1.16) and its user page of 5.4 shows "25.0°C": printable ASCII and the
    // Latin-1 characters from 160 (the degree sign is 176) are the product's choice.
    d.shownCodes = {{32, 126}, {160, 255}};
    // The four parameter fields: SM118..SM134, SM135..SM151, SM152..SM168, SM169..SM185.
    d.fields = {{QStringLiteral("SM118")},
                {QStringLiteral("SM135")},
                {QStringLiteral("SM152")},
                {QStringLiteral("SM169")}};
    // SM107's list (2.1.2): "se tramite il terminale si modifica la variabile VW30, si avrà
    // ... SM107 = 1". The list in the manual's order; the serial buffers (17..22) are not
    // shown as fields here.
    d.areaCodes = {
        {1, QStringLiteral("V")},          {2, QStringLiteral("SM")},
        {3, QStringLiteral("AI")},         {4, QStringLiteral("TR")},
        {5, QStringLiteral("AQ")},         {6, QStringLiteral("I")},
        {7, QStringLiteral("Q")},          {8, QStringLiteral("T")},
        {9, QStringLiteral("PT")},         {10, QStringLiteral("C")},
        {11, QStringLiteral("PV")},        {12, QStringLiteral("VD"), true},
        {13, QStringLiteral("SMD"), true}, {14, QStringLiteral("M")},
        {15, QStringLiteral("EEP")},       {16, QStringLiteral("MMC")},
        {23, QStringLiteral("DISP")},
    };

    // 2.1.2 SM110: "Bit0 Pulsante SWAP, Bit1 Pulsante UP, Bit2 Pulsante DOWN, Bit3 Pulsante SET".
    // 5.2: SWAP "permette di scorrere in modo circolare tutte le pagine" and, a field being
    // edited, "passare dalla modifica dei campi in modo incrementale alla modifica a cifre";
    // UP / DOWN change the value by one or by 1*10^n; SET "permette di abilitare la modifica
    // ai campi numerici ... con la pressione del tasto SET si passa alla modifica da un campo
    // all'altro", held "per circa 2 secondi ... si entra nella pagina di immissione della
    // password".
    p.keys = {
        {QStringLiteral("SWAP"), QStringLiteral("SM110.0"), QStringLiteral("S"),
         QT_TRANSLATE_NOOP("rung::model::Target",
                           "scrolls through the pages the program enables; while a value is "
                           "entered, switches between steps of one and editing digit by digit"),
         PanelKeyRole::Swap},
        {QStringLiteral("UP"), QStringLiteral("SM110.1"), QStringLiteral("Up"),
         QT_TRANSLATE_NOOP("rung::model::Target", "increments the field being edited"),
         PanelKeyRole::Up},
        {QStringLiteral("DOWN"), QStringLiteral("SM110.2"), QStringLiteral("Down"),
         QT_TRANSLATE_NOOP("rung::model::Target", "decrements the field being edited"),
         PanelKeyRole::Down},
        {QStringLiteral("SET"), QStringLiteral("SM110.3"), QStringLiteral("Return"),
         QT_TRANSLATE_NOOP("rung::model::Target",
                           "edits the page's fields in turn, storing each value; held for 2 s, "
                           "opens the password page"),
         PanelKeyRole::Set},
    };
    // 5.5: page 253 "A questa pagina si accede tenendo premuto per circa 2 secondi il tasto
    // SET"; 2.1.2 SM109: "per permettere la modifica dei campi input protetti da password è
    // necessario immettere la password utente 1234"; SM100 / SM101 the standby.
    d.passwordPage = 253;
    d.passwordDevice = QStringLiteral("SM109");
    // 2.1.2 SM107 / SM108: "se tramite il terminale si modifica la variabile VW30, si avrà, per
    // il solo ciclo di scansione successivo alla modifica, SM107 = 1 e SM108 = 30. Nel ciclo
    // successivo le due aree verranno automaticamente poste a 0."
    d.lastAreaDevice = QStringLiteral("SM107");
    d.lastNumberDevice = QStringLiteral("SM108");
    d.passwordDigits = 4;
    d.userPassword = 1234;
    d.passwordHoldMs = 2000;
    d.standbyBrightnessDevice = QStringLiteral("SM100");
    d.standbyDelayDevice = QStringLiteral("SM101");

    // The system pages 3..5 (5.3, "Descrizione pagine di sistema"). Page 3, system info: "la
    // versione del programma di BOOT e del Firmware, il nome dell'applicazione ladder caricata,
    // i protocolli associati alle porte seriali ed il numero dello slave ... Tale numero può
    // essere modificato solo previa immissione della password di sistema 1357" (also 2.1.2
    // SM109); the number is SMW4 (1.6.4: "INDIRIZZO MODULO = OFFSET INDIRIZZO (SMW4)", the
    // PL110-2A has no rotary switch), within the station numbers of the ports' MODBUS slave
    // (target_pl110_comm.cpp). The simulator has no BOOT or firmware version: a dash, no
    // number. The application's name and the ports' protocols are what the project or the
    // network station running the PLC says (model::PanelContext): the name on row 4 (the rows 2 and
    // 3 the versions'), cut at the row's end as the display would cut it (the whole name in the
    // page's note), then COM1, EXP1, COM2 a row each with the application its settings give it
    // (PortApplication::displayName, target_pl110_comm.cpp); the slave address below them.
    // Where nothing says them (no context), a dash. Page 4, "data ed ora dell'orologio
    // interno", SM9..SM15 (2.1.2) in their ranges. Page 5 as the manual's figure draws it
    // ("*** DISPLAY SETUP ***", "STANDBY BRIGHTNESS", "OFF %", "STANDBY DELAY", "2 min"):
    // SM100 in % ("default 0=OFF"), SM101 in minutes, every value of its word. The layout of
    // pages 3 and 4 is not in the manual: the values plainly, one to a row *(choice)*.
    d.systemTexts = {
        {3,
         {QStringLiteral("SYSTEM INFO"),
          QStringLiteral("BOOT") + QString(16, QLatin1Char(' ')) + QChar(0x2014),
          QStringLiteral("FIRMWARE") + QString(12, QLatin1Char(' ')) + QChar(0x2014), QString(),
          QString(), QString(), QString(), QStringLiteral("SLAVE ADDRESS:")},
         QT_TRANSLATE_NOOP("rung::model::PanelView",
                           "System info: the simulator has no BOOT or firmware version (shown "
                           "as a dash); the slave address is SMW4, changed with the keys after "
                           "the system password 1357")},
        {4,
         {QStringLiteral("DATE & TIME"), QString(), QStringLiteral("DATE           /  /"),
          QString(), QStringLiteral("TIME           :  :"), QString(),
          QStringLiteral("DAY OF WEEK")},
         QT_TRANSLATE_NOOP("rung::model::PanelView",
                           "Date and time: the simulator's clock does not count; SM9..SM15 keep "
                           "what the program or the keys write")},
        {5,
         {QStringLiteral("*** DISPLAY SETUP ***"), QString(), QStringLiteral("STANDBY BRIGHTNESS"),
          QStringLiteral("                    %"), QString(), QStringLiteral("STANDBY DELAY"),
          QStringLiteral("                  min")},
         nullptr},
    };
    d.contextPage = 3;
    d.applicationRow = 4;
    d.portsRow = 5;
    const auto number = [](int page, const char *device, int row, int column, int digits,
                           int lowest, int highest, int password = 0) {
        PanelSystemField f;
        f.page = page;
        f.device = QString::fromLatin1(device);
        f.row = row;
        f.column = column;
        f.digits = digits;
        f.editable = true;
        f.lowest = lowest;
        f.highest = highest;
        f.password = password;
        return f;
    };
    d.systemFields = {
        number(3, "SM4", 8, 19, 3, 1, 255, 1357),
        // DD/MM/YY, hh:mm:ss, the day of the week 0 (Sunday) .. 6.
        number(4, "SM12", 3, 14, 2, 1, 31),
        number(4, "SM13", 3, 17, 2, 1, 12),
        number(4, "SM14", 3, 20, 2, 0, 99),
        number(4, "SM11", 5, 14, 2, 0, 23),
        number(4, "SM10", 5, 17, 2, 0, 59),
        number(4, "SM9", 5, 20, 2, 0, 59),
        number(4, "SM15", 7, 21, 1, 0, 6),
        number(5, "SM100", 4, 17, 3, 0, 100),
        number(5, "SM101", 7, 13, 5, 0, 32767),
    };
    for (PanelSystemField &f : d.systemFields) {
        f.zeros = f.page == 4;
        if (f.device == QLatin1String("SM100"))
            f.zeroText = QStringLiteral("OFF");
    }

    // The defaults of 2.1.2's table: SM101 2 minutes, SM102 31 (every system page), SM104 page
    // 1, each field one digit at rows 2, 4, 6, 8, column 15.
    p.powerOn = {
        {QStringLiteral("SM101"), 2}, {QStringLiteral("SM102"), 31}, {QStringLiteral("SM104"), 1}};
    const int rows[] = {2, 4, 6, 8};
    for (int k = 0; k < 4; ++k) {
        const int first = 118 + 17 * k;
        p.powerOn.push_back({QStringLiteral("SM%1").arg(first + 11), 1});       // digits
        p.powerOn.push_back({QStringLiteral("SM%1").arg(first + 14), rows[k]}); // row
        p.powerOn.push_back({QStringLiteral("SM%1").arg(first + 15), 15});      // column
    }
}

} // namespace rung::model::detail
