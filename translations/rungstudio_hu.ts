<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="hu">
<context>
    <name>QsciScintilla</name>
    <message>
        <location filename="../editor/qscintilla_tr.h" line="+11"/>
        <source>&amp;Undo</source>
        <translation>&amp;Visszavonás</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>&amp;Redo</source>
        <translation>&amp;Mégis</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cu&amp;t</source>
        <translation>&amp;Kivágás</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>&amp;Copy</source>
        <translation>&amp;Másolás</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Paste</source>
        <translation>&amp;Beillesztés</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Delete</source>
        <translation>Törlés</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Select All</source>
        <translation>Az összes kijelölése</translation>
    </message>
</context>
<context>
    <name>rung::app::AboutDialog</name>
    <message>
        <location filename="../app/gui/about_dialog.cpp" line="+51"/>
        <source>About Rung Studio</source>
        <translation>A Rung Studio névjegye</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Ladder and instruction-list editor for %1.</source>
        <translation>Létradiagram- és utasításlista-szerkesztő a következő PLC-khez: %1.</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>User guide</source>
        <translation>Felhasználói kézikönyv</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The user guide is not installed beside the program.</source>
        <translation>A felhasználói kézikönyv nincs telepítve a program mellé.</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>GNU GPL, version 3 or later</source>
        <translation>GNU GPL, 3. vagy későbbi változat</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>GNU LGPL, version 3</source>
        <translation>GNU LGPL, 3. változat</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>GNU GPL, version 3</source>
        <translation>GNU GPL, 3. változat</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>GNU LGPL, version 3 or later</source>
        <translation>GNU LGPL, 3. vagy későbbi változat</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Built with:</source>
        <translation>Felhasznált összetevők:</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Copyright and licences</source>
        <translation>Szerzői jog és licencek</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>About &amp;Qt</source>
        <translation>A &amp;Qt névjegye</translation>
    </message>
</context>
<context>
    <name>rung::app::BreakpointDialog</name>
    <message>
        <location filename="../app/gui/breakpoint_dialog.cpp" line="+41"/>
        <source>Breakpoint Condition</source>
        <translation>Töréspont feltétele</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Always</source>
        <translation>Mindig</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>When the bit rises</source>
        <translation>Amikor a bit felfut</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>When the bit falls</source>
        <translation>Amikor a bit lefut</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>While the bit is ON</source>
        <translation>Amíg a bit BE</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>While the bit is OFF</source>
        <translation>Amíg a bit KI</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>When the word compares</source>
        <translation>Amikor a szó összehasonlítása teljesül</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Stop</source>
        <translation>&amp;Megállás</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>a device, e.g. %1 or %2</source>
        <translation>operandus, pl. %1 vagy %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Device</source>
        <translation>&amp;Operandus</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>&amp;Compare</source>
        <translation>Össze&amp;hasonlítás</translation>
    </message>
    <message>
        <location line="+40"/>
        <source>Type the device the condition watches</source>
        <translation>Írja be a feltétel által figyelt operandust</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 is no device of this PLC: %2</source>
        <translation>%1 nem operandusa ennek a PLC-nek: %2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 is a bit: compare a word (D, a timer&apos;s or counter&apos;s value)</source>
        <translation>%1 egy bit: szót hasonlítson össze (D, időzítő vagy számláló értéke)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 is a word: watch a bit, or compare the word</source>
        <translation>%1 egy szó: bitet figyeljen, vagy hasonlítsa össze a szót</translation>
    </message>
</context>
<context>
    <name>rung::app::Cli</name>
    <message>
        <location filename="../app/cli/cli.cpp" line="+61"/>
        <location line="+48"/>
        <location filename="../app/cli/cli_network.cpp" line="+147"/>
        <source>unexpected argument %1</source>
        <translation>váratlan argumentum: %1</translation>
    </message>
    <message>
        <location line="-78"/>
        <source>usage:
  rungstudio-cli check FILE [--target %1] [--model M]
  rungstudio-cli convert FILE [--target T] [--model M] [--from il|ladder|project|plcopen] --to il|ladder|project|plcopen [-o OUT] [--force] [--map FILE]
  rungstudio-cli simulate FILE [--target T] [--model M] --scans N [--period MS] [--set DEV=VALUE@SCAN]... --trace DEV[,DEV...]
  rungstudio-cli serve FILE [--target T] [--model M] --protocol vigor|modbus|modbus-tcp|hostlink (--pty | --port NAME | --tcp HOST:PORT) [--station N] [--baud B] [--frame 8N1] [--period MS] [--fault KIND]
FILE is a listing (.il), a ladder text (.ladder) or a project (.rung).
--lang en|hu|it: the language of the messages (else the locale&apos;s, LANG).
Exit status: 0 no error, 1 the program has errors, 2 usage or I/O error.</source>
        <translation>használat:
  rungstudio-cli check FILE [--target %1] [--model M]
  rungstudio-cli convert FILE [--target T] [--model M] [--from il|ladder|project|plcopen] --to il|ladder|project|plcopen [-o OUT] [--force] [--map FILE]
  rungstudio-cli simulate FILE [--target T] [--model M] --scans N [--period MS] [--set DEV=VALUE@SCAN]... --trace DEV[,DEV...]
  rungstudio-cli serve FILE [--target T] [--model M] --protocol vigor|modbus|modbus-tcp|hostlink (--pty | --port NAME | --tcp HOST:PORT) [--station N] [--baud B] [--frame 8N1] [--period MS] [--fault KIND]
A FILE utasításlista (.il), létra-szöveg (.ladder) vagy projekt (.rung).
--lang en|hu|it: az üzenetek nyelve (különben a területi beállításé, LANG).
Kilépési kód: 0 nincs hiba, 1 a programban hiba van, 2 használati vagy I/O hiba.</translation>
    </message>
    <message>
        <location line="+111"/>
        <source>nothing written: the list as typed would be lost</source>
        <translation>semmi sem íródott ki: a begépelt lista elveszne</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>nothing written: the listing would leave out the contacts above</source>
        <translation>semmi sem íródott ki: az utasításlistából kimaradnának a fenti érintkezők</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>nothing written: the input does not parse or convert whole</source>
        <translation>nem íródott semmi: a bemenet nem értelmezhető vagy nem alakítható át teljesen</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>nothing written: the input has errors (--force writes it anyway)</source>
        <translation>nem íródott semmi: a bemenet hibás (a --force így is kiírja)</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>cannot write %1: %2</source>
        <translation>%1 nem írható: %2</translation>
    </message>
    <message>
        <location line="+49"/>
        <source>no command given</source>
        <translation>nincs megadva parancs</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unknown command %1</source>
        <translation>ismeretlen parancs: %1</translation>
    </message>
    <message>
        <location filename="../app/cli/cli_common.cpp" line="+98"/>
        <source>%1 needs a value</source>
        <translation>%1 után érték kell</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>no FILE given</source>
        <translation>nincs megadva FILE</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>--from must be il, ladder or project, not %1</source>
        <translation>a --from értéke il, ladder vagy project lehet, nem %1</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1: which PLC? Give --target %2 or a &quot;; target: NAME&quot; first line</source>
        <translation>%1: melyik PLC? Adja meg: --target %2, vagy egy &quot;; target: NAME&quot; első sort</translation>
    </message>
    <message>
        <location line="+74"/>
        <source>%1:rung %2:%3:%4</source>
        <extracomment>A finding&apos;s place on the ladder, after the file as a compiler writes file:line:column: %1 the file, %2 the rung&apos;s number, %3 the row, %4 the column. Keep the colons.</extracomment>
        <translation>%1:létrafok %2:%3:%4</translation>
    </message>
    <message>
        <location line="-154"/>
        <source>%1 holds an instruction list typed in Rung Studio that is not in its program: the list had errors when the project was saved, and is kept as typed under the key &quot;pendingListing&quot;; the rungs are the last valid program. Open the project in Rung Studio and fix the list.</source>
        <translation>A(z) %1 egy Rung Studióban begépelt utasításlistát tartalmaz, amely nincs benne a programjában: a lista hibás volt a projekt mentésekor, és begépelt formájában a „pendingListing” kulcs alatt maradt meg; a létrafokok az utolsó érvényes programot tartalmazzák. Nyissa meg a projektet a Rung Studióban, és javítsa ki a listát.</translation>
    </message>
    <message>
        <location line="+97"/>
        <location line="+27"/>
        <location filename="../app/cli/cli_plcopen.cpp" line="+28"/>
        <source>%1 has no model %2</source>
        <translation>a(z) %1 rendszernek nincs %2 modellje</translation>
    </message>
    <message>
        <location line="+18"/>
        <location filename="../app/cli/cli_network.cpp" line="+52"/>
        <location filename="../app/cli/cli_plcopen.cpp" line="+36"/>
        <location line="+3"/>
        <source>error</source>
        <translation>hiba</translation>
    </message>
    <message>
        <location line="+1"/>
        <location filename="../app/cli/cli_network.cpp" line="+0"/>
        <source>warning</source>
        <translation>figyelmeztetés</translation>
    </message>
    <message>
        <location line="+1"/>
        <location filename="../app/cli/cli_plcopen.cpp" line="-8"/>
        <location line="+58"/>
        <source>note</source>
        <translation>megjegyzés</translation>
    </message>
    <message>
        <location filename="../app/cli/cli_language.cpp" line="+25"/>
        <source>--lang must be one of %1</source>
        <translation>a --lang értéke csak ezek egyike lehet: %1</translation>
    </message>
    <message>
        <location filename="../app/cli/cli.cpp" line="-138"/>
        <source>--to must be il, ladder, project or plcopen</source>
        <translation>a --to értéke il, ladder, project vagy plcopen lehet</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>--map is for --from plcopen</source>
        <translation>a --map a --from plcopen mellé való</translation>
    </message>
    <message>
        <location filename="../app/cli/cli_plcopen.cpp" line="-101"/>
        <source>--from plcopen needs --target: which PLC the program is for</source>
        <translation>a --from plcopen mellé --target kell: melyik PLC-hez készül a program</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>unknown target %1</source>
        <translation>ismeretlen célrendszer: %1</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>%1: note: the file was written by Rung Studio for %2; it is read for %3</source>
        <translation>%1: megjegyzés: a fájlt a Rung Studio %2 PLC-hez írta; %3 PLC-hez olvassuk be</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>variable %1 (%2) names no device of %3, and none is free for it</source>
        <translation>a(z) %1 (%2) változó nem a(z) %3 PLC operandusa, és nincs szabad operandus hozzá</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>variable %1 (%2) names no device of %3; proposed: %4</source>
        <translation>a(z) %1 (%2) változó nem a(z) %3 PLC operandusa; javasolt: %4</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>A mapping file with the devices proposed (check them, then give it with --map FILE):</source>
        <translation>Hozzárendelő fájl a javasolt operandusokkal (ellenőrizze, majd adja meg: --map FÁJL):</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>nothing written: the file holds no ladder to import</source>
        <translation>nem íródott semmi: a fájlban nincs beolvasható létradiagram</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>nothing written: the file holds what %1 cannot take, listed above (--force writes the rest)</source>
        <translation>nem íródott semmi: a fájlban olyasmi van, amit a(z) %1 nem tud fogadni, fent felsorolva (a --force a többit kiírja)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>written without what is listed above (--force)</source>
        <translation>kiírva a fent felsoroltak nélkül (--force)</translation>
    </message>
</context>
<context>
    <name>rung::app::CompareWindow</name>
    <message>
        <location filename="../app/gui/compare_window.cpp" line="+46"/>
        <source>%1 is a program for %2; the open program is for %3: only programs of one PLC are compared</source>
        <translation>%1 program a(z) %2 PLC-hez, a megnyitott program a(z) %3 PLC-hez készült: csak azonos PLC programjai hasonlíthatók össze</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>%1, line %2, column %3: %4; a file that does not read whole is not compared</source>
        <translation>%1, %2. sor, %3. oszlop: %4; a nem teljesen beolvasható fájl nem hasonlítható össze</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>Compare With</source>
        <translation>Összehasonlítás</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Rung Studio projects (*.rung);;Instruction lists (*.il *.txt);;Ladder texts (*.ladder)</source>
        <translation>Rung Studio projektek (*.rung);;Utasításlisták (*.il *.txt);;Létra-szövegek (*.ladder)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Cannot compare</source>
        <translation>Az összehasonlítás nem sikerült</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Compare: %1 and %2</source>
        <translation>Összehasonlítás: %1 és %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>A (left): %1        B (right): %2</source>
        <translation>A (bal): %1        B (jobb): %2</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Ladder</source>
        <translation>Létradiagram</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Change</source>
        <translation>Változás</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>A: %1</source>
        <translation>A: %1</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>B: %1</source>
        <translation>B: %1</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Instruction List</source>
        <translation>Utasításlista</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Report</source>
        <translation>Jelentés</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&amp;Previous Change</source>
        <translation>&amp;Előző változás</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Next Change</source>
        <translation>&amp;Következő változás</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>P&amp;rint...</source>
        <translation>&amp;Nyomtatás...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Previous change (Alt+Up)</source>
        <translation>Előző változás (Alt+Fel)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Next change (Alt+Down)</source>
        <translation>Következő változás (Alt+Le)</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>The programs are the same.</source>
        <translation>A programok azonosak.</translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>%n rung(s) differ.</source>
        <translation>
            <numerusform>%n létrafok eltér.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+7"/>
        <source>%n difference(s) besides the rungs (symbols, set values, watch lists): see the Report.</source>
        <translation>
            <numerusform>%n eltérés a létrafokokon kívül (szimbólumok, beállított értékek, figyelőlisták): lásd a Jelentést.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Alt+Down: next change, Alt+Up: previous.</source>
        <translation>Alt+Le: következő változás, Alt+Fel: előző.</translation>
    </message>
    <message>
        <location line="+18"/>
        <location line="+1"/>
        <source>rung %1</source>
        <translation>%1. létrafok</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>~ changed</source>
        <translation>~ módosítva</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>+ only in B</source>
        <translation>+ csak B-ben</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>- only in A</source>
        <translation>- csak A-ban</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>No change before this one.</source>
        <translation>Ez előtt nincs változás.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>No change after this one.</source>
        <translation>Ez után nincs változás.</translation>
    </message>
</context>
<context>
    <name>rung::app::ConnectionPanel</name>
    <message>
        <location filename="../app/gui/connection_panel_link.cpp" line="+50"/>
        <source>ON</source>
        <translation>BE</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>OFF</source>
        <translation>KI</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Set %1 %2</source>
        <translation>%1 beállítása: %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Write %1 = %2</source>
        <translation>%1 írása: %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Write the preset of %1 = %2</source>
        <translation>%1 beállított értékének írása: %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Force %1 %2</source>
        <translation>%1 kényszerítése: %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Release the force on %1</source>
        <translation>%1 kényszerítésének feloldása</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Release every force</source>
        <translation>Minden kényszerítés feloldása</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>Cancelled: nothing was sent to the PLC</source>
        <translation>Megszakítva: semmi sem lett elküldve a PLC-nek</translation>
    </message>
    <message>
        <location filename="../app/gui/connection_panel.cpp" line="+209"/>
        <source>Settings</source>
        <translation>Beállítások</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Protocol:</source>
        <translation>Protokoll:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Serial port</source>
        <translation>Soros port</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>TCP</source>
        <translation>TCP</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Station:</source>
        <translation>Állomás:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Timeout (ms):</source>
        <translation>Időtúllépés (ms):</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Retries:</source>
        <translation>Ismétlések:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Test Connection</source>
        <translation>Kapcsolat tesztelése</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Traffic</source>
        <translation>Adatforgalom</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Record</source>
        <translation>Rögzítés</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Clear</source>
        <translation>Törlés</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save...</source>
        <translation>Mentés...</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>PLC: %1</source>
        <translation>PLC: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PLC: %1, model %2</source>
        <translation>PLC: %1, modell: %2</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The link protocol of the %1 is not published, so the IDE cannot talk to it. Instead: export the program as a console listing (File &gt; Export Instruction List) and load it with the PLC&apos;s own tool; to study the link, capture its traffic with &apos;rungstudio-cli record&apos;.</source>
        <translation>A(z) %1 kommunikációs protokollja nem nyilvános, ezért az IDE nem tud vele kapcsolatot teremteni. Helyette: exportálja a programot konzollistaként (Fájl &gt; Utasításlista exportálása), és töltse be a PLC saját eszközével; a kapcsolat tanulmányozásához rögzítse az adatforgalmát a &apos;rungstudio-cli record&apos; paranccsal.</translation>
    </message>
    <message>
        <location filename="../app/gui/connection_panel_link.cpp" line="+23"/>
        <source>Change the PLC&apos;s Memory</source>
        <translation>A PLC memóriájának módosítása</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 on %2?

This changes the memory of a real PLC, which may be driving a machine. You are asked once for each connection; later changes go at once.</source>
        <translation>%1 ezen: %2?

Ez egy valódi PLC memóriáját módosítja, amely gépet vezérelhet. Kapcsolatonként egyszer kérdezünk; a további módosítások azonnal mennek.</translation>
    </message>
    <message>
        <location line="+115"/>
        <source>Choose the serial port the PLC is on (or type its path)</source>
        <translation>Válassza ki a soros portot, amelyen a PLC van (vagy írja be az elérési útját)</translation>
    </message>
    <message>
        <location line="-69"/>
        <source>%1: done, the PLC acknowledged it</source>
        <translation>%1: kész, a PLC nyugtázta</translation>
    </message>
    <message>
        <location line="-3"/>
        <source>A command</source>
        <translation>Egy parancs</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: not done: %2</source>
        <translation>%1: nem történt meg: %2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>These PLCs cannot send their program back, so the IDE cannot know whether the PLC runs the program shown here. Compare by reading devices: watch them in the ladder or the watch table.</source>
        <translation>Ezek a PLC-k nem tudják visszaküldeni a programjukat, ezért az IDE nem tudhatja, hogy a PLC az itt látható programot futtatja-e. Hasonlítsa össze operandusok olvasásával: figyelje őket a létradiagramon vagy a figyelőtáblában.</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>Switch to %1</source>
        <translation>Átváltás %1 módba</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>The PLC runs its program: its outputs switch as the program says.</source>
        <translation>A PLC futtatja a programját: a kimenetei a program szerint kapcsolnak.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The PLC runs its program and takes writes from the IDE.</source>
        <translation>A PLC futtatja a programját, és fogadja az IDE írásait.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The PLC stops running its program.</source>
        <translation>A PLC leállítja a programja futtatását.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>PLC Mode</source>
        <translation>PLC üzemmód</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Switch %1 to %2?

%3</source>
        <translation>%1 átváltása %2 módba?

%3</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Type the host name or IP address of the PLC or its gateway</source>
        <translation>Írja be a PLC vagy az átjárója gépnevét vagy IP-címét</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Already connected: the panel shows what the PLC reports</source>
        <translation>Már csatlakozva: a panel mutatja, amit a PLC jelent</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A test is under way</source>
        <translation>Egy teszt folyamatban van</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Testing %1...</source>
        <translation>%1 tesztelése...</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>The PLC answers (this protocol does not report the model)</source>
        <translation>A PLC válaszol (ez a protokoll nem jelenti a modellt)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The PLC answers: %1</source>
        <translation>A PLC válaszol: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>, version %1</source>
        <translation>, verzió: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>; mode %1</source>
        <translation>; üzemmód: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>; round trip %1 ms</source>
        <translation>; válaszidő: %1 ms</translation>
    </message>
    <message>
        <location line="+6"/>
        <location line="+11"/>
        <source>No answer: %1</source>
        <translation>Nincs válasz: %1</translation>
    </message>
    <message>
        <location line="-1"/>
        <source>No answer from the PLC</source>
        <translation>A PLC nem válaszol</translation>
    </message>
    <message>
        <location line="+40"/>
        <location line="+4"/>
        <source>Offline</source>
        <translation>Offline</translation>
    </message>
    <message>
        <location line="-4"/>
        <source>Offline: no link to this PLC</source>
        <translation>Offline: ehhez a PLC-hez nincs kapcsolat</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Connecting to %1...</source>
        <translation>Kapcsolódás ehhez: %1...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Connecting to %1: %2</source>
        <translation>Kapcsolódás ehhez: %1: %2</translation>
    </message>
    <message>
        <location line="-23"/>
        <source>Online: %1</source>
        <translation>Online: %1</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>%1
The values shown are the last read, marked stale.</source>
        <translation>%1
A látható értékek az utoljára olvasottak, elavultként jelölve.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Cannot connect: %1</source>
        <translation>Nem lehet kapcsolódni: %1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Disconnect</source>
        <translation>Bontás</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Connect</source>
        <translation>Kapcsolódás</translation>
    </message>
    <message>
        <location line="+42"/>
        <source>Errors %1, retries %2, timeouts %3, refused %4, reconnects %5
Round trip %6 ms (mean %7, max %8); refresh %9 ms, %10 frame(s)</source>
        <translation>Hibák: %1, ismétlések: %2, időtúllépések: %3, elutasítva: %4, újracsatlakozások: %5
Válaszidő: %6 ms (átlag %7, max. %8); frissítés: %9 ms, %10 keret</translation>
    </message>
    <message>
        <location line="+65"/>
        <source>PC&gt;PLC</source>
        <extracomment>the direction of bytes in the traffic log: from the PC to the PLC, and back</extracomment>
        <translation>PC&gt;PLC</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PLC&gt;PC</source>
        <translation>PLC&gt;PC</translation>
    </message>
    <message>
        <location line="+11"/>
        <location line="+6"/>
        <source>Cannot write %1: %2</source>
        <translation>%1 nem írható: %2</translation>
    </message>
    <message>
        <location filename="../app/gui/connection_panel.cpp" line="-39"/>
        <source>A serial port, or a path typed in: a pseudo-terminal such as the one
&apos;rungstudio-cli serve --pty&apos; prints, or the link that
&apos;serve --pty --link PATH&apos; keeps at PATH, which still leads to the
PLC after serve restarts</source>
        <translation>Soros port, vagy beírt elérési út: egy pszeudoterminál, például az, amelyet a
&apos;rungstudio-cli serve --pty&apos; kiír, vagy a hivatkozás, amelyet a
&apos;serve --pty --link ÚTVONAL&apos; az ÚTVONAL helyén tart, és amely a serve
újraindítása után is a PLC-hez vezet</translation>
    </message>
</context>
<context>
    <name>rung::app::DebugController</name>
    <message>
        <location filename="../app/gui/debug_controller.cpp" line="+43"/>
        <location line="+169"/>
        <source>Simulation</source>
        <translation>Szimuláció</translation>
    </message>
    <message>
        <location line="-160"/>
        <location line="+161"/>
        <source>Scan Debugger</source>
        <translation>Ciklushibakereső</translation>
    </message>
    <message>
        <location line="-98"/>
        <source>Online Edit</source>
        <translation>Online szerkesztés</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Apply Keeping the Memory</source>
        <translation>Alkalmazás a memória megtartásával</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Restart from Power-On</source>
        <translation>Újraindítás a bekapcsolási állapotból</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stop the Simulation</source>
        <translation>A szimuláció leállítása</translation>
    </message>
    <message>
        <location line="+66"/>
        <source>Breakpoint set at %1</source>
        <translation>Töréspont beállítva: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Breakpoint at %1 removed</source>
        <translation>Töréspont eltávolítva: %1</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Stop before line %1: %2</source>
        <extracomment>where the breakpoint is: %1 line, %2 the instruction</extracomment>
        <translation>Megállás a(z) %1. sor előtt: %2</translation>
    </message>
</context>
<context>
    <name>rung::app::DebugEntries</name>
    <message>
        <location filename="../app/gui/debug_entries.cpp" line="+17"/>
        <source>S&amp;tep Instruction</source>
        <translation>Lé&amp;pés egy utasítással</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>F&amp;inish Scan</source>
        <translation>Ciklus &amp;befejezése</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Toggle &amp;Breakpoint</source>
        <translation>&amp;Töréspont be/ki</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Breakpoint Co&amp;ndition...</source>
        <translation>Tö&amp;réspont feltétele...</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Remove All Brea&amp;kpoints</source>
        <translation>Minden töréspont eltá&amp;volítása</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Return to &amp;Live</source>
        <translation>Vissza az élő állapot&amp;hoz</translation>
    </message>
</context>
<context>
    <name>rung::app::DebugMarks</name>
    <message>
        <location filename="../app/gui/debug_marks.cpp" line="+35"/>
        <source>line %1</source>
        <translation>%1. sor</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>rung %1</source>
        <translation>%1. létrafok</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>No instruction on line %1 to stop at</source>
        <translation>A(z) %1. sorban nincs utasítás, amelynél meg lehetne állni</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Rung %1 is not in the instruction list: no breakpoint there</source>
        <translation>A(z) %1. létrafok nincs az utasításlistában: ott nem lehet töréspont</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>No instruction at %1 to stop at</source>
        <translation>Itt (%1) nincs utasítás, amelynél meg lehetne állni</translation>
    </message>
</context>
<context>
    <name>rung::app::Diff</name>
    <message>
        <location filename="../app/cli/cli_diff.cpp" line="+59"/>
        <source>%1 does not read whole, so it is not compared</source>
        <translation>%1 nem olvasható be teljesen, ezért nincs összehasonlítva</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>  rungstudio-cli diff A B [--target T] [--model M] [--from il|ladder|project] [--format text|json]
        (exit 0 the same, 1 different, 2 error)</source>
        <translation>  rungstudio-cli diff A B [--target T] [--model M] [--from il|ladder|project] [--format text|json]
        (kilépési kód 0 azonos, 1 eltérő, 2 hiba)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>  rungstudio-cli show FILE   (a project as text to read and diff: git&apos;s textconv)</source>
        <translation>  rungstudio-cli show FILE   (a projekt szövegként, olvasáshoz és összehasonlításhoz: a git textconv-ja)</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1 needs a value</source>
        <translation>%1 után érték kell</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>unknown option %1</source>
        <translation>ismeretlen kapcsoló: %1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>diff takes two files, A and B</source>
        <translation>a diff két fájlt vár, A-t és B-t</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>--format must be text or json, not %1</source>
        <translation>a --format értéke text vagy json lehet, nem %1</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>diff needs at least one file that is not /dev/null</source>
        <translation>a diff legalább egy olyan fájlt vár, amely nem /dev/null</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1 is a program for %2 and %3 one for %4: only programs of one PLC are compared</source>
        <translation>%1 program %2 PLC-hez, %3 pedig %4 PLC-hez: csak azonos PLC programjai hasonlíthatók össze</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>usage:</source>
        <translation>használat:</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>not read as a project: %1</source>
        <translation>nem olvasható projektként: %1</translation>
    </message>
</context>
<context>
    <name>rung::app::ExampleTitles</name>
    <message>
        <location filename="../app/gui/example_titles.cpp" line="+21"/>
        <source>Add once a second</source>
        <translation>Összeadás másodpercenként</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Timers counting down and up</source>
        <translation>Lefelé és felfelé számoló időzítők</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Parts counter and reject tracking</source>
        <translation>Darabszámláló és selejtkövetés</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stairway light</source>
        <translation>Lépcsőházi világítás</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Setpoints on the display, set with the keys</source>
        <translation>Alapjelek a kijelzőn, a gombokkal beállítva</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Extending a counter&apos;s range</source>
        <translation>Számlálási tartomány bővítése</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Off delay</source>
        <translation>Kikapcsolási késleltetés</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Flasher</source>
        <translation>Villogó</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Latch, START has priority</source>
        <translation>Öntartás, a START az erősebb</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Latch, STOP has priority</source>
        <translation>Öntartás, a STOP az erősebb</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Traffic light</source>
        <translation>Közlekedési lámpa</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Easy Link: a master and two slaves</source>
        <translation>Easy Link: egy master és két slave</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CPU Link</source>
        <translation>CPU Link</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Parallel Link</source>
        <translation>Parallel Link</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>MODBUS master (MBUS) and slaves</source>
        <translation>MODBUS master (MBUS) és slave-ek</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>MODBUS master with a table of requests</source>
        <translation>MODBUS master kéréstáblázattal</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Non-protocol communication (RS)</source>
        <translation>Protokoll nélküli kommunikáció (RS)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>VB-1COM module (FROM / TO)</source>
        <translation>VB-1COM modul (FROM / TO)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PL110 EXP1 MODBUS master</source>
        <translation>PL110 EXP1 MODBUS master</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PL110 free-port (SEND)</source>
        <translation>PL110 szabad port (SEND)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CPM1 peripheral port (Host Link) on a pseudo-terminal</source>
        <translation>CPM1 perifériacsatlakozó (Host Link) pszeudoterminálon</translation>
    </message>
</context>
<context>
    <name>rung::app::FileController</name>
    <message>
        <location filename="../app/gui/file_controller.cpp" line="+72"/>
        <source>&amp;New Project...</source>
        <translation>Ú&amp;j projekt...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>New Net&amp;work</source>
        <translation>Új háló&amp;zat</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&amp;Open...</source>
        <translation>&amp;Megnyitás...</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Open &amp;Recent</source>
        <translation>&amp;Legutóbbi fájlok</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>E&amp;xamples</source>
        <translation>&amp;Példák</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Save</source>
        <translation>M&amp;entés</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Save &amp;As...</source>
        <translation>Mentés m&amp;ásként...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Co&amp;mpare With...</source>
        <translation>Össze&amp;hasonlítás...</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&amp;Import Instruction List...</source>
        <translation>Utasításlista &amp;importálása...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Export Instruction List...</source>
        <translation>Utasításlista e&amp;xportálása...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Import &amp;PLCopen XML...</source>
        <translation>PLCopen XML imp&amp;ortálása...</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Expor&amp;t PLCopen XML...</source>
        <translation>PLCopen XML expor&amp;tálása...</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The instruction list has errors, so the ladder is not the program as typed: fix the list first.</source>
        <translation>Az utasításlistában hibák vannak, ezért a létradiagram nem a begépelt program: előbb javítsa a listát.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Export &amp;Ladder</source>
        <translation>Létradiagram exportálá&amp;sa</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>As &amp;PDF...</source>
        <translation>&amp;PDF-ként...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>As &amp;SVG...</source>
        <translation>&amp;SVG-ként...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>As P&amp;NG...</source>
        <translation>P&amp;NG-ként...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Print Pre&amp;view...</source>
        <translation>N&amp;yomtatási kép...</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Quit</source>
        <translation>&amp;Kilépés</translation>
    </message>
    <message>
        <location line="+45"/>
        <source>Rung Studio was not closed properly last time. Recover the unsaved program?</source>
        <translation>A Rung Studio legutóbb nem záródott be szabályosan. Helyreállítja a nem mentett programot?</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Rung Studio was not closed properly last time. Recover the unsaved changes to %1?</source>
        <translation>A Rung Studio legutóbb nem záródott be szabályosan. Helyreállítja a(z) %1 nem mentett módosításait?</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+7"/>
        <source>Recover</source>
        <translation>Helyreállítás</translation>
    </message>
    <message>
        <location line="+48"/>
        <source>Cannot open the file</source>
        <translation>A fájl nem nyitható meg</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1: networks cannot be opened here</source>
        <translation>%1: hálózat itt nem nyitható meg</translation>
    </message>
    <message>
        <location line="+179"/>
        <source>Rung Studio projects (*.rung);;Instruction lists (*.il *.txt);;Ladder texts (*.ladder);;Scenario tests (*.rungtest);;Networks of PLCs (*.rungnet)</source>
        <translation>Rung Studio projektek (*.rung);;Utasításlisták (*.il *.txt);;Létra-szövegek (*.ladder);;Forgatókönyv-tesztek (*.rungtest);;PLC-hálózatok (*.rungnet)</translation>
    </message>
    <message>
        <location line="+171"/>
        <source>Networks</source>
        <translation>Hálózatok</translation>
    </message>
    <message>
        <location line="-323"/>
        <source>%1 names %2, but the Tests dock lists the scenarios beside the project</source>
        <translation>%1 a(z) %2 programot nevezi meg, de a Tesztek panel a projekt melletti forgatókönyveket sorolja fel</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>%1, line %2, column %3: %4</source>
        <translation>%1, %2. sor, %3. oszlop: %4</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>%1 has errors; the ladder follows once they are fixed</source>
        <translation>%1 hibás; a létradiagram a hibák javítása után követi</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>Cannot save</source>
        <translation>A mentés nem sikerült</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Saved %1</source>
        <translation>Mentve: %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Saved %1 with the instruction list as typed; it has errors, so the ladder holds the last valid program until they are fixed</source>
        <translation>Mentve: %1, az utasításlistával úgy, ahogy begépelte; hibás, ezért a létradiagram az utolsó érvényes programot mutatja, amíg a hibákat ki nem javítja</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Unsaved changes</source>
        <translation>Nem mentett változások</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save the changes to the program?</source>
        <translation>Menti a program változásait?</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>New Project</source>
        <translation>Új projekt</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>PLC family:</source>
        <translation>PLC-család:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Model:</source>
        <translation>Modell:</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Open</source>
        <translation>Megnyitás</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>Replace File</source>
        <translation>Fájl cseréje</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 already exists. Replace it?</source>
        <translation>%1 már létezik. Lecseréli?</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Save As</source>
        <translation>Mentés másként</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Rung Studio projects (*.rung)</source>
        <translation>Rung Studio projektek (*.rung)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Import Instruction List</source>
        <translation>Utasításlista importálása</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Instruction lists (*.il *.txt);;All files (*)</source>
        <translation>Utasításlisták (*.il *.txt);;Minden fájl (*)</translation>
    </message>
    <message>
        <location line="+12"/>
        <location line="+8"/>
        <location line="+10"/>
        <source>Cannot export</source>
        <translation>Az exportálás nem sikerült</translation>
    </message>
    <message>
        <location line="-14"/>
        <source>Export Instruction List</source>
        <translation>Utasításlista exportálása</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Instruction lists (*.il *.txt)</source>
        <translation>Utasításlisták (*.il *.txt)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Export Ladder</source>
        <translation>Létradiagram exportálása</translation>
    </message>
    <message>
        <location line="+73"/>
        <source>Cannot open the example</source>
        <translation>A példa nem nyitható meg</translation>
    </message>
</context>
<context>
    <name>rung::app::FrontPanelController</name>
    <message>
        <location filename="../app/gui/front_panel_controller.cpp" line="+65"/>
        <source>Front Panel</source>
        <translation>Előlap</translation>
    </message>
</context>
<context>
    <name>rung::app::Gui</name>
    <message>
        <location filename="../app/gui/command_line.cpp" line="+22"/>
        <source>Ladder and instruction-list IDE for small PLCs</source>
        <translation>Létradiagram- és utasításlista-fejlesztőkörnyezet kis PLC-khez</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>A project (.rung) or an instruction list to open</source>
        <translation>Megnyitandó projekt (.rung) vagy utasításlista</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Target of an instruction list: %1</source>
        <translation>Az utasításlista célrendszere: %1</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Unknown target %1: use %2</source>
        <translation>Ismeretlen célrendszer: %1; használható: %2</translation>
    </message>
    <message>
        <location line="-13"/>
        <source>Save a picture of the window and quit</source>
        <translation>Kép mentése az ablakról, majd kilépés</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Open one file at a time</source>
        <translation>Egyszerre egy fájl nyitható meg</translation>
    </message>
    <message>
        <location filename="../app/gui/application.cpp" line="+80"/>
        <source>Rung Studio</source>
        <translation>Rung Studio</translation>
    </message>
</context>
<context>
    <name>rung::app::LayoutController</name>
    <message>
        <location filename="../app/gui/layout_controller.cpp" line="+156"/>
        <source>Ladder and List &amp;Side by Side</source>
        <translation>Létradiagram és lista &amp;egymás mellett</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&amp;Reset Window Layout</source>
        <translation>&amp;Ablakelrendezés visszaállítása</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Every panel back to its first place, closed ones shown again</source>
        <translation>Minden panel vissza az első helyére, a bezártak újra látszanak</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Ladder</source>
        <translation>Létradiagram</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Instruction List</source>
        <translation>Utasításlista</translation>
    </message>
</context>
<context>
    <name>rung::app::LineSettingsForm</name>
    <message>
        <location filename="../app/gui/line_settings_form.cpp" line="+105"/>
        <source>Port:</source>
        <translation>Port:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Refresh</source>
        <translation>Frissítés</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Look for serial ports again</source>
        <translation>Soros portok keresése újra</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Baud rate:</source>
        <translation>Átviteli sebesség (baud):</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Format:</source>
        <translation>Formátum:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Data bits, parity (N none, E even, O odd) and stop bits</source>
        <translation>Adatbitek, paritás (N nincs, E páros, O páratlan) és stopbitek</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+12"/>
        <source>Host:</source>
        <translation>Gép:</translation>
    </message>
    <message>
        <location line="-11"/>
        <source>TCP port:</source>
        <translation>TCP-port:</translation>
    </message>
    <message>
        <location line="+45"/>
        <source>No port found</source>
        <translation>Nem található port</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Choose or type a port</source>
        <translation>Válasszon vagy írjon be portot</translation>
    </message>
</context>
<context>
    <name>rung::app::ListingController</name>
    <message>
        <location filename="../app/gui/listing_controller.cpp" line="+66"/>
        <source>The list as typed had errors and now shows the ladder&apos;s program; Ctrl+Z in the list brings it back</source>
        <translation>A begépelt lista hibás volt, most a létradiagram programját mutatja; a listában a Ctrl+Z visszahozza</translation>
    </message>
    <message>
        <location line="+94"/>
        <source>The list as typed was taken first and changed rung %1, so the ladder edit was not made: make it again on the rung as it is now.</source>
        <translation>A begépelt lista került előbb a programba, és megváltoztatta a(z) %1. létrafokot, ezért a létradiagram módosítása nem történt meg: végezze el újra a létrafok mostani állapotán.</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Replace the Instruction List?</source>
        <translation>Lecseréli az utasításlistát?</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The instruction list as typed has errors (line %1: %2).</source>
        <translation>A begépelt utasításlista hibás (%1. sor: %2).</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>This change to the ladder replaces the list with the ladder&apos;s program; Ctrl+Z in the list brings the typed text back. Cancel keeps the list as typed and leaves the ladder as it is.</source>
        <translation>A létradiagram e módosítása a listát a létradiagram programjára cseréli; a listában a Ctrl+Z visszahozza a begépelt szöveget. A Mégse megtartja a begépelt listát, és a létradiagramot változatlanul hagyja.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Replace the List</source>
        <translation>Lista cseréje</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>The instruction list has %1: line %2: %3. The ladder shows the last valid program.</source>
        <translation>Az utasításlistában %1 van: %2. sor: %3. A létradiagram az utolsó érvényes programot mutatja.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>an error</source>
        <translation>egy hiba</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1 errors</source>
        <translation>%1 hiba</translation>
    </message>
    <message>
        <location line="+53"/>
        <source>&amp;Redo</source>
        <translation>&amp;Mégis</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>&amp;Undo</source>
        <translation>&amp;Visszavonás</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Redo %1</source>
        <extracomment>%1 is the step&apos;s label, e.g. &quot;Insert rung&quot;</extracomment>
        <translation>&amp;Mégis: %1</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>&amp;Undo %1</source>
        <translation>&amp;Visszavonás: %1</translation>
    </message>
</context>
<context>
    <name>rung::app::MainWindow</name>
    <message>
        <location filename="../app/gui/main_window.cpp" line="+165"/>
        <source>Problems</source>
        <translation>Problémák</translation>
    </message>
    <message>
        <location line="+5"/>
        <location line="+141"/>
        <source>Project</source>
        <translation>Projekt</translation>
    </message>
    <message>
        <location line="-134"/>
        <location line="+137"/>
        <source>Symbols</source>
        <translation>Szimbólumok</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_actions.cpp" line="+55"/>
        <source>&amp;File</source>
        <translation>&amp;Fájl</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Main</source>
        <translation>Fő</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>&amp;Edit</source>
        <translation>&amp;Szerkesztés</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>Normally &amp;Open Contact</source>
        <translation>&amp;Záró érintkező</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Normally &amp;Closed Contact</source>
        <translation>&amp;Nyitó érintkező</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Parallel Contact</source>
        <translation>&amp;Párhuzamos érintkező</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Rising-Edge Contact</source>
        <translation>&amp;Felfutó él érintkező</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Falling-Edge Contact</source>
        <translation>&amp;Lefutó él érintkező</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Parall&amp;el Normally Closed Contact</source>
        <translation>Párhuzamos n&amp;yitó érintkező</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Parallel Ri&amp;sing-Edge Contact</source>
        <translation>Pár&amp;huzamos felfutó él érintkező</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Parallel Fallin&amp;g-Edge Contact</source>
        <translation>Párhuzamos lefutó él érint&amp;kező</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Co&amp;il</source>
        <translation>&amp;Tekercs</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>I&amp;nstruction</source>
        <translation>&amp;Utasítás</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Horizontal Wire</source>
        <translation>&amp;Vízszintes vezeték</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Vertical Link</source>
        <translation>Függőleges ö&amp;sszekötés</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Place &amp;Element</source>
        <translation>Elem el&amp;helyezése</translation>
    </message>
    <message>
        <location line="+56"/>
        <source>&amp;Import Symbols (CSV)...</source>
        <translation>Szimbólumok im&amp;portálása (CSV)...</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>E&amp;xport Symbols (CSV)...</source>
        <translation>Szimbólumok e&amp;xportálása (CSV)...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Add to Watc&amp;h List</source>
        <translation>Hozzá&amp;adás a figyelőlistához</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>In&amp;sert Rung</source>
        <translation>Létra&amp;fok beszúrása</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>De&amp;lete Rung</source>
        <translation>Létrafok tör&amp;lése</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Insert R&amp;ow</source>
        <translation>Sor beszú&amp;rása</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Delete Ro&amp;w</source>
        <translation>S&amp;or törlése</translation>
    </message>
    <message>
        <location line="+59"/>
        <source>F5 normally open contact, F6 normally closed contact, F7 coil, F8 instruction
Shift+F5 / Shift+F6 the same contacts in parallel with the row above
Shift+F7 / Shift+F8 rising / falling edge contact (Alt: in parallel)
F9 horizontal wire, Shift+F9 vertical link, Ctrl+F9 / Ctrl+F10 delete them
Type an instruction into the cell: %1
Insert: insert a cell, Ctrl+Insert: insert a row, Shift+Insert: insert a rung
Delete: clear, Ctrl+Delete: delete the row, Shift+Delete: delete the rung
Ctrl+Z / Ctrl+Y: undo / redo, Ctrl+wheel: zoom, F4: check the program</source>
        <translation>F5 záró érintkező, F6 nyitó érintkező, F7 tekercs, F8 utasítás
Shift+F5 / Shift+F6 ugyanezek az érintkezők a fölötte lévő sorral párhuzamosan
Shift+F7 / Shift+F8 felfutó / lefutó él érintkező (Alt: párhuzamosan)
F9 vízszintes vezeték, Shift+F9 függőleges összekötés, Ctrl+F9 / Ctrl+F10 ezek törlése
Utasítás beírása a cellába: %1
Insert: cella beszúrása, Ctrl+Insert: sor beszúrása, Shift+Insert: létrafok beszúrása
Delete: törlés, Ctrl+Delete: a sor törlése, Shift+Delete: a létrafok törlése
Ctrl+Z / Ctrl+Y: visszavonás / mégis, Ctrl+görgő: nagyítás, F4: a program ellenőrzése</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Simulation: F10 run, F11 pause, Shift+F11 stop, F12 single scan, Ctrl+Shift+F12 power cycle</source>
        <translation>Szimuláció: F10 futtatás, F11 szünet, Shift+F11 leállítás, F12 egy ciklus, Ctrl+Shift+F12 ki-bekapcsolás</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Online: Ctrl+W go online / offline, Ctrl+1 STOP (PROGRAM), Ctrl+3 MONITOR, Ctrl+4 RUN</source>
        <translation>Online: Ctrl+W online kapcsolódás / bontás, Ctrl+1 STOP (PROGRAM), Ctrl+3 MONITOR, Ctrl+4 RUN</translation>
    </message>
    <message>
        <location line="-162"/>
        <source>Select</source>
        <translation>Kijelölés</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Select (Esc)</source>
        <translation>Kijelölés (Esc)</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1 (%2): click the cells to place it</source>
        <translation>%1 (%2): kattintson a cellákra az elhelyezéshez</translation>
    </message>
    <message>
        <location line="+9"/>
        <location line="+10"/>
        <source>%1: click a cell to place it; Esc or a right click ends</source>
        <translation>%1: kattintson egy cellára az elhelyezéshez; Esc vagy jobb kattintás befejezi</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Cu&amp;t Rung</source>
        <translation>Létrafok k&amp;ivágása</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Copy Rung</source>
        <translation>Létrafok má&amp;solása</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Paste Rungs</source>
        <translation>Létrafokok &amp;beillesztése</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&amp;Find Device...</source>
        <translation>Operandus &amp;keresése...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Find &amp;Next</source>
        <translation>Következő &amp;találat</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Find Pre&amp;vious</source>
        <translation>&amp;Előző találat</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Replace &amp;Device...</source>
        <translation>Operandus &amp;cseréje...</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Import Symbols</source>
        <translation>Szimbólumok importálása</translation>
    </message>
    <message>
        <location line="+0"/>
        <location filename="../app/gui/main_window_tools.cpp" line="+224"/>
        <source>CSV files (*.csv)</source>
        <translation>CSV-fájlok (*.csv)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Cannot import</source>
        <translation>Az importálás nem sikerült</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Rung Co&amp;mment...</source>
        <translation>Létrafok megje&amp;gyzése...</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Communic&amp;ation Ports...</source>
        <translation>Kommu&amp;nikációs portok...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The PLC&apos;s own port settings, kept in the project: what Ladder Master calls the 2nd COM Port Setting, CPU Link, the PL110&apos;s COM1 / EXP1 / COM2 protocols</source>
        <translation>A PLC saját portbeállításai, a projektben tárolva: amit a Ladder Master 2nd COM Port Settingnek nevez, a CPU Link, a PL110 COM1 / EXP1 / COM2 protokolljai</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>&amp;View</source>
        <translation>&amp;Nézet</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Show Symbol &amp;Names</source>
        <translation>Szimbólumne&amp;vek megjelenítése</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Names from the symbol table in place of the addresses</source>
        <translation>A szimbólumtábla nevei a címek helyett</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&amp;Fit Ladder to Width</source>
        <translation>Létradiagram &amp;igazítása a szélességhez</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Zoom &amp;In</source>
        <translation>&amp;Nagyítás</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Zoom &amp;Out</source>
        <translation>&amp;Kicsinyítés</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Check Program</source>
        <translation>Program ellen&amp;őrzése</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&amp;Language</source>
        <translation>N&amp;yelv</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>&amp;Help</source>
        <translation>Sú&amp;gó</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Keyboard...</source>
        <translation>&amp;Billentyűzet...</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Keyboard</source>
        <translation>Billentyűzet</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>&amp;About Rung Studio</source>
        <translation>A Rung Studio &amp;névjegye</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="-119"/>
        <source>Rung Comment</source>
        <translation>Létrafok megjegyzése</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Comment above rung %1:</source>
        <translation>Megjegyzés a(z) %1. létrafok fölött:</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>&lt;b&gt;%1&lt;/b&gt;&lt;br&gt;Target: %2, model %3&lt;br&gt;%4, %5</source>
        <translation>&lt;b&gt;%1&lt;/b&gt;&lt;br&gt;PLC-család: %2, modell: %3&lt;br&gt;%4, %5</translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>%n rung(s)</source>
        <translation>
            <numerusform>%n létrafok</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>%n step(s)</source>
        <translation>
            <numerusform>%n lépés</numerusform>
        </translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 / %2 steps</source>
        <translation>%1 / %2 lépés</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Line %1, column %2</source>
        <translation>%1. sor, %2. oszlop</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Rung %1, row %2, column %3</source>
        <translation>%1. létrafok, %2. sor, %3. oszlop</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_monitor.cpp" line="+54"/>
        <source>Cannot save</source>
        <translation>A mentés nem sikerült</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_panels.cpp" line="+73"/>
        <location filename="../app/gui/main_window_tools.cpp" line="+4"/>
        <source>Cannot export</source>
        <translation>Az exportálás nem sikerült</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_tools.cpp" line="-157"/>
        <source>Cut rungs</source>
        <translation>Létrafokok kivágása</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Cannot paste the cells: %1</source>
        <translation>A cellák nem illeszthetők be: %1</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Line %1: %2</source>
        <translation>%1. sor: %2</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>The clipboard holds no rungs</source>
        <translation>A vágólapon nincsenek létrafokok</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cannot paste: %1</source>
        <translation>A beillesztés nem sikerült: %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Paste rung</source>
        <translation>Létrafok beillesztése</translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>Paste %n rungs</source>
        <translation>
            <numerusform>%n létrafok beillesztése</numerusform>
        </translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Find Device</source>
        <translation>Operandus keresése</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Device:</source>
        <translation>Operandus:</translation>
    </message>
    <message>
        <location line="+27"/>
        <location line="+3"/>
        <location line="+6"/>
        <source>Replace Device</source>
        <translation>Operandus cseréje</translation>
    </message>
    <message>
        <location line="-9"/>
        <source>Replace the device:</source>
        <translation>A cserélendő operandus:</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>with:</source>
        <translation>erre:</translation>
    </message>
    <message numerus="yes">
        <location line="+8"/>
        <source>%n place(s) changed</source>
        <translation>
            <numerusform>%n helyen történt módosítás</numerusform>
        </translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Replace %1 with %2</source>
        <translation>%1 cseréje erre: %2</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>(no device) %1</source>
        <translation>(nincs operandus) %1</translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>%n row(s) of the symbol table name no device of this PLC and are left out of the file: %1. Export the other symbols?</source>
        <translation>
            <numerusform>A szimbólumtábla %n sora nem ennek a PLC-nek az operandusát adja meg, ezért kimarad a fájlból: %1. Exportálja a többi szimbólumot?</numerusform>
        </translation>
    </message>
    <message>
        <location line="+19"/>
        <location line="+11"/>
        <source>Communication Ports</source>
        <translation>Kommunikációs portok</translation>
    </message>
    <message>
        <location line="-10"/>
        <source>The %1 has no port settings a program or a network uses.</source>
        <translation>A(z) %1 nem rendelkezik olyan portbeállítással, amelyet program vagy hálózat használ.</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>The communication ports are as they were</source>
        <translation>A kommunikációs portok változatlanok</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Communication ports set: File &gt; Save keeps them in the project</source>
        <translation>Kommunikációs portok beállítva: a Fájl &gt; Mentés a projektben tárolja őket</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="+84"/>
        <location filename="../app/gui/main_window_tools.cpp" line="-55"/>
        <source>Cross Reference</source>
        <translation>Kereszthivatkozás</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_tools.cpp" line="+22"/>
        <location line="+7"/>
        <source>Export Symbols</source>
        <translation>Szimbólumok exportálása</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_simulation.cpp" line="+32"/>
        <source>The instruction list has errors, so the ladder still shows the last program without them: correct the list (or undo) before simulating</source>
        <translation>Az utasításlistában hibák vannak, ezért a létra még az utolsó hibátlan programot mutatja: a szimuláció előtt javítsa a listát (vagy vonja vissza a módosítást)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_monitor.cpp" line="+25"/>
        <source>Simulation</source>
        <translation>Szimuláció</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Online PLC</source>
        <translation>Online PLC</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>History (read-only)</source>
        <translation>Előzmények (csak olvasható)</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>The ladder, the instruction list and the watch lists show the values of: %1</source>
        <translation>A létradiagram, az utasításlista és a figyelőlisták értékeinek forrása: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_panels.cpp" line="-9"/>
        <source>Export Timing Chart</source>
        <translation>Idődiagram exportálása</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Timing chart exported to %1</source>
        <translation>Az idődiagram exportálva ide: %1</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Watch</source>
        <translation>Figyelés</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Inputs and Outputs</source>
        <translation>Be- és kimenetek</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Timing Chart</source>
        <translation>Idődiagram</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_monitor.cpp" line="-51"/>
        <source>Save Traffic Log</source>
        <translation>Adatforgalom-napló mentése</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Text files (*.txt)</source>
        <translation>Szövegfájlok (*.txt)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_panels.cpp" line="+1"/>
        <source>Tests</source>
        <translation>Tesztek</translation>
    </message>
</context>
<context>
    <name>rung::app::Network</name>
    <message>
        <location filename="../app/cli/cli_network.cpp" line="-176"/>
        <source>usage:</source>
        <translation>használat:</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>station %1 (%2) does not start</source>
        <translation>a(z) %1 állomás (%2) nem indul el</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>  rungstudio-cli check NET.rungnet
  rungstudio-cli serve NET.rungnet
  rungstudio-cli simulate NET.rungnet --scans N [--period MS] [--set STATION/DEV=VALUE@SCAN]... --trace STATION/DEV[,...] [--traffic FILE]</source>
        <translation>  rungstudio-cli check NET.rungnet
  rungstudio-cli serve NET.rungnet
  rungstudio-cli simulate NET.rungnet --scans N [--period MS] [--set ÁLLOMÁS/OPERANDUS=ÉRTÉK@CIKLUS]... --trace ÁLLOMÁS/OPERANDUS[,...] [--traffic FÁJL]</translation>
    </message>
    <message>
        <location line="+43"/>
        <source>--traffic needs a file</source>
        <translation>a --traffic után fájlnév kell</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1: a network file names each station&apos;s PLC</source>
        <translation>%1: a hálózatfájl minden állomás PLC-jét maga nevezi meg</translation>
    </message>
    <message>
        <location line="+29"/>
        <location line="+14"/>
        <source>cannot write %1: %2</source>
        <translation>%1 nem írható: %2</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1: line %2: runtime error at step %3: %4</source>
        <translation>%1: %2. sor: futási hiba a(z) %3. lépésnél: %4</translation>
    </message>
    <message>
        <location line="+40"/>
        <source>%1: %2: %3</source>
        <translation>%1: %2: %3</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1: a station&apos;s program has errors; the wiring is checked once every program starts</source>
        <translation>%1: egy állomás programja hibás; a bekötés ellenőrzése akkor következik, ha minden program elindul</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1: %2: %3: %4</source>
        <extracomment>%1 the network file, %2 where in it (a wire, a station&apos;s line), %3 error or warning</extracomment>
        <translation>%1: %2: %3: %4</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>%1: no bridges: nothing of the network reaches a real line (&quot;bridges&quot;, docs/network-format.md); simulate runs it on virtual time</source>
        <translation>%1: nincsenek hidak: a hálózatból semmi sem jut el valódi vonalra („bridges”, docs/network-format.md); a simulate virtuális időben futtatja</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>%1 runs in real time; stop it with Ctrl+C</source>
        <translation>a(z) %1 valós időben fut; leállítás: Ctrl+C</translation>
    </message>
</context>
<context>
    <name>rung::app::NetworkBridgeController</name>
    <message>
        <location filename="../app/gui/network_bridge_controller.cpp" line="+30"/>
        <source>%1: pseudo-terminal</source>
        <extracomment>%1 a station&apos;s port (&quot;s5/CP2&quot;); the rest what its bridge goes to</extracomment>
        <translation>%1: pszeudoterminál</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: serial port %2</source>
        <translation>%1: %2 soros port</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: TCP to %2</source>
        <translation>%1: TCP-kapcsolat ide: %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: listens on %2</source>
        <translation>%1: figyel itt: %2</translation>
    </message>
    <message>
        <location line="+74"/>
        <source>Copied %1: where %2 is reached</source>
        <translation>Másolva: %1, itt érhető el a(z) %2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Bridges</source>
        <translation>Hidak</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>No bridge: right-click a station&apos;s port in the Network view and choose Bridge To to put it on a pseudo-terminal, a serial port or TCP.</source>
        <translation>Nincs híd: kattintson jobb gombbal egy állomás portjára a Hálózat nézetben, és válassza a Híd ide menüt, hogy pszeudoterminálra, soros portra vagy TCP-re tegye.</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>not open</source>
        <translation>nincs nyitva</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Copy</source>
        <translation>Másolás</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Copy where the bridge is reached to the clipboard</source>
        <translation>A híd elérési helyének másolása a vágólapra</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Edit...</source>
        <translation>Szerkesztés...</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Remove</source>
        <translation>Eltávolítás</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Not running: the network is not built (the status bar says why)</source>
        <translation>Nem fut: a hálózat nincs felépítve (az állapotsor megmondja, miért)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Changed: Stop builds the network again with this bridge</source>
        <translation>Módosítva: a Megállás ezzel a híddal építi fel újra a hálózatot</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Open: give this path to a master on this computer</source>
        <translation>Nyitva: adja meg ezt az útvonalat egy masternek ezen a számítógépen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Open: %1</source>
        <translation>Nyitva: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Opening...</source>
        <translation>Megnyitás...</translation>
    </message>
</context>
<context>
    <name>rung::app::NetworkBridgeDialog</name>
    <message>
        <location filename="../app/gui/network_bridge_dialog.cpp" line="+43"/>
        <source>Bridge of %1</source>
        <extracomment>%1 a station&apos;s port, &quot;s5/CP2&quot;</extracomment>
        <translation>%1 hídja</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>While the network runs, %1 is put on a real line: a master on this computer or the network reaches the simulated station, or the station reaches a real device.</source>
        <translation>Amíg a hálózat fut, a(z) %1 valódi vonalra kerül: ezen a számítógépen vagy a hálózaton egy master eléri a szimulált állomást, vagy az állomás elér egy valódi eszközt.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&amp;Pseudo-terminal (a master on this computer)</source>
        <translation>&amp;Pszeudoterminál (master ezen a számítógépen)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Serial port</source>
        <translation>&amp;Soros port</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>TCP: &amp;connect to a serial device server</source>
        <translation>TCP: &amp;kapcsolódás soros eszközszerverhez</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>TCP: &amp;listen for a master</source>
        <translation>TCP: &amp;várakozás egy masterre</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>The serial port the real line is on (a USB adapter: /dev/ttyUSB0)</source>
        <translation>A soros port, amelyen a valódi vonal van (USB-átalakító: /dev/ttyUSB0)</translation>
    </message>
    <message>
        <location line="+63"/>
        <source>Listen on:</source>
        <translation>Figyelési cím:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>any free port</source>
        <translation>bármely szabad port</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>An IP address of this computer, 0.0.0.0 for all of them, or localhost</source>
        <translation>E számítógép egy IP-címe, 0.0.0.0 az összeshez, vagy localhost</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The serial device server&apos;s host name or IP address</source>
        <translation>A soros eszközszerver gépneve vagy IP-címe</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>A new pseudo-terminal (/dev/pts/N) opens when the network window builds the network, and stays while the window is open (Stop keeps it). Its path is shown on the port and in the Bridges dock, with a Copy button: give it to the master (mbpoll, an HMI, another Rung Studio&apos;s Connection dock).</source>
        <translation>Amikor a hálózati ablak felépíti a hálózatot, új pszeudoterminál (/dev/pts/N) nyílik, és megmarad, amíg az ablak nyitva van (a Megállás megtartja). Útvonala a porton és a Hidak panelen látszik, Másolás gombbal: adja meg a masternek (mbpoll, HMI, egy másik Rung Studio Kapcsolat panelje).</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The serial port opens at the port&apos;s own rate and format, so that the simulated station and the real line agree: changing them here changes the port&apos;s settings.</source>
        <translation>A soros port a port saját sebességével és formátumával nyílik meg, hogy a szimulált állomás és a valódi vonal egyezzen: ha itt módosítja őket, a port beállításai változnak.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>A serial device server in TCP server mode passes the bytes to its serial line: the simulated station reaches the real device behind it.</source>
        <translation>A TCP-szerver módban működő soros eszközszerver a bájtokat a soros vonalára továbbítja: a szimulált állomás eléri a mögötte lévő valódi eszközt.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>A master connects over TCP and sends the serial line&apos;s bytes (RTU over TCP, not Modbus TCP), one master at a time.</source>
        <translation>Egy master TCP-n kapcsolódik, és a soros vonal bájtjait küldi (RTU TCP-n át, nem Modbus TCP), egyszerre egy master.</translation>
    </message>
    <message>
        <location line="+44"/>
        <source>Choose the serial port, or type its name</source>
        <translation>Válassza ki a soros portot, vagy írja be a nevét</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Type the device server&apos;s host name or IP address</source>
        <translation>Írja be az eszközszerver gépnevét vagy IP-címét</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Type the address to listen on (0.0.0.0 for all of them)</source>
        <translation>Írja be a figyelési címet (0.0.0.0 az összeshez)</translation>
    </message>
</context>
<context>
    <name>rung::app::NetworkChart</name>
    <message>
        <location filename="../app/gui/network_chart.cpp" line="+107"/>
        <source>Follow</source>
        <translation>Követés</translation>
    </message>
    <message>
        <location line="-1"/>
        <source>Add station/device, e.g. %1</source>
        <translation>Állomás/operandus hozzáadása, pl. %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Type a station&apos;s device above (%1) to draw it</source>
        <translation>Írjon be fent egy állomás operandusát (%1) a kirajzolásához</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Trigger: %1 rises, %2 &gt; 100</source>
        <translation>Trigger: %1 rises, %2 &gt; 100</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A condition on one station&apos;s device, checked after each of its scans: STATION/DEVICE rises, falls, or = &lt;&gt; &lt; &lt;= &gt; &gt;= VALUE (the same as Simulation &gt; Stop When...)</source>
        <translation>Egy állomás operandusára vonatkozó feltétel, amelyet az állomás minden ciklusa után vizsgál: ÁLLOMÁS/OPERANDUS rises (felfutó él), falls (lefutó él), vagy = &lt;&gt; &lt; &lt;= &gt; &gt;= ÉRTÉK (ugyanaz, mint Szimuláció &gt; Megállási feltétel...)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Stop the network</source>
        <translation>A hálózat megállítása</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Only mark</source>
        <translation>Csak jelölés</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stop the network: every station pauses at the end of its scan when the condition becomes true</source>
        <translation>A hálózat megállítása: amikor a feltétel igazzá válik, minden állomás megáll a ciklusa végén</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Arm</source>
        <translation>Élesítés</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Watch for the trigger (Enter in its field does the same)</source>
        <translation>A trigger figyelése (a mezőben az Enter ugyanezt teszi)</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Armed: stops the network when %1</source>
        <translation>Élesítve: a hálózat megáll, ha %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Armed: marks when %1</source>
        <translation>Élesítve: jelöl, ha %1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1 at %2 (scan %3)</source>
        <extracomment>%1 the condition, %2 the virtual time, %3 the scan of its station</extracomment>
        <translation>%1: %2 (%3. ciklus)</translation>
    </message>
    <message>
        <location line="+54"/>
        <source>%1: write STATION/DEVICE, e.g. %2 (stations: %3)</source>
        <translation>%1: ÁLLOMÁS/OPERANDUS alakban írja, pl. %2 (állomások: %3)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Not added to the timing chart: %1</source>
        <translation>Nem került az idődiagramra: %1</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1 keeps no history of %2</source>
        <translation>%1 nem őrzi %2 előzményeit</translation>
    </message>
    <message>
        <location line="+160"/>
        <source>A: %1</source>
        <translation>A: %1</translation>
    </message>
</context>
<context>
    <name>rung::app::NetworkDebugController</name>
    <message>
        <location filename="../app/gui/network_debug_controller.cpp" line="+238"/>
        <source>%1 stopped at its breakpoint on line %2; the other stations wait at the end of their scan</source>
        <extracomment>%1 station, %2 line of its instruction list</extracomment>
        <translation>%1 megállt a(z) %2. sor töréspontjánál; a többi állomás a ciklusa végén várakozik</translation>
    </message>
    <message>
        <location line="+43"/>
        <source>Stop &amp;When...</source>
        <translation>Megállási feltéte&amp;l...</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>No network is running</source>
        <translation>Nem fut hálózat</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Stop the network after the scan in which a station&apos;s condition becomes true,
written STATION/CONDITION, e.g. %1/%2 &gt; 100 or %1/%3 rises (empty: never):</source>
        <extracomment>%1 a station&apos;s name, %2 a word of it, %3 a bit of it</extracomment>
        <translation>A hálózat megáll annak a ciklusnak a végén, amelyben egy állomás feltétele igazzá válik,
ÁLLOMÁS/FELTÉTEL alakban, pl. %1/%2 &gt; 100 vagy %1/%3 rises (üres: soha):</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Stop When</source>
        <translation>Megállási feltétel</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Scan Debugger</source>
        <translation>Ciklushibakereső</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Instruction List</source>
        <translation>Utasításlista</translation>
    </message>
    <message>
        <location line="+110"/>
        <source>no station</source>
        <translation>nincs állomás</translation>
    </message>
    <message>
        <location line="+79"/>
        <source>Stopped: %1 became true</source>
        <extracomment>the status bar while the network&apos;s trigger holds it: %1 the condition (&quot;s2/D10 &gt; 100&quot;)</extracomment>
        <translation>Megállt: %1 igazzá vált</translation>
    </message>
    <message>
        <location line="-63"/>
        <source>Breakpoint set at %1 of %2</source>
        <extracomment>%1 the place (&quot;line 3&quot;, &quot;rung 2&quot;), %2 the station</extracomment>
        <translation>Töréspont beállítva: %2, %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Breakpoint at %1 of %2 removed</source>
        <translation>Töréspont eltávolítva: %2, %1</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Stop %1 before line %2: %3</source>
        <extracomment>where the breakpoint is: %1 station, %2 line, %3 the instruction</extracomment>
        <translation>%1 álljon meg a(z) %2. sor előtt: %3</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>%1 stopped before line %2</source>
        <extracomment>the status bar while a station&apos;s scan is stopped inside: %1 station, %2 line</extracomment>
        <translation>%1 megállt a(z) %2. sor előtt</translation>
    </message>
    <message>
        <location filename="../app/gui/network_debug_stop.cpp" line="+25"/>
        <source>No stop condition</source>
        <translation>Nincs megállási feltétel</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The network stops when %1 becomes true</source>
        <translation>A hálózat megáll, amikor %1 igazzá válik</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The timing chart marks when %1 becomes true</source>
        <translation>Az idődiagram jelöli, amikor %1 igazzá válik</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>%1: write STATION/CONDITION with a station of the network (%2)</source>
        <extracomment>%1 what was typed, %2 the stations&apos; names</extracomment>
        <translation>%1: ÁLLOMÁS/FELTÉTEL alakban írja, a hálózat egy állomásával (%2)</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>%1 cannot be watched in %2</source>
        <translation>%1 nem figyelhető a(z) %2 állomásban</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1 became true after scan %2 (%3): the network stopped there</source>
        <extracomment>%1 the condition (&quot;s2/D10 &gt; 100&quot;), %2 scan number, %3 virtual time</extracomment>
        <translation>%1 igazzá vált a(z) %2. ciklus után (%3): a hálózat ott megállt</translation>
    </message>
</context>
<context>
    <name>rung::app::NetworkDocument</name>
    <message>
        <location filename="../app/gui/network_document.cpp" line="+49"/>
        <source>pseudo-terminal</source>
        <translation>pszeudoterminál</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>serial port</source>
        <translation>soros port</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>TCP connection</source>
        <translation>TCP-kapcsolat</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>TCP listener</source>
        <translation>TCP-figyelő</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>The network has no file yet: use Save As</source>
        <translation>A hálózatnak még nincs fájlja: használja a Mentés másként parancsot</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>Untitled network</source>
        <translation>Névtelen hálózat</translation>
    </message>
    <message>
        <location line="+54"/>
        <source>%1: cannot read the program (%2)</source>
        <translation>%1: a program nem olvasható (%2)</translation>
    </message>
    <message>
        <location line="+101"/>
        <source>&quot;%1&quot; is no station name (letters, digits, _ and -, at most 32)</source>
        <translation>„%1” nem állomásnév (betűk, számjegyek, _ és -, legfeljebb 32)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>A station or device is already named &quot;%1&quot;</source>
        <translation>Már van „%1” nevű állomás vagy eszköz</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: no such program</source>
        <translation>%1: nincs ilyen program</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+29"/>
        <source>&quot;%1&quot; is no target</source>
        <translation>„%1” nem célrendszer</translation>
    </message>
    <message>
        <location line="-20"/>
        <source>Add Station %1</source>
        <translation>%1 állomás hozzáadása</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>%1 has no model &quot;%2&quot;</source>
        <translation>A(z) %1 rendszernek nincs „%2” modellje</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1 exists already: choose another name</source>
        <translation>%1 már létezik: válasszon másik nevet</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>wire %1 (%2) goes: fewer than two ends are left</source>
        <translation>a(z) %1 vezeték (%2) megszűnik: kettőnél kevesebb végpontja marad</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the fault %1 on wire %2 goes</source>
        <translation>a(z) %2 vezeték %1 hibája megszűnik</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 comes off wire %2</source>
        <translation>%1 lekerül a(z) %2 vezetékről</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the bridge of %1 (%2) goes</source>
        <translation>a(z) %1 hídja (%2) megszűnik</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the fault %1 (silent) goes</source>
        <translation>a(z) %1 hiba (néma) megszűnik</translation>
    </message>
    <message>
        <location line="+6"/>
        <location line="+32"/>
        <location line="+93"/>
        <source>No station is named &quot;%1&quot;</source>
        <translation>Nincs „%1” nevű állomás</translation>
    </message>
    <message>
        <location line="-108"/>
        <source>Remove Station %1</source>
        <translation>%1 állomás eltávolítása</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>No station port or device is named &quot;%1&quot;</source>
        <translation>Nincs „%1” nevű állomásport vagy eszköz</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1 (%2 %3) has no port %4</source>
        <translation>A(z) %1 (%2 %3) állomásnak nincs %4 portja</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>A wire joins two different ends</source>
        <translation>Egy vezeték két különböző végpontot köt össze</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1 and %2 are on wire %3 already</source>
        <translation>%1 és %2 már a(z) %3 vezetéken van</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>Connect %1 to %2</source>
        <translation>%1 összekötése ezzel: %2</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Disconnect %1</source>
        <translation>%1 leválasztása</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 is on no wire</source>
        <translation>%1 nincs vezetéken</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Remove Wire %1</source>
        <translation>%1 vezeték eltávolítása</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>No wire is named &quot;%1&quot;</source>
        <translation>Nincs „%1” nevű vezeték</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>Port Settings of %1/%2</source>
        <translation>%1/%2 port beállításai</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>A bridge goes from a station&apos;s port (STATION/PORT), not from &quot;%1&quot;</source>
        <translation>A híd egy állomás portjából indul (ÁLLOMÁS/PORT), nem ebből: „%1”</translation>
    </message>
    <message>
        <location line="-9"/>
        <source>%1 has a bridge already</source>
        <translation>%1 már rendelkezik híddal</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>A %1 bridge needs where it goes</source>
        <translation>A híd (%1) célját meg kell adni</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&quot;%1&quot; is not HOST:PORT</source>
        <translation>„%1” nem GÉP:PORT alakú</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>%1 runs %2, whose frames are not published: it cannot be bridged</source>
        <translation>%1 a(z) %2 protokollt futtatja, amelynek keretei nem publikusak: nem köthető hídra</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Add Bridge %1</source>
        <translation>%1 híd hozzáadása</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Change Bridge %1</source>
        <translation>%1 hídjának módosítása</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1 has no bridge</source>
        <translation>%1 nem rendelkezik híddal</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Remove Bridge %1</source>
        <translation>%1 híd eltávolítása</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The period is 1 to 1000000 ms, not %1</source>
        <translation>A ciklusidő 1 és 1000000 ms között lehet, nem %1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Network Period %1 ms</source>
        <translation>Hálózati ciklusidő: %1 ms</translation>
    </message>
</context>
<context>
    <name>rung::app::NetworkHistoryController</name>
    <message>
        <location filename="../app/gui/network_history_controller.cpp" line="+90"/>
        <source>The network is stopped: run it, then pause it to see any instant of its past</source>
        <translation>A hálózat le van állítva: futtassa, majd állítsa szünetre, hogy a múltja bármely pillanatát lássa</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Pause the network to see every station at the cursor&apos;s time</source>
        <translation>Állítsa szünetre a hálózatot, hogy minden állomást a kurzor időpontjában lásson</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>That instant is no longer recorded: the history starts at %1</source>
        <extracomment>%1 the oldest virtual time still recorded, h:mm:ss.hh</extracomment>
        <translation>Az a pillanat már nincs rögzítve: az előzmények %1-tól kezdődnek</translation>
    </message>
    <message>
        <location line="+50"/>
        <source>History: %1, every station (read-only)</source>
        <extracomment>%1 the virtual time shown, h:mm:ss.hh; every station of the network shows that instant</extracomment>
        <translation>Előzmények: %1, minden állomás (csak olvasható)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Every station&apos;s ladder, inputs and outputs, front panel and watched values show this instant. Run, Single Scan, Stop or Return to Live (Ctrl+Shift+L) go back to the present</source>
        <translation>Minden állomás létradiagramja, be- és kimenetei, előlapja és figyelt értékei ezt a pillanatot mutatják. A Futtatás, az Egy ciklus, a Megállás vagy a Vissza az élő állapothoz (Ctrl+Shift+L) visszavisz a jelenbe</translation>
    </message>
</context>
<context>
    <name>rung::app::NetworkPortDialog</name>
    <message>
        <location filename="../app/gui/network_port_dialog.cpp" line="+61"/>
        <source>Port Settings: %1</source>
        <translation>Port beállításai: %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 %2: %3</source>
        <translation>%1 %2: %3</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 %2, port %3</source>
        <translation>%1 %2, %3 port</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>&amp;Application:</source>
        <translation>&amp;Alkalmazás:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Station number:</source>
        <translation>Á&amp;llomásszám:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Baud rate:</source>
        <translation>Átviteli &amp;sebesség (baud):</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Format:</source>
        <translation>&amp;Formátum:</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>CPU Link master (station 0)</source>
        <translation>CPU Link master (0. állomás)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source> x 10 ms</source>
        <translation> x 10 ms</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Total s&amp;laves (%1..%2):</source>
        <translation>S&amp;lave-ek száma (%1..%2):</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Transfer range mode (%1..%2):</source>
        <translation>Átviteli &amp;tartomány módja (%1..%2):</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Retries (%1..%2):</source>
        <translation>Ismét&amp;lések (%1..%2):</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>T&amp;ime-out (%1..%2):</source>
        <translation>&amp;Időtúllépés (%1..%2):</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Parallel Link</source>
        <translation>Parallel Link</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Master</source>
        <translation>Master</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Slave</source>
        <translation>Slave</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Low speed</source>
        <translation>Alacsony sebesség</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>High speed</source>
        <translation>Nagy sebesség</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>R&amp;ole:</source>
        <translation>S&amp;zerep:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>S&amp;peed (the master&apos;s decides):</source>
        <translation>Se&amp;besség (a masteré dönt):</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>MODBUS</source>
        <translation>MODBUS</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&amp;Mode:</source>
        <translation>&amp;Mód:</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Start and end characters</source>
        <translation>Kezdő- és zárókarakter</translation>
    </message>
    <message>
        <location line="+5"/>
        <location line="+1"/>
        <source>none</source>
        <translation>nincs</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Start c&amp;haracter (%1..%2):</source>
        <translation>&amp;Kezdőkarakter (%1..%2):</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;End character (%1..%2):</source>
        <translation>&amp;Zárókarakter (%1..%2):</translation>
    </message>
    <message>
        <location line="+25"/>
        <location line="+88"/>
        <location line="+10"/>
        <source>%1 (default)</source>
        <translation>%1 (alapértelmezett)</translation>
    </message>
    <message>
        <location line="-37"/>
        <source>%1 %2 has no such port</source>
        <translation>A(z) %1 %2 rendszernek nincs ilyen portja</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>default: %1</source>
        <translation>alapértelmezett: %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1..%2, default %3</source>
        <translation>%1..%2, alapértelmezett: %3</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1 (not a rate of %2)</source>
        <translation>%1 (nem a(z) %2 sebessége)</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1 always uses %2</source>
        <translation>A(z) %1 mindig %2 formátumú</translation>
    </message>
    <message>
        <location line="+62"/>
        <source>the project&apos;s settings</source>
        <translation>a projekt beállításai</translation>
    </message>
    <message>
        <location line="+47"/>
        <source>Port Settings</source>
        <translation>Port beállításai</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The %1 %2&apos;s port:</source>
        <translation>A(z) %1 %2 portja:</translation>
    </message>
</context>
<context>
    <name>rung::app::NetworkStationDialog</name>
    <message>
        <location filename="../app/gui/network_station_dialog.cpp" line="+25"/>
        <source>Add New Project Station</source>
        <translation>Állomás új projekttel</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>&amp;Browse...</source>
        <translation>&amp;Tallózás...</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Name:</source>
        <translation>&amp;Név:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;PLC:</source>
        <translation>&amp;PLC:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Model:</source>
        <translation>&amp;Modell:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Project &amp;file:</source>
        <translation>Projekt&amp;fájl:</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>New Project</source>
        <translation>Új projekt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Rung Studio projects (*.rung)</source>
        <translation>Rung Studio projektek (*.rung)</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>A name is letters, digits, _ and -, at most 32</source>
        <translation>A név betűkből, számjegyekből, _ és - jelekből áll, legfeljebb 32</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>A station or device is already named &quot;%1&quot;</source>
        <translation>Már van „%1” nevű állomás vagy eszköz</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Choose where the project is saved</source>
        <translation>Válassza ki, hová kerüljön a projekt</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 exists already: a new project never overwrites a file</source>
        <translation>%1 már létezik: egy új projekt sosem ír felül fájlt</translation>
    </message>
</context>
<context>
    <name>rung::app::NetworkTrafficModel</name>
    <message>
        <location filename="../app/gui/network_traffic_model.cpp" line="+203"/>
        <source>Request: %1</source>
        <translation>Kérés: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Reply: %1</source>
        <translation>Válasz: %1</translation>
    </message>
    <message>
        <location line="+54"/>
        <source>When the frame&apos;s first byte left: virtual time, seconds.milliseconds.microseconds</source>
        <translation>Amikor a keret első bájtja elindult: virtuális idő, másodperc.ezredmásodperc.mikroszekundum</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The station or device the frame is for; a reply&apos;s is the master</source>
        <translation>Az állomás vagy eszköz, amelynek a keret szól; a válaszé a master</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The address as the receiving PLC&apos;s device, with the address on the wire</source>
        <translation>A cím a fogadó PLC operandusaként, mellette a vezetéken utazó cím</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Bytes (Computer Link), registers or bits (MODBUS), words, present values or flags (Host Link), characters (text)</source>
        <translation>Bájtok (Computer Link), regiszterek vagy bitek (MODBUS), szavak, aktuális értékek vagy jelzők (Host Link), karakterek (szöveg)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The PLC&apos;s error or exception code, or what is wrong with the frame</source>
        <translation>A PLC hiba- vagy kivételkódja, vagy hogy mi a hiba a keretben</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>A fault or a collision that changed the frame</source>
        <translation>Hiba vagy ütközés, amely megváltoztatta a keretet</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Time (s)</source>
        <translation>Idő (s)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Wire</source>
        <translation>Vezeték</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Sender</source>
        <translation>Küldő</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Receiver</source>
        <translation>Címzett</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Protocol</source>
        <translation>Protokoll</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Station</source>
        <translation>Állomás</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Command</source>
        <translation>Parancs</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Address</source>
        <translation>Cím</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Count</source>
        <translation>Darab</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Data</source>
        <translation>Adat</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Error</source>
        <translation>Hiba</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Note</source>
        <translation>Megjegyzés</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Bytes</source>
        <translation>Bájtok</translation>
    </message>
</context>
<context>
    <name>rung::app::NetworkTrafficView</name>
    <message>
        <location filename="../app/gui/network_traffic_view.cpp" line="+171"/>
        <source>&amp;Errors only</source>
        <translation>Csak &amp;hibák</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Save...</source>
        <translation>&amp;Mentés...</translation>
    </message>
    <message>
        <location line="-2"/>
        <source>Only the frames with an error code, a problem (a wrong sum or CRC, a frame cut short) or a fault&apos;s note</source>
        <translation>Csak a hibakódos, hibás (rossz összeg vagy CRC, csonka keret) vagy hibajelzéssel (fault) megjelölt keretek</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Save the frames shown as CSV or as text</source>
        <translation>A látható keretek mentése CSV-ként vagy szövegként</translation>
    </message>
    <message>
        <location line="-7"/>
        <source>&amp;Wire:</source>
        <translation>&amp;Vezeték:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>S&amp;tation:</source>
        <translation>Ál&amp;lomás:</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>All wires</source>
        <translation>Minden vezeték</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>All stations</source>
        <translation>Minden állomás</translation>
    </message>
    <message numerus="yes">
        <location line="+129"/>
        <source>%n frame(s)</source>
        <translation>
            <numerusform>%n keret</numerusform>
        </translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 of %2 frames</source>
        <translation>%1 / %2 keret</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 older frames were let go (the view keeps the last %2)</source>
        <translation>%1 régebbi keret elengedve (a nézet az utolsó %2 keretet tartja meg)</translation>
    </message>
    <message>
        <location line="+9"/>
        <location line="+22"/>
        <location line="+9"/>
        <location line="+27"/>
        <source>Cannot write %1: %2</source>
        <translation>Nem írható: %1: %2</translation>
    </message>
    <message>
        <location line="-19"/>
        <source>%1 older frames were let go before these (the view keeps the last %2)</source>
        <translation>ezek előtt %1 régebbi keret elengedve (a nézet az utolsó %2 keretet tartja meg)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 of %2 frames: wire %3, station %4%5</source>
        <translation>%1 / %2 keret: vezeték: %3, állomás: %4%5</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+1"/>
        <source>all</source>
        <translation>mind</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>, errors only</source>
        <translation>, csak hibák</translation>
    </message>
    <message>
        <location line="+19"/>
        <location line="+9"/>
        <location line="+10"/>
        <source>Save Traffic</source>
        <translation>Adatforgalom mentése</translation>
    </message>
    <message>
        <location line="-18"/>
        <source>CSV (*.csv);;Text, as rungstudio-cli writes it (*.txt)</source>
        <translation>CSV (*.csv);;Szöveg, ahogy a rungstudio-cli írja (*.txt)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 already exists. Replace it?</source>
        <translation>%1 már létezik. Lecseréli?</translation>
    </message>
</context>
<context>
    <name>rung::app::NetworkView</name>
    <message>
        <location filename="../app/gui/network_canvas.cpp" line="+59"/>
        <source>%1: scan period %2 ms</source>
        <translation>%1: ciklusidő %2 ms</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>scan period %1 ms</source>
        <translation>ciklusidő %1 ms</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>program not readable</source>
        <translation>a program nem olvasható</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>station %1, %2 %3</source>
        <translation>%1. állomás, %2 %3</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>, %1 slaves, range %2</source>
        <translation>, %1 slave, %2. tartomány</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>master</source>
        <translation>master</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>slave</source>
        <translation>slave</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>settings refused</source>
        <translation>a beállítások hibásak</translation>
    </message>
    <message>
        <location filename="../app/gui/network_view.cpp" line="+209"/>
        <source>bridge: failed (%1)</source>
        <extracomment>a bridge whose line did not open; the tooltip says why</extracomment>
        <translation>híd: hibás (%1)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>pseudo-terminal</source>
        <translation>pszeudoterminál</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>bridge: pseudo-terminal</source>
        <extracomment>%1 the pseudo-terminal&apos;s path while the network runs</extracomment>
        <translation>híd: pszeudoterminál</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>bridge: pseudo-terminal %1</source>
        <translation>híd: pszeudoterminál %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>bridge: serial %1</source>
        <translation>híd: soros port %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>bridge: TCP to %1</source>
        <translation>híd: TCP ide: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>bridge: listens on %1</source>
        <translation>híd: figyel itt: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/network_canvas.cpp" line="+20"/>
        <source>MODBUS slave (simulated)</source>
        <translation>MODBUS slave (szimulált)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>serial line (simulated)</source>
        <translation>soros vonal (szimulált)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>station %1, %2</source>
        <translation>%1. állomás, %2</translation>
    </message>
    <message>
        <location line="+154"/>
        <source>dashed: no frames on the wire (the manual does not publish them)</source>
        <translation>szaggatott: a vezetéken nincsenek keretek (a kézikönyv nem közli őket)</translation>
    </message>
    <message>
        <location filename="../app/gui/network_view.cpp" line="-103"/>
        <source>Network</source>
        <translation>Hálózat</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>%1 is a simulated device: edit it in the network file</source>
        <translation>%1 szimulált eszköz: a hálózatfájlban szerkeszthető</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Remove Station</source>
        <translation>Állomás eltávolítása</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Remove station %1? With it:
%2
(Edit &gt; Undo brings it back.)</source>
        <translation>Eltávolítja a(z) %1 állomást? Vele együtt:
%2
(A Szerkesztés &gt; Visszavonás visszahozza.)</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>Add Station from Program</source>
        <translation>Állomás programból</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Programs (*.rung *.il *.ladder);;All files (*)</source>
        <translation>Programok (*.rung *.il *.ladder);;Minden fájl (*)</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Network Period</source>
        <translation>Hálózati ciklusidő</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Scan period of the stations that give none (ms):</source>
        <translation>A saját ciklusidőt nem adó állomások ciklusideje (ms):</translation>
    </message>
    <message>
        <location line="+84"/>
        <source>&amp;Pseudo-terminal</source>
        <translation>&amp;Pszeudoterminál</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&amp;Serial Port...</source>
        <translation>&amp;Soros port...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>TCP &amp;Listen...</source>
        <translation>TCP-&amp;figyelés...</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Port &amp;Settings...</source>
        <translation>Port &amp;beállításai...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Disconnect</source>
        <translation>&amp;Leválasztás</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>Add New Pro&amp;ject Station...</source>
        <translation>Állomás új pro&amp;jekttel...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Network Period...</source>
        <translation>&amp;Hálózati ciklusidő...</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Zoom O&amp;ut</source>
        <translation>&amp;Kicsinyítés</translation>
    </message>
    <message>
        <location line="+51"/>
        <location line="+10"/>
        <source>Save Network</source>
        <translation>Hálózat mentése</translation>
    </message>
    <message>
        <location line="-9"/>
        <source>%1 cannot hold everything in this network:
%2

Save anyway, leaving this out of the file?</source>
        <translation>A(z) %1 nem tudja megőrizni a hálózat minden részét:
%2

Menti mégis, ezek nélkül?</translation>
    </message>
    <message>
        <location line="-67"/>
        <source>Remove &amp;Wire</source>
        <translation>&amp;Vezeték eltávolítása</translation>
    </message>
    <message>
        <location line="-47"/>
        <source>&amp;Bridge To</source>
        <translation>Híd &amp;ide</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>&amp;TCP Device Server...</source>
        <translation>&amp;TCP-eszközszerver...</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>Edit &amp;Bridge...</source>
        <translation>Hí&amp;d szerkesztése...</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Copy %1</source>
        <translation>%1 má&amp;solása</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Remove Brid&amp;ge</source>
        <translation>Híd &amp;törlése</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>&amp;Open Program</source>
        <translation>Program &amp;megnyitása</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Remove Station %1...</source>
        <translation>%1 állomás &amp;eltávolítása...</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Add Station from &amp;Program...</source>
        <translation>Állomás &amp;programból...</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Zoom &amp;In</source>
        <translation>&amp;Nagyítás</translation>
    </message>
</context>
<context>
    <name>rung::app::NetworkWatchModel</name>
    <message>
        <location filename="../app/gui/network_watch_model.cpp" line="+49"/>
        <source>No network is open</source>
        <translation>Nincs megnyitott hálózat</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1: write STATION/DEVICE, e.g. %2 (stations: %3)</source>
        <extracomment>%1 what was typed, %2 the stations, e.g. &quot;master, s5, s2&quot;</extracomment>
        <translation>%1: ÁLLOMÁS/OPERANDUS alakban írja, pl. %2 (állomások: %3)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1: no station &quot;%2&quot; (stations: %3)</source>
        <translation>%1: nincs „%2” nevű állomás (állomások: %3)</translation>
    </message>
    <message>
        <location line="+71"/>
        <location line="+42"/>
        <source>ON</source>
        <translation>BE</translation>
    </message>
    <message>
        <location line="-42"/>
        <source>OFF</source>
        <translation>KI</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Station/Device</source>
        <translation>Állomás/operandus</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Value</source>
        <translation>Érték</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Model</source>
        <extracomment>the PLC model of the row&apos;s station (&quot;VB&quot;, &quot;PL110-2A&quot;)</extracomment>
        <translation>Modell</translation>
    </message>
</context>
<context>
    <name>rung::app::NetworkWindow</name>
    <message>
        <location filename="../app/gui/network_window.cpp" line="+263"/>
        <location line="+222"/>
        <source>Network</source>
        <translation>Hálózat</translation>
    </message>
    <message>
        <location line="-219"/>
        <source>&amp;Network</source>
        <translation>&amp;Hálózat</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Edit Station Program</source>
        <translation>Állomás programjának &amp;szerkesztése</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&amp;Save Network</source>
        <translation>Hálózat &amp;mentése</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Save Network &amp;As...</source>
        <translation>Hálózat mentése más&amp;ként...</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Close Network</source>
        <translation>Hálózat &amp;bezárása</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Edit</source>
        <translation>&amp;Szerkesztés</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Undo</source>
        <translation>&amp;Visszavonás</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Redo</source>
        <translation>&amp;Mégis</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Add Station From a &amp;Program...</source>
        <translation>Állomás hozzáadása &amp;programból...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Add Station as a &amp;New Project...</source>
        <translation>Állomás hozzáadása ú&amp;j projektként...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Network Peri&amp;od...</source>
        <translation>Hálózati &amp;ciklusidő...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Simulation</source>
        <translation>Szi&amp;muláció</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1 (%2)</source>
        <extracomment>a toolbar button&apos;s tooltip: its name and its key</extracomment>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&amp;Run</source>
        <translation>&amp;Futtatás</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&amp;Pause</source>
        <translation>&amp;Szünet</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Stop</source>
        <translation>&amp;Megállás</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Single S&amp;can</source>
        <translation>Egy &amp;ciklus</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Run &amp;For...</source>
        <translation>Futtatás &amp;ennyi ideig...</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Run For</source>
        <extracomment>the virtual time to run the network for, in seconds</extracomment>
        <translation>Futtatás ennyi ideig</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Virtual time to run the network for (seconds):</source>
        <translation>A hálózat futtatásának virtuális ideje (másodperc):</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Power C&amp;ycle</source>
        <translation>&amp;Ki-bekapcsolás</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Spee&amp;d</source>
        <translation>Sebessé&amp;g</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>x%1 Real Time</source>
        <translation>x%1 valós idő</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>As &amp;Fast as Possible</source>
        <translation>A lehető &amp;leggyorsabban</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Station:</source>
        <translation>Állomás:</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>F&amp;aults</source>
        <translation>H&amp;ibák</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&amp;View</source>
        <translation>&amp;Nézet</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>No network is open</source>
        <translation>Nincs megnyitott hálózat</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Cut Wire %1 (%2)</source>
        <extracomment>%1 a wire&apos;s name, %2 its ends (&quot;master/CP2, s5/CP2&quot;)</extracomment>
        <translation>%1 vezeték elvágása (%2)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Wire %1 is cut: nothing it carries arrives</source>
        <translation>A(z) %1 vezeték elvágva: semmi sem jut át rajta</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Wire %1 is joined again</source>
        <translation>A(z) %1 vezeték újra összekötve</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Corrupt the Next Frame on %1</source>
        <translation>A következő keret elrontása ezen: %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The next frame on %1 will arrive with its second byte changed</source>
        <translation>A(z) %1 következő kerete megváltozott második bájttal érkezik</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Baud Rate of %1: %2 (changed)...</source>
        <extracomment>%1 a station&apos;s port (&quot;s5/CP2&quot;); %2 the rate set by hand, if any</extracomment>
        <translation>%1 átviteli sebessége: %2 (módosítva)...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Change the Baud Rate of %1...</source>
        <translation>%1 átviteli sebességének módosítása...</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Baud Rate</source>
        <translation>Átviteli sebesség</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 sends and reads at (the other ends keep theirs):</source>
        <translation>%1 ezzel a sebességgel küld és olvas (a többi végpont megtartja a sajátját):</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Silence %1</source>
        <translation>%1 elnémítása</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Stop ends every fault made here</source>
        <translation>A Megállás minden itt okozott hibát megszüntet</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Stations</source>
        <translation>Állomások</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Inputs and Outputs</source>
        <translation>Be- és kimenetek</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Front Panel</source>
        <translation>Előlap</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Network Watch</source>
        <translation>Hálózat figyelése</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Station/device, e.g. %1</source>
        <translation>Állomás/operandus, pl. %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Watch</source>
        <translation>&amp;Figyelés</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Remove From Watch</source>
        <translation>Eltávolítás a figyelésből</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Add to the Timing Chart</source>
        <translation>Hozzáadás az idődiagramhoz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Timing Chart</source>
        <translation>Idődiagram</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Traffic</source>
        <translation>Adatforgalom</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Double-click a station to edit its program</source>
        <translation>Kattintson duplán egy állomásra a programja szerkesztéséhez</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Ladder</source>
        <translation>Létradiagram</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Close Network</source>
        <translation>Hálózat bezárása</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 has edits that are not saved. Save them?</source>
        <translation>%1 nem mentett módosításokat tartalmaz. Menti őket?</translation>
    </message>
    <message>
        <location filename="../app/gui/network_window_session.cpp" line="+73"/>
        <source>%1: the listing does not draw as a ladder</source>
        <translation>%1: az utasításlista nem rajzolható létradiagramként</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>An empty network: add stations from the Network view&apos;s menu (right click)</source>
        <translation>Üres hálózat: állomásokat a Hálózat nézet menüjéből adhat hozzá (jobb kattintás)</translation>
    </message>
    <message>
        <location line="+41"/>
        <source>The network has no station yet: add one from the Network view&apos;s menu</source>
        <translation>A hálózatnak még nincs állomása: adjon hozzá egyet a Hálózat nézet menüjéből</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>A station&apos;s program is edited in the main window: Network &gt; Edit Station Program; Stop reads it again</source>
        <translation>Az állomás programja a főablakban szerkeszthető: Hálózat &gt; Állomás programjának szerkesztése; a Megállás újra beolvassa</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1 (%2 %3)</source>
        <extracomment>a station in the selector: its name, the PLC family and model, e.g. &quot;s5 (Vigor M/VB/VH VB)&quot;</extracomment>
        <translation>%1 (%2 %3)</translation>
    </message>
    <message>
        <location line="+50"/>
        <source>The network was edited: Stop builds it again with the change</source>
        <translation>A hálózat módosult: a Megállás a módosítással építi fel újra</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>%1%2 - Network - Rung Studio</source>
        <extracomment>the window&apos;s title: the network file&apos;s name, * when it has unsaved edits</extracomment>
        <translation>%1%2 - Hálózat - Rung Studio</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Save Network</source>
        <translation>Hálózat mentése</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Networks of PLCs (*.rungnet)</source>
        <translation>PLC-hálózatok (*.rungnet)</translation>
    </message>
    <message>
        <location line="+72"/>
        <source>No network</source>
        <translation>Nincs hálózat</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Running</source>
        <translation>Fut</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Stepping</source>
        <translation>Léptetés</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Paused</source>
        <translation>Szüneteltetve</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Stopped</source>
        <translation>Leállítva</translation>
    </message>
    <message numerus="yes">
        <location line="+4"/>
        <source>%1, %2, %n station(s)</source>
        <extracomment>%1 run state, %2 virtual time, %3 number of stations</extracomment>
        <translation>
            <numerusform>%1, %2, %n állomás</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>rung::app::Online</name>
    <message>
        <location filename="../app/cli/cli_online.cpp" line="+17"/>
        <source>usage:</source>
        <translation>használat:</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>%1 needs a value</source>
        <translation>%1 után érték kell</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>unknown option %1</source>
        <translation>ismeretlen kapcsoló: %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>--target and --protocol are needed</source>
        <translation>a --target és a --protocol megadása kötelező</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>unknown target %1</source>
        <translation>ismeretlen célrendszer: %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>unknown protocol %1: vigor, modbus, modbus-tcp or hostlink</source>
        <translation>ismeretlen protokoll: %1; lehet vigor, modbus, modbus-tcp vagy hostlink</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>give exactly one of --port, --tcp and --pty</source>
        <translation>a --port, a --tcp és a --pty közül pontosan egyet adjon meg</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>modbus-tcp needs --tcp HOST:PORT (for RTU frames on a port: modbus)</source>
        <translation>a modbus-tcp a --tcp HOST:PORT kapcsolót igényli (RTU keretekhez porton: modbus)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>--tcp needs HOST:PORT, e.g. 127.0.0.1:502; got %1</source>
        <translation>a --tcp HOST:PORT alakú értéket vár, pl. 127.0.0.1:502; kapott érték: %1</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>%1 must be a number from %2 to %3; got %4</source>
        <translation>%1 értéke %2 és %3 közötti szám legyen; kapott érték: %4</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>--frame must be data bits, parity and stop bits, e.g. 8N1 or 7E2; got %1</source>
        <translation>a --frame adatbitek, paritás és stopbitek megadása, pl. 8N1 vagy 7E2; kapott érték: %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>no device given</source>
        <translation>nincs megadva operandus</translation>
    </message>
    <message>
        <location line="+74"/>
        <source>  rungstudio-cli read  --target T --protocol vigor|modbus|modbus-tcp|hostlink
        (--port NAME | --tcp HOST:PORT | --pty PATH) [--station N] [--baud B]
        [--frame 8N1] [--timeout MS] [--retries N] DEVICE...
  rungstudio-cli write (the same options) DEVICE=VALUE...
Exit status of read and write: 0 done, 1 the PLC did not answer or refused, 2 usage, device, value or port error.</source>
        <translation>  rungstudio-cli read  --target T --protocol vigor|modbus|modbus-tcp|hostlink
        (--port NÉV | --tcp HOST:PORT | --pty ÚTVONAL) [--station N] [--baud B]
        [--frame 8N1] [--timeout MS] [--retries N] OPERANDUS...
  rungstudio-cli write (ugyanezek a kapcsolók) OPERANDUS=ÉRTÉK...
A read és a write kilépési kódja: 0 kész, 1 a PLC nem válaszolt vagy elutasította, 2 használati, operandus-, érték- vagy porthiba.</translation>
    </message>
    <message>
        <location line="+69"/>
        <source>%1: write DEVICE=VALUE</source>
        <translation>%1: OPERANDUS=ÉRTÉK alakban adja meg</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1: %2 is not a value for %3 (a bit takes 0 or 1, ON or OFF; a word a number, 0x for hexadecimal)</source>
        <translation>%1: a(z) %2 nem lehet %3 értéke (egy bit 0 vagy 1, ON vagy OFF; egy szó szám, hexadecimálisan 0x előtaggal)</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>note: %1</source>
        <translation>megjegyzés: %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>not written: %1</source>
        <translation>nem íródott ki: %1</translation>
    </message>
    <message>
        <location line="-16"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
</context>
<context>
    <name>rung::app::OnlineController</name>
    <message>
        <location filename="../app/gui/online_controller.cpp" line="+74"/>
        <source>Go Online</source>
        <translation>Online kapcsolódás</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The simulation is running. Going online pauses it: the views then show the PLC&apos;s values. Go online?</source>
        <translation>A szimuláció fut. Az online kapcsolódás szünetelteti: a nézetek ezután a PLC értékeit mutatják. Kapcsolódik?</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Simulate</source>
        <translation>Szimuláció</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>The IDE is online to %1. Go offline to simulate?</source>
        <translation>Az IDE online kapcsolatban van ezzel: %1. Bontja a kapcsolatot a szimulációhoz?</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The simulation stays paused while the IDE is online</source>
        <translation>A szimuláció szünetel, amíg az IDE online</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>Connection</source>
        <translation>Kapcsolat</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Online</source>
        <translation>&amp;Online</translation>
    </message>
    <message>
        <location line="+7"/>
        <location line="+73"/>
        <source>Go &amp;Online</source>
        <translation>&amp;Online kapcsolódás</translation>
    </message>
    <message>
        <location line="-63"/>
        <source>&amp;Test Connection</source>
        <translation>Kapcsolat &amp;tesztelése</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>PLC to &amp;STOP / PROGRAM</source>
        <translation>PLC &amp;STOP / PROGRAM módba</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>PLC to &amp;MONITOR</source>
        <translation>PLC &amp;MONITOR módba</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>PLC to &amp;RUN</source>
        <translation>PLC &amp;RUN módba</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Release All &amp;Forces in the PLC</source>
        <translation>Minden &amp;kényszerítés feloldása a PLC-ben</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Online: %1</source>
        <translation>Online: %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Going online. The IDE cannot know whether the PLC runs the program shown: compare by reading devices</source>
        <translation>Online kapcsolódás. Az IDE nem tudhatja, hogy a PLC a látható programot futtatja-e: hasonlítsa össze operandusok olvasásával</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Offline</source>
        <translation>Offline</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1 cannot switch the PLC between RUN and STOP: use the switch on the PLC</source>
        <translation>A(z) %1 nem tudja a PLC-t RUN és STOP között váltani: használja a PLC kapcsolóját</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Go &amp;Offline</source>
        <translation>&amp;Offline (kapcsolat bontása)</translation>
    </message>
</context>
<context>
    <name>rung::app::PlcopenImportDialog</name>
    <message>
        <location filename="../app/gui/plcopen_exchange.cpp" line="+34"/>
        <location line="+16"/>
        <source>Cannot export</source>
        <translation>Az exportálás nem sikerült</translation>
    </message>
    <message>
        <location line="-11"/>
        <location line="+17"/>
        <source>Export PLCopen XML</source>
        <translation>PLCopen XML exportálása</translation>
    </message>
    <message>
        <location line="-16"/>
        <source>PLCopen XML (*.xml)</source>
        <translation>PLCopen XML (*.xml)</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Import PLCopen XML</source>
        <translation>PLCopen XML importálása</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PLCopen XML (*.xml);;All files (*)</source>
        <translation>PLCopen XML (*.xml);;Minden fájl (*)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Cannot open the file</source>
        <translation>A fájl nem nyitható meg</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Import PLCopen XML: %1</source>
        <translation>PLCopen XML importálása: %1</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>PLC family:</source>
        <translation>PLC-család:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Model:</source>
        <translation>Modell:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Variables without a device: a free one is proposed; change it where the program needs another.</source>
        <translation>Operandus nélküli változók: a program egy szabad operandust javasol; írjon be mást, ahol a program mást kíván.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Variable</source>
        <translation>Változó</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Type</source>
        <translation>Típus</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Line</source>
        <translation>Sor</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Device</source>
        <translation>Operandus</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Not imported (element, line and why):</source>
        <translation>Nem kerül beolvasásra (elem, sor és ok):</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Import the rest and leave out what is listed</source>
        <translation>A többi beolvasása, a felsoroltak kihagyásával</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>&amp;Import</source>
        <translation>&amp;Beolvasás</translation>
    </message>
    <message>
        <location line="+23"/>
        <location line="+53"/>
        <source>(no such device)</source>
        <translation>(nincs ilyen operandus)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>line %1: %2: %3</source>
        <translation>%1. sor: %2: %3</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The file holds no ladder to import.</source>
        <translation>A fájlban nincs beolvasható létradiagram.</translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>Everything in the file is imported: %n rung(s).</source>
        <translation>
            <numerusform>A fájl teljes tartalma beolvasásra kerül: %n létrafok.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>%n item(s) of the file are not imported; %1 variable(s) have no device yet.</source>
        <translation>
            <numerusform>A fájl %n eleme nem kerül beolvasásra; %1 változónak még nincs operandusa.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+31"/>
        <source>Some variables still have no device: give each one a device of %1.</source>
        <translation>Néhány változónak még nincs operandusa: adjon mindegyiknek egy %1 operandust.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The file holds what %1 cannot take, listed here. Tick &quot;%2&quot; to import the rest.</source>
        <translation>A fájlban olyasmi van, amit a(z) %1 nem tud fogadni, itt felsorolva. A többi beolvasásához jelölje be: „%2”.</translation>
    </message>
    <message>
        <location line="-198"/>
        <source>%1 is written. Other tools will read it, with these notes:

%2</source>
        <translation>A(z) %1 kiíródott. Más eszközök beolvassák, ezekkel a megjegyzésekkel:

%2</translation>
    </message>
    <message>
        <location line="+168"/>
        <source>Imported, but working otherwise than in the file:</source>
        <translation>Beolvasva, de a fájlban leírttól eltérően működik:</translation>
    </message>
</context>
<context>
    <name>rung::app::PortOptions</name>
    <message>
        <location filename="../app/cli/cli_port_options.cpp" line="+16"/>
        <source>unexpected argument %1</source>
        <translation>váratlan argumentum: %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 needs a value</source>
        <translation>%1 után érték kell</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>--baud must be a number from 50 to 4000000; got %1</source>
        <translation>a --baud 50 és 4000000 közötti szám legyen; kapott érték: %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>--frame must be data bits, parity and stop bits, e.g. 8N1 or 7E2; got %1</source>
        <translation>a --frame adatbitek, paritás és stopbitek megadása, pl. 8N1 vagy 7E2; kapott érték: %1</translation>
    </message>
</context>
<context>
    <name>rung::app::ProgramExport</name>
    <message>
        <location filename="../app/gui/ladder_export.cpp" line="+82"/>
        <source>%1 could not be written</source>
        <translation>%1 nem írható</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>%1: the ladder can be exported as PDF, SVG or PNG</source>
        <translation>%1: a létradiagram PDF, SVG vagy PNG formátumba exportálható</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>%1    page %2 of %3</source>
        <translation>%1    %2. oldal / %3</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Instruction list, line %1: %2</source>
        <translation>Utasításlista, %1. sor: %2</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+7"/>
        <source>Rung %1: %2</source>
        <translation>%1. létrafok: %2</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Rung %1 is not in the list: %2</source>
        <translation>A(z) %1. létrafok nincs a listában: %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Nothing was written: the instruction list would not hold the whole program.
%1</source>
        <translation>Semmi sem íródott ki: az utasításlista nem tartalmazná a teljes programot.
%1</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
</context>
<context>
    <name>rung::app::Record</name>
    <message>
        <location filename="../app/cli/cli_record.cpp" line="+38"/>
        <source>  rungstudio-cli record --pc PORT --plc PORT [--baud B] [--frame 8N1] [-o FILE]
        [--seconds S]   (PORT: a serial port, a /dev/pts path, or pty for a new one)</source>
        <translation>  rungstudio-cli record --pc PORT --plc PORT [--baud B] [--frame 8N1] [-o FILE]
        [--seconds S]   (PORT: soros port, /dev/pts útvonal, vagy pty egy újhoz)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>usage:</source>
        <translation>használat:</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>--pc and --plc are needed: the two ports to join</source>
        <translation>a --pc és a --plc kell: az összekötendő két port</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>--seconds must be a positive number; got %1</source>
        <translation>a --seconds pozitív szám legyen; kapott érték: %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the PC&apos;s side: %1</source>
        <translation>a PC oldala: %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the PLC&apos;s side: %1</source>
        <translation>a PLC oldala: %1</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>cannot write %1: %2</source>
        <translation>%1 nem írható: %2</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Passing bytes between %1 (PC) and %2 (PLC); stop with Ctrl+C</source>
        <translation>Bájtok továbbítása %1 (PC) és %2 (PLC) között; leállítás: Ctrl+C</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>%1 bytes from the PC, %2 bytes from the PLC, in %3 records</source>
        <translation>%1 bájt a PC-től, %2 bájt a PLC-től, %3 bejegyzésben</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 records were lost: the capture was not written as fast as they came</source>
        <translation>%1 bejegyzés elveszett: a felvétel írása nem tartott lépést az érkezésükkel</translation>
    </message>
</context>
<context>
    <name>rung::app::RecoveryFile</name>
    <message>
        <location filename="../app/gui/recovery.cpp" line="+84"/>
        <source>The recovery file could not be written: %1</source>
        <translation>A helyreállítási fájl nem írható: %1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The recovery file could not be written: %1: %2</source>
        <translation>A helyreállítási fájl nem írható: %1: %2</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>%1 could not be read and is kept: %2</source>
        <translation>A(z) %1 nem olvasható, ezért megmaradt: %2</translation>
    </message>
</context>
<context>
    <name>rung::app::ScanDebuggerView</name>
    <message>
        <location filename="../app/gui/scan_debugger_view.cpp" line="+23"/>
        <source>ON</source>
        <translation>BE</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>OFF</source>
        <translation>KI</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1: %2 (top)</source>
        <extracomment>a stack entry: %1 depth (1 = bottom), %2 ON/OFF</extracomment>
        <translation>%1: %2 (teteje)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>(empty)</source>
        <translation>(üres)</translation>
    </message>
    <message>
        <location line="+151"/>
        <source>Logic result:</source>
        <translation>Logikai eredmény:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Step Instruction</source>
        <translation>Lépés egy utasítással</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Finish Scan</source>
        <translation>Ciklus befejezése</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Continue</source>
        <translation>Folytatás</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Breakpoints:</source>
        <translation>Töréspontok:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Where</source>
        <translation>Hol</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Stops</source>
        <translation>Megáll</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Condition...</source>
        <translation>Feltétel...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Remove</source>
        <translation>Eltávolítás</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Remove All</source>
        <translation>Mindet eltávolítja</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>Block stack (%1 / %2):</source>
        <translation>Blokkverem (%1 / %2):</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 stack:</source>
        <translation>%1-verem:</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Not stopped inside a scan. Step Instruction starts a scan and stops before its first instruction; a breakpoint stops a running scan.</source>
        <translation>Nincs megállítva ciklus közben. A Lépés egy utasítással ciklust indít, és az első utasítása előtt megáll; a töréspont a futó ciklust állítja meg.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The simulation is off.</source>
        <translation>A szimuláció ki van kapcsolva.</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Stopped before step %1 (line %2, rung %3): %4</source>
        <extracomment>%1 step, %2 line, %3 rung, %4 the instruction, e.g. &quot;OUT Y0&quot;</extracomment>
        <translation>Megállva a(z) %1. lépés előtt (%2. sor, %3. létrafok): %4</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Stopped at the end of the program</source>
        <translation>Megállva a program végén</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>A breakpoint stopped the scan.</source>
        <translation>Töréspont állította meg a ciklust.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stepping one instruction at a time.</source>
        <translation>Léptetés utasításonként.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Inside an interlock (IL/MC) whose condition is OFF</source>
        <translation>Olyan reteszelésen (IL/MC) belül, amelynek feltétele KI</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Inside a step (STL) that is not active</source>
        <translation>Nem aktív lépésen (STL) belül</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Rung %1 (no longer there)</source>
        <translation>%1. létrafok (már nincs meg)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Rung %1, line %2: %3</source>
        <extracomment>%1 rung, %2 line, %3 the instruction</extracomment>
        <translation>%1. létrafok, %2. sor: %3</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>No breakpoint is set: Ctrl+B sets one where the cursor is</source>
        <translation>Nincs töréspont: a Ctrl+B a kurzor helyére tesz egyet</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Choose a breakpoint in the list first</source>
        <translation>Előbb válasszon egy töréspontot a listában</translation>
    </message>
</context>
<context>
    <name>rung::app::Serve</name>
    <message>
        <location filename="../app/cli/cli_serve.cpp" line="+188"/>
        <source>unexpected argument %1</source>
        <translation>váratlan argumentum: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 needs a valid value</source>
        <translation>a(z) %1 kapcsolóhoz érvényes érték kell</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>no FILE given</source>
        <translation>nincs megadva FILE</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>--protocol is required</source>
        <translation>a --protocol megadása kötelező</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unknown protocol %1 (vigor, modbus, modbus-tcp, hostlink)</source>
        <translation>ismeretlen protokoll: %1 (vigor, modbus, modbus-tcp, hostlink)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>give one of --pty, --port NAME and --tcp HOST:PORT</source>
        <translation>adja meg a --pty, a --port NAME és a --tcp HOST:PORT közül pontosan egyet</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>--protocol modbus-tcp is served over --tcp HOST:PORT</source>
        <translation>a --protocol modbus-tcp a --tcp HOST:PORT kapcsolón szolgál ki</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>--tcp needs HOST:PORT with a numeric address, e.g. 127.0.0.1:1502, not %1</source>
        <translation>a --tcp numerikus címet és portot vár (HOST:PORT), pl. 127.0.0.1:1502, nem ezt: %1</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>--frame needs data bits, parity and stop bits, e.g. 8N1 or 7E2, not %1</source>
        <translation>a --frame adatbitet, paritást és stopbitet vár, pl. 8N1 vagy 7E2, nem ezt: %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>--station %1 is outside %2..%3, the stations of %4</source>
        <translation>a(z) %1. állomás kívül esik a(z) %4 állomásszámain (%2..%3)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>unknown fault %1 (%2)</source>
        <translation>ismeretlen hibamód: %1 (%2)</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>%1 does not speak %2; it speaks %3</source>
        <translation>a(z) %1 nem ismeri ezt: %2; ezeket ismeri: %3</translation>
    </message>
    <message>
        <location line="+45"/>
        <source>%1 serves %2 (%3, %4, station %5) on %6; stop it with Ctrl+C</source>
        <translation>a(z) %1 kiszolgálja: %2 (%3, %4, %5. állomás), itt: %6; leállítás: Ctrl+C</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>%1 requests answered, %2 refused with an error, %3 for other stations or broadcast, %4 frames dropped; %5 writes</source>
        <translation>%1 kérés megválaszolva, %2 hibakóddal elutasítva, %3 más állomásnak szólt vagy körözvény volt, %4 keret eldobva; %5 írás</translation>
    </message>
    <message>
        <location line="-304"/>
        <source>usage: rungstudio-cli serve FILE [--target T] [--model M] --protocol vigor|modbus|modbus-tcp|hostlink (--pty [--link PATH] | --port NAME | --tcp HOST:PORT) [--station N] [--baud B] [--frame 8N1|7E1|7E2|...] [--period MS] [--fault bad-checksum|silent|wrong-station|garbage|truncated|split]</source>
        <translation>használat: rungstudio-cli serve FILE [--target T] [--model M] --protocol vigor|modbus|modbus-tcp|hostlink (--pty [--link PATH] | --port NAME | --tcp HOST:PORT) [--station N] [--baud B] [--frame 8N1|7E1|7E2|...] [--period MS] [--fault bad-checksum|silent|wrong-station|garbage|truncated|split]</translation>
    </message>
    <message>
        <location line="+46"/>
        <source>--link %1: %2</source>
        <translation>--link %1: %2</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>--link %1: something that is not a link to a pseudo-terminal is there already; it is left as it is: remove it or give another path</source>
        <translation>--link %1: ott már van valami, ami nem pszeudoterminálra mutató hivatkozás; érintetlen marad: törölje, vagy adjon meg másik útvonalat</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>--link %1: the link cannot be made: %2</source>
        <translation>--link %1: a hivatkozás nem hozható létre: %2</translation>
    </message>
    <message>
        <location line="+108"/>
        <source>--link names the pseudo-terminal of --pty (a port keeps its own name, a TCP address is given)</source>
        <translation>a --link a --pty pszeudoterminálját nevezi meg (egy port megtartja a saját nevét, a TCP-cím adott)</translation>
    </message>
    <message>
        <location line="+114"/>
        <source>%1 (a link to %2, removed at the end)</source>
        <translation>%1 (hivatkozás erre: %2, a végén törlődik)</translation>
    </message>
    <message>
        <location line="-54"/>
        <source>%1 has no published protocol to serve (its manual gives none)</source>
        <translation>a(z) %1 PLC-nek nincs nyilvános protokollja, amelyen kiszolgálható lenne (a kézikönyve sem ad meg ilyet)</translation>
    </message>
</context>
<context>
    <name>rung::app::Simulate</name>
    <message>
        <location filename="../app/cli/cli_simulate.cpp" line="+17"/>
        <source>usage: rungstudio-cli simulate FILE [--target T] [--model M] --scans N [--period MS] [--set DEV=VALUE@SCAN]... --trace DEV[,DEV...]
FILE is a listing (.il), a ladder text (.ladder) or a project (.rung).</source>
        <translation>használat: rungstudio-cli simulate FÁJL [--target T] [--model M] --scans N [--period MS] [--set OPERANDUS=ÉRTÉK@CIKLUS]... --trace OPERANDUS[,OPERANDUS...]
A FÁJL utasításlista (.il), létradiagram-szöveg (.ladder) vagy projekt (.rung).</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>%1 needs a value</source>
        <translation>%1 után érték kell</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>unexpected argument %1</source>
        <translation>váratlan argumentum: %1</translation>
    </message>
    <message>
        <location filename="../app/cli/cli_load_program.cpp" line="+47"/>
        <location line="+7"/>
        <location line="+33"/>
        <source>the program does not start</source>
        <translation>a program nem indul el</translation>
    </message>
    <message>
        <location filename="../app/cli/cli_simulate.cpp" line="+29"/>
        <source>runtime error at step %1: %2</source>
        <translation>futási hiba a(z) %1. lépésnél: %2</translation>
    </message>
</context>
<context>
    <name>rung::app::SimulationController</name>
    <message numerus="yes">
        <location filename="../app/gui/simulation_controller.cpp" line="+101"/>
        <source>The program has %n error(s): the simulation does not start; the Problems list shows them</source>
        <translation>
            <numerusform>A programban %n hiba van: a szimuláció nem indul el; a Problémák lista mutatja őket</numerusform>
        </translation>
    </message>
    <message>
        <location line="+83"/>
        <source>The edited program has errors: the simulation goes on with the program before the edit (stop it to simulate what is shown)</source>
        <translation>A módosított programban hibák vannak: a szimuláció a módosítás előtti programmal folytatódik (állítsa le, hogy a látható programot szimulálja)</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>The program was edited: the simulation stopped. Run starts the edited program from power-on</source>
        <translation>A program megváltozott: a szimuláció leállt. A Futtatás a módosított programot indítja, a bekapcsolási állapotból</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Online edit: the edited program restarted from power-on</source>
        <translation>Online szerkesztés: a módosított program a bekapcsolási állapotból indult újra</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Online edit: the edited program takes over when the stopped scan ends; the memory is kept</source>
        <translation>Online szerkesztés: a módosított program a megállított ciklus végén lép életbe; a memória megmarad</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Online edit: the edited program runs from the next scan on; the memory is kept</source>
        <translation>Online szerkesztés: a módosított program a következő ciklustól fut; a memória megmarad</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The edited program is for another memory layout: the running memory cannot be kept. Restart it from power-on, or stop the simulation?</source>
        <translation>A módosított program más memóriafelosztású: a futó memória nem tartható meg. Újraindítja a bekapcsolási állapotból, vagy leállítja a szimulációt?</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>no longer uses %1 (their values stay as they are)</source>
        <translation>már nem használja: %1 (értékük változatlan marad)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>now uses %1 (they start from the values the memory holds)</source>
        <translation>most használja: %1 (a memóriában lévő értékekről indulnak)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The edited program %1. Apply it keeping the memory, restart it from power-on, or stop the simulation?</source>
        <extracomment>%1 what changed, e.g. &quot;no longer uses T0 (...); now uses T5 (...)&quot;</extracomment>
        <translation>A módosított program %1. Alkalmazza a memória megtartásával, újraindítja a bekapcsolási állapotból, vagy leállítja a szimulációt?</translation>
    </message>
    <message>
        <location line="+82"/>
        <source> | the program before the edit</source>
        <translation> | a módosítás előtti program</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Simulation off</source>
        <translation>Szimuláció kikapcsolva</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Stopped</source>
        <translation>Leállítva</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Paused</source>
        <translation>Szüneteltetve</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Running x%1</source>
        <translation>Fut x%1</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Running at full speed</source>
        <translation>Fut, teljes sebességgel</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Stepping</source>
        <translation>Léptetés</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 | %2 | %3 scans | scan %4 ms</source>
        <extracomment>%1 run state, %2 simulated time h:mm:ss.cc, %3 scans, %4 scan period in ms</extracomment>
        <translation>%1 | %2 | %3 ciklus | ciklusidő %4 ms</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Evaluation of a scan on this computer: %1 µs (%2..%3)</source>
        <extracomment>the time the last scan took to evaluate on this computer: current, minimum, maximum</extracomment>
        <translation>Egy ciklus kiértékelése ezen a számítógépen: %1 µs (%2..%3)</translation>
    </message>
    <message>
        <location filename="../app/gui/simulation_debug.cpp" line="+117"/>
        <source>always</source>
        <translation>mindig</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>when %1 rises</source>
        <translation>amikor %1 felfut</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>when %1 falls</source>
        <translation>amikor %1 lefut</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>while %1 is ON</source>
        <translation>amíg %1 BE</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>while %1 is OFF</source>
        <translation>amíg %1 KI</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>when %1 %2 %3</source>
        <extracomment>a breakpoint&apos;s condition, e.g. &quot;when D10 &gt; 100&quot;</extracomment>
        <translation>amikor %1 %2 %3</translation>
    </message>
    <message>
        <location filename="../app/gui/simulation_history.cpp" line="+66"/>
        <source>History: rebuilding...</source>
        <translation>Előzmények: újraépítés...</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>No history: the simulation is off</source>
        <translation>Nincsenek előzmények: a szimuláció ki van kapcsolva</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>No history yet: run the simulation</source>
        <translation>Még nincsenek előzmények: futtassa a szimulációt</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Recorded: the last %1 of simulated time (scans %2..%3, %4 MB); at least the last hour is kept</source>
        <extracomment>%1 h:mm:ss of simulated time, %2 %3 first and last scan, %4 memory in MB</extracomment>
        <translation>Rögzítve: a szimulált idő utolsó %1 része (%2..%3. ciklus, %4 MB); legalább az utolsó óra megmarad</translation>
    </message>
</context>
<context>
    <name>rung::app::SimulationMenu</name>
    <message>
        <location filename="../app/gui/simulation_menu.cpp" line="+46"/>
        <source>&amp;Simulation</source>
        <translation>Szi&amp;muláció</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>&amp;Run</source>
        <translation>&amp;Futtatás</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Pause</source>
        <translation>&amp;Szünet</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Stop (Back to Power-On)</source>
        <translation>&amp;Leállítás (bekapcsolási állapot)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Single S&amp;can</source>
        <translation>Egy &amp;ciklus</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Po&amp;wer Cycle</source>
        <translation>&amp;Ki-bekapcsolás</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Run Sc&amp;ans...</source>
        <translation>Ciklus&amp;ok futtatása...</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Run Scans</source>
        <translation>Ciklusok futtatása</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Scans to run:</source>
        <translation>Futtatandó ciklusok:</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>R&amp;un For...</source>
        <translation>Futtatás enn&amp;yi ideig...</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Run For</source>
        <translation>Futtatás ennyi ideig</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Simulated time to run, in seconds:</source>
        <translation>Szimulált futási idő másodpercben:</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Spee&amp;d</source>
        <translation>S&amp;ebesség</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>x%1 Real Time</source>
        <translation>x%1 valós idő</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>As &amp;Fast as Possible</source>
        <translation>A lehető &amp;leggyorsabban</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Scan Peri&amp;od</source>
        <translation>Cikl&amp;usidő</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 ms</source>
        <extracomment>the virtual scan period, e.g. &quot;10 ms&quot;</extracomment>
        <translation>%1 ms</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Release All &amp;Forces</source>
        <translation>&amp;Minden kényszerítés feloldása</translation>
    </message>
</context>
<context>
    <name>rung::app::SimulationPanel</name>
    <message>
        <location filename="../app/gui/simulation_panel.cpp" line="+161"/>
        <source>Run</source>
        <translation>Futtatás</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Scans:</source>
        <translation>Ciklusok:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Run Scans</source>
        <translation>Ciklusok futtatása</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Simulated time:</source>
        <translation>Szimulált idő:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source> s</source>
        <extracomment>seconds of simulated time</extracomment>
        <translation> s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Run For</source>
        <translation>Futtatás ennyi ideig</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Speed:</source>
        <translation>Sebesség:</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>x%1 real time</source>
        <translation>x%1 valós idő</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>As fast as possible</source>
        <translation>A lehető leggyorsabban</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Scan period:</source>
        <translation>Ciklusidő:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source> ms</source>
        <extracomment>milliseconds</extracomment>
        <translation> ms</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Power Cycle</source>
        <translation>Ki-bekapcsolás</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Off and on again: the retentive areas keep their values, the rest starts as at power-on</source>
        <translation>Ki- és újra bekapcsolás: a remanens területek megtartják értéküket, a többi a bekapcsoláskori állapotból indul</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Statistics</source>
        <translation>Statisztika</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>History</source>
        <translation>Előzmények</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Show scan:</source>
        <translation>Ciklus megjelenítése:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Return to Live</source>
        <translation>Vissza az élő állapothoz</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>The simulation is off: Run, Single Scan or Run Scans starts it.</source>
        <translation>A szimuláció ki van kapcsolva: a Futtatás, az Egy ciklus vagy a Ciklusok futtatása indítja.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Simulated time: %1
Scans: %2
Scan period: %3 ms
Evaluation: %4 µs (%5..%6)</source>
        <extracomment>the statistics block: simulated time, scans, the scan period, the evaluation time of the last scan on this computer (current, minimum..maximum)</extracomment>
        <translation>Szimulált idő: %1
Ciklusok: %2
Ciklusidő: %3 ms
Kiértékelés: %4 µs (%5..%6)</translation>
    </message>
</context>
<context>
    <name>rung::app::SymbolTable</name>
    <message>
        <location filename="../app/gui/symbol_table.cpp" line="+95"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>%1, line %2: %3</source>
        <translation>%1, %2. sor: %3</translation>
    </message>
</context>
<context>
    <name>rung::app::Terminal</name>
    <message>
        <location filename="../app/cli/cli_terminal.cpp" line="+103"/>
        <source>  rungstudio-cli terminal --port PORT [--baud B] [--frame 8N1] [--wait MS]
        (each line of stdin: hex bytes, &quot;text\r&quot;, or a capture line)</source>
        <translation>  rungstudio-cli terminal --port PORT [--baud B] [--frame 8N1] [--wait MS]
        (a szabványos bemenet minden sora: hexa bájtok, &quot;szöveg\r&quot; vagy egy felvétel sora)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>usage:</source>
        <translation>használat:</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>--port is needed</source>
        <translation>a --port kell</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>--wait must be a number from 1 to 60000; got %1</source>
        <translation>a --wait 1 és 60000 közötti szám legyen; kapott érték: %1</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>line %1: &quot;%2&quot; is neither hex bytes (02 30 31), a quoted text (&quot;@00RD\r&quot;) nor a capture line</source>
        <translation>%1. sor: „%2” nem hexa bájtok (02 30 31), nem idézőjeles szöveg (&quot;@00RD\r&quot;) és nem is egy felvétel sora</translation>
    </message>
</context>
<context>
    <name>rung::app::Test</name>
    <message>
        <location filename="../app/cli/cli_test.cpp" line="+46"/>
        <source>  rungstudio-cli test FILE|DIR... [--junit OUT.xml]   (scenario tests, .rungtest)</source>
        <translation>  rungstudio-cli test FILE|DIR... [--junit OUT.xml]   (forgatókönyv-tesztek, .rungtest)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>--junit needs a value</source>
        <translation>a --junit után érték kell</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>unknown option %1</source>
        <translation>ismeretlen kapcsoló: %1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>no scenario given</source>
        <translation>nincs megadva forgatókönyv</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1: no .%2 file in the folder</source>
        <translation>%1: a mappában nincs .%2 fájl</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1: no such file or folder</source>
        <translation>%1: nincs ilyen fájl vagy mappa</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>error</source>
        <translation>hiba</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>note</source>
        <translation>megjegyzés</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1 scenario(s), %2 expectation(s): %3 failed; %4 scenario(s) did not pass</source>
        <extracomment>The summary of a test run: %1 scenario files, %2 expectations, %3 failed expectations, %4 scenarios that failed or did not run.</extracomment>
        <translation>%1 forgatókönyv, %2 elvárás: %3 nem teljesült; %4 forgatókönyv nem ment át</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>cannot write %1: %2</source>
        <translation>%1 nem írható: %2</translation>
    </message>
</context>
<context>
    <name>rung::app::TestsPanel</name>
    <message>
        <location filename="../app/gui/tests_panel.cpp" line="+52"/>
        <source>unknown target %1</source>
        <translation>ismeretlen célrendszer: %1</translation>
    </message>
    <message>
        <location line="+94"/>
        <source>Run All</source>
        <translation>Mind futtatása</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Run</source>
        <translation>Futtatás</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Refresh</source>
        <translation>Frissítés</translation>
    </message>
    <message>
        <location filename="../app/gui/tests_panel_record.cpp" line="+70"/>
        <source>Record...</source>
        <translation>Rögzítés...</translation>
    </message>
    <message>
        <location filename="../app/gui/tests_panel.cpp" line="+2"/>
        <source>Runs the selected scenario</source>
        <translation>A kijelölt forgatókönyv futtatása</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Scenario / expectation</source>
        <translation>Forgatókönyv / elvárás</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Result</source>
        <translation>Eredmény</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Save the project: its scenario tests (.rungtest) are the files beside it that name it</source>
        <translation>Mentse a projektet: a forgatókönyv-tesztjei (.rungtest) a mellette lévő, rá hivatkozó fájlok</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Scenario tests (.rungtest) that name this project, in %1 and below</source>
        <translation>Az ezt a projektet megnevező forgatókönyv-tesztek (.rungtest) itt és alatta: %1</translation>
    </message>
    <message>
        <location line="+53"/>
        <source>%1 names no program: its first statement is `program FILE`</source>
        <translation>%1 nem nevez meg programot: az első utasítása `program FÁJL`</translation>
    </message>
    <message>
        <location line="+44"/>
        <source>the open program has errors: %1</source>
        <translation>a megnyitott programban hibák vannak: %1</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>No scenario test names this project</source>
        <translation>Egy forgatókönyv-teszt sem hivatkozik erre a projektre</translation>
    </message>
    <message>
        <location line="+69"/>
        <source>not run</source>
        <translation>nem futott</translation>
    </message>
    <message numerus="yes">
        <location line="+8"/>
        <source>passed: %n expectation(s)</source>
        <translation>
            <numerusform>sikeres: %n elvárás</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+5"/>
        <source>FAILED: %n expectation(s)</source>
        <translation>
            <numerusform>SIKERTELEN: %n elvárás</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2"/>
        <source>did not run</source>
        <translation>nem futott le</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>line %1</source>
        <translation>%1. sor</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>error: %1</source>
        <translation>hiba: %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <location line="+46"/>
        <source>line %1: %2</source>
        <translation>%1. sor: %2</translation>
    </message>
    <message>
        <location line="-41"/>
        <source>ok</source>
        <translation>rendben</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>FAILED: %1 (double-click: the timing chart)</source>
        <translation>SIKERTELEN: %1 (dupla kattintás: idődiagram)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Scenario tests: %1 passed, %2 failed</source>
        <translation>Forgatókönyv-tesztek: %1 sikeres, %2 sikertelen</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Timing chart of %1, line %2</source>
        <translation>%1 idődiagramja, %2. sor</translation>
    </message>
    <message>
        <location filename="../app/gui/tests_panel_record.cpp" line="+80"/>
        <source>Nothing to record: start a simulation and work its inputs first</source>
        <translation>Nincs mit rögzíteni: előbb indítson szimulációt és kezelje a bemeneteit</translation>
    </message>
    <message>
        <location line="+15"/>
        <location line="+8"/>
        <location line="+7"/>
        <location line="+4"/>
        <location line="+9"/>
        <location line="+6"/>
        <location line="+5"/>
        <source>Record a Scenario</source>
        <translation>Forgatókönyv rögzítése</translation>
    </message>
    <message>
        <location line="-38"/>
        <source>Save the project first: a scenario names the project&apos;s file.</source>
        <translation>Előbb mentse a projektet: a forgatókönyv a projekt fájljára hivatkozik.</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Scenario tests (*.rungtest)</source>
        <translation>Forgatókönyv-tesztek (*.rungtest)</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>Recorded %1</source>
        <translation>Rögzítve: %1</translation>
    </message>
    <message>
        <location line="-142"/>
        <source>Offline: the recording ends here; Stop Recording... writes it</source>
        <translation>Offline: a rögzítés itt véget ér; a Rögzítés leállítása... megírja</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Stop Recording...</source>
        <translation>Rögzítés leállítása...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Writes the scenario of what the PLC did since Record...: its inputs and outputs as each refresh read them</source>
        <translation>Forgatókönyvet ír abból, amit a PLC a Rögzítés... óta tett: a bemeneteit és kimeneteit, ahogy az egyes frissítések kiolvasták őket</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Writes a scenario of the simulation so far: the inputs as you worked them, the outputs as they were seen; online, records what the PLC&apos;s inputs and outputs do until Stop Recording...</source>
        <translation>Forgatókönyvet ír az eddigi szimulációból: a bemeneteket, ahogy kezelte őket, a kimeneteket, ahogy látszottak; online a PLC bemeneteit és kimeneteit rögzíti a Rögzítés leállítása... gombig</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Not online: go online to record what a PLC does</source>
        <translation>Nincs online kapcsolat: lépjen online, hogy rögzítse, mit tesz a PLC</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>The program reads no input and drives no output: nothing to record</source>
        <translation>A program nem olvas bemenetet és nem vezérel kimenetet: nincs mit rögzíteni</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>This PLC&apos;s session keeps no history: it cannot be recorded</source>
        <translation>Ennek a PLC-nek a kapcsolata nem őriz előzményeket: nem rögzíthető</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Recording the PLC&apos;s inputs and outputs: Stop Recording... writes the scenario</source>
        <translation>A PLC bemeneteinek és kimeneteinek rögzítése: a Rögzítés leállítása... megírja a forgatókönyvet</translation>
    </message>
    <message>
        <location line="+107"/>
        <source>%1 is written. What it does not hold:</source>
        <translation>A(z) %1 elkészült. Amit nem tartalmaz:</translation>
    </message>
</context>
<context>
    <name>rung::app::VirtualPlc</name>
    <message>
        <location filename="../app/virtual_plc/virtual_plc.cpp" line="+98"/>
        <location line="+10"/>
        <source>the virtual PLC is stopping</source>
        <translation>a virtuális PLC leáll</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>the simulation did not take the write within the time allowed</source>
        <translation>a szimuláció a megengedett időn belül nem hajtotta végre az írást</translation>
    </message>
    <message>
        <location line="+71"/>
        <source>The virtual PLC needs a QCoreApplication for its simulation thread</source>
        <translation>A virtuális PLC szimulációs szálához QCoreApplication kell</translation>
    </message>
</context>
<context>
    <name>rung::comms::Driver</name>
    <message>
        <location filename="../comms/driver/driver.cpp" line="+42"/>
        <source>station 0 is the Modbus broadcast address: no PLC answers it, so nothing could be read and no write acknowledged; give the PLC&apos;s own station (1..247, or 255 for any PL110)</source>
        <translation>a 0-s állomás a Modbus körüzenet-címe: egyetlen PLC sem válaszol rá, így semmit sem lehetne olvasni, és egyetlen írást sem nyugtázna senki; adja meg a PLC saját állomáscímét (1..247, vagy bármely PL110-hez 255)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>station %1 is outside %2&apos;s %3..%4</source>
        <translation>a(z) %1. állomás kívül esik a(z) %2 %3..%4 tartományán</translation>
    </message>
    <message>
        <location line="+33"/>
        <location filename="../comms/driver/link.cpp" line="+16"/>
        <location filename="../comms/driver/protocol_driver.cpp" line="+74"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location line="+49"/>
        <source>%1 has no address in %2, so it cannot be read over it</source>
        <translation>%1 nem szerepel a(z) %2 címtérképében, ezért azon keresztül nem olvasható</translation>
    </message>
    <message>
        <location line="+48"/>
        <source>%1 and %2 more</source>
        <translation>%1 és még %2</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+33"/>
        <source>reading %1 from %2</source>
        <translation>%1 olvasása innen: %2</translation>
    </message>
    <message>
        <location filename="../comms/driver/driver_commands.cpp" line="+19"/>
        <source>ON</source>
        <translation>BE</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>OFF</source>
        <translation>KI</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>%1: %2 has no word address in %3</source>
        <translation>%1: %2 nem rendelkezik szócímmel a(z) %3 címtérképében</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>%1: %2 does not fit %3 (%4..%5)</source>
        <translation>%1: a(z) %2 nem fér el ebben: %3 (%4..%5)</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>%1: %2 is not a bit in %3</source>
        <translation>%1: %2 nem bit a(z) %3 címtérképében</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>setting %1 %2 on %3</source>
        <translation>%1 %2 állítása itt: %3</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>writing %1 = %2 to %3</source>
        <translation>%1 = %2 írása ide: %3</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>writing the set value of %1 = %2 to %3</source>
        <translation>%1 beállított értékének írása (%2) ide: %3</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>%1: the set value of %2 is a constant of the program in the PLC; %3 cannot change it (change the program, or make the set value a register)</source>
        <translation>%1: %2 beállított értéke a PLC-ben lévő program állandója; a(z) %3 nem tudja megváltoztatni (módosítsa a programot, vagy adja meg a beállított értéket regiszterben)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>forcing %1 %2 on %3</source>
        <translation>%1 kényszerítése %2 állapotba itt: %3</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>releasing %1 on %2</source>
        <translation>%1 kényszerítésének megszüntetése itt: %2</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: %2 has no command that releases one bit; release all forced bits instead (KC)</source>
        <translation>%1: a(z) %2 protokollnak nincs parancsa egyetlen bit kényszerítésének megszüntetésére; szüntesse meg az összes kényszerítést (KC)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>releasing every forced bit on %1</source>
        <translation>minden kényszerítés megszüntetése itt: %1</translation>
    </message>
    <message>
        <location line="+34"/>
        <location filename="../comms/driver/host_link_driver.cpp" line="+154"/>
        <source>switching %1 to %2</source>
        <translation>%1 átkapcsolása %2 módba</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: the PLC has RUN and STOP only</source>
        <translation>%1: a PLC-nek csak RUN és STOP üzemmódja van</translation>
    </message>
    <message>
        <location filename="../comms/driver/host_link_driver.cpp" line="-131"/>
        <location filename="../comms/driver/modbus_driver.cpp" line="+29"/>
        <source>%1 unit %2 on %3</source>
        <translation>%1, %2. egység, %3</translation>
    </message>
    <message>
        <location line="+68"/>
        <source>%1: the completion flags of timers and counters are read-only over Host Link (RG)</source>
        <translation>%1: az időzítők és számlálók lejárt-jelzői Host Linken csak olvashatók (RG)</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>Host Link forces bits of the IR / SR channels (CIO) only</source>
        <translation>Host Linken csak az IR / SR csatornák bitjei kényszeríthetők (CIO)</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>reading the mode of %1</source>
        <translation>%1 üzemmódjának olvasása</translation>
    </message>
    <message>
        <location line="+40"/>
        <source>%1 was in RUN mode: switched to MONITOR, where Host Link writes are accepted (the program goes on running)</source>
        <translation>%1 RUN módban volt: átkapcsolva MONITOR módba, ahol a Host Link írásokat elfogadja (a program tovább fut)</translation>
    </message>
    <message>
        <location line="+12"/>
        <location filename="../comms/driver/modbus_driver.cpp" line="+105"/>
        <source>reading the model of %1</source>
        <translation>%1 típusának olvasása</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>model code %1h</source>
        <translation>típuskód: %1h</translation>
    </message>
    <message>
        <location filename="../comms/driver/link.cpp" line="+59"/>
        <source>%1 is not open</source>
        <translation>%1 nincs megnyitva</translation>
    </message>
    <message>
        <location line="+50"/>
        <source>cancelled</source>
        <translation>megszakítva</translation>
    </message>
    <message>
        <location line="+40"/>
        <location line="+9"/>
        <source>%1 (%2 attempts)</source>
        <translation>%1 (%2 kísérlet)</translation>
    </message>
    <message>
        <location filename="../comms/driver/modbus_driver.cpp" line="-45"/>
        <source>%1: Modbus has no function that writes discrete inputs</source>
        <translation>%1: a Modbusnak nincs függvénye a diszkrét bemenetek írására</translation>
    </message>
    <message>
        <location line="+54"/>
        <source>device type %1</source>
        <translation>eszköztípus: %1</translation>
    </message>
    <message>
        <location filename="../comms/driver/online_session.cpp" line="+116"/>
        <source>%1 is not connected: nothing was sent</source>
        <translation>%1 nincs csatlakoztatva: semmi sem lett elküldve</translation>
    </message>
    <message>
        <location line="+230"/>
        <source>Connection lost: %1. Trying again.</source>
        <translation>Megszakadt a kapcsolat: %1. Újrapróbálkozás.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Connection to %1 lost: %2. Trying again.</source>
        <translation>Megszakadt a kapcsolat ezzel: %1: %2. Újrapróbálkozás.</translation>
    </message>
    <message>
        <location line="-7"/>
        <source>Cannot reach %1: %2. Trying again.</source>
        <translation>%1 nem érhető el: %2. Újrapróbálkozás.</translation>
    </message>
    <message>
        <location line="-246"/>
        <source>%1 cannot force bits: its protocol has no force command. Set the bit instead (the program may overwrite it).</source>
        <translation>%1 nem tud biteket kényszeríteni: a protokolljának nincs kényszerítő parancsa. Állítsa inkább a bitet (a program felülírhatja).</translation>
    </message>
    <message>
        <location line="+305"/>
        <source>Cannot connect to %1: %2</source>
        <translation>Nem sikerült kapcsolódni ide: %1: %2</translation>
    </message>
    <message>
        <location filename="../comms/driver/protocol_driver.cpp" line="-38"/>
        <source>Vigor Computer Link</source>
        <translation>Vigor Computer Link</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Modbus RTU</source>
        <translation>Modbus RTU</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Modbus TCP</source>
        <translation>Modbus TCP</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Host Link</source>
        <translation>Host Link</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>STOP</source>
        <translation>STOP</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>PROGRAM</source>
        <translation>PROGRAM</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>MONITOR</source>
        <translation>MONITOR</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>RUN</source>
        <translation>RUN</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>unknown mode</source>
        <translation>ismeretlen üzemmód</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>cannot force over %1: the protocol has no force command; write the bit instead (the program may overwrite it)</source>
        <translation>%1 protokollon nem lehet kényszeríteni: nincs kényszerítő parancsa; írja inkább a bitet (a program felülírhatja)</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>%1 has no command to change RUN / STOP</source>
        <translation>a(z) %1 protokollnak nincs parancsa a RUN / STOP váltására</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>%1 does not speak %2</source>
        <translation>%1 nem ismeri a(z) %2 protokollt</translation>
    </message>
    <message>
        <location filename="../comms/driver/vigor_driver.cpp" line="+19"/>
        <source>%1 station %2 on %3</source>
        <translation>%1, %2. állomás, %3</translation>
    </message>
    <message>
        <location filename="../comms/driver/driver.cpp" line="+83"/>
        <source>%1 does not fit %2 (0..9999)</source>
        <translation>%1 nem fér el ebben: %2 (0..9999)</translation>
    </message>
    <message>
        <location filename="../comms/driver/driver_commands.cpp" line="-153"/>
        <source>%1: %2 holds four BCD digits (#0000..#9999); %3h is not one</source>
        <translation>%1: a(z) %2 négy BCD-számjegyet tárol (#0000..#9999); a(z) %3h nem ilyen</translation>
    </message>
</context>
<context>
    <name>rung::comms::Protocol</name>
    <message>
        <location filename="../comms/protocol/host_link.cpp" line="+99"/>
        <source>normal completion (end code %1)</source>
        <translation>normál befejezés (befejezési kód: %1)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>not executable in RUN mode (end code %1): switch the PLC to MONITOR to write</source>
        <translation>RUN üzemmódban nem hajtható végre (befejezési kód: %1): íráshoz kapcsolja a PLC-t MONITOR módba</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>not executable in MONITOR mode (end code %1)</source>
        <translation>MONITOR üzemmódban nem hajtható végre (befejezési kód: %1)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the PLC&apos;s memory is write-protected (end code %1)</source>
        <translation>a PLC memóriája írásvédett (befejezési kód: %1)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>address over: the area ends before the last word asked for (end code %1)</source>
        <translation>címtúllépés: a terület a kért utolsó szó előtt véget ér (befejezési kód: %1)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>not executable in PROGRAM mode (end code %1)</source>
        <translation>PROGRAM üzemmódban nem hajtható végre (befejezési kód: %1)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the PLC received the command with a wrong FCS (end code %1): noise on the line or a wrong parity setting</source>
        <translation>a PLC hibás FCS-sel kapta a parancsot (befejezési kód: %1): zaj a vonalon vagy rossz paritásbeállítás</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the PLC found the command&apos;s format wrong (end code %1)</source>
        <translation>a PLC szerint a parancs formátuma hibás (befejezési kód: %1)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>a number in the command is out of range (end code %1)</source>
        <translation>a parancs egy száma tartományon kívül esik (befejezési kód: %1)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the PLC does not support the command (end code %1)</source>
        <translation>a PLC nem támogatja a parancsot (befejezési kód: %1)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the command&apos;s frame is too long (end code %1)</source>
        <translation>a parancs kerete túl hosszú (befejezési kód: %1)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>end code %1</source>
        <translation>befejezési kód: %1</translation>
    </message>
    <message>
        <location filename="../comms/protocol/host_link_master.cpp" line="+91"/>
        <source>Host Link: the reply starts with byte %1 instead of &quot;@&quot;: not a Host Link answer</source>
        <translation>Host Link: a válasz %1 bájttal kezdődik &quot;@&quot; helyett: nem Host Link válasz</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Host Link: %1 characters without the end of a frame (CR)</source>
        <translation>Host Link: %1 karakter keretvég (CR) nélkül</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Host Link: a frame too short to hold an FCS: %1</source>
        <translation>Host Link: túl rövid keret, nem fér el benne FCS: %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Host Link: wrong FCS in the reply (received %1, computed %2): noise on the line or a wrong parity setting</source>
        <translation>Host Link: hibás FCS a válaszban (érkezett: %1, számított: %2): zaj a vonalon vagy rossz paritásbeállítás</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Host Link: the reply has no unit number and header: %1</source>
        <translation>Host Link: a válaszban nincs egységszám és fejléc: %1</translation>
    </message>
    <message>
        <location line="+10"/>
        <location line="+65"/>
        <source>Host Link: unit %1 answered, unit %2 was asked</source>
        <translation>Host Link: a(z) %1. egység válaszolt, a(z) %2. egységet kérdeztük</translation>
    </message>
    <message>
        <location line="-59"/>
        <source>Host Link: the PLC did not recognise the command %1 (IC)</source>
        <translation>Host Link: a PLC nem ismerte fel a(z) %1 parancsot (IC)</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Host Link: the reply has no end code: %1</source>
        <translation>Host Link: a válaszban nincs befejezési kód: %1</translation>
    </message>
    <message>
        <location line="+51"/>
        <source>Host Link: the reply is for %1, the command was %2</source>
        <translation>Host Link: a válasz a(z) %1 parancsra szól, a parancs %2 volt</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Host Link: TEST returned &quot;%1&quot;, not the &quot;%2&quot; that was sent</source>
        <translation>Host Link: a TEST &quot;%1&quot; karaktereket adott vissza, nem az elküldött &quot;%2&quot; karaktereket</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Host Link: %1 refused: %2</source>
        <translation>Host Link: a(z) %1 elutasítva: %2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Host Link: the reply to %1 holds %2 characters of data that do not fit the command</source>
        <translation>Host Link: a(z) %1 válasza %2 adatkaraktert tartalmaz, ami nem illik a parancshoz</translation>
    </message>
    <message>
        <location line="+47"/>
        <source>Host Link: no reply from unit %1 within %2 ms</source>
        <translation>Host Link: a(z) %1. egység %2 ms alatt nem válaszolt</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Host Link: the reply stopped after %1 parts and %2 characters (%3) within %4 ms</source>
        <translation>Host Link: a válasz %1 rész és %2 karakter (%3) után megszakadt %4 ms alatt</translation>
    </message>
    <message>
        <location filename="../comms/protocol/modbus.cpp" line="+50"/>
        <source>Modbus ASCII: a frame of %1 characters: %2</source>
        <translation>Modbus ASCII: %1 karakteres keret: %2</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Modbus ASCII: &quot;%1&quot; is no hex digit pair</source>
        <translation>Modbus ASCII: a(z) „%1” nem hexadecimális számjegypár</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Modbus ASCII: wrong LRC (received %1, computed %2): noise on the line or a wrong baud rate or parity</source>
        <translation>Modbus ASCII: hibás LRC (érkezett %1, számított %2): zaj a vonalon, vagy hibás átviteli sebesség vagy paritás</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>illegal function (exception %1h): the device does not support this function code</source>
        <translation>érvénytelen funkció (%1h kivétel): az eszköz nem támogatja ezt a funkciókódot</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>illegal data address (exception %1h): the address or the count is outside the device&apos;s map</source>
        <translation>érvénytelen adatcím (%1h kivétel): a cím vagy a darabszám kívül esik az eszköz címtérképén</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>illegal data value (exception %1h)</source>
        <translation>érvénytelen adatérték (%1h kivétel)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>server device failure (exception %1h); the PL110 manual uses this code for an illegal data value</source>
        <translation>a szolgáltató eszköz hibája (%1h kivétel); a PL110 kézikönyve ezt a kódot érvénytelen adatértékre használja</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>acknowledge (exception %1h): the device accepted a long task</source>
        <translation>nyugtázás (%1h kivétel): az eszköz hosszú feladatot fogadott el</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>server device busy (exception %1h)</source>
        <translation>a szolgáltató eszköz foglalt (%1h kivétel)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>memory parity error (exception %1h)</source>
        <translation>memória-paritáshiba (%1h kivétel)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>gateway path unavailable (exception %1h)</source>
        <translation>az átjáró útvonala nem érhető el (%1h kivétel)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>gateway target device failed to respond (exception %1h)</source>
        <translation>az átjáró mögötti eszköz nem válaszolt (%1h kivétel)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>unknown exception code %1h</source>
        <translation>ismeretlen kivételkód: %1h</translation>
    </message>
    <message>
        <location filename="../comms/protocol/modbus_master.cpp" line="+82"/>
        <source>Modbus RTU: the reply starts %1, not an answer to function %2h</source>
        <translation>Modbus RTU: a válasz így kezdődik: %1, ez nem a(z) %2h funkció válasza</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Modbus RTU: %1 bytes more than the %2-byte reply: %3</source>
        <translation>Modbus RTU: %1 bájttal több a(z) %2 bájtos válasznál: %3</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Modbus RTU: wrong CRC in the reply (received %1, computed %2): noise on the line or a wrong baud rate or parity</source>
        <translation>Modbus RTU: hibás CRC a válaszban (érkezett: %1, számított: %2): zaj a vonalon, vagy rossz átviteli sebesség vagy paritás</translation>
    </message>
    <message>
        <location line="+15"/>
        <location filename="../comms/protocol/modbus_slave.cpp" line="+210"/>
        <source>Modbus TCP: not a Modbus header (protocol %1, length %2): %3</source>
        <translation>Modbus TCP: nem Modbus fejléc (protokoll: %1, hossz: %2): %3</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Modbus TCP: %1 bytes more than the reply&apos;s length</source>
        <translation>Modbus TCP: %1 bájttal több a válasz hosszánál</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Modbus TCP: the reply is for transaction %1, the request was %2</source>
        <translation>Modbus TCP: a válasz a(z) %1. tranzakcióra szól, a kérés %2 volt</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Modbus ASCII: no CR LF within %1 characters of the colon</source>
        <translation>Modbus ASCII: a kettőspont után %1 karakteren belül nincs CR LF</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Modbus ASCII: %1 characters after the reply&apos;s CR LF</source>
        <translation>Modbus ASCII: %1 karakter a válasz CR LF-je után</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Modbus ASCII: a reply without a function code</source>
        <translation>Modbus ASCII: válasz funkciókód nélkül</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Modbus: unit %1 answered, unit %2 was asked</source>
        <translation>Modbus: a(z) %1. egység válaszolt, a(z) %2. egységet kérdeztük</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Modbus: an exception reply of %1 bytes</source>
        <translation>Modbus: %1 bájtos kivételválasz</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Modbus: function %1h refused: %2</source>
        <translation>Modbus: a(z) %1h funkció elutasítva: %2</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Modbus: the reply is for function %1h, the request was %2h</source>
        <translation>Modbus: a válasz a(z) %1h funkcióra szól, a kérés %2h volt</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Modbus: the reply to function %1h does not match the request: %2</source>
        <translation>Modbus: a(z) %1h funkció válasza nem illik a kéréshez: %2</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>Modbus: no reply from unit %1 within %2 ms</source>
        <translation>Modbus: a(z) %1. egység %2 ms alatt nem válaszolt</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Modbus: the reply stopped after %1 bytes (%2) within %3 ms</source>
        <translation>Modbus: a válasz %1 bájt (%2) után megszakadt %3 ms alatt</translation>
    </message>
    <message>
        <location filename="../comms/protocol/vigor_link.cpp" line="+32"/>
        <source>no error (error 00h)</source>
        <translation>nincs hiba (00h hiba)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the PLC could not read the request&apos;s characters as hexadecimal (ASCII conversion error %1h)</source>
        <translation>a PLC nem tudta hexadecimálisként olvasni a kérés karaktereit (%1h ASCII-konverziós hiba)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the PLC received the request with a wrong sum (sum check error %1h): noise on the line or a wrong parity setting</source>
        <translation>a PLC hibás összeggel kapta a kérést (%1h összegellenőrzési hiba): zaj a vonalon vagy rossz paritásbeállítás</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the PLC does not know the command (error %1h)</source>
        <translation>a PLC nem ismeri a parancsot (%1h hiba)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>communication error (error %1h): the PLC may be in STOP or the parity does not match</source>
        <translation>kommunikációs hiba (%1h hiba): a PLC STOP állapotban lehet, vagy nem egyezik a paritás</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>address out of range (error %1h)</source>
        <translation>tartományon kívüli cím (%1h hiba)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>unknown error code %1h</source>
        <translation>ismeretlen hibakód: %1h</translation>
    </message>
    <message>
        <location filename="../comms/protocol/vigor_link_master.cpp" line="+43"/>
        <source>Vigor link: the reply starts with byte %1 instead of ACK (06h): not a Computer Link answer</source>
        <translation>Vigor link: a válasz %1 bájttal kezdődik ACK (06h) helyett: nem Computer Link válasz</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Vigor link: %1 bytes without the end of a frame (ETX)</source>
        <translation>Vigor link: %1 bájt keretvég (ETX) nélkül</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Vigor link: wrong sum in the reply (received %1, computed %2): noise on the line or a wrong parity setting</source>
        <translation>Vigor link: hibás összeg a válaszban (érkezett: %1, számított: %2): zaj a vonalon vagy rossz paritásbeállítás</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Vigor link: a reply of %1 bytes is too short or has an odd number of hex digits: %2</source>
        <translation>Vigor link: a(z) %1 bájtos válasz túl rövid, vagy páratlan számú hexadecimális jegyet tartalmaz: %2</translation>
    </message>
    <message>
        <location line="+10"/>
        <location line="+9"/>
        <source>Vigor link: the reply holds characters that are not upper-case hexadecimal: %1</source>
        <translation>Vigor link: a válaszban nem nagybetűs hexadecimális karakterek vannak: %1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Vigor link: station %1 answered, station %2 was asked</source>
        <translation>Vigor link: a(z) %1. állomás válaszolt, a(z) %2. állomást kérdeztük</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Vigor link: the reply is for command %1h, the request was %2h</source>
        <translation>Vigor link: a válasz a(z) %1h parancsra szól, a kérés %2h volt</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Vigor link: %1</source>
        <translation>Vigor link: %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Vigor link: the reply carries %1 data bytes, %2 expected</source>
        <translation>Vigor link: a válasz %1 adatbájtot hoz, %2 volt várható</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Vigor link: no reply from station %1 within %2 ms</source>
        <translation>Vigor link: a(z) %1. állomás %2 ms alatt nem válaszolt</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Vigor link: the reply stopped after %1 bytes (%2) within %3 ms</source>
        <translation>Vigor link: a válasz %1 bájt (%2) után megszakadt %3 ms alatt</translation>
    </message>
    <message>
        <location filename="../comms/transport/pty_transport.cpp" line="+39"/>
        <source>Cannot create a pseudo-terminal: %1</source>
        <translation>Nem hozható létre pszeudoterminál: %1</translation>
    </message>
    <message>
        <location line="+45"/>
        <location line="+7"/>
        <location filename="../comms/transport/serial_transport.cpp" line="+85"/>
        <location line="+8"/>
        <location line="+12"/>
        <source>Cannot open %1: %2</source>
        <translation>%1 nem nyitható meg: %2</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Cannot open %1: it is not a terminal</source>
        <translation>%1 nem nyitható meg: nem terminál</translation>
    </message>
    <message>
        <location line="+22"/>
        <location line="+34"/>
        <location filename="../comms/transport/serial_transport.cpp" line="+38"/>
        <location line="+23"/>
        <location filename="../comms/transport/tcp_listen_transport.cpp" line="+46"/>
        <location line="+16"/>
        <location filename="../comms/transport/tcp_transport.cpp" line="+116"/>
        <location line="+30"/>
        <source>%1 is not open</source>
        <translation>%1 nincs megnyitva</translation>
    </message>
    <message>
        <location line="-22"/>
        <location filename="../comms/transport/serial_transport.cpp" line="-13"/>
        <location filename="../comms/transport/tcp_transport.cpp" line="-24"/>
        <source>Writing to %1 failed: %2</source>
        <translation>Sikertelen írás ide: %1: %2</translation>
    </message>
    <message>
        <location line="+6"/>
        <location filename="../comms/transport/serial_transport.cpp" line="+2"/>
        <location filename="../comms/transport/tcp_transport.cpp" line="+8"/>
        <source>Writing to %1 did not finish in time</source>
        <translation>Az írás ide: %1 nem fejeződött be időben</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>%1 was closed by the other side: %2</source>
        <translation>%1 kapcsolatát a másik oldal lezárta: %2</translation>
    </message>
    <message>
        <location line="+14"/>
        <location filename="../comms/transport/tcp_transport.cpp" line="+22"/>
        <source>%1 was closed by the other side</source>
        <translation>%1 kapcsolatát a másik oldal lezárta</translation>
    </message>
    <message>
        <location filename="../comms/transport/serial_transport.cpp" line="-138"/>
        <source>permission denied: add your user to the group that owns %1 (usually &quot;dialout&quot;: sudo usermod -aG dialout $USER, then log in again)</source>
        <translation>hozzáférés megtagadva: vegye fel a felhasználót a(z) %1 tulajdonos csoportjába (általában &quot;dialout&quot;: sudo usermod -aG dialout $USER, majd jelentkezzen be újra)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the port is busy: another program has it open</source>
        <translation>a port foglalt: egy másik program használja</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>no such port (unplugged?)</source>
        <translation>nincs ilyen port (kihúzták?)</translation>
    </message>
    <message>
        <location line="+93"/>
        <source>%1 does not accept the line settings: %2</source>
        <translation>%1 nem fogadja el a vonalbeállításokat: %2</translation>
    </message>
    <message>
        <location line="+54"/>
        <source>%1 failed while reading (unplugged?): %2</source>
        <translation>%1 olvasás közben meghibásodott (kihúzták?): %2</translation>
    </message>
    <message>
        <location line="+11"/>
        <location line="+11"/>
        <source>%1 is gone (unplugged?)</source>
        <translation>%1 eltűnt (kihúzták?)</translation>
    </message>
    <message>
        <location filename="../comms/transport/tcp_transport.cpp" line="-83"/>
        <source>Cannot take the TCP connection: %1</source>
        <translation>A TCP-kapcsolat nem vehető át: %1</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Cannot connect to %1: %2</source>
        <translation>Nem sikerült kapcsolódni ide: %1: %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Cannot connect to %1 within %2 ms</source>
        <translation>Nem sikerült %2 ms alatt kapcsolódni ide: %1</translation>
    </message>
    <message>
        <location line="+87"/>
        <source>Cannot listen on %1:%2: %3</source>
        <translation>Nem lehet figyelni ezen: %1:%2: %3</translation>
    </message>
    <message>
        <location filename="../comms/protocol/host_link_master.cpp" line="-111"/>
        <source>Host Link: the reply to %1 goes on past the %2 characters of data the command asks for (part %3): not the answer to this command</source>
        <translation>Host Link: a(z) %1 válasza túlmegy a parancs által kért %2 adatkarakteren (%3. rész): nem erre a parancsra érkezett válasz</translation>
    </message>
    <message>
        <location filename="../comms/protocol/host_link_slave.cpp" line="+45"/>
        <source>Host Link: %1 characters arrived before the command was answered; the %2 beyond the first %3 were dropped</source>
        <translation>Host Link: %1 karakter érkezett, mielőtt a parancs választ kapott volna; az első %3 utáni %2 karakter eldobva</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Host Link: a new command began where part %1 of the %2 command was due; the unfinished command was dropped</source>
        <translation>Host Link: a(z) %2 parancs %1. része helyett új parancs kezdődött; a befejezetlen parancs eldobva</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Host Link: %1 characters without a CR (a part holds at most %2): dropped, waiting for the next &quot;@&quot;</source>
        <translation>Host Link: %1 karakter CR nélkül (egy rész legfeljebb %2 karakter): eldobva, várakozás a következő &quot;@&quot; jelre</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>Host Link: the %1 command goes on past %2 characters in %3 parts, longer than any command; answered with end code 18</source>
        <translation>Host Link: a(z) %1 parancs %3 részben túlmegy %2 karakteren, hosszabb bármely parancsnál; válasz: 18-as végkód</translation>
    </message>
    <message>
        <location filename="../comms/protocol/modbus_slave.cpp" line="-63"/>
        <source>Modbus: %1 bytes arrived before the request was answered; the %2 beyond the first %3 were dropped</source>
        <translation>Modbus: %1 bájt érkezett, mielőtt a kérés választ kapott volna; az első %3 utáni %2 bájt eldobva</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>Modbus ASCII: no CR LF within %1 characters of the colon: dropped</source>
        <translation>Modbus ASCII: a kettőspont után %1 karakteren belül nincs CR LF: eldobva</translation>
    </message>
    <message>
        <location line="+72"/>
        <source>Modbus RTU: a frame of function %1h runs past %2 bytes, the longest an RTU frame can be: dropped with what follows until the line is quiet</source>
        <translation>Modbus RTU: a(z) %1h funkció kerete túlmegy %2 bájton, ami egy RTU keret legnagyobb hossza: eldobva a vonal elcsendesedéséig érkezőkkel együtt</translation>
    </message>
    <message>
        <location filename="../comms/protocol/vigor_link_slave.cpp" line="+53"/>
        <source>Vigor link: %1 bytes arrived before the request was answered; the %2 beyond the first %3 were dropped</source>
        <translation>Vigor link: %1 bájt érkezett, mielőtt a kérés választ kapott volna; az első %3 utáni %2 bájt eldobva</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>Vigor link: %1 bytes from STX without ETX (a request holds at most %2): dropped up to the next STX</source>
        <translation>Vigor link: %1 bájt STX-től ETX nélkül (egy kérés legfeljebb %2 bájt): eldobva a következő STX-ig</translation>
    </message>
    <message>
        <location filename="../comms/transport/fd_waiter.cpp" line="+15"/>
        <source>no wake-up pipe for cancelling a read: %1</source>
        <translation>nincs ébresztő cső az olvasás megszakításához: %1</translation>
    </message>
    <message>
        <location filename="../comms/transport/pty_transport.cpp" line="-100"/>
        <source>Cannot open %1 again: the pseudo-terminal this program made ended when it was closed; make a new one and give its path to the peer</source>
        <translation>%1 nem nyitható meg újra: a program által létrehozott pszeudoterminál a bezárásakor megszűnt; hozzon létre újat, és adja meg az útvonalát a másik félnek</translation>
    </message>
    <message>
        <location filename="../comms/slave/memory_image.cpp" line="+86"/>
        <source>%1 cannot be written in this PLC&apos;s memory</source>
        <translation>a(z) %1 nem írható ennek a PLC-nek a memóriájában</translation>
    </message>
    <message>
        <location filename="../comms/slave/slave_server.cpp" line="+87"/>
        <location line="+29"/>
        <source>%1 does not speak this protocol</source>
        <translation>a(z) %1 nem ismeri ezt a protokollt</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The slave listens already</source>
        <translation>A slave már figyel</translation>
    </message>
    <message>
        <location line="+88"/>
        <source>The slave has been stopped</source>
        <translation>A slave le van állítva</translation>
    </message>
    <message>
        <location line="+124"/>
        <source>A TCP client was refused: %1 clients are served already</source>
        <translation>Egy TCP-kliens elutasítva: már %1 kliens kiszolgálása folyik</translation>
    </message>
</context>
<context>
    <name>rung::comms::Relay</name>
    <message>
        <location filename="../comms/driver/relay.cpp" line="+32"/>
        <location line="+14"/>
        <location line="+5"/>
        <source>the PC&apos;s side</source>
        <translation>a PC oldala</translation>
    </message>
    <message>
        <location line="-18"/>
        <location line="+14"/>
        <location line="+3"/>
        <source>the PLC&apos;s side</source>
        <translation>a PLC oldala</translation>
    </message>
    <message>
        <location line="-13"/>
        <source>%1 (%2) cannot be opened: %3</source>
        <translation>%1 (%2) nem nyitható meg: %3</translation>
    </message>
    <message>
        <location line="+61"/>
        <source>%1 (%2) stopped taking bytes: %3</source>
        <translation>%1 (%2) nem fogad több bájtot: %3</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 (%2) failed: %3</source>
        <translation>%1 (%2) hibára futott: %3</translation>
    </message>
</context>
<context>
    <name>rung::editor::CompareView</name>
    <message>
        <location filename="../editor/compare_view.cpp" line="+49"/>
        <source>the same</source>
        <translation>azonos</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>moved</source>
        <translation>áthelyezve</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>changed</source>
        <translation>módosítva</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>moved and changed</source>
        <translation>áthelyezve és módosítva</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>inserted</source>
        <translation>beszúrva</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>deleted</source>
        <translation>törölve</translation>
    </message>
    <message>
        <location line="+161"/>
        <source>Both programs are empty.</source>
        <translation>Mindkét program üres.</translation>
    </message>
    <message>
        <location line="+47"/>
        <source>A: rung %1</source>
        <translation>A: %1. létrafok</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>B: rung %1</source>
        <translation>B: %1. létrafok</translation>
    </message>
    <message>
        <location line="+46"/>
        <source>(not in A)</source>
        <translation>(A-ban nincs)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>(not in B)</source>
        <translation>(B-ben nincs)</translation>
    </message>
</context>
<context>
    <name>rung::editor::CrossReferenceModel</name>
    <message>
        <location filename="../editor/cross_reference_model.cpp" line="+120"/>
        <source>contact</source>
        <translation>érintkező</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>coil</source>
        <translation>tekercs</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>box</source>
        <translation>funkcióblokk</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>rung %1</source>
        <translation>%1. létrafok</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>The first %1 uses; type a device or a prefix for the rest</source>
        <translation>Az első %1 előfordulás; a többihez írjon be egy operandust vagy előtagot</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>Device</source>
        <translation>Operandus</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Step</source>
        <translation>Lépés</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Use</source>
        <translation>Használat</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Instruction</source>
        <translation>Utasítás</translation>
    </message>
</context>
<context>
    <name>rung::editor::CrossReferenceView</name>
    <message>
        <location filename="../editor/cross_reference_view.cpp" line="+36"/>
        <source>Device or prefix (%1, %2)</source>
        <translation>Operandus vagy előtag (%1, %2)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Device or prefix (%1, %2); empty: every device</source>
        <translation>Operandus vagy előtag (%1, %2); üresen: minden operandus</translation>
    </message>
</context>
<context>
    <name>rung::editor::Document</name>
    <message>
        <location filename="../editor/commands/document_commands.cpp" line="+26"/>
        <source>Edit symbols</source>
        <translation>Szimbólumok szerkesztése</translation>
    </message>
    <message>
        <location filename="../editor/document.cpp" line="+77"/>
        <source>Untitled</source>
        <translation>Névtelen</translation>
    </message>
    <message>
        <location line="+73"/>
        <source>Insert rung</source>
        <translation>Létrafok beszúrása</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Delete rung</source>
        <translation>Létrafok törlése</translation>
    </message>
    <message numerus="yes">
        <location line="+0"/>
        <source>Delete %n rungs</source>
        <translation>
            <numerusform>%n létrafok törlése</numerusform>
        </translation>
    </message>
    <message>
        <location line="+46"/>
        <source>Edit instruction list</source>
        <translation>Utasításlista szerkesztése</translation>
    </message>
    <message>
        <location line="+50"/>
        <source>Rung %1: %2 (row %3, column %4) is on no path to an output, so the list leaves it out; the ladder keeps it while this line stays.</source>
        <translation>A(z) %1. létrafok: %2 (%3. sor, %4. oszlop) nincs rajta egyetlen kimenethez vezető áramúton sem, ezért a lista kihagyja; a létradiagram megtartja, amíg ez a sor megvan.</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>it has nothing to list yet</source>
        <translation>még nincs benne semmi, ami a listába kerülhetne</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Rung %1 is not in the list: %2. Edit it in the ladder; this line keeps its place.</source>
        <translation>A(z) %1. létrafok nincs a listában: %2. A létradiagramon szerkeszthető; ez a sor őrzi a helyét.</translation>
    </message>
</context>
<context>
    <name>rung::editor::FrontPanel</name>
    <message>
        <location filename="../editor/front_panel.cpp" line="+376"/>
        <source>%1: %2 (key %3; held down, %4 is 1)</source>
        <translation>%1: %2 (billentyű: %3; lenyomva tartva %4 = 1)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: %2 (writes %3)</source>
        <translation>%1: %2 (ide ír: %3)</translation>
    </message>
    <message>
        <location line="+51"/>
        <source>This PLC has no front panel that its manual describes</source>
        <translation>Ennek a PLC-nek a kézikönyve nem ír le előlapot</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Run the simulation (F10) to see the PLC&apos;s front panel</source>
        <translation>A PLC előlapjának megjelenítéséhez indítsa a szimulációt (F10)</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>Display mode %1 (%2)</source>
        <translation>%1. kijelzési mód (%2)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Page %1 (%2)</source>
        <translation>%1. oldal (%2)</translation>
    </message>
</context>
<context>
    <name>rung::editor::IlEditor</name>
    <message>
        <location filename="../editor/il_editor.cpp" line="+104"/>
        <location line="+386"/>
        <source>Instruction list</source>
        <translation>Utasításlista</translation>
    </message>
</context>
<context>
    <name>rung::editor::IlLexer</name>
    <message>
        <location filename="../editor/il_lexer.cpp" line="+22"/>
        <source>Default</source>
        <translation>Alapértelmezett</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Instruction</source>
        <translation>Utasítás</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Device</source>
        <translation>Operandus</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Constant</source>
        <translation>Konstans</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Comment</source>
        <translation>Megjegyzés</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Step number</source>
        <translation>Lépésszám</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Unknown word</source>
        <translation>Ismeretlen szó</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Rung not in the list</source>
        <translation>A listában nem szereplő létrafok</translation>
    </message>
</context>
<context>
    <name>rung::editor::IoPanel</name>
    <message>
        <location filename="../editor/io_panel.cpp" line="+83"/>
        <source>Inputs are switches</source>
        <translation>A bemenetek kapcsolók</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Inputs are push buttons</source>
        <translation>A bemenetek nyomógombok</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A switch stays where it is put; a push button is ON only while held (mouse, or Space on the focused button). The right button sets one input on its own</source>
        <translation>A kapcsoló ott marad, ahová állították; a nyomógomb csak lenyomva tartva BE (egérrel, vagy a kijelölt gombon a Szóközzel). A jobb egérgomb egyetlen bemenetet állít be külön</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+229"/>
        <source>Inputs take effect at the next scan</source>
        <translation>A bemenetek a következő ciklusban hatnak</translation>
    </message>
    <message>
        <location line="-228"/>
        <location line="+229"/>
        <source>Run the simulation (F10) to work the inputs</source>
        <translation>A bemenetek kezeléséhez indítsa a szimulációt (F10)</translation>
    </message>
    <message>
        <location line="-146"/>
        <source>Further inputs the program uses</source>
        <translation>A program további bemenetei</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Further outputs the program uses</source>
        <translation>A program további kimenetei</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Inputs</source>
        <translation>Bemenetek</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Outputs</source>
        <translation>Kimenetek</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Analog inputs</source>
        <translation>Analóg bemenetek</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Analog outputs</source>
        <translation>Analóg kimenetek</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>This model has no terminals to show</source>
        <translation>Ennek a modellnek nincs megjeleníthető kapcsa</translation>
    </message>
    <message>
        <location line="+51"/>
        <source>Switch</source>
        <translation>Kapcsoló</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Push Button</source>
        <translation>Nyomógomb</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Force ON</source>
        <translation>Kényszerítés BE</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Force OFF</source>
        <translation>Kényszerítés KI</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Release</source>
        <translation>Feloldás</translation>
    </message>
</context>
<context>
    <name>rung::editor::LadderView</name>
    <message>
        <location filename="../editor/ladder_view.cpp" line="+41"/>
        <location line="+503"/>
        <source>Ladder diagram</source>
        <translation>Létradiagram</translation>
    </message>
    <message>
        <location line="-407"/>
        <source>Edit rung comment</source>
        <translation>Létrafok megjegyzésének szerkesztése</translation>
    </message>
    <message>
        <location line="+215"/>
        <source>Type one instruction, for example &quot;%1 %2&quot;</source>
        <translation>Egy utasítást írjon be, például: &quot;%1 %2&quot;</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>%1 is drawn with vertical links, not typed into a cell</source>
        <translation>%1 függőleges összekötésekkel rajzolható, cellába nem írható</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Contacts go in the grid; the right-hand column holds coils and boxes</source>
        <translation>Az érintkezők a rácsba kerülnek; a jobb oldali oszlopban tekercsek és funkcióblokkok állnak</translation>
    </message>
    <message>
        <location line="+24"/>
        <location line="+13"/>
        <source>Place %1</source>
        <translation>%1 elhelyezése</translation>
    </message>
    <message>
        <location line="+22"/>
        <location filename="../editor/ladder_view_mouse.cpp" line="+157"/>
        <source>Draw a wire</source>
        <translation>Vezeték rajzolása</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Toggle a vertical link</source>
        <translation>Függőleges összekötés be/ki</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Delete</source>
        <translation>Törlés</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Insert a cell</source>
        <translation>Cella beszúrása</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Insert a row</source>
        <translation>Sor beszúrása</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Delete a row</source>
        <translation>Sor törlése</translation>
    </message>
    <message>
        <location filename="../editor/ladder_view_mouse.cpp" line="+12"/>
        <source>Draw a vertical link</source>
        <translation>Függőleges összekötés rajzolása</translation>
    </message>
    <message>
        <location filename="../editor/ladder_view_keys.cpp" line="+154"/>
        <source>%1 has no such contact</source>
        <translation>%1 nem rendelkezik ilyen érintkezővel</translation>
    </message>
    <message>
        <location line="+78"/>
        <source>There is no wire under the cursor</source>
        <translation>A kurzor alatt nincs vezeték</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Delete a wire</source>
        <translation>Vezeték törlése</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>There is no vertical link at the cursor</source>
        <translation>A kurzornál nincs függőleges összekötés</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Delete a vertical link</source>
        <translation>Függőleges összekötés törlése</translation>
    </message>
    <message>
        <location filename="../editor/ladder_view_selection.cpp" line="+85"/>
        <source>Delete cells</source>
        <translation>Cellák törlése</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Paste cells</source>
        <translation>Cellák beillesztése</translation>
    </message>
    <message>
        <location filename="../editor/ladder_view_find.cpp" line="+45"/>
        <source>%1 is not used in the program</source>
        <translation>%1 nincs használatban a programban</translation>
    </message>
    <message>
        <location filename="../editor/ladder_view_monitor.cpp" line="+241"/>
        <source>current %1, set %2, %3</source>
        <extracomment>a timer&apos;s or counter&apos;s live state in a tooltip: current value, set value, done bit</extracomment>
        <translation>aktuális %1, beállított %2, %3</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>ON</source>
        <translation>BE</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>OFF</source>
        <translation>KI</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1 (forced)</source>
        <translation>%1 (kényszerített)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The last values known: the source is offline</source>
        <translation>Az utolsó ismert értékek: a forrás nem elérhető</translation>
    </message>
</context>
<context>
    <name>rung::editor::MonitorCommands</name>
    <message>
        <location filename="../editor/monitor_commands.cpp" line="+131"/>
        <source>Force %1 O&amp;N</source>
        <translation>%1 kényszerítése &amp;BE</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Force %1 O&amp;FF</source>
        <translation>%1 kényszerítése &amp;KI</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Release %1</source>
        <translation>%1 kényszerítésének &amp;feloldása</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Set %1 &amp;ON</source>
        <translation>%1 BE-kapcso&amp;lása</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Set %1 OFF</source>
        <translation>%1 KI-kapcsolása</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&amp;Write %1...</source>
        <translation>%1 &amp;írása...</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Write &amp;Preset of %1...</source>
        <translation>%1 beállított értékének í&amp;rása...</translation>
    </message>
    <message>
        <location line="+7"/>
        <location line="+99"/>
        <source>The preset of %1 is the constant %2 of the program: change it in the program</source>
        <translation>%1 beállított értéke a program %2 konstansa: a programban változtassa meg</translation>
    </message>
    <message>
        <location line="-86"/>
        <source>%1 forced ON</source>
        <translation>%1 kényszerítve BE</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1 forced OFF</source>
        <translation>%1 kényszerítve KI</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 released</source>
        <translation>%1 kényszerítése feloldva</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1 set ON</source>
        <translation>%1 BE-kapcsolva</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1 set OFF</source>
        <translation>%1 KI-kapcsolva</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>Write %1</source>
        <translation>%1 írása</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>New value of %1 (a whole number, 0x before a hexadecimal one):</source>
        <translation>%1 új értéke (egész szám, hexadecimális elé 0x):</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>&quot;%1&quot; is no value for %2: type a whole number (0x before a hexadecimal one)</source>
        <translation>„%1” nem érték ehhez: %2; írjon egész számot (hexadecimális elé 0x)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 written: %2</source>
        <translation>%1 írva: %2</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Write Preset of %1</source>
        <translation>%1 beállított értékének írása</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>New preset of %1:</source>
        <translation>%1 új beállított értéke:</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>&quot;%1&quot; is no preset for %2: type a whole number from 0</source>
        <translation>„%1” nem beállított érték ehhez: %2; írjon 0-tól kezdődő egész számot</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Preset of %1 written: %2</source>
        <translation>%1 beállított értéke írva: %2</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>&quot;%1&quot; is no preset for %2: the preset is 0..9999 (BCD)</source>
        <translation>„%1” nem beállított érték ehhez: %2; a beállított érték 0..9999 (BCD)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Preset of %1 written: %2 (in %3)</source>
        <translation>%1 beállított értéke írva: %2 (itt: %3)</translation>
    </message>
</context>
<context>
    <name>rung::editor::ProblemsView</name>
    <message>
        <location filename="../editor/problems_view.cpp" line="+52"/>
        <source>Severity</source>
        <translation>Súlyosság</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Code</source>
        <translation>Kód</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Place</source>
        <translation>Hely</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Message</source>
        <translation>Üzenet</translation>
    </message>
    <message>
        <location line="+68"/>
        <location line="+47"/>
        <source>Problems</source>
        <translation>Problémák</translation>
    </message>
    <message>
        <location line="-97"/>
        <source>Error</source>
        <translation>Hiba</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+68"/>
        <source>Warning</source>
        <translation>Figyelmeztetés</translation>
    </message>
    <message>
        <location line="-67"/>
        <source>Note</source>
        <translation>Megjegyzés</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>line %1</source>
        <translation>%1. sor</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+53"/>
        <source>rung %1, row %2</source>
        <translation>%1. létrafok, %2. sor</translation>
    </message>
    <message>
        <location line="-52"/>
        <source>rung %1</source>
        <translation>%1. létrafok</translation>
    </message>
    <message>
        <location line="-11"/>
        <source>%1 (fix available)</source>
        <translation>%1 (javítás elérhető)</translation>
    </message>
    <message>
        <location line="+86"/>
        <source>1 error</source>
        <translation>1 hiba</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1 errors</source>
        <translation>%1 hiba</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>1 warning</source>
        <translation>1 figyelmeztetés</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1 warnings</source>
        <translation>%1 figyelmeztetés</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Problems (%1)</source>
        <translation>Problémák (%1)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>, </source>
        <translation>, </translation>
    </message>
    <message>
        <location line="+10"/>
        <source>No problems found</source>
        <translation>Nincs probléma</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Show</source>
        <translation>Megjelenítés</translation>
    </message>
</context>
<context>
    <name>rung::editor::SymbolTableModel</name>
    <message>
        <location filename="../editor/symbol_table_model.cpp" line="+34"/>
        <source>No device yet: the row becomes a symbol when it names one</source>
        <translation>Még nincs operandus: a sor szimbólum lesz, amint operandust kap</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>No symbol yet: edit the row to make it one</source>
        <translation>Még nem szimbólum: szerkessze a sort, hogy az legyen</translation>
    </message>
    <message>
        <location line="+122"/>
        <source>Device</source>
        <translation>Operandus</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Name</source>
        <translation>Név</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Comment</source>
        <translation>Megjegyzés</translation>
    </message>
</context>
<context>
    <name>rung::editor::TimingChart</name>
    <message>
        <location filename="../editor/timing_chart.cpp" line="+181"/>
        <source>Devices and ranges to draw, with commas; they can also be dragged here from the ladder or the watch table</source>
        <translation>Kirajzolandó operandusok és tartományok, vesszővel elválasztva; a létradiagramról vagy a figyelőtáblából ide is húzhatók</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Zoom in (+, Ctrl+wheel)</source>
        <translation>Nagyítás (+, Ctrl+görgő)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Zoom out (-, Ctrl+wheel)</source>
        <translation>Kicsinyítés (-, Ctrl+görgő)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Whole History</source>
        <translation>Teljes előzmény</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Show everything recorded</source>
        <translation>Minden rögzített adat megjelenítése</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Follow</source>
        <translation>Követés</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Keep the newest scan at the right edge</source>
        <translation>A legutóbbi ciklus a jobb szélen marad</translation>
    </message>
    <message>
        <location line="-15"/>
        <source>Add: %1, %2, then Enter</source>
        <translation>Hozzáadás: %1, %2, majd Enter</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Type devices above (%1, %2) or drag them here from the ladder or the watch table</source>
        <translation>Írjon be fent operandusokat (%1, %2), vagy húzza ide őket a létradiagramról vagy a figyelőtáblából</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Trigger: %1 rises, %2 &gt; 100</source>
        <translation>Trigger: %1 rises, %2 &gt; 100</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A condition checked after every scan: DEVICE rises, DEVICE falls, or DEVICE = &lt;&gt; &lt; &lt;= &gt; &gt;= VALUE</source>
        <translation>Minden ciklus után vizsgált feltétel: OPERANDUS rises (felfutó él), OPERANDUS falls (lefutó él), vagy OPERANDUS = &lt;&gt; &lt; &lt;= &gt; &gt;= ÉRTÉK</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Stop the simulation</source>
        <translation>A szimuláció leállítása</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Only mark</source>
        <translation>Csak jelölés</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Arm</source>
        <translation>Élesítés</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Watch for the trigger (Enter in its field does the same)</source>
        <translation>A trigger figyelése (a mezőben az Enter ugyanezt teszi)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Export</source>
        <translation>Exportálás</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save the chart as CSV (every change), PNG or SVG</source>
        <translation>A diagram mentése CSV (minden változás), PNG vagy SVG formában</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Click: cursor A; Shift+click or right click: cursor B; wheel: scroll; Ctrl+wheel: zoom; right click on a name: its format</source>
        <translation>Kattintás: A kurzor; Shift+kattintás vagy jobb kattintás: B kurzor; görgő: görgetés; Ctrl+görgő: nagyítás; jobb kattintás egy néven: a formátuma</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>The trigger could not be armed on this source</source>
        <translation>A trigger ezen a forráson nem élesíthető</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>This source keeps no history of some devices: the chart cannot draw them</source>
        <translation>Ez a forrás néhány operandusnak nem őrzi az előzményét: a diagram nem tudja kirajzolni őket</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Not added to the timing chart: %1</source>
        <translation>Nem került az idődiagramra: %1</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>The timing chart draws at most %1 devices</source>
        <translation>Az idődiagram legfeljebb %1 operandust rajzol</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>Show As</source>
        <translation>Megjelenítés</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Remove</source>
        <translation>Eltávolítás</translation>
    </message>
    <message>
        <location line="+110"/>
        <source>A: %1</source>
        <translation>A: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>B: %1</source>
        <translation>B: %1</translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>B − A: %1 (%n scan(s))</source>
        <extracomment>the time between the cursors, and how many scans that is</extracomment>
        <translation>
            <numerusform>B − A: %1 (%n ciklus)</numerusform>
        </translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Click the chart for cursor A, Shift+click for cursor B</source>
        <translation>Kattintson a diagramra az A kurzorhoz, Shift+kattintás a B kurzorhoz</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Trigger not armed: %1</source>
        <translation>A trigger nincs élesítve: %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Trigger not armed: this source cannot watch %1</source>
        <translation>A trigger nincs élesítve: ez a forrás nem tudja figyelni: %1</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Armed: stops when %1</source>
        <translation>Élesítve: megáll, ha %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Armed: marks when %1</source>
        <translation>Élesítve: jelöl, ha %1</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>%1 at %2 (scan %3)</source>
        <translation>%1: %2 (%3. ciklus)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Trigger: %1 at %2 (scan %3); the simulation is paused there</source>
        <translation>Trigger: %1: %2 (%3. ciklus); a szimuláció ott szünetel</translation>
    </message>
    <message>
        <location line="+12"/>
        <location line="+8"/>
        <source>Cannot write %1: %2</source>
        <translation>Nem írható: %1: %2</translation>
    </message>
    <message>
        <location line="+15"/>
        <location line="+13"/>
        <location line="+7"/>
        <source>Cannot write %1</source>
        <translation>Nem írható: %1</translation>
    </message>
    <message>
        <location line="-10"/>
        <source>Timing chart</source>
        <translation>Idődiagram</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1 is no export format (CSV, PNG, SVG)</source>
        <translation>%1 nem exportálási formátum (CSV, PNG, SVG)</translation>
    </message>
</context>
<context>
    <name>rung::editor::WatchListModel</name>
    <message>
        <location filename="../editor/watch_list_model.cpp" line="+116"/>
        <location line="+10"/>
        <location line="+52"/>
        <location line="+7"/>
        <location line="+170"/>
        <source>ON</source>
        <translation>BE</translation>
    </message>
    <message>
        <location line="-239"/>
        <location line="+10"/>
        <location line="+52"/>
        <location line="+7"/>
        <location line="+173"/>
        <source>OFF</source>
        <translation>KI</translation>
    </message>
    <message>
        <location line="-236"/>
        <source>%1 of %2, %3</source>
        <translation>%1 / %2, %3</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1 (forced)</source>
        <translation>%1 (kényszerített)</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Watch list %1</source>
        <translation>Figyelőlista: %1</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>not a device</source>
        <translation>nem operandus</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Not forced</source>
        <translation>Nincs kényszerítve</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Forced %1</source>
        <translation>Kényszerítve: %1</translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+32"/>
        <source>Forced</source>
        <translation>Kényszerítve</translation>
    </message>
    <message>
        <location line="-8"/>
        <source>Device</source>
        <translation>Operandus</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Symbol</source>
        <translation>Szimbólum</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Value</source>
        <translation>Érték</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Format</source>
        <translation>Formátum</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Double-click or F2: write a value; a bit flips</source>
        <translation>Dupla kattintás vagy F2: érték írása; egy bit átvált</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Double-click: show the word in decimal, signed, hexadecimal, binary or BCD</source>
        <translation>Dupla kattintás: a szó decimális, előjeles, hexadecimális, bináris vagy BCD alakban</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Double-click: force a bit ON or OFF, or release it</source>
        <translation>Dupla kattintás: egy bit kényszerítése BE vagy KI, vagy feloldása</translation>
    </message>
    <message>
        <location filename="../editor/watch_list_model_rows.cpp" line="+218"/>
        <source>Not added to the watch list: %1</source>
        <translation>Nem került a figyelőlistára: %1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Watch 1</source>
        <translation>Figyelés 1</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Add %1 to the watch list</source>
        <translation>%1 hozzáadása a figyelőlistához</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Remove %1 from the watch list</source>
        <translation>%1 eltávolítása a figyelőlistáról</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Show %1 as %2</source>
        <translation>%1 megjelenítése: %2</translation>
    </message>
    <message>
        <location filename="../editor/watch_list_model.cpp" line="+82"/>
        <source>%1 is a timer or counter: its current value follows the program and cannot be written here</source>
        <translation>%1 időzítő vagy számláló: aktuális értékét a program határozza meg, itt nem írható</translation>
    </message>
    <message>
        <location line="+47"/>
        <source>&quot;%1&quot; is no value for %2: type ON or OFF (1 or 0)</source>
        <translation>„%1” nem érték ehhez: %2; írjon BE vagy KI értéket (1 vagy 0)</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>type a whole number (0x before a hexadecimal one)</source>
        <translation>írjon be egy egész számot (hexadecimális előtt 0x)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>type up to %1 hexadecimal digits</source>
        <translation>írjon be legfeljebb %1 hexadecimális számjegyet</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>type up to %1 binary digits (0 and 1)</source>
        <translation>írjon be legfeljebb %1 bináris számjegyet (0 és 1)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>type up to %1 decimal digits (BCD)</source>
        <translation>írjon be legfeljebb %1 decimális számjegyet (BCD)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>a %1-bit word holds %2..%3</source>
        <translation>egy %1 bites szó értéke %2..%3</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&quot;%1&quot; is no value for %2: %3</source>
        <translation>„%1” nem érték ehhez: %2: %3</translation>
    </message>
</context>
<context>
    <name>rung::editor::WatchListView</name>
    <message>
        <location filename="../editor/watch_list_view.cpp" line="+49"/>
        <location line="+41"/>
        <source>Watch lists</source>
        <translation>Figyelőlisták</translation>
    </message>
    <message>
        <location line="+71"/>
        <location line="+20"/>
        <source>Set ON</source>
        <translation>BE-kapcsolás</translation>
    </message>
    <message>
        <location line="-20"/>
        <location line="+24"/>
        <source>Set OFF</source>
        <translation>KI-kapcsolás</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Force ON</source>
        <translation>Kényszerítés BE</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Force OFF</source>
        <translation>Kényszerítés KI</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Release</source>
        <translation>Kényszerítés feloldása</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Write Value...</source>
        <translation>Érték írása...</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Show As</source>
        <translation>Megjelenítés</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Remove</source>
        <translation>Eltávolítás</translation>
    </message>
</context>
<context>
    <name>rung::editor::WatchPanel</name>
    <message>
        <location filename="../editor/watch_panel.cpp" line="+41"/>
        <source>Add: a device or a range (%1), then Enter</source>
        <translation>Hozzáadás: operandus vagy tartomány (%1), majd Enter</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Several at once with commas: %1, %2, %3. Devices can also be dragged here from the ladder or the cross reference</source>
        <translation>Egyszerre több, vesszővel: %1, %2, %3. Operandusok a létradiagramról vagy a kereszthivatkozásból ide is húzhatók</translation>
    </message>
</context>
<context>
    <name>rung::model::Address</name>
    <message>
        <location filename="../model/target/address.cpp" line="+137"/>
        <source>A device is missing</source>
        <translation>Hiányzik egy operandus</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1: a number is expected after %2</source>
        <translation>%1: %2 után szám kell</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 is not a device of %2</source>
        <translation>%1 nem operandusa a(z) %2 rendszernek</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1: the number is too large</source>
        <translation>%1: a szám túl nagy</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: %2 is numbered in octal</source>
        <translation>%1: a(z) %2 operandusok számozása oktális</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1: a bit number is expected after the point</source>
        <translation>%1: a pont után bitszám kell</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+16"/>
        <source>%1: bit %2 is beyond 00..15</source>
        <translation>%1: a(z) %2 bit kívül esik a 00..15 tartományon</translation>
    </message>
    <message>
        <location line="-10"/>
        <source>%1: unexpected &apos;%2&apos; after the device</source>
        <translation>%1: váratlan &apos;%2&apos; az operandus után</translation>
    </message>
    <message>
        <location line="+49"/>
        <source>%1: %2 has no bit numbers</source>
        <translation>%1: a(z) %2 operandusnak nincsenek bitszámai</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+28"/>
        <source>%1: %2 has no %3</source>
        <translation>%1: a(z) %2 típusnak nincsenek %3</translation>
    </message>
    <message>
        <location line="-11"/>
        <location line="+14"/>
        <source>%1 is beyond %2&apos;s %3 %4</source>
        <translation>%1 kívül esik a(z) %2 %3 tartományán (%4)</translation>
    </message>
    <message>
        <location line="-12"/>
        <source>%1 is beyond %2&apos;s %3</source>
        <translation>%1 kívül esik a(z) %2 %3 tartományán</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>A constant is missing</source>
        <translation>Hiányzik egy konstans</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>%1: %2 writes constants without K or H</source>
        <translation>%1: a(z) %2 a konstansokat K és H nélkül írja</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>write a constant as K (decimal) or H (hexadecimal)</source>
        <translation>a konstanst K (decimális) vagy H (hexadecimális) előtaggal kell írni</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>write a constant with # (e.g. #0150)</source>
        <translation>a konstanst # jellel kell írni (pl. #0150)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>write a constant as a plain number (e.g. 150)</source>
        <translation>a konstanst egyszerű számként kell írni (pl. 150)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: %2 has no # constants; %3</source>
        <translation>%1: a(z) %2 nem ismer # konstanst; %3</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location line="+128"/>
        <source>%1: both ends of a range must be devices of one kind (D0..D15)</source>
        <translation>%1: a tartomány mindkét vége azonos fajta operandus kell legyen (D0..D15)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1: the range runs backwards</source>
        <translation>%1: a tartomány visszafelé halad</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: %2 devices; a range holds at most %3</source>
        <translation>%1: %2 operandus; egy tartomány legfeljebb %3 lehet</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>%1: the PLC has no %2 inside this range</source>
        <translation>%1: a PLC-nek nincs %2 operandusa ebben a tartományban</translation>
    </message>
    <message>
        <location line="-152"/>
        <source>%1: digits are expected</source>
        <translation>%1: számjegyek kellenek</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1: &apos;%2&apos; is not a digit</source>
        <translation>%1: a(z) &apos;%2&apos; nem számjegy</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1: the constant is too large</source>
        <translation>%1: a konstans túl nagy</translation>
    </message>
</context>
<context>
    <name>rung::model::Checks</name>
    <message>
        <location filename="../model/checks/checks_ladder.cpp" line="+68"/>
        <source>Reverse current: power would cross an element right to left to reach row %1</source>
        <translation>Visszáram: az áram jobbról balra haladna át egy elemen, hogy elérje a(z) %1. sort</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Duplicate the shared contact into each branch</source>
        <translation>A közös érintkező megkettőzése minden ágba</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Open branch: row %1 is not connected to the left rail</source>
        <translation>Nyitott ág: a(z) %1. sor nincs a bal oldali gyűjtősínhez kötve</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1 has no condition: it is wired straight to the left rail</source>
        <translation>%1 feltétel nélküli: közvetlenül a bal oldali gyűjtősínre van kötve</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>%1 (row %2, column %3) is not on any path from the left rail to an output: the list leaves it out</source>
        <translation>%1 (%2. sor, %3. oszlop) nincs rajta egyetlen áramúton sem a bal oldali gyűjtősíntől egy kimenetig: a lista kihagyja</translation>
    </message>
    <message>
        <location line="+58"/>
        <location filename="../model/checks/checks_list.cpp" line="+55"/>
        <source>Append %1</source>
        <translation>%1 hozzáfűzése a végére</translation>
    </message>
    <message>
        <location filename="../model/checks/checks_blocks_and_stack.cpp" line="+59"/>
        <source>Rewrite the rung in the canonical form</source>
        <translation>A létrafok átírása kanonikus formára</translation>
    </message>
    <message>
        <location line="+47"/>
        <source>More than %1 %2 in a row: the PLC rejects the program</source>
        <translation>Több mint %1 %2 egymás után: a PLC elutasítja a programot</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>Stacked %1: combine each block with %1 as soon as it is complete</source>
        <translation>Halmozott %1: minden blokkot kapcsoljon %1-vel, amint elkészült</translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>Stacked %1: %n blocks are open; an OR chain needs less stack</source>
        <translation>
            <numerusform>Halmozott %1: %n blokk nyitott; egy OR-lánc kevesebb vermet igényel</numerusform>
        </translation>
    </message>
    <message>
        <location line="+7"/>
        <source>A single contact joined with %1 is simpler as %2</source>
        <translation>Egyetlen érintkező %1 kapcsolással egyszerűbb %2 formában</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>The block after a single contact can be written shorter; the contact stays in front of the %1</source>
        <translation>Az egyetlen érintkező utáni blokk rövidebben is írható; az érintkező a(z) %1 előtt marad</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>A single device in parallel with a block belongs on the lower row: the block first, then an OR, drops the %1</source>
        <translation>Egy blokkal párhuzamos egyetlen operandus az alsó sorba való: előbb a blokk, majd egy OR, így elmarad a(z) %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Contacts in series need no %1: each can follow the one before it as %2</source>
        <translation>Soros érintkezőkhöz nem kell %1: mindegyik %2 utasítással követheti az előzőt</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The block after a single contact can move to the front and drop the %1</source>
        <translation>Az egyetlen érintkező utáni blokk előre kerülhet, így elmarad a(z) %1</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Put the single device below the block and drop the %1</source>
        <translation>Az egyetlen operandus kerüljön a blokk alá, így elmarad a(z) %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Join the contacts in series and drop the %1</source>
        <translation>Az érintkezők sorba kötése, így elmarad a(z) %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Move the block to the front and drop the %1</source>
        <translation>A blokk kerüljön előre, így elmarad a(z) %1</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>MPS nests more than %1 deep</source>
        <translation>Az MPS-ek egymásba ágyazása %1 szintnél mélyebb</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 without a matching MPS</source>
        <translation>%1 hozzá tartozó MPS nélkül</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>An output with no contacts of its own belongs on top of the branch and needs no %1</source>
        <translation>A saját érintkező nélküli kimenet az ág tetejére való, és nem kell hozzá %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Put the output on top and drop the %1</source>
        <translation>A kimenet kerüljön felülre, így elmarad a(z) %1</translation>
    </message>
    <message numerus="yes">
        <location line="+12"/>
        <source>%n MPS left without MPP at the end of the rung</source>
        <translation>
            <numerusform>%n MPS maradt MPP nélkül a létrafok végén</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/checks/checks_operands.cpp" line="+160"/>
        <source>%1 cannot be written: the program only reads it (%2)</source>
        <translation>%1 nem írható: a program csak olvassa (%2)</translation>
    </message>
    <message>
        <location filename="../model/checks/checks_duplicates.cpp" line="+20"/>
        <source>%1 is programmed twice; the PLC allows it once only in a program (the first is on line %2)</source>
        <translation>a(z) %1 kétszer szerepel a programban; a PLC csak egyszer engedi egy programban (az első a(z) %2. sorban van)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 is programmed twice; the PLC allows it once only in a program (the first is in rung %2)</source>
        <translation>a(z) %1 kétszer szerepel a programban; a PLC csak egyszer engedi egy programban (az első a(z) %2. létrafokon van)</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>%1 is driven twice; a coil may be driven only once (the first is on line %2)</source>
        <translation>%1 kétszer van vezérelve; egy tekercs csak egyszer vezérelhető (az első a(z) %2. sorban)</translation>
    </message>
    <message>
        <location line="+10"/>
        <location filename="../model/listing/structure.cpp" line="+19"/>
        <source>%1 (the PLC says &quot;%2&quot;)</source>
        <translation>%1 (a PLC üzenete: &quot;%2&quot;)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 is driven twice; a coil may be driven only once (the first is in rung %2)</source>
        <translation>%1 kétszer van vezérelve; egy tekercs csak egyszer vezérelhető (az első a(z) %2. létrafokon)</translation>
    </message>
    <message>
        <location filename="../model/checks/checks_nesting.cpp" line="+51"/>
        <source>END is missing</source>
        <translation>Hiányzik az END</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Instructions after END are never executed</source>
        <translation>Az END utáni utasítások sosem hajtódnak végre</translation>
    </message>
    <message>
        <location filename="../model/listing/structure.cpp" line="+222"/>
        <source>IL inside IL: close the first with ILC</source>
        <translation>IL az IL-en belül: az elsőt zárja le ILC-vel</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>Jump number %1 is beyond 00..%2</source>
        <translation>A(z) %1 ugrásszám kívül esik a 00..%2 tartományon</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>JMP inside JMP: close the first jump</source>
        <translation>JMP a JMP-n belül: zárja le az első ugrást</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>A second %1 %2: several JMP may share a number, only one JME</source>
        <translation>Második %1 %2: több JMP osztozhat egy számon, de csak egy JME lehet</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1 %2 without a JMP before it</source>
        <translation>%1 %2 előtte lévő JMP nélkül</translation>
    </message>
    <message>
        <location line="-221"/>
        <source>%1 cannot stand inside a step (STEP(08) .. STEP(08))</source>
        <translation>%1 nem állhat lépésen belül (STEP(08) .. STEP(08))</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1 %2 inside subroutine %3: close that one with %4 first</source>
        <translation>%1 %2 a(z) %3. szubrutinon belül: előbb azt zárja le %4 utasítással</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>A second %1 %2: each subroutine number is defined once</source>
        <translation>Második %1 %2: minden szubrutinszám csak egyszer definiálható</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1 without %2 before it</source>
        <translation>%1 előtte álló %2 nélkül</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1 without a control bit ends the steps, but no step is open</source>
        <translation>A vezérlőbit nélküli %1 lezárja a lépéseket, de nincs nyitott lépés</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>%1 is after the main program and outside the subroutines: it never runs</source>
        <translation>%1 a főprogram után és a szubrutinokon kívül áll: soha nem fut le</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1 %2 is not closed with %3</source>
        <translation>%1 %2 nincs lezárva %3 utasítással</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The steps are not closed with %1 without a control bit</source>
        <translation>A lépések nincsenek lezárva vezérlőbit nélküli %1 utasítással</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 %2: there is no %3 %2 before END</source>
        <translation>%1 %2: az END előtt nincs %3 %2</translation>
    </message>
    <message>
        <location line="+101"/>
        <location line="+51"/>
        <source>%1 without %2</source>
        <translation>%1 %2 nélkül</translation>
    </message>
    <message>
        <location line="-45"/>
        <source>IL and JMP overlap: the jump opened inside the interlock is still open</source>
        <translation>Az IL és a JMP átfedi egymást: a reteszelésen belül nyitott ugrás még nyitva van</translation>
    </message>
    <message>
        <location line="+52"/>
        <source>IL and JMP overlap: the interlock opened inside the jump is still open</source>
        <translation>Az IL és a JMP átfedi egymást: az ugráson belül nyitott reteszelés még nyitva van</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>IL without ILC</source>
        <translation>IL ILC nélkül</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>JMP without its end (%1)</source>
        <translation>JMP lezárás nélkül (%1)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>JMP %1 has no JME %1</source>
        <translation>A JMP %1 utasításnak nincs JME %1 párja</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>JMP %1 has no JME %1 after it</source>
        <translation>A JMP %1 utasítás után nincs JME %1 pár</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The step ladder is not closed with RET</source>
        <translation>A léptetőlánc nincs RET-tel lezárva</translation>
    </message>
    <message>
        <location filename="../model/checks/checks_operands.cpp" line="-20"/>
        <source>Set value %1 is out of range</source>
        <translation>A(z) %1 beállított érték tartományon kívül esik</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>%1 cannot be written: the PLC drives it (%2)</source>
        <translation>%1 nem írható: a PLC vezérli (%2)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1 cannot drive %2: %3 are not relays</source>
        <translation>%1 nem vezérelheti ezt: %2 (a(z) %3 nem relék)</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Number %1 is used as a timer and as a counter; they share one bank</source>
        <translation>A(z) %1 szám időzítőként és számlálóként is használatban van; közös tartományuk van</translation>
    </message>
    <message>
        <location filename="../model/checks/checks_duplicates.cpp" line="-11"/>
        <source>%1 is driven twice; the later one wins (first on line %2)</source>
        <translation>%1 kétszer van vezérelve; a későbbi érvényesül (az első a(z) %2. sorban)</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1 is driven twice; the later one wins (first in rung %2)</source>
        <translation>%1 kétszer van vezérelve; a későbbi érvényesül (az első a(z) %2. létrafokon)</translation>
    </message>
    <message>
        <location filename="../model/checks/checks_length.cpp" line="+15"/>
        <source>The program needs %1 steps; %2 holds %3</source>
        <translation>A program %1 lépést igényel; a(z) %2 kapacitása %3</translation>
    </message>
    <message>
        <location filename="../model/checks/operand_rules.cpp" line="+17"/>
        <source>operand %1</source>
        <translation>%1. operandus</translation>
    </message>
    <message>
        <location line="+53"/>
        <source>the %1 of %2 must be #DDSS with bits DD and SS from 00 to 15, not %3</source>
        <translation>a(z) %2 %1 értéke #DDSS legyen, DD és SS bit 00 és 15 között, nem %3</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the %1 of %2 must be #0DNS with digits D, N and S from 0 to 3, not %3</source>
        <translation>a(z) %2 %1 értéke #0DNS legyen, D, N és S számjegy 0 és 3 között, nem %3</translation>
    </message>
    <message>
        <location line="+157"/>
        <source>the %1 of %2 must be BCD (#0000..#9999), not %3</source>
        <translation>a(z) %2 %1 értéke BCD legyen (#0000..#9999), nem %3</translation>
    </message>
    <message>
        <location line="-46"/>
        <source>%1 or %2</source>
        <translation>%1 vagy %2</translation>
    </message>
    <message>
        <location line="-95"/>
        <source>%1 uses %2..%3, which runs from %4 into %5: a block stays in one</source>
        <translation>%1 a(z) %2..%3 tartományt használja, amely a(z) %4 területről átnyúlik a(z) %5 területre: egy blokk egy területen belül marad</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1 uses %2..%3, but %4 does not exist</source>
        <translation>%1 a(z) %2..%3 tartományt használja, de %4 nem létezik</translation>
    </message>
    <message>
        <location line="+113"/>
        <location line="+38"/>
        <source>the %1 of %2 must be %3, not %4</source>
        <translation>a(z) %2 %1 értéke %3 lehet, nem %4</translation>
    </message>
    <message>
        <location line="-33"/>
        <location line="+80"/>
        <source>%1 takes its %2 from %3 only, not %4</source>
        <translation>%1 a(z) %2 értékét csak ebből veszi: %3, nem ebből: %4</translation>
    </message>
    <message>
        <location line="-72"/>
        <source>the %1 of %2 must be a device, not %3</source>
        <translation>a(z) %2 %1 operandus legyen, nem %3</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>the %1 of %2 must be at least %3, not %4</source>
        <translation>a(z) %2 %1 értéke legalább %3 lehet, nem %4</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the %1 of %2 must be from %3 to %4, not %5</source>
        <translation>a(z) %2 %1 értéke %3 és %4 között lehet, nem %5</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>the %1 of %2 must be a number, not %3</source>
        <translation>a(z) %2 %1 értéke szám kell legyen, nem %3</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>%1 moves whole words: %2 cannot be its %3</source>
        <translation>%1 egész szavakat mozgat: %2 nem lehet a(z) %3</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1 takes its %2 from a constant or from %3, not %4</source>
        <translation>%1 a(z) %2 értékét konstansból vagy ebből veszi: %3, nem ebből: %4</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>%1 takes only %2..%3, not %4</source>
        <translation>a(z) %1 csak %2..%3 operandust fogad el, nem %4</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>the %1 of %2 is a word: %3 is a single bit</source>
        <translation>a(z) %2 %1 egy szó: %3 egyetlen bit</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>the %1 of %2 is a word: %3 starts no word of 16 bits (%4 and %5 do)</source>
        <translation>a(z) %2 %1 egy szó: %3 nem 16 bites szó eleje (%4 és %5 az)</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>the %1 of %2 is a bit: %3 is a whole channel (%4 is its first bit)</source>
        <translation>a(z) %2 %1 egy bit: %3 egy teljes csatorna (első bitje %4)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the %1 of %2 is a bit: %3 is a whole word (%4 is its first bit)</source>
        <translation>a(z) %2 %1 egy bit: %3 egy teljes szó (első bitje %4)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the %1 of %2 is a bit: %3 is a whole word</source>
        <translation>a(z) %2 %1 egy bit: %3 egy teljes szó</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>the %1 of %2 must be a channel with bits (IR, HR, LR), not %3</source>
        <translation>a(z) %2 %1 bitcímezhető csatorna legyen (IR, HR, LR), nem %3</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1 %2 %3: the last device must be of the kind of the first and not before it</source>
        <translation>%1 %2 %3: az utolsó operandus az elsővel azonos fajtájú legyen, és ne előzze meg</translation>
    </message>
    <message>
        <location line="+47"/>
        <source>%1 cannot write %2: %3 are written only by %4</source>
        <translation>a(z) %1 nem írhatja a(z) %2 operandust: a(z) %3 csak a(z) %4 írhatja</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1 is not simulated: it does nothing in the simulator</source>
        <translation>%1 nincs szimulálva: a szimulátorban nem csinál semmit</translation>
    </message>
    <message>
        <location filename="../model/checks/checks_switched.cpp" line="+64"/>
        <source>%1 runs only while %2 is ON, and no instruction sets %2</source>
        <translation>%1 csak akkor működik, amíg %2 BE, és egyetlen utasítás sem kapcsolja be: %2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 stops while %2 is ON, and line %3 writes %2</source>
        <translation>%1 áll, amíg %2 BE, és a(z) %3. sor írja: %2</translation>
    </message>
    <message>
        <location filename="../model/checks/unmodelled.cpp" line="+53"/>
        <source>%1 is not simulated: %2</source>
        <translation>%1 nincs szimulálva: %2</translation>
    </message>
    <message>
        <location filename="../model/checks/operand_rules.cpp" line="-307"/>
        <source>the %1 of %2 holds %3 (character %4), which does not fit a byte: a character is stored as its Latin-1 code, 0..255</source>
        <translation>%2 %1 operandusa %3 karaktert tartalmaz (a(z) %4. karakter), amely nem fér el egy bájtban: egy karakter a Latin-1 kódjaként tárolódik, 0..255</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1 stores two characters a word, but %2 holds %3 bits a word: write 1 character per word</source>
        <translation>%1 szavanként két karaktert tárol, de %2 szavai %3 bitesek: írjon szavanként 1 karaktert</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>the %1 of %2 (length %3) is stored in %4..%5, but %6 does not exist: the text is too long for its place</source>
        <translation>%2 %1 operandusa (hossza %3) a(z) %4..%5 helyre kerül, de %6 nem létezik: a szöveg túl hosszú a helyéhez</translation>
    </message>
    <message>
        <location line="+333"/>
        <source>the display shows %1 of the %2 of %3 as a space: it draws the character codes %4</source>
        <translation>a kijelző %3 %2 operandusában a(z) %1 helyén szóközt mutat: a(z) %4 karakterkódokat jeleníti meg</translation>
    </message>
</context>
<context>
    <name>rung::model::Compare</name>
    <message>
        <location filename="../model/compare/compare_report.cpp" line="+21"/>
        <source>the same</source>
        <translation>azonos</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>moved</source>
        <translation>áthelyezve</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>changed</source>
        <translation>módosítva</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>moved and changed</source>
        <translation>áthelyezve és módosítva</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>inserted</source>
        <translation>beszúrva</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>deleted</source>
        <translation>törölve</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>contact</source>
        <translation>érintkező</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>output</source>
        <translation>kimenet</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>branches</source>
        <translation>ágak</translation>
    </message>
    <message>
        <location line="+41"/>
        <source>name</source>
        <translation>név</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>comment</source>
        <translation>megjegyzés</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>- rung %1 of A: %2</source>
        <extracomment>A rung only in the first program (A): %1 its number there, %2 &quot;deleted&quot;.</extracomment>
        <translation>- A %1. létrafoka: %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>+ rung %1 of B: %2</source>
        <extracomment>A rung only in the second program (B): %1 its number there, %2 &quot;inserted&quot;.</extracomment>
        <translation>+ B %1. létrafoka: %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>rung %1: %2</source>
        <translation>%1. létrafok: %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>rung %1 -&gt; %2: %3</source>
        <extracomment>A rung of A (number %1) that is rung %2 of B, and what happened to it (%3).</extracomment>
        <translation>%1. -&gt; %2. létrafok: %3</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>+ %1 added: %2</source>
        <translation>+ %1 hozzáadva: %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>- %1 removed: %2</source>
        <translation>- %1 eltávolítva: %2</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>* the branches joining the contacts changed</source>
        <translation>* az érintkezőket összekötő ágak megváltoztak</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>* %1 changed: %2 -&gt; %3</source>
        <translation>* %1 módosítva: %2 -&gt; %3</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>operand %1: %2 -&gt; %3</source>
        <extracomment>An operand that changed: %1 its number (1 = the first), %2 and %3 the old and the new operand.</extracomment>
        <translation>%1. operandus: %2 -&gt; %3</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>* comment changed: %1 -&gt; %2</source>
        <translation>* megjegyzés módosítva: %1 -&gt; %2</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>+ %1 added: %2 %3</source>
        <extracomment>%1 what (&quot;symbol X0&quot;, &quot;set value T0&quot;), %2 the field (&quot;name&quot;, &quot;comment&quot;, &quot;value&quot;).</extracomment>
        <translation>+ %1 hozzáadva: %2 %3</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>- %1 removed: %2 %3</source>
        <translation>- %1 eltávolítva: %2 %3</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>* %1 changed: %2 %3 -&gt; %4</source>
        <translation>* %1 módosítva: %2 %3 -&gt; %4</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>+ watch list %1 added: %2</source>
        <translation>+ %1 figyelőlista hozzáadva: %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>- watch list %1 removed: %2</source>
        <translation>- %1 figyelőlista eltávolítva: %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>+ watch list %1: %2 added</source>
        <translation>+ %1 figyelőlista: %2 hozzáadva</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>- watch list %1: %2 removed</source>
        <translation>- %1 figyelőlista: %2 eltávolítva</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>* watch list %1: the order changed: %2 -&gt; %3</source>
        <translation>* %1 figyelőlista: a sorrend megváltozott: %2 -&gt; %3</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>* watch list %1: %2 shown as %3 -&gt; %4</source>
        <extracomment>A watch list row shown in another format: %1 the list, %2 the device, %3 and %4 the formats (dec, signed, hex, bin, bcd).</extracomment>
        <translation>* %1 figyelőlista: %2 megjelenítése %3 -&gt; %4</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>+ B holds an instruction list typed with errors that is not in its rungs (pendingListing)</source>
        <translation>+ B egy hibásan begépelt utasításlistát tartalmaz, amely nincs a létrafokaiban (pendingListing)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>- A holds an instruction list typed with errors that is not in its rungs (pendingListing)</source>
        <translation>- A egy hibásan begépelt utasításlistát tartalmaz, amely nincs a létrafokaiban (pendingListing)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>* the instruction lists typed with errors that are not in the rungs differ (pendingListing)</source>
        <translation>* a hibásan begépelt, a létrafokokban nem szereplő utasításlisták eltérnek (pendingListing)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>+ symbol row not yet a symbol: %1</source>
        <translation>+ még nem szimbólum sor: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>- symbol row not yet a symbol: %1</source>
        <translation>- még nem szimbólum sor: %1</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>* model changed: %1 -&gt; %2</source>
        <translation>* modell módosítva: %1 -&gt; %2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>symbol %1</source>
        <translation>%1 szimbólum</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>set value %1</source>
        <translation>%1 beállított érték</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>The programs are the same (rungs: %1).</source>
        <translation>A programok azonosak (létrafokok: %1).</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Rungs: %1 in A, %2 in B; %3 the same, %4 moved, %5 changed, %6 moved and changed, %7 inserted, %8 deleted.</source>
        <extracomment>The summary of a comparison: %1 rungs in A, %2 in B, then how many of each kind.</extracomment>
        <translation>Létrafokok: %1 az A-ban, %2 a B-ben; %3 azonos, %4 áthelyezve, %5 módosítva, %6 áthelyezve és módosítva, %7 beszúrva, %8 törölve.</translation>
    </message>
</context>
<context>
    <name>rung::model::Convert</name>
    <message>
        <location filename="../model/convert/convert_to_ladder.cpp" line="+216"/>
        <source>%1 joins the condition of a branch point in parallel with another block; the ladder cannot draw this: repeat the shared contacts in this branch instead</source>
        <translation>%1 egy elágazási pont feltételét párhuzamosan köti egy másik blokkal; ezt a létradiagram nem tudja megrajzolni: ismételje meg a közös érintkezőket ebben az ágban</translation>
    </message>
    <message>
        <location line="+77"/>
        <source>%1 has no block to continue; start the rung with a load</source>
        <translation>%1 előtt nincs folytatható blokk; a létrafokot töltő (LD) utasítással kezdje</translation>
    </message>
    <message>
        <location line="+8"/>
        <location line="+18"/>
        <source>%1 has no block to join in parallel</source>
        <translation>%1 előtt nincs párhuzamosan kapcsolható blokk</translation>
    </message>
    <message numerus="yes">
        <location line="-9"/>
        <source>%1 needs two blocks, but %n is open</source>
        <translation>
            <numerusform>%1 két blokkot igényel, de %n nyitott</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+19"/>
        <source>MPS needs exactly one open block, but %n is open</source>
        <translation>
            <numerusform>Az MPS pontosan egy nyitott blokkot igényel, de %n nyitott</numerusform>
        </translation>
    </message>
    <message>
        <location line="+12"/>
        <source>%1 without a matching MPS</source>
        <translation>%1 hozzá tartozó MPS nélkül</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>%1 needs %2 input blocks, but %3 are open</source>
        <translation>%1 %2 bemeneti blokkot igényel, de %3 nyitott</translation>
    </message>
    <message>
        <location line="+9"/>
        <location filename="../model/convert/convert_to_list.cpp" line="+48"/>
        <source>%1 has an input with no condition</source>
        <translation>%1 egyik bemenetének nincs feltétele</translation>
    </message>
    <message>
        <location line="+15"/>
        <location line="+4"/>
        <location line="+6"/>
        <location filename="../model/convert/convert_to_list.cpp" line="+12"/>
        <source>%1 has no condition</source>
        <translation>%1 feltétel nélküli</translation>
    </message>
    <message>
        <location line="-5"/>
        <source>%1 needs one block, but %2 are open</source>
        <translation>%1 egy blokkot igényel, de %2 nyitott</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>The rung starting on line %1 ends without an output</source>
        <translation>A(z) %1. sorban kezdődő létrafok kimenet nélkül ér véget</translation>
    </message>
    <message numerus="yes">
        <location line="+4"/>
        <source>The rung starting on line %1 leaves %n MPS without MPP</source>
        <translation>
            <numerusform>A(z) %1. sorban kezdődő létrafok %n MPS-t hagy MPP nélkül</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/convert/convert_to_list.cpp" line="+33"/>
        <source>%1 has no INV element</source>
        <translation>%1 nem tartalmaz INV elemet</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 has no such contact</source>
        <translation>%1 nem rendelkezik ilyen érintkezővel</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>%1 has no branch stack</source>
        <translation>%1 nem rendelkezik elágazási veremmel</translation>
    </message>
    <message>
        <location line="+80"/>
        <source>A block cannot start with INV</source>
        <translation>Blokk nem kezdődhet INV-vel</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>An output has no condition</source>
        <translation>Egy kimenetnek nincs feltétele</translation>
    </message>
    <message>
        <location line="+97"/>
        <source>A branch reads a device that an earlier branch of the same rung writes, and %1 cannot hold this branch point (IL does not nest); draw the branches as separate rungs</source>
        <translation>Egy ág olyan operandust olvas, amelyet ugyanennek a létrafoknak egy korábbi ága ír, és a(z) %1 nem tudja megtartani ezt az elágazási pontot (az IL nem ágyazható egymásba); rajzolja az ágakat külön létrafokokként</translation>
    </message>
    <message>
        <location line="+98"/>
        <source>A box with several inputs must stand alone in its rung</source>
        <translation>A több bemenetű funkcióblokknak egyedül kell állnia a létrafokán</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Row %1 is not connected to the left rail</source>
        <translation>A(z) %1. sor nincs a bal oldali gyűjtősínhez kötve</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Reverse current: the network feeding row %1 can only close through an element crossed right to left</source>
        <translation>Visszáram: a(z) %1. sort tápláló hálózat csak jobbról balra bejárt elemen át záródhat</translation>
    </message>
</context>
<context>
    <name>rung::model::InstructionList</name>
    <message>
        <location filename="../model/listing/il_parse.cpp" line="+164"/>
        <source>Too many errors; the rest of the listing was not read</source>
        <translation>Túl sok hiba; a lista többi része nem lett beolvasva</translation>
    </message>
    <message>
        <location line="+158"/>
        <source>Program sections such as &apos;%1&apos; are not supported: a listing is one main program, run at every scan</source>
        <translation>A programszakaszok (például &apos;%1&apos;) nem támogatottak: az utasításlista egyetlen főprogram, amely minden ciklusban lefut</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Program sections such as &apos;%1&apos; are not supported: a listing is one main program, run at every scan; put what runs once under LD %2 (ON in the first scan). Interrupt programs are not supported</source>
        <translation>A programszakaszok (például &apos;%1&apos;) nem támogatottak: az utasításlista egyetlen főprogram, amely minden ciklusban lefut; ami egyszer fut, kerüljön az LD %2 alá (az első ciklusban BE). Megszakítási programok nem támogatottak</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>Unknown instruction &apos;%1&apos; for %2</source>
        <translation>Ismeretlen utasítás: &apos;%1&apos; (%2)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Unknown instruction &apos;%1&apos; for %2; did you mean %3?</source>
        <translation>Ismeretlen utasítás: &apos;%1&apos; (%2); erre gondolt: %3?</translation>
    </message>
    <message>
        <location line="+41"/>
        <source>%1 cannot compare values</source>
        <translation>%1 nem tud értékeket összehasonlítani</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>A second operand is missing after &apos;%1&apos;</source>
        <translation>Hiányzik a második operandus &apos;%1&apos; után</translation>
    </message>
    <message>
        <location line="+19"/>
        <location line="+210"/>
        <source>&apos;%1...&apos; is too long for an operand</source>
        <translation>A(z) &apos;%1...&apos; túl hosszú egy operandushoz</translation>
    </message>
    <message numerus="yes">
        <location line="-135"/>
        <source>%1 needs %n operand(s): %2</source>
        <translation>
            <numerusform>%1 %n operandust igényel: %2</numerusform>
        </translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 takes no operand</source>
        <translation>%1 nem vár operandust</translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>Unexpected &apos;%1&apos;: %2 takes %n operand(s)</source>
        <translation>
            <numerusform>Váratlan &apos;%1&apos;: %2 %n operandust vár</numerusform>
        </translation>
    </message>
    <message>
        <location line="+34"/>
        <source>%1: a set value is a BCD constant #0000..#9999 or a channel</source>
        <translation>%1: a beállított érték BCD konstans (#0000..#9999) vagy csatorna</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>%1 is out of range: %2..%3 fit here</source>
        <translation>%1 tartományon kívül esik: itt %2..%3 lehet</translation>
    </message>
    <message>
        <location line="+73"/>
        <source>%1: a label number is expected</source>
        <translation>%1: címkeszám kell</translation>
    </message>
    <message>
        <location line="+43"/>
        <location line="+46"/>
        <source>%1 is a constant; a device is expected here</source>
        <translation>%1 konstans; ide operandus kell</translation>
    </message>
    <message>
        <location line="-32"/>
        <source>%1: %2 is expected here</source>
        <translation>%1: itt %2 kell</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>%1 is a word (%2 bits); a single device is expected here</source>
        <translation>%1 egy szó (%2 bit); ide egyetlen operandus kell</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1: an index register modifies only the word operands of application instructions and set values</source>
        <translation>%1: indexregiszter csak az alkalmazói utasítások szó operandusait és a beállított értékeket módosítja</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>a timer</source>
        <translation>egy időzítő</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>a counter</source>
        <translation>egy számláló</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>a step relay</source>
        <translation>egy lépésrelé</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>a bit device</source>
        <translation>egy bit típusú operandus</translation>
    </message>
    <message>
        <location filename="../model/listing/operand_text.cpp" line="+159"/>
        <source>%1: K%2 is no digit count here; K1..K%3 (groups of 4 bits) fit a word</source>
        <translation>%1: a K%2 itt nem számjegyszám; egy szóba K1..K%3 (4 bites csoportok) fér</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1: K%2 takes a bit device (the first of its bits), not %3</source>
        <translation>%1: a K%2 bit típusú operandust vár (az első bitjét), nem ezt: %3</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1 takes the %2 bits %3..%4, but %5 does not exist</source>
        <translation>%1 a(z) %3..%4 %2 bitet foglalja, de %5 nem létezik</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1: an index register cannot be indexed</source>
        <translation>%1: indexregiszter nem indexelhető</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: index registers modify words (D0E0, K4M0E0) and K constants, not the bit %2</source>
        <translation>%1: indexregiszter szót (D0E0, K4M0E0) és K konstanst módosít, nem a(z) %2 bitet</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1: index registers modify K constants, not %2</source>
        <translation>%1: indexregiszter K konstanst módosít, nem ezt: %2</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1: %2 is not an index register (%3)</source>
        <translation>%1: %2 nem indexregiszter (%3)</translation>
    </message>
    <message>
        <location filename="../model/listing/il_parse.cpp" line="-344"/>
        <source>The text &quot;%1&quot; has no closing quote; a quote inside a text is written twice (&quot;&quot;)</source>
        <translation>A(z) &quot;%1&quot; szövegnek nincs záró idézőjele; a szövegen belüli idézőjelet kétszer kell írni (&quot;&quot;)</translation>
    </message>
    <message>
        <location line="+198"/>
        <source>&quot;%1&quot;: a text in quotes is not expected here</source>
        <translation>&quot;%1&quot;: itt nem állhat idézőjeles szöveg</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1: a text in double quotes is expected here, as &quot;%2&quot;</source>
        <translation>%1: itt idézőjeles szöveg kell, például &quot;%2&quot;</translation>
    </message>
</context>
<context>
    <name>rung::model::Ladder</name>
    <message>
        <location filename="../model/ladder/replace_device.cpp" line="+22"/>
        <source>%1 cannot replace %2 in rung %3: %4 is expected there.</source>
        <translation>%1 nem helyettesítheti a(z) %2 eszközt a(z) %3. létrafokban: ott %4 kell.</translation>
    </message>
</context>
<context>
    <name>rung::model::LadderText</name>
    <message>
        <location filename="../model/ladder/ladder_text.cpp" line="+195"/>
        <source>A ladder text starts with &quot;LADDER &lt;target&gt; WIDTH &lt;n&gt;&quot;</source>
        <translation>A létra-szöveg így kezdődik: &quot;LADDER &lt;target&gt; WIDTH &lt;n&gt;&quot;</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>This ladder is for %1, not %2</source>
        <translation>Ez a létradiagram a(z) %1 rendszerhez készült, nem a(z) %2 rendszerhez</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The cell width must be a number from 5 to 200</source>
        <translation>A cellaszélesség 5 és 200 közötti szám lehet</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Expected &quot;RUNG &lt;n&gt; ROWS &lt;rows&gt; COLUMNS &lt;columns&gt;&quot;</source>
        <translation>A várt forma: &quot;RUNG &lt;n&gt; ROWS &lt;rows&gt; COLUMNS &lt;columns&gt;&quot;</translation>
    </message>
    <message>
        <location line="+18"/>
        <location line="+9"/>
        <source>The rung has fewer rows than its header says</source>
        <translation>A létrafoknak kevesebb sora van, mint amennyit a fejléce megad</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>A row starts with the left rail &apos;|&apos;</source>
        <translation>A sor a bal oldali &apos;|&apos; gyűjtősínnel kezdődik</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>A cell is empty, a wire, or a contact &quot;-[ %1 ]-&quot;</source>
        <translation>A cella üres, vezeték, vagy egy &quot;-[ %1 ]-&quot; érintkező</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>An output is written in parentheses: (%1 %2)</source>
        <translation>A kimenetet zárójelben kell írni: (%1 %2)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>(^) marks a further input of a box above it</source>
        <translation>A (^) a fölötte álló funkcióblokk további bemenetét jelöli</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>One output instruction is expected</source>
        <translation>Egy kimeneti utasítás a várt</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>&apos;~%1&apos;: a power-flow element is ~, ~P or ~N</source>
        <translation>&apos;~%1&apos;: az áramútelem jele ~, ~P vagy ~N</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>&apos;%1&apos; is not a contact mark (&apos; &apos;, &apos;/&apos;, &apos;P&apos;, &apos;N&apos;, &apos;~&apos;)</source>
        <translation>A(z) &apos;%1&apos; nem érintkezőjel (&apos; &apos;, &apos;/&apos;, &apos;P&apos;, &apos;N&apos;, &apos;~&apos;)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The contact has no device</source>
        <translation>Az érintkezőnek nincs operandusa</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>%1 is a word; a contact takes a bit device</source>
        <translation>%1 egy szó; az érintkező bit típusú operandust vár</translation>
    </message>
    <message>
        <location line="+69"/>
        <source>&apos;%1&apos; is not a contact</source>
        <translation>A(z) &apos;%1&apos; nem érintkező</translation>
    </message>
</context>
<context>
    <name>rung::model::PanelView</name>
    <message>
        <location filename="../model/image/panel_view.cpp" line="+131"/>
        <source>Display mode %1: the manual describes mode %2 (one %3-digit value) and mode %4 (two %5-digit values)</source>
        <translation>%1. kijelzési mód: a kézikönyv a(z) %2. módot (egy %3 jegyű érték) és a(z) %4. módot (két %5 jegyű érték) írja le</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>The register named by %1 (%2) does not exist</source>
        <translation>A(z) %1 által megnevezett regiszter (%2) nem létezik</translation>
    </message>
    <message>
        <location line="+110"/>
        <source>Application &quot;%1&quot;; the ports&apos; protocols as their settings give them</source>
        <translation>Alkalmazás: „%1”; a portok protokolljai a beállításaik szerint</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The application&apos;s name and the ports&apos; protocols are not known here: shown as dashes</source>
        <translation>Az alkalmazás neve és a portok protokolljai itt nem ismertek: kötőjel jelzi őket</translation>
    </message>
    <message>
        <location line="+154"/>
        <source>No page is shown: the program enables none</source>
        <translation>Nincs megjelenített oldal: a program egyet sem engedélyez</translation>
    </message>
    <message>
        <location filename="../model/target/target_pl110_panel.cpp" line="+139"/>
        <source>System info: the simulator has no BOOT or firmware version (shown as a dash); the slave address is SMW4, changed with the keys after the system password 1357</source>
        <translation>Rendszerinformáció: a szimulátornak nincs BOOT- és firmware-verziója (kötőjel jelzi); a slave címe az SMW4, a gombokkal az 1357-es rendszerjelszó megadása után módosítható</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Date and time: the simulator&apos;s clock does not count; SM9..SM15 keep what the program or the keys write</source>
        <translation>Dátum és idő: a szimulátor órája nem jár; az SM9..SM15 azt tartja, amit a program vagy a gombok beleírnak</translation>
    </message>
</context>
<context>
    <name>rung::model::Plcopen</name>
    <message>
        <location filename="../model/exchange/plcopen_import.cpp" line="+128"/>
        <source>not a PLCopen TC6 XML 2.01 project (the root is &lt;%1&gt; in &quot;%2&quot;, &lt;project&gt; in &quot;%3&quot; is expected)</source>
        <translation>nem PLCopen TC6 XML 2.01 projekt (a gyökér &lt;%1&gt; a(z) „%2” névtérben, &lt;project&gt; várható a(z) „%3” névtérben)</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>a %1 is not imported: %2 runs one ladder, with no user functions or function blocks</source>
        <translation>%1 nem kerül beolvasásra: a(z) %2 egy létradiagramot futtat, felhasználói függvények és funkcióblokkok nélkül</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the file has no program</source>
        <translation>a fájlban nincs program</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>a body in %1 is not imported: only ladder (LD) is</source>
        <translation>a(z) %1 nyelvű törzs nem kerül beolvasásra: csak a létradiagram (LD)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the program has no ladder (LD) body</source>
        <translation>a programnak nincs létradiagram (LD) törzse</translation>
    </message>
    <message>
        <location line="+159"/>
        <source>the mapping file gives %1: %2</source>
        <translation>a hozzárendelő fájl szerint %1: %2</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>%1 at %2: %3 has no such device (docs/plcopen.md, located variables); give one in a mapping file</source>
        <translation>%1 itt: %2: a(z) %3 PLC-nek nincs ilyen operandusa (docs/plcopen.md, címzett változók); adjon meg egyet hozzárendelő fájlban</translation>
    </message>
    <message>
        <location line="+159"/>
        <source>input %1 is not a variable or a literal</source>
        <translation>a(z) %1 bemenet nem változó és nem konstans</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>line %1: &quot;%2&quot; is not NAME = DEVICE</source>
        <translation>%1. sor: „%2” nem NÉV = OPERANDUS alakú</translation>
    </message>
    <message>
        <location filename="../model/exchange/plcopen_power.cpp" line="+66"/>
        <source>its input is connected to nothing: not imported</source>
        <translation>a bemenete semmihez sem kapcsolódik: nem kerül beolvasásra</translation>
    </message>
    <message>
        <location line="+98"/>
        <source>it is connected to element %1, which the file does not have</source>
        <translation>a(z) %1 elemhez kapcsolódik, amely nincs a fájlban</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the power flow runs in a loop: not imported</source>
        <translation>az áramút körbe fut: nem kerül beolvasásra</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>a contact both negated and on an edge is not imported</source>
        <translation>a nyitó és egyben élvezérelt érintkező nem kerül beolvasásra</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 has no such contact</source>
        <translation>a(z) %1 PLC-nek nincs ilyen érintkezője</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>no connector is named %1</source>
        <translation>nincs %1 nevű csatlakozó</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>a %1 carries no power flow %2 can take</source>
        <translation>a(z) %1 nem visz olyan áramutat, amelyet a(z) %2 fogadni tud</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>a comparison needs IN1 and IN2</source>
        <translation>az összehasonlításhoz IN1 és IN2 kell</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>%1 has no compare contact %2</source>
        <translation>a(z) %1 PLC-nek nincs %2 összehasonlító érintkezője</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>%1 has no element for %2 in the power flow</source>
        <translation>a(z) %1 PLC-nek nincs az áramútban %2 elemnek megfelelő eleme</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>output %1 of %2 as power flow is not imported</source>
        <translation>a(z) %2 %1 kimenete áramútként nem kerül beolvasásra</translation>
    </message>
    <message>
        <location filename="../model/exchange/plcopen_outputs.cpp" line="+22"/>
        <source>one instruction is expected</source>
        <translation>egy utasítás várható</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>a negated coil that also sets, resets or pulses is not imported</source>
        <translation>a negált tekercs, amely egyben beír, töröl vagy impulzust ad, nem kerül beolvasásra</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 has no such coil</source>
        <translation>a(z) %1 PLC-nek nincs ilyen tekercse</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>PT must be a time literal (T#1s) to be a set value: not imported</source>
        <translation>a PT-nek időkonstansnak (T#1s) kell lennie, hogy beállított érték legyen: nem kerül beolvasásra</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1 has no pulse timer (TP)</source>
        <translation>a(z) %1 PLC-nek nincs impulzusidőzítője (TP)</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>%1 has no %2 timer that times %3 ms on %4</source>
        <translation>a(z) %1 PLC-nek nincs olyan %2 időzítője, amely %3 ms-ot mér a(z) %4 operandussal</translation>
    </message>
    <message>
        <location line="+117"/>
        <source>MOVE&apos;s OUT goes to no variable: not imported</source>
        <translation>a MOVE OUT kimenete nem megy változóba: nem kerül beolvasásra</translation>
    </message>
    <message>
        <location line="-17"/>
        <source>%1 has no move instruction</source>
        <translation>a(z) %1 PLC-nek nincs mozgató utasítása</translation>
    </message>
    <message>
        <location filename="../model/exchange/plcopen_rungs.cpp" line="+256"/>
        <source>the ladder does not use it and it names no device: not imported</source>
        <translation>a létradiagram nem használja, és nem jelöl operandust: nem kerül beolvasásra</translation>
    </message>
    <message>
        <location line="+115"/>
        <source>IEC jumps, labels and returns are not imported: %1&apos;s own jumps work otherwise; write them in Rung Studio</source>
        <translation>az IEC ugrások, címkék és visszatérések nem kerülnek beolvasásra: a(z) %1 saját ugrásai másként működnek; írja meg őket a Rung Studióban</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>its power comes from %1 (line %2), which is not imported</source>
        <translation>az áramútja innen jön: %1 (%2. sor), amely nem kerül beolvasásra</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>its power goes to %1 (line %2), which is not imported</source>
        <translation>az áramútja ide megy: %1 (%2. sor), amely nem kerül beolvasásra</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>no output uses it: not imported</source>
        <translation>egyetlen kimenet sem használja: nem kerül beolvasásra</translation>
    </message>
    <message>
        <location filename="../model/exchange/plcopen_write.cpp" line="+96"/>
        <source>%1 is written as a block of %2&apos;s own: other tools read the file but do not know this block</source>
        <translation>a(z) %1 a(z) %2 saját blokkjaként íródik ki: más eszközök beolvassák a fájlt, de ezt a blokkot nem ismerik</translation>
    </message>
    <message>
        <location filename="../model/exchange/plcopen_xml.cpp" line="+25"/>
        <source>line %1: the XML nests deeper than %2 levels</source>
        <translation>%1. sor: az XML %2 szintnél mélyebben ágyazott</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>line %1, column %2: the file is not well-formed XML (%3)</source>
        <translation>%1. sor, %2. oszlop: a fájl nem szabályos XML (%3)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the file holds no XML element</source>
        <translation>a fájlban nincs XML elem</translation>
    </message>
    <message>
        <location filename="../model/exchange/plcopen_import.cpp" line="-379"/>
        <source>a second program is not imported: a project is one ladder (the program %1 is)</source>
        <translation>a második program nem kerül beolvasásra: egy projekt egy létradiagram (a(z) %1 program kerül beolvasásra)</translation>
    </message>
    <message>
        <location line="+254"/>
        <source>%1 is not imported: %2 keeps a counter&apos;s present value as BCD digits</source>
        <translation>a(z) %1 nem kerül beolvasásra: a(z) %2 a számláló aktuális értékét BCD számjegyekként tárolja</translation>
    </message>
    <message>
        <location filename="../model/exchange/plcopen_power.cpp" line="-288"/>
        <source>%1 as a contact is not imported: only a timer&apos;s or counter&apos;s bit (Q) is</source>
        <translation>a(z) %1 érintkezőként nem kerül beolvasásra: csak az időzítő vagy a számláló bitje (Q)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1 is not imported: the bit of %2 %3 is %4</source>
        <translation>a(z) %1 nem kerül beolvasásra: a(z) %2 %3 bitje a(z) %4</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>its input %1 is negated: not imported</source>
        <translation>a(z) %1 bemenete negált: nem kerül beolvasásra</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>its input %1 on a %2 edge is not imported</source>
        <translation>a(z) %1 bemenet edge=„%2” jelöléssel nem kerül beolvasásra</translation>
    </message>
    <message>
        <location line="+274"/>
        <source>%1 has no contact that is never ON for an input left FALSE</source>
        <translation>a(z) %1 PLC-nek nincs soha BE nem kapcsoló érintkezője a FALSE értéken hagyott bemenethez</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>its EN has a condition: while EN is OFF an IEC block stops where it stands, which %1&apos;s timers and counters do not; not imported</source>
        <translation>az EN bemenetének feltétele van: amíg az EN KI, az IEC blokk ott áll meg, ahol tart, a(z) %1 időzítői és számlálói viszont nem; nem kerül beolvasásra</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>input %1 is %2, not power: not imported</source>
        <translation>a(z) %1 bemenet értéke %2, nem áramút: nem kerül beolvasásra</translation>
    </message>
    <message>
        <location filename="../model/exchange/plcopen_outputs.cpp" line="-1"/>
        <source>%1 has no instruction to make a BCD value binary</source>
        <translation>a(z) %1 PLC-nek nincs utasítása BCD érték binárissá alakítására</translation>
    </message>
    <message>
        <location filename="../model/exchange/plcopen_rungs.cpp" line="-210"/>
        <source>the instruction list in the file differs from its ladder (another tool changed the ladder?): the ladder is imported</source>
        <translation>a fájlban lévő utasításlista eltér a létradiagramjától (egy másik eszköz módosította a létradiagramot?): a létradiagram kerül beolvasásra</translation>
    </message>
    <message>
        <location line="+196"/>
        <source>this block is not imported: contacts, coils, TON, TOF, CTU, CTD, CTUD, MOVE, the comparisons, NOT, R_TRIG and F_TRIG are (docs/plcopen.md)</source>
        <translation>ez a blokk nem kerül beolvasásra: az érintkezők, tekercsek, a TON, TOF, CTU, CTD, CTUD, MOVE, az összehasonlítások, a NOT, R_TRIG és F_TRIG igen (docs/plcopen.md)</translation>
    </message>
    <message>
        <location filename="../model/exchange/plcopen_write.cpp" line="+3"/>
        <source>%1 is written as a block of %2&apos;s own (%3): other tools read the file but do not know this block</source>
        <translation>a(z) %1 a(z) %2 saját blokkjaként íródik ki (%3): más eszközök beolvassák a fájlt, de ezt a blokkot nem ismerik</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>the instruction list is not written beside the ladder: rung %1 does not convert (%2)</source>
        <translation>az utasításlista nem íródik ki a létradiagram mellé: a(z) %1. létrafok nem alakítható át (%2)</translation>
    </message>
    <message>
        <location filename="../model/exchange/plcopen_counters.cpp" line="+26"/>
        <source>%1&apos;s %2 stops counting at its set value, where CV counts on past PV (Q is the same); its reset is an RST, which acts where it stands in the program, not when the counter runs as R does</source>
        <translation>a(z) %1 %2 számlálója megáll a beállított értéknél, míg a CV a PV fölött is tovább számol (a Q ugyanaz); törlése RST, amely ott hat, ahol a programban áll, nem akkor, amikor a számláló fut, ahogy az R</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1&apos;s %2 stops counting at 0, where CV counts on below 0 (Q is the same), and it is OFF until it has counted down, where a CTD is ON until LD first loads PV</source>
        <translation>a(z) %1 %2 számlálója 0-nál megáll, míg a CV 0 alá is tovább számol (a Q ugyanaz), és KI marad, amíg le nem számolt, míg a CTD BE van, amíg az LD először be nem tölti a PV-t</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1&apos;s %2 stops counting at its set value, where CV counts on past PV (Q is the same)</source>
        <translation>a(z) %1 %2 számlálója megáll a beállított értéknél, míg a CV a PV fölött is tovább számol (a Q ugyanaz)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1&apos;s %2 stops counting at 0, where CV counts on below 0, and %1 compares the count at the end of the scan, where a CTUD sets QD when it runs</source>
        <translation>a(z) %1 %2 számlálója 0-nál megáll, míg a CV 0 alá is tovább számol, és a(z) %1 a programciklus végén hasonlítja össze a számlálást, míg a CTUD a futásakor állítja a QD-t</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1 compares the count of %2 with PV at the end of the scan, where a CTUD sets QU when it runs</source>
        <translation>a(z) %1 a programciklus végén hasonlítja össze a(z) %2 számlálását a PV-vel, míg a CTUD a futásakor állítja a QU-t</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1&apos;s %2 wraps around at its limits, where IEC&apos;s CTUD stops</source>
        <translation>a(z) %1 %2 számlálója a határainál körbefordul, míg az IEC CTUD megáll</translation>
    </message>
    <message>
        <location filename="../model/exchange/plcopen_export.cpp" line="+139"/>
        <source>%1 reads a set value in a word as BCD digits, where PV is a number</source>
        <translation>a(z) %1 a szóban tárolt beállított értéket BCD számjegyekként olvassa, míg a PV egy szám</translation>
    </message>
    <message>
        <location line="+287"/>
        <source>%1 is written as an IEC %2: %3</source>
        <translation>a(z) %1 IEC %2 blokkként íródik ki: %3</translation>
    </message>
    <message>
        <location filename="../model/exchange/plcopen_import_counters.cpp" line="+59"/>
        <source>%1 is no counter of %2: give %3 a counter in the mapping file</source>
        <translation>a(z) %1 nem a(z) %2 számlálója: adjon a(z) %3 változónak számlálót a hozzárendelő fájlban</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>%1 has no counter that counts as %2 does on %3</source>
        <translation>a(z) %1 PLC-nek nincs olyan számlálója a(z) %3 operanduson, amely úgy számol, mint a(z) %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>it uses %1 together, which no counter of %2 has</source>
        <translation>együtt használja a(z) %1 bemeneteket, amelyek a(z) %2 egyik számlálójának sincsenek meg</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>PV is not given: not imported</source>
        <translation>nincs megadva PV: nem kerül beolvasásra</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>PV %1 is a variable: %2 reads a set value in a word as BCD digits; not imported</source>
        <translation>a(z) %1 PV változó: a(z) %2 a szóban tárolt beállított értéket BCD számjegyekként olvassa; nem kerül beolvasásra</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>PV %1 is a variable: %2 keeps a counter&apos;s set value in the PLC, a number; not imported</source>
        <translation>a(z) %1 PV változó: a(z) %2 a számláló beállított értékét a PLC-ben tárolja, számként; nem kerül beolvasásra</translation>
    </message>
    <message>
        <location line="+62"/>
        <source>%1 (%2) is imported as %3&apos;s %4: %5</source>
        <translation>a(z) %1 (%2) a(z) %3 %4 utasításaként kerül beolvasásra: %5</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 (%2) is imported as %3&apos;s %4, which counts the other way: its bit is %1&apos;s Q once %5 has been ON, and its present value is not CV</source>
        <translation>a(z) %1 (%2) a(z) %3 %4 utasításaként kerül beolvasásra, amely a másik irányba számol: a bitje a(z) %1 Q kimenete, miután a(z) %5 egyszer BE volt, aktuális értéke viszont nem a CV</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1.CV is not imported: %2 counts the other way, its present value is not CV</source>
        <translation>a(z) %1.CV nem kerül beolvasásra: a(z) %2 a másik irányba számol, aktuális értéke nem a CV</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>%1 of %2 to a variable is not imported: only a counter&apos;s CV is</source>
        <translation>a(z) %2 %1 kimenete változóba nem kerül beolvasásra: csak a számláló CV kimenete</translation>
    </message>
</context>
<context>
    <name>rung::model::PortConfig</name>
    <message>
        <location filename="../model/comm/port_config.cpp" line="+56"/>
        <source>%1: needs a whole number from %2 to %3</source>
        <translation>%1: %2 és %3 közötti egész szám kell</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>%1: needs &quot;%2&quot; or &quot;%3&quot;</source>
        <translation>%1: „%2” vagy „%3” kell</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>%1: %2 has no serial port a network can use</source>
        <translation>%1: a(z) %2 PLC-nek nincs hálózatban használható soros portja</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: %2 has no port %3 (its ports: %4)</source>
        <translation>%1: a(z) %2 PLC-nek nincs %3 portja (a portjai: %4)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: the %2 %3 has no port %4</source>
        <translation>%1: a(z) %2 %3 típusnak nincs %4 portja</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1: needs the name of an application</source>
        <translation>%1: egy alkalmazás neve kell</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1: %2 is no application of %3 (%4)</source>
        <translation>%1: a(z) %2 nem alkalmazása a(z) %3 portnak (%4)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1: the %2 %3 has no %4 on %5 (it has: %6)</source>
        <translation>%1: a(z) %2 %3 típuson a(z) %5 porton nincs %4 (ami van: %6)</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1: %2 takes no setting &quot;%3&quot;</source>
        <translation>%1: a(z) %2 nem fogad „%3” beállítást</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1: %2 is not a rate of %3 (%4)</source>
        <translation>%1: a(z) %2 nem átviteli sebessége a(z) %3 alkalmazásnak (%4)</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1: &quot;%2&quot; is no character format (data bits 7 or 8, parity N, E or O, stop bits 1 or 2: 8N1, 7E1)</source>
        <translation>%1: a(z) „%2” nem karakterformátum (adatbitek 7 vagy 8, paritás N, E vagy O, stopbitek 1 vagy 2: 8N1, 7E1)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1: %2 always uses %3</source>
        <translation>%1: a(z) %2 mindig %3 formátumot használ</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>%1: needs an object of settings</source>
        <translation>%1: beállításokat tartalmazó objektum kell</translation>
    </message>
</context>
<context>
    <name>rung::model::PowerFlow</name>
    <message>
        <location filename="../model/image/power_flow.cpp" line="+416"/>
        <source>ON</source>
        <translation>BE</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>OFF</source>
        <translation>KI</translation>
    </message>
    <message>
        <location line="-35"/>
        <source>%1/%2 ×%3 s</source>
        <extracomment>a timer&apos;s time elapsed / set value in its units, then the unit: &quot;23/50 ×0.1 s&quot;</extracomment>
        <translation>%1/%2 ×%3 s</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>%1 = %2</source>
        <extracomment>a device and its value under a box: &quot;D0 = 12&quot;</extracomment>
        <translation>%1 = %2</translation>
    </message>
</context>
<context>
    <name>rung::model::Project</name>
    <message>
        <location filename="../model/project/project.cpp" line="+211"/>
        <source>Line %1, column %2 (byte %3): the file is not valid JSON (%4)</source>
        <translation>%1. sor, %2. oszlop (%3. bájt): a fájl nem érvényes JSON (%4)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The file is JSON but not a Rung Studio project (no top-level object)</source>
        <translation>A fájl JSON, de nem Rung Studio projekt (nincs legfelső szintű objektum)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The file is JSON but not a Rung Studio project (&quot;format&quot; is not &quot;%1&quot;)</source>
        <translation>A fájl JSON, de nem Rung Studio projekt (a &quot;format&quot; nem &quot;%1&quot;)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The project was written by a newer Rung Studio (schema %1); this version reads schema %2 and older</source>
        <translation>A projektet egy újabb Rung Studio írta (%1. séma); ez a verzió a %2. és korábbi sémát olvassa</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&quot;schema&quot; must be a positive number</source>
        <translation>A &quot;schema&quot; pozitív szám kell legyen</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>&quot;target&quot;: unknown PLC family &quot;%1&quot;</source>
        <translation>&quot;target&quot;: ismeretlen PLC-család: &quot;%1&quot;</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&quot;model&quot;: %1 has no model &quot;%2&quot;</source>
        <translation>&quot;model&quot;: a(z) %1 rendszernek nincs &quot;%2&quot; modellje</translation>
    </message>
    <message>
        <location line="+22"/>
        <location line="+67"/>
        <source>%1: an object with &quot;device&quot; and &quot;name&quot; is expected</source>
        <translation>%1: &quot;device&quot; és &quot;name&quot; mezőket tartalmazó objektum a várt</translation>
    </message>
    <message>
        <location line="-43"/>
        <source>setValues.%1: a whole number between -%2 and %2 is expected</source>
        <translation>setValues.%1: -%2 és %2 közötti egész szám a várt</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1: an object with &quot;name&quot; and &quot;devices&quot; is expected</source>
        <translation>%1: &quot;name&quot; és &quot;devices&quot; mezőket tartalmazó objektum a várt</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>%1.devices[%2]: a device name is expected</source>
        <translation>%1.devices[%2]: operandusnév a várt</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1.formats.%2: &quot;%3&quot; is no format (dec, signed, hex, bin, bcd)</source>
        <translation>%1.formats.%2: „%3” nem formátum (dec, signed, hex, bin, bcd)</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>a string</source>
        <translation>karakterlánc</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>an array</source>
        <translation>tömb</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>an object</source>
        <translation>objektum</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>a number</source>
        <translation>szám</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>another value</source>
        <translation>egyéb érték</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1: %2 is expected</source>
        <translation>%1: a várt típus: %2</translation>
    </message>
    <message>
        <location line="+104"/>
        <source>%1.outputs: [row, &quot;instruction&quot;] with a row inside the rung is expected</source>
        <translation>%1.outputs: [sor, &quot;utasítás&quot;] a várt forma, a létrafokon belüli sorral</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1.outputs: row %2 has two outputs</source>
        <translation>%1.outputs: a(z) %2. sornak két kimenete van</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>%1.outputs: &quot;%2&quot; takes up to %3 input rows, one box per rung</source>
        <translation>%1.outputs: &quot;%2&quot; legfeljebb %3 bemeneti sort fogad, létrafokonként egy funkcióblokkot</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1.outputs: the input rows of &quot;%2&quot; start at its own row and go down inside the rung</source>
        <translation>%1.outputs: &quot;%2&quot; bemeneti sorai a saját sorától indulnak lefelé, a létrafokon belül</translation>
    </message>
    <message>
        <location line="-125"/>
        <source>%1: a rung object is expected</source>
        <translation>%1: létrafok-objektum a várt</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>%1: &quot;rows&quot; must be 1..1000 and &quot;columns&quot; 0..1000</source>
        <translation>%1: a &quot;rows&quot; értéke 1..1000, a &quot;columns&quot; értéke 0..1000 lehet</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1.cells: %2 rows are expected, the file has %3</source>
        <translation>%1.cells: %2 sor a várt, a fájlban %3 van</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1.cells[%2]: an array of cells is expected</source>
        <translation>%1.cells[%2]: cellák tömbje a várt</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1.cells[%2]: %3 cells are expected, the file has %4</source>
        <translation>%1.cells[%2]: %3 cella a várt, a fájlban %4 van</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1.cells[%2][%3]: a cell is a string (&quot;&quot;, &quot;-&quot; or a contact)</source>
        <translation>%1.cells[%2][%3]: a cella egy karakterlánc (&quot;&quot;, &quot;-&quot; vagy egy érintkező)</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>%1.links: [%2, %3] is outside the rung</source>
        <translation>%1.links: [%2, %3] a létrafokon kívül esik</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>one instruction is expected</source>
        <translation>egyetlen utasítás a várt</translation>
    </message>
    <message>
        <location filename="../model/project/file_read.cpp" line="+13"/>
        <source>%1: cannot open the file (%2)</source>
        <translation>%1: a fájl nem nyitható meg (%2)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: the file is %2 MB; the most Rung Studio reads is %3 MB</source>
        <translation>%1: a fájl %2 MB; a Rung Studio legfeljebb %3 MB-ot olvas be</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: the file is larger than %2 MB, the most Rung Studio reads</source>
        <translation>%1: a fájl nagyobb %2 MB-nál, ennél többet a Rung Studio nem olvas be</translation>
    </message>
    <message>
        <location filename="../model/project/project.cpp" line="+165"/>
        <source>%1: cannot write the file (%2)</source>
        <translation>%1: a fájl nem írható (%2)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1: saving failed (%2); the previous file is unchanged</source>
        <translation>%1: a mentés sikertelen (%2); az előző fájl változatlan</translation>
    </message>
    <message>
        <location filename="../model/project/program_file.cpp" line="+30"/>
        <source>unknown target %1 (%2)</source>
        <translation>ismeretlen célrendszer: %1 (%2)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1: unknown target %2 (%3)</source>
        <translation>%1: ismeretlen célrendszer: %2 (%3)</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1 is a %2 project, not %3</source>
        <translation>%1 egy %2 projekt, nem %3</translation>
    </message>
</context>
<context>
    <name>rung::model::SymbolsCsv</name>
    <message>
        <location filename="../model/project/symbols_csv.cpp" line="+113"/>
        <source>a symbol without a device</source>
        <translation>operandus nélküli szimbólum</translation>
    </message>
</context>
<context>
    <name>rung::model::Target</name>
    <message>
        <location filename="../model/target/target_cpm1.cpp" line="+34"/>
        <source>Host Link</source>
        <translation>Host Link</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>the CPU unit&apos;s peripheral port (Host Link, 9600 bps 7E2, unit 0)</source>
        <translation>a CPU-egység perifériacsatlakozója (Host Link, 9600 bps 7E2, 0. egység)</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>input channels</source>
        <translation>bemeneti csatornák</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>output channels</source>
        <translation>kimeneti csatornák</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>work channels</source>
        <translation>munkacsatornák</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>special channels</source>
        <translation>speciális csatornák</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>holding relays</source>
        <translation>tartórelék</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>link relays</source>
        <translation>link relék</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>temporary relays</source>
        <translation>átmeneti relék</translation>
    </message>
    <message>
        <location line="+4"/>
        <location filename="../model/target/target_pl110.cpp" line="+87"/>
        <location filename="../model/target/target_vpc.cpp" line="+61"/>
        <source>timers</source>
        <translation>időzítők</translation>
    </message>
    <message>
        <location line="+8"/>
        <location filename="../model/target/target_pl110.cpp" line="+5"/>
        <location filename="../model/target/target_vigor.cpp" line="+241"/>
        <location filename="../model/target/target_vpc.cpp" line="+5"/>
        <source>counters</source>
        <translation>számlálók</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>data memory</source>
        <translation>adatmemória</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>read-only data memory</source>
        <translation>csak olvasható adatmemória</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>always ON</source>
        <translation>mindig BE</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>always OFF</source>
        <translation>mindig KI</translation>
    </message>
    <message>
        <location line="+2"/>
        <location filename="../model/target/target_pl110.cpp" line="+73"/>
        <location filename="../model/target/target_vigor.cpp" line="+43"/>
        <source>ON for the first scan</source>
        <translation>az első ciklusban BE</translation>
    </message>
    <message>
        <location line="+2"/>
        <location filename="../model/target/target_vigor.cpp" line="+8"/>
        <source>1 min clock</source>
        <translation>1 perces órajel</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>0.02 s clock</source>
        <translation>0,02 s-os órajel</translation>
    </message>
    <message>
        <location line="+2"/>
        <location filename="../model/target/target_vpc.cpp" line="+58"/>
        <source>0.1 s clock</source>
        <translation>0,1 s-os órajel</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>0.2 s clock</source>
        <translation>0,2 s-os órajel</translation>
    </message>
    <message>
        <location line="+2"/>
        <location filename="../model/target/target_vigor.cpp" line="-2"/>
        <location filename="../model/target/target_vpc.cpp" line="+2"/>
        <source>1 s clock</source>
        <translation>1 s-os órajel</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>ER: instruction execution error</source>
        <translation>ER: utasítás-végrehajtási hiba</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>CY: carry</source>
        <translation>CY: átvitel</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>GR: greater than</source>
        <translation>GR: nagyobb</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>EQ: equal</source>
        <translation>EQ: egyenlő</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>LE: less than</source>
        <translation>LE: kisebb</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>ON for one cycle when a step starts</source>
        <translation>Egy ciklusig BE, amikor egy lépés elindul</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>FAL number of a non-fatal error in 253.00..253.07 (BCD)</source>
        <translation>nem lényegi hiba FAL száma a 253.00..253.07 biteken (BCD)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>analog setting 0 (BCD 0..200)</source>
        <translation>0. analóg beállítás (BCD 0..200)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>analog setting 1 (BCD 0..200)</source>
        <translation>1. analóg beállítás (BCD 0..200)</translation>
    </message>
    <message>
        <location line="+5"/>
        <location filename="../model/target/target_pl110.cpp" line="+87"/>
        <location filename="../model/target/target_vigor.cpp" line="+95"/>
        <location filename="../model/target/target_vpc.cpp" line="+5"/>
        <source>Start a block with a normally open contact</source>
        <translation>Blokk kezdése záró érintkezővel</translation>
    </message>
    <message>
        <location line="+3"/>
        <location filename="../model/target/target_pl110.cpp" line="+1"/>
        <location filename="../model/target/target_vigor.cpp" line="+3"/>
        <location filename="../model/target/target_vpc.cpp" line="+1"/>
        <source>Start a block with a normally closed contact</source>
        <translation>Blokk kezdése nyitó érintkezővel</translation>
    </message>
    <message>
        <location line="+3"/>
        <location filename="../model/target/target_pl110.cpp" line="+2"/>
        <location filename="../model/target/target_vigor.cpp" line="+9"/>
        <location filename="../model/target/target_vpc.cpp" line="+2"/>
        <source>Normally open contact in series</source>
        <translation>Záró érintkező sorosan</translation>
    </message>
    <message>
        <location line="+2"/>
        <location filename="../model/target/target_pl110.cpp" line="+1"/>
        <location filename="../model/target/target_vigor.cpp" line="+3"/>
        <location filename="../model/target/target_vpc.cpp" line="+1"/>
        <source>Normally closed contact in series</source>
        <translation>Nyitó érintkező sorosan</translation>
    </message>
    <message>
        <location line="+2"/>
        <location filename="../model/target/target_pl110.cpp" line="+3"/>
        <location filename="../model/target/target_vigor.cpp" line="+9"/>
        <location filename="../model/target/target_vpc.cpp" line="+2"/>
        <source>Normally open contact in parallel</source>
        <translation>Záró érintkező párhuzamosan</translation>
    </message>
    <message>
        <location line="+2"/>
        <location filename="../model/target/target_pl110.cpp" line="+1"/>
        <location filename="../model/target/target_vigor.cpp" line="+3"/>
        <location filename="../model/target/target_vpc.cpp" line="+1"/>
        <source>Normally closed contact in parallel</source>
        <translation>Nyitó érintkező párhuzamosan</translation>
    </message>
    <message>
        <location line="+4"/>
        <location filename="../model/target/target_pl110.cpp" line="+5"/>
        <location filename="../model/target/target_vigor.cpp" line="+18"/>
        <location filename="../model/target/target_vpc.cpp" line="+2"/>
        <source>Connect the last two blocks in series</source>
        <translation>Az utolsó két blokk soros kapcsolása</translation>
    </message>
    <message>
        <location line="+2"/>
        <location filename="../model/target/target_pl110.cpp" line="+2"/>
        <location filename="../model/target/target_vigor.cpp" line="+3"/>
        <location filename="../model/target/target_vpc.cpp" line="+2"/>
        <source>Connect the last two blocks in parallel</source>
        <translation>Az utolsó két blokk párhuzamos kapcsolása</translation>
    </message>
    <message>
        <location line="+2"/>
        <location filename="../model/target/target_pl110.cpp" line="+33"/>
        <location filename="../model/target/target_vigor.cpp" line="+12"/>
        <location filename="../model/target/target_vpc.cpp" line="+2"/>
        <source>Output coil</source>
        <translation>Kimeneti tekercs</translation>
    </message>
    <message>
        <location line="+2"/>
        <location filename="../model/target/target_vpc.cpp" line="+3"/>
        <source>Inverted output coil</source>
        <translation>Negált kimeneti tekercs</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Set (latch) a bit</source>
        <translation>Bit beállítása (tárolás)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Reset a bit</source>
        <translation>Bit törlése</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Keep: set = last but one block, reset = last block; reset wins</source>
        <translation>Keep: beállítás = utolsó előtti blokk, törlés = utolsó blokk; a törlés az erősebb</translation>
    </message>
    <message>
        <location line="+6"/>
        <location filename="../model/target/target_vigor.cpp" line="+9"/>
        <source>ON for one scan on a rising edge</source>
        <translation>Egy ciklusig BE felfutó élre</translation>
    </message>
    <message>
        <location line="+4"/>
        <location filename="../model/target/target_vigor.cpp" line="+3"/>
        <source>ON for one scan on a falling edge</source>
        <translation>Egy ciklusig BE lefutó élre</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Timer, 0.1 s, counts down from the BCD set value</source>
        <translation>Időzítő, 0,1 s, a BCD beállított értéktől lefelé számol</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>High-speed timer, 0.01 s, counts down from the BCD set value</source>
        <translation>Nagysebességű időzítő, 0,01 s, a BCD beállított értéktől lefelé számol</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Down counter: count = last but one block, reset = last block</source>
        <translation>Lefelé számláló: számlálás = utolsó előtti blokk, törlés = utolsó blokk</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Reversible counter: up, down and reset inputs; wraps at the limits</source>
        <translation>Kétirányú számláló: fel, le és törlés bemenet; a határoknál körbefordul</translation>
    </message>
    <message>
        <location line="+7"/>
        <location filename="../model/target/target_vpc.cpp" line="+41"/>
        <source>Interlock: what follows runs under this condition</source>
        <translation>Reteszelés: ami követi, ezzel a feltétellel fut</translation>
    </message>
    <message>
        <location line="+4"/>
        <location filename="../model/target/target_vpc.cpp" line="+3"/>
        <source>Clear the interlock</source>
        <translation>A reteszelés feloldása</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Jump: while OFF, skip to the JME with the same number</source>
        <translation>Ugrás: amíg KI, az azonos számú JME-ig ugrik</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>End of the jump with this number</source>
        <translation>Az ilyen számú ugrás vége</translation>
    </message>
    <message>
        <location line="+42"/>
        <source>analog settings</source>
        <translation>analóg beállítások</translation>
    </message>
    <message>
        <location filename="../model/target/target_cpm1_instructions.cpp" line="+70"/>
        <source>subroutine number</source>
        <translation>szubrutin száma</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>FAL number</source>
        <translation>FAL szám</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>start word</source>
        <translation>kezdő szó</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>end word</source>
        <translation>záró szó</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>result</source>
        <translation>eredmény</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>bit designator</source>
        <translation>bitkijelölő szó</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>digit designator</source>
        <translation>számjegykijelölő szó</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+2"/>
        <source>control bit</source>
        <translation>vezérlőbit</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Move a channel or a constant</source>
        <translation>Csatorna vagy konstans mozgatása</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Move the inverse of S to D</source>
        <translation>S inverzének mozgatása D-be</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Move one bit: Bi = #DDSS, destination bit DD, source bit SS</source>
        <translation>Egy bit mozgatása: Bi = #DDSS, DD a célbit, SS a forrásbit</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Move digits: Di = #0DNS, first destination digit D, N+1 digits, first source digit S</source>
        <translation>Számjegyek mozgatása: Di = #0DNS, D az első célszámjegy, N+1 számjegy, S az első forrásszámjegy</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Shift register: data, shift pulse and reset inputs; St..E</source>
        <translation>Léptetőregiszter: adat-, léptető- és törlőbemenet; St..E</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Shift the words St..E up by one word, #0000 into St</source>
        <translation>Az St..E szavak léptetése egy szóval feljebb, St-be #0000 kerül</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Compare two words: GR 255.05, EQ 255.06, LE 255.07</source>
        <translation>Két szó összehasonlítása: GR 255.05, EQ 255.06, LE 255.07</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>R = the value of the BCD digits of S</source>
        <translation>R = S BCD számjegyeinek értéke</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>R = S as BCD digits</source>
        <translation>R = S BCD számjegyekkel</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Invert every bit of a channel</source>
        <translation>Egy csatorna minden bitjének negálása</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>R = I1 AND I2, bit by bit</source>
        <translation>R = I1 AND I2, bitenként</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>R = I1 OR I2, bit by bit</source>
        <translation>R = I1 OR I2, bitenként</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>R = I1 XOR I2, bit by bit</source>
        <translation>R = I1 XOR I2, bitenként</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Add 1 to a BCD channel (9999 -&gt; 0000)</source>
        <translation>BCD csatorna növelése 1-gyel (9999 -&gt; 0000)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Subtract 1 from a BCD channel (0000 -&gt; 9999)</source>
        <translation>BCD csatorna csökkentése 1-gyel (0000 -&gt; 9999)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Set the carry flag CY (255.04)</source>
        <translation>Az átvitel jelző (CY, 255.04) beállítása</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Clear the carry flag CY (255.04)</source>
        <translation>Az átvitel jelző (CY, 255.04) törlése</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>R = Au + Ad + CY in BCD; CY on a carry</source>
        <translation>R = Au + Ad + CY BCD-ben; átvitelnél CY</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>R = Mi - Su - CY in BCD; below zero: the 10&apos;s complement and CY</source>
        <translation>R = Mi - Su - CY BCD-ben; nulla alatt: a 10-es komplemens és CY</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>R+1, R = Md x Mr in BCD (8 digits)</source>
        <translation>R+1, R = Md x Mr BCD-ben (8 számjegy)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>R = Dd / Dr in BCD, R+1 = the remainder</source>
        <translation>R = Dd / Dr BCD-ben, R+1 = a maradék</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>R = Au + Ad + CY in binary; CY above FFFF</source>
        <translation>R = Au + Ad + CY binárisan; FFFF felett CY</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>R = Mi - Su - CY in binary; below zero: the 2&apos;s complement and CY</source>
        <translation>R = Mi - Su - CY binárisan; nulla alatt: a kettes komplemens és CY</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Run subroutine N, then go on after SBS</source>
        <translation>Az N. szubrutin futtatása, majd folytatás az SBS után</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Start of subroutine N (after the main program; ends the main program)</source>
        <translation>Az N. szubrutin kezdete (a főprogram után; itt ér véget a főprogram)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>End of the subroutine: back after its SBS</source>
        <translation>A szubrutin vége: vissza a hívó SBS utánra</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Non-fatal error N: N into 253.00..253.07, the program goes on; FAL 00 clears it</source>
        <translation>Nem lényegi hiba N: N a 253.00..253.07 bitekbe, a program tovább fut; a FAL 00 törli</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Start of the step of control bit B; without B: end of the steps</source>
        <translation>A B vezérlőbitű lépés kezdete; B nélkül: a lépések vége</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>End the current step and start the step of control bit B</source>
        <translation>Az aktuális lépés lezárása és a B vezérlőbitű lépés indítása</translation>
    </message>
    <message>
        <location filename="../model/target/target_cpm1.cpp" line="-37"/>
        <location filename="../model/target/target_vigor.cpp" line="+25"/>
        <source>No operation</source>
        <translation>Nincs művelet</translation>
    </message>
    <message>
        <location line="+3"/>
        <location filename="../model/target/target_pl110.cpp" line="+199"/>
        <location filename="../model/target/target_vigor.cpp" line="-1"/>
        <location filename="../model/target/target_vpc.cpp" line="+5"/>
        <source>End of the program</source>
        <translation>A program vége</translation>
    </message>
    <message>
        <location filename="../model/target/target_pl110.cpp" line="-457"/>
        <source>IF contact: ON while S1 ? S2 is true</source>
        <translation>IF érintkező: BE, amíg S1 ? S2 igaz</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>digital inputs</source>
        <translation>digitális bemenetek</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>digital outputs</source>
        <translation>digitális kimenetek</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>bistable relays</source>
        <translation>bistabil relék</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>markers</source>
        <translation>markerek</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>timers (with SM0.13 ON)</source>
        <translation>időzítők (SM0.13 bekapcsolva)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>variables</source>
        <translation>változók</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>special markers</source>
        <translation>speciális markerek</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>variables, double words</source>
        <translation>változók, duplaszavak</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>special markers, double words</source>
        <translation>speciális markerek, duplaszavak</translation>
    </message>
    <message>
        <location line="+6"/>
        <location filename="../model/target/target_vpc.cpp" line="-106"/>
        <source>analog inputs</source>
        <translation>analóg bemenetek</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>trimmers</source>
        <translation>trimmerek</translation>
    </message>
    <message>
        <location line="+4"/>
        <location filename="../model/target/target_vpc.cpp" line="+5"/>
        <source>analog outputs</source>
        <translation>analóg kimenetek</translation>
    </message>
    <message>
        <location line="+5"/>
        <location line="+3"/>
        <source>timer presets</source>
        <translation>időzítők beállított értékei</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>counter presets</source>
        <translation>számlálók beállított értékei</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>EEPROM words</source>
        <translation>EEPROM szavak</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>MMC words</source>
        <translation>MMC szavak</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>display characters</source>
        <translation>kijelző karakterei</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>RUN/STOP (1 = RUN)</source>
        <translation>RUN/STOP (1 = RUN)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>60 s clock (30 s ON, 30 s OFF)</source>
        <translation>60 s-os órajel (30 s BE, 30 s KI)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>1 s clock (0.5 s ON, 0.5 s OFF)</source>
        <translation>1 s-os órajel (0,5 s BE, 0,5 s KI)</translation>
    </message>
    <message>
        <location line="+2"/>
        <location filename="../model/target/target_vpc.cpp" line="+25"/>
        <source>toggles every scan</source>
        <translation>minden ciklusban átvált</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>TEST: inputs are taken from SM37</source>
        <translation>TEST: a bemenetek az SM37-ből jönnek</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>inputs I1..I8 in TEST mode (bit 0 = I1), cleared at power-on</source>
        <translation>az I1..I8 bemenetek TEST módban (0. bit = I1), bekapcsoláskor törlődik</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>counters C1..C16 off, timers T49..T64 on</source>
        <translation>C1..C16 számlálók kikapcsolva, T49..T64 időzítők bekapcsolva</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>last scan time (0.1 ms)</source>
        <translation>utolsó ciklusidő (0,1 ms)</translation>
    </message>
    <message>
        <location line="+2"/>
        <location filename="../model/target/target_vigor.cpp" line="-174"/>
        <source>minimum scan time (0.1 ms)</source>
        <translation>legkisebb ciklusidő (0,1 ms)</translation>
    </message>
    <message>
        <location line="+2"/>
        <location filename="../model/target/target_vigor.cpp" line="+2"/>
        <source>maximum scan time (0.1 ms)</source>
        <translation>legnagyobb ciklusidő (0,1 ms)</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>the encoders&apos; load bits and the stepper motor output on AQ1 are not modelled; the word is plain memory</source>
        <translation>az enkóderek betöltőbitjeit és az AQ1 léptetőmotor-kimenetét a szimulátor nem modellezi; a szó egyszerű memória</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the protocol address (the offset and the rotary switch) is not modelled; the word is plain memory</source>
        <translation>a protokollcímet (az eltolást és a forgókapcsolót) a szimulátor nem modellezi; a szó egyszerű memória</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the real-time clock is not modelled: the word keeps what the program writes and does not count</source>
        <translation>a valós idejű órát a szimulátor nem modellezi: a szó azt tartja, amit a program beleír, és nem számol</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>the encoders are not modelled: no count, no load, no rate; the word is plain memory</source>
        <translation>az enkódereket a szimulátor nem modellezi: nincs számlálás, betöltés, sebesség; a szó egyszerű memória</translation>
    </message>
    <message>
        <location line="-4"/>
        <source>the timed interrupts and the stepper ramp are not modelled (interrupt programs are not supported)</source>
        <translation>az időzített megszakításokat és a léptetőmotor rámpáját a szimulátor nem modellezi (megszakításprogram nem támogatott)</translation>
    </message>
    <message>
        <location filename="../model/target/target_pl110_comm.cpp" line="+38"/>
        <source>MODBUS RTU slave</source>
        <translation>MODBUS RTU slave</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>MODBUS RTU master (COM / EXP)</source>
        <translation>MODBUS RTU master (COM / EXP)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>NAIS MATSUSHITA-MASTER (COM / EXP, no frames)</source>
        <translation>NAIS MATSUSHITA-MASTER (COM / EXP, keretek nélkül)</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>COM1, the RS-485 port</source>
        <translation>COM1, az RS-485 port</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>EXP1, the expansion port</source>
        <translation>EXP1, a bővítőport</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>COM2, the USB programming port (57600 8N1)</source>
        <translation>COM2, az USB programozóport (57600 8N1)</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>COM1 transmit buffer (bytes)</source>
        <translation>COM1 adási puffer (bájtok)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>COM1 receive buffer (bytes)</source>
        <translation>COM1 vételi puffer (bájtok)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>EXP1 transmit buffer (bytes)</source>
        <translation>EXP1 adási puffer (bájtok)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>EXP1 receive buffer (bytes)</source>
        <translation>EXP1 vételi puffer (bájtok)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>COM2 transmit buffer (bytes)</source>
        <translation>COM2 adási puffer (bájtok)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>COM2 receive buffer (bytes)</source>
        <translation>COM2 vételi puffer (bájtok)</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>serial port</source>
        <translation>soros port</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>number of characters</source>
        <translation>karakterek száma</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Send n characters of the port&apos;s transmit buffer (free-port mode)</source>
        <translation>A port adási pufferének n karakterét küldi (free-port mód)</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>index</source>
        <translation>index</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>operation</source>
        <translation>művelet</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>slave</source>
        <translation>slave</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>data type</source>
        <translation>adattípus</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>data number</source>
        <translation>adatszám</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>PL110 area</source>
        <translation>PL110 terület</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>number of words or bits</source>
        <translation>szavak vagy bitek száma</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>COM1 master query COM_1..COM_16: read or write a slave&apos;s words or bits while ON</source>
        <translation>COM1 master lekérdezés COM_1..COM_16: egy slave szavait vagy bitjeit olvassa vagy írja, amíg BE</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>EXP1 master query EXP_1..EXP_16: read or write a slave&apos;s words or bits while ON</source>
        <translation>EXP1 master lekérdezés EXP_1..EXP_16: egy slave szavait vagy bitjeit olvassa vagy írja, amíg BE</translation>
    </message>
    <message>
        <location filename="../model/target/target_pl110.cpp" line="+8"/>
        <source>the input filters and analog settings are not modelled: an analog input reads the value set in the simulator</source>
        <translation>a bemeneti szűrőket és az analóg beállításokat a szimulátor nem modellezi: az analóg bemenet a szimulátorban beállított értéket olvassa</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>not in the manual&apos;s table of special markers: 4.2.19 names SM32..SM34 for free-port and SM35..SM37 for the characters received, the table (2.1.2) has SM78 / SM88 / SM98 and SM79 / SM89 / SM99, which the simulator follows; the word is plain memory</source>
        <translation>nincs a kézikönyv speciális markereinek táblázatában: a 4.2.19 az SM32..SM34-et nevezi meg a free-porthoz és az SM35..SM37-et a vett karakterekhez, a táblázat (2.1.2) szerint ezek az SM78 / SM88 / SM98 és az SM79 / SM89 / SM99, és a szimulátor a táblázatot követi; a szó egyszerű memória</translation>
    </message>
    <message>
        <location line="+6"/>
        <location line="+5"/>
        <source>the protocol&apos;s baud rate and format come from the port&apos;s settings (project or network file), not from the program; the word is plain memory</source>
        <translation>a protokoll átviteli sebessége és formátuma a port beállításaiból (projekt vagy hálózati fájl) jön, nem a programból; a szó egyszerű memória</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>COM2 runs the MODBUS slave only: its status, reply delay, supervision time and counters are not modelled; the word is plain memory</source>
        <translation>a COM2 csak MODBUS slave-ként működik: állapotát, válaszkésleltetését, felügyeleti idejét és számlálóit a szimulátor nem modellezi; a szó egyszerű memória</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>NOT contact: invert the power flow</source>
        <translation>NOT érintkező: az áramút negálása</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>P contact: power flows for one scan when it turns ON</source>
        <translation>P érintkező: bekapcsoláskor egy ciklusig vezet</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>N contact: power flows for one scan when it turns OFF</source>
        <translation>N érintkező: kikapcsoláskor egy ciklusig vezet</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Start a block with an immediate input contact</source>
        <translation>Blokk kezdése közvetlen bemeneti érintkezővel</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Start a block with a normally closed immediate input contact</source>
        <translation>Blokk kezdése közvetlen bemeneti nyitó érintkezővel</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Immediate input contact in series</source>
        <translation>Közvetlen bemeneti érintkező sorosan</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Normally closed immediate input contact in series</source>
        <translation>Közvetlen bemeneti nyitó érintkező sorosan</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Immediate input contact in parallel</source>
        <translation>Közvetlen bemeneti érintkező párhuzamosan</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Normally closed immediate input contact in parallel</source>
        <translation>Közvetlen bemeneti nyitó érintkező párhuzamosan</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Immediate output coil: writes the terminal at once</source>
        <translation>Közvetlen kimeneti tekercs: azonnal írja a kimeneti kapcsot</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Bistable relay coil: each activation toggles the relay</source>
        <translation>Bistabil relé tekercse: minden működtetés átbillenti a relét</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>bit number</source>
        <translation>bitszám</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Set a bit (0..15) of a word to 1</source>
        <translation>Egy szó egy bitjének (0..15) 1-be állítása</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Reset a bit (0..15) of a word to 0</source>
        <translation>Egy szó egy bitjének (0..15) 0-ba állítása</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>preset</source>
        <translation>előre beállított érték</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>time base (ms)</source>
        <translation>időalap (ms)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>On-delay timer: T ON once the time reaches PT; OFF resets</source>
        <translation>Bekapcsolás-késleltetésű időzítő: T BE, amint az idő eléri a PT-t; KI törli</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Off-delay timer: T ON at once, OFF when PT has elapsed after OFF</source>
        <translation>Kikapcsolás-késleltetésű időzítő: T azonnal BE, KI után PT elteltével KI</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Accumulating on-delay timer: keeps its time while OFF</source>
        <translation>Összegző bekapcsolás-késleltetésű időzítő: KI állapotban megtartja az idejét</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Up counter: UP, DOWN and RESET inputs; C ON while the count &gt;= PV</source>
        <translation>Felfelé számláló: UP, DOWN és RESET bemenetek; C BE, amíg a számláló &gt;= PV</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Down counter from PV: UP, DOWN and RESET (load PV) inputs; C ON at 0</source>
        <translation>Lefelé számláló PV-től: UP, DOWN és RESET (PV betöltése) bemenetek; C BE 0-nál</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>operator</source>
        <translation>műveleti jel</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Math formula: D = S1 op S2, op one of + - * / | &amp; ^ &lt;&lt; &gt;&gt;</source>
        <translation>Matematikai képlet: D = S1 op S2, op a következők egyike: + - * / | &amp; ^ &lt;&lt; &gt;&gt;</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Move a value or a word to D</source>
        <translation>Érték vagy szó mozgatása D-be</translation>
    </message>
    <message>
        <location line="+11"/>
        <location filename="../model/target/target_vigor.cpp" line="+204"/>
        <location line="+74"/>
        <location line="+102"/>
        <source>number of words</source>
        <translation>szavak száma</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Move n words from S (or the value S) to D</source>
        <translation>n szó mozgatása S-ből (vagy az S érték) D-be</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Indexed move: D[index] = S, the area used as a vector</source>
        <translation>Indexelt mozgatás: D[index] = S, a terület vektorként használva</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Set the range of an AI, TR, AQ or PID output</source>
        <translation>AI, TR, AQ vagy PID kimenet tartományának beállítása</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Tune an on/off positioner</source>
        <translation>Kétállású pozicionáló hangolása</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>On/off positioner</source>
        <translation>Kétállású pozicionáló</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Start a PID loop</source>
        <translation>PID-szabályozókör indítása</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PID control loop</source>
        <translation>PID-szabályozókör</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Set the output of a PID loop</source>
        <translation>PID-szabályozókör kimenetének beállítása</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Setpoint generator with acceleration and deceleration ramps</source>
        <translation>Alapjel-generátor gyorsító és lassító rámpával</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Convert a value</source>
        <translation>Érték konvertálása</translation>
    </message>
    <message>
        <location line="+59"/>
        <source>row</source>
        <translation>sor</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>column</source>
        <translation>oszlop</translation>
    </message>
    <message>
        <location line="-20"/>
        <source>state (0 disabled, 1 shown, 2 editable)</source>
        <translation>állapot (0 tiltott, 1 megjelenített, 2 módosítható)</translation>
    </message>
    <message>
        <location line="-8"/>
        <source>variable shown</source>
        <translation>megjelenített változó</translation>
    </message>
    <message>
        <location line="-6"/>
        <source>display field</source>
        <translation>kijelzőmező</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>minimum</source>
        <translation>minimum</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>maximum</source>
        <translation>maximum</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Set a display field: its state, variable and limits</source>
        <translation>Kijelzőmező beállítása: állapota, változója és határai</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>type (0 16 bit signed, 1 16 bit unsigned, 2 32 bit signed)</source>
        <translation>típus (0 16 bites előjeles, 1 16 bites előjel nélküli, 2 32 bites előjeles)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>total digits</source>
        <translation>számjegyek összesen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>decimals</source>
        <translation>tizedesjegyek</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>fill (0 spaces, 1 zeros)</source>
        <translation>kitöltés (0 szóközök, 1 nullák)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Format a display field: type, digits, decimals, fill</source>
        <translation>Kijelzőmező formátuma: típus, számjegyek, tizedesjegyek, kitöltés</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>access (0 free, 1 password)</source>
        <translation>hozzáférés (0 szabad, 1 jelszóval)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Place a display field: row, column and access</source>
        <translation>Kijelzőmező elhelyezése: sor, oszlop és hozzáférés</translation>
    </message>
    <message>
        <location filename="../model/target/target_vigor.cpp" line="-656"/>
        <source>Compare contact: ON while S1 ? S2</source>
        <translation>Összehasonlító érintkező: BE, amíg S1 ? S2</translation>
    </message>
    <message>
        <location line="+162"/>
        <location filename="../model/target/target_vpc.cpp" line="-68"/>
        <source>inputs</source>
        <translation>bemenetek</translation>
    </message>
    <message>
        <location line="+5"/>
        <location filename="../model/target/target_vpc.cpp" line="+5"/>
        <source>outputs</source>
        <translation>kimenetek</translation>
    </message>
    <message>
        <location line="+4"/>
        <location filename="../model/target/target_vpc.cpp" line="+14"/>
        <source>auxiliary relays</source>
        <translation>segédrelék</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>latched auxiliary relays</source>
        <translation>remanens segédrelék</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>special relays</source>
        <translation>speciális relék</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>step relays</source>
        <translation>lépésrelék</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>latched step relays</source>
        <translation>remanens lépésrelék</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>timers (100 ms)</source>
        <translation>időzítők (100 ms)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>timers (10 ms)</source>
        <translation>időzítők (10 ms)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>accumulating timers (1 ms)</source>
        <translation>összegző időzítők (1 ms)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>accumulating timers (100 ms)</source>
        <translation>összegző időzítők (100 ms)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>latched counters</source>
        <translation>remanens számlálók</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>32-bit counters</source>
        <translation>32 bites számlálók</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>data registers</source>
        <translation>adatregiszterek</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>latched data registers</source>
        <translation>remanens adatregiszterek</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>special registers</source>
        <translation>speciális regiszterek</translation>
    </message>
    <message>
        <location line="+9"/>
        <location line="+4"/>
        <source>index registers</source>
        <translation>indexregiszterek</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>ON while the PLC runs</source>
        <translation>BE, amíg a PLC fut</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>10 ms clock</source>
        <translation>10 ms-os órajel</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>100 ms clock</source>
        <translation>100 ms-os órajel</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>SMOV works on hexadecimal digits</source>
        <translation>Az SMOV hexadecimális számjegyekkel dolgozik</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>current scan time (0.1 ms)</source>
        <translation>aktuális ciklusidő (0,1 ms)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>parallel operation or RS communication error, PLC keeps running</source>
        <translation>párhuzamos üzem vagy RS-kommunikáció hibája, a PLC tovább fut</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>parallel link: this unit is the master</source>
        <translation>párhuzamos kapcsolat: ez az egység a master</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>parallel link: this unit is a slave</source>
        <translation>párhuzamos kapcsolat: ez az egység slave</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>parallel operation normal</source>
        <translation>párhuzamos üzem rendben</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>CP2 modem: start dialing (OFF to ON)</source>
        <translation>CP2 modem: tárcsázás indítása (KI -&gt; BE)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>CP2 modem: dialing failed</source>
        <translation>CP2 modem: a tárcsázás sikertelen</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>RS instruction send flag</source>
        <translation>RS utasítás küldésjelzője</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>RS instruction receive done</source>
        <translation>RS utasítás: a vétel kész</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>CP2 modem CD signal</source>
        <translation>CP2 modem CD jele</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>time-out during RS</source>
        <translation>időtúllépés RS közben</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>parallel operation high-speed transfer</source>
        <translation>párhuzamos üzem nagysebességű átvitele</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>CPU link communication failed (master); M9184..M9190 slaves 1..7</source>
        <translation>a CPU-kapcsolat kommunikációja sikertelen (master); M9184..M9190: 1..7. slave</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>RS communication error code</source>
        <translation>RS-kommunikáció hibakódja</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>display mode of the display screen</source>
        <translation>a kijelző megjelenítési módja</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>number of the D register shown in mode 3</source>
        <translation>a 3. módban megjelenített D regiszter száma</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>computer link station number</source>
        <translation>számítógépes kapcsolat állomásszáma</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>RS: number of data left to send</source>
        <translation>RS: a még elküldendő adatok száma</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>RS: number of data received</source>
        <translation>RS: a fogadott adatok száma</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>RS, LINK and MBUS time-out, x 10 ms (0: 100 ms)</source>
        <translation>RS, LINK és MBUS időtúllépés, x 10 ms (0: 100 ms)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>CPU link communication time-out time</source>
        <translation>CPU-kapcsolat: kommunikációs időtúllépési idő</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>CPU link: number of slave stations</source>
        <translation>CPU-kapcsolat: a slave állomások száma</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>CPU link: transfer range mode</source>
        <translation>CPU-kapcsolat: átviteli tartomány módja</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>CPU link: communication retries</source>
        <translation>CPU-kapcsolat: kommunikációs ismétlések száma</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>current network scan time</source>
        <translation>aktuális hálózati ciklusidő</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>maximum network scan time</source>
        <translation>legnagyobb hálózati ciklusidő</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>CPU link: communication errors of the master; D9204..D9210 slaves 1..7</source>
        <translation>CPU-kapcsolat: a master kommunikációs hibáinak száma; D9204..D9210: 1..7. slave</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>CPU link: error code of slave 1 (D9213..D9218: slaves 2..7): 00H none, 01H time-out, 05H sum error</source>
        <translation>CPU-kapcsolat: az 1. slave hibakódja (D9213..D9218: 2..7. slave): 00H nincs, 01H időtúllépés, 05H ellenőrzőösszeg-hiba</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Start a block with a rising-edge contact</source>
        <translation>Blokk kezdése felfutó él érintkezővel</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Start a block with a falling-edge contact</source>
        <translation>Blokk kezdése lefutó él érintkezővel</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Rising-edge contact in series</source>
        <translation>Felfutó él érintkező sorosan</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Falling-edge contact in series</source>
        <translation>Lefutó él érintkező sorosan</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Rising-edge contact in parallel</source>
        <translation>Felfutó él érintkező párhuzamosan</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Falling-edge contact in parallel</source>
        <translation>Lefutó él érintkező párhuzamosan</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Push the result onto the branch stack</source>
        <translation>Az eredmény mentése az elágazási verembe</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Read the top of the branch stack</source>
        <translation>Az elágazási verem tetejének olvasása</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Pop the branch stack</source>
        <translation>Kivétel az elágazási veremből</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Invert the result</source>
        <translation>Az eredmény negálása</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Set (latch) a device</source>
        <translation>Operandus beállítása (tárolás)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Reset a device, a timer or a counter</source>
        <translation>Operandus, időzítő vagy számláló törlése</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>On-delay timer: T0..T199 100 ms, T200..T245 10 ms units; T246..T249 1 ms, T250..T255 100 ms accumulating (reset with RST)</source>
        <translation>Bekapcsolás-késleltető időzítő: T0..T199 100 ms-os, T200..T245 10 ms-os egységekben; T246..T249 1 ms-os, T250..T255 100 ms-os összegző (RST nullázza)</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>Move 32 bits: S (S, S+1) to D (low word), D+1 (high word)</source>
        <translation>32 bit mozgatása: S (S, S+1) a D-be (alsó szó) és a D+1-be (felső szó)</translation>
    </message>
    <message>
        <location line="+88"/>
        <source>module number</source>
        <translation>modul száma</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>buffer memory word</source>
        <translation>puffermemória-szó</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>Write n words to special module m1, at m2, once on a rising edge</source>
        <translation>n szó írása az m1 speciális modulba, m2-től, egyszer, felfutó élre</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Check code: the sum of n bytes from S into D, their parity into D+1 (M9161 ON: one byte a word)</source>
        <translation>Ellenőrző kód: az S-től kezdődő n bájt összege a D-be, paritásuk a D+1-be (M9161 BE: szavanként egy bájt)</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>first input or output</source>
        <translation>első bemenet vagy kimenet</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>number of digits</source>
        <translation>számjegyek száma</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Convert n ASCII characters from S to hexadecimal in D</source>
        <translation>n ASCII karakter átalakítása S-től hexadecimálissá D-be</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Convert n hexadecimal digits from S to ASCII in D</source>
        <translation>n hexadecimális számjegy átalakítása S-től ASCII-vé D-be</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>first word to send</source>
        <translation>első küldendő szó</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>first word received</source>
        <translation>első fogadott szó</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Serial communication on CP2: send m words from S, receive n words into D</source>
        <translation>Soros kommunikáció a CP2-n: m szó küldése S-től, n szó fogadása D-be</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>table</source>
        <translation>táblázat</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>working area</source>
        <translation>munkaterület</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Easy Link between PLCs: table from S1, working area S2</source>
        <translation>Easy Link PLC-k között: táblázat S1-től, munkaterület S2</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>MODBUS master: table from S1, working area S2</source>
        <translation>MODBUS master: táblázat S1-től, munkaterület S2</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>variable resistor</source>
        <translation>potenciométer</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Read the variable resistor (volume) VRn into D</source>
        <translation>A VRn változtatható ellenállás (potenciométer) értékének beolvasása D-be</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Swap the high and low bytes of D</source>
        <translation>D felső és alsó bájtjának felcserélése</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>digit position</source>
        <translation>számjegy helye</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Move m2 digits of S from digit m1 to D from digit n</source>
        <translation>S m2 számjegyének mozgatása az m1. számjegytől D-be az n. számjegytől</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>32 bits: D, D+1 = (S1, S1+1) / (S2, S2+1), D+2, D+3 = remainder</source>
        <translation>32 bit: D, D+1 = (S1, S1+1) / (S2, S2+1), D+2, D+3 = maradék</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Alternate: D changes state at each rising edge of the input</source>
        <translation>Váltás: D minden felfutó élnél állapotot vált</translation>
    </message>
    <message>
        <location line="-319"/>
        <source>Counter: counts rising edges, reset with RST</source>
        <translation>Számláló: a felfutó éleket számolja, törlés RST-vel</translation>
    </message>
    <message>
        <location line="-391"/>
        <source>Computer Link</source>
        <translation>Computer Link</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>CP1, the main unit&apos;s RS-232 port (Computer Link, 19200 bps, station 0)</source>
        <translation>CP1, az alapegység RS-232 portja (Computer Link, 19200 bps, 0. állomás)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>CP2, the second communication port (a card or a module)</source>
        <translation>CP2, a második kommunikációs port (kártya vagy modul)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Easy Link</source>
        <translation>Easy Link</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>CPU Link</source>
        <translation>CPU Link</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Parallel Link</source>
        <translation>Parallel Link</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>MODBUS</source>
        <translation>MODBUS</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Non Protocol</source>
        <translation>Non Protocol (protokoll nélküli)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>CP3, the VB-CADP&apos;s RS-485 port (Computer Link, 19200 bps, station 0..99)</source>
        <translation>CP3, a VB-CADP RS-485 portja (Computer Link, 19200 bps, 0..99. állomás)</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>VB-1COM serial module</source>
        <translation>VB-1COM soros modul</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>a VB-1COM serial module, numbered as FROM / TO name it</source>
        <translation>VB-1COM soros modul, a FROM / TO által használt számmal</translation>
    </message>
    <message>
        <location line="+100"/>
        <source>variable resistors (panel)</source>
        <translation>potenciométerek (előlap)</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>RS, CCD, ASCI, HEX: 8-bit mode, one byte a word (OFF: 16-bit)</source>
        <translation>RS, CCD, ASCI, HEX: 8 bites mód, szavanként egy bájt (KI: 16 bites)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>ON for one scan when LINK or MBUS completed its table</source>
        <translation>egy ciklusig ON, amikor a LINK vagy az MBUS végigért a táblázatán</translation>
    </message>
    <message>
        <location line="+174"/>
        <source>Step ladder: start of step S</source>
        <translation>Léptetőlánc: az S lépés kezdete</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>End of the step ladder</source>
        <translation>A léptetőlánc vége</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Move S to D</source>
        <translation>S mozgatása D-be</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>Move n words from S to D</source>
        <translation>n szó mozgatása S-ből D-be</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Compare S1 with S2: D, D+1, D+2 = &gt;, =, &lt;</source>
        <translation>S1 összehasonlítása S2-vel: D, D+1, D+2 = &gt;, =, &lt;</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Reset every device from D1 to D2</source>
        <translation>Minden operandus törlése D1-től D2-ig</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>D = S1 + S2</source>
        <translation>D = S1 + S2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>D = S1 - S2</source>
        <translation>D = S1 - S2</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>D, D+1 = S1 x S2 (32-bit product)</source>
        <translation>D, D+1 = S1 x S2 (32 bites szorzat)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>D = S1 / S2, D+1 = remainder</source>
        <translation>D = S1 / S2, D+1 = maradék</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>D = D + 1</source>
        <translation>D = D + 1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>D = D - 1</source>
        <translation>D = D - 1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>D = S1 AND S2, bit by bit</source>
        <translation>D = S1 AND S2, bitenként</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>D = S1 OR S2, bit by bit</source>
        <translation>D = S1 OR S2, bitenként</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>D = S1 XOR S2, bit by bit</source>
        <translation>D = S1 XOR S2, bitenként</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>D = every bit of S inverted</source>
        <translation>D = S minden bitje negálva</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>D = S as BCD digits</source>
        <translation>D = S BCD számjegyekkel</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>D = the value of the BCD digits S</source>
        <translation>D = az S BCD számjegyek értéke</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>Read n words of special module m1, from m2</source>
        <translation>n szó olvasása az m1 speciális modul m2 címétől</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Write n words to special module m1, at m2</source>
        <translation>n szó írása az m1 speciális modul m2 címére</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>Refresh n inputs or outputs now</source>
        <translation>n bemenet vagy kimenet azonnali frissítése</translation>
    </message>
    <message>
        <location filename="../model/target/target_vpc.cpp" line="-41"/>
        <source>Compare contact between two decimal operands</source>
        <translation>Összehasonlító érintkező két decimális operandus között</translation>
    </message>
    <message>
        <location line="+44"/>
        <source>retentive auxiliary relays</source>
        <translation>remanens segédrelék</translation>
    </message>
    <message>
        <location line="+7"/>
        <location line="+4"/>
        <source>system relays</source>
        <translation>rendszerrelék</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>registers</source>
        <translation>regiszterek</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>parallel output (o00..o11)</source>
        <translation>párhuzamos kimenet (o00..o11)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>parallel input (i00..i11)</source>
        <translation>párhuzamos bemenet (i00..i11)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>RUN: always ON</source>
        <translation>RUN: mindig BE</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>ERR: program error</source>
        <translation>ERR: programhiba</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>CON: PC connected</source>
        <translation>CON: PC csatlakoztatva</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>VPCIO connected</source>
        <translation>VPCIO csatlakoztatva</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>0.01 s clock</source>
        <translation>0,01 s-os órajel</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>Transfer while the condition is OFF: d,s  d+s  d-s</source>
        <translation>Átvitel, amíg a feltétel KI: d,s  d+s  d-s</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Transfer while the condition is ON: d,s  d+s  d-s</source>
        <translation>Átvitel, amíg a feltétel BE: d,s  d+s  d-s</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Latching relay: set = last but one block, reset = last block</source>
        <translation>Tartórelé: beállítás = utolsó előtti blokk, törlés = utolsó blokk</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Timer: 00..15 count down, 16..31 count up, 0.01 s</source>
        <translation>Időzítő: 00..15 lefelé, 16..31 felfelé számol, 0,01 s</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Counter: count = last but one block, reset = last block</source>
        <translation>Számláló: számlálás = utolsó előtti blokk, törlés = utolsó blokk</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Jump: skip up to JPE while the condition is OFF</source>
        <translation>Ugrás: JPE-ig átugorja a programot, amíg a feltétel KI</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>End of a jump</source>
        <translation>Ugrás vége</translation>
    </message>
    <message>
        <location line="+65"/>
        <source>input LED: lit while the input is ON</source>
        <translation>bemeneti LED: világít, amíg a bemenet BE</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>output LED: lit while the output is ON</source>
        <translation>kimeneti LED: világít, amíg a kimenet BE</translation>
    </message>
    <message>
        <location filename="../model/target/target_cpm1_maps.cpp" line="+20"/>
        <source>Omron Host Link (C-mode)</source>
        <translation>Omron Host Link (C mód)</translation>
    </message>
    <message>
        <location filename="../model/target/target_pl110_maps.cpp" line="+22"/>
        <source>PL110 MODBUS slave</source>
        <translation>PL110 MODBUS szolga</translation>
    </message>
    <message>
        <location filename="../model/target/target_vigor_maps.cpp" line="+15"/>
        <source>Vigor Computer Link</source>
        <translation>Vigor Computer Link</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>Vigor CP2 MODBUS slave</source>
        <translation>Vigor CP2 MODBUS szolga</translation>
    </message>
    <message>
        <location filename="../model/target/target_cpm1.cpp" line="+76"/>
        <source>lit while the PLC has power</source>
        <translation>világít, amíg a PLC feszültség alatt van</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>lit in RUN or MONITOR mode; dark in PROGRAM mode or on an error</source>
        <translation>világít RUN vagy MONITOR üzemmódban; nem világít PROGRAM üzemmódban vagy hiba esetén</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>lit on a fatal error: the CPU stopped; blinks on a non-fatal error the CPU goes on after (FAL 01..99 in 253.00..253.07, an instruction skipped with ER 255.03)</source>
        <translation>világít lényegi hibánál: a CPU leállt; villog nem lényegi hibánál, amely után a CPU tovább dolgozik (FAL 01..99 a 253.00..253.07 biteken, ER 255.03 mellett kihagyott utasítás)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>lit while the PLC communicates: a byte sent or received on its peripheral port within the last 0.2 s</source>
        <translation>világít, amíg a PLC kommunikál: az utolsó 0,2 s-ban bájtot küldött vagy fogadott a perifériacsatlakozóján</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>analog setting: 0..200 as BCD into its channel</source>
        <translation>analóg beállítás: 0..200 BCD-ben a csatornájába</translation>
    </message>
    <message>
        <location filename="../model/target/target_vigor.cpp" line="+203"/>
        <source>variable resistor read by VRRD, 0..255</source>
        <translation>a VRRD által olvasott potenciométer, 0..255</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>lit while the program runs</source>
        <translation>világít, amíg a program fut</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>lit when a program error stopped the PLC</source>
        <translation>világít, ha programhiba leállította a PLC-t</translation>
    </message>
    <message>
        <location filename="../model/target/target_pl110_panel.cpp" line="-124"/>
        <source>steady: the PLC is in RUN; slow blink (0.5 s on, 0.5 s off): no ladder program runs</source>
        <translation>folyamatosan világít: a PLC RUN üzemmódban van; lassan villog (0,5 s be, 0,5 s ki): nem fut létraprogram</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+2"/>
        <location line="+2"/>
        <source>lit while the port transmits a packet</source>
        <translation>világít, amíg a port adatcsomagot küld</translation>
    </message>
    <message>
        <location line="+58"/>
        <source>increments the field being edited</source>
        <translation>növeli a módosítás alatt álló mezőt</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>decrements the field being edited</source>
        <translation>csökkenti a módosítás alatt álló mezőt</translation>
    </message>
    <message>
        <location filename="../model/target/target_pl110.cpp" line="-84"/>
        <source>characters per word</source>
        <translation>karakter szavanként</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>text</source>
        <translation>szöveg</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Store a text from D: 1 or 2 characters per word, high byte first</source>
        <translation>Szöveg tárolása D-től: szavanként 1 vagy 2 karakter, elöl a felső bájt</translation>
    </message>
    <message>
        <location filename="../model/target/target_pl110_panel.cpp" line="-8"/>
        <source>scrolls through the pages the program enables; while a value is entered, switches between steps of one and editing digit by digit</source>
        <translation>lapozza a program által engedélyezett oldalakat; érték bevitele közben vált az egyesével léptetés és a számjegyenkénti szerkesztés között</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>edits the page&apos;s fields in turn, storing each value; held for 2 s, opens the password page</source>
        <translation>sorra szerkeszti az oldal mezőit, mindegyik értékét eltárolva; 2 s-ig nyomva tartva megnyitja a jelszó oldalát</translation>
    </message>
</context>
<context>
    <name>rung::model::Trigger</name>
    <message>
        <location filename="../model/image/trigger.cpp" line="+39"/>
        <source>Type a condition: &quot;%1 rises&quot;, &quot;%1 falls&quot; or &quot;%2 &gt; 100&quot;</source>
        <translation>Írjon be egy feltételt: &quot;%1 rises&quot;, &quot;%1 falls&quot; vagy &quot;%2 &gt; 100&quot;</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>&quot;%1&quot; is not a whole number (0x before a hexadecimal one)</source>
        <translation>„%1” nem egész szám (hexadecimális előtt 0x)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&quot;%1&quot; is no condition: write &quot;%2 rises&quot;, &quot;%2 falls&quot; or &quot;%3 &gt; 100&quot;</source>
        <translation>„%1” nem feltétel: írja így: &quot;%2 rises&quot;, &quot;%2 falls&quot; vagy &quot;%3 &gt; 100&quot;</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1 is a word: compare it with a value (&quot;%1 &gt; 100&quot;)</source>
        <translation>%1 szó: hasonlítsa össze egy értékkel (&quot;%1 &gt; 100&quot;)</translation>
    </message>
</context>
<context>
    <name>rung::model::TypedListing</name>
    <message>
        <location filename="../model/convert/typed_listing.cpp" line="+79"/>
        <source>This line keeps %1 (row %2, column %3) of rung %4, but no rung follows it: delete the line to let the contact go, or undo</source>
        <translation>Ez a sor a(z) %4. létrafok %1 érintkezőjét (%2. sor, %3. oszlop) őrzi, de nem követi létrafok: törölje a sort, és az érintkező elmarad, vagy vonja vissza a szerkesztést</translation>
    </message>
    <message>
        <location line="+48"/>
        <source>%1 (row %2, column %3) of rung %4 finds no place in the rung typed below this line: delete the line to let it go, or undo</source>
        <translation>A(z) %4. létrafok %1 érintkezője (%2. sor, %3. oszlop) nem fér el a sor alatt beírt létrafokban: törölje a sort, és az érintkező elmarad, vagy vonja vissza a szerkesztést</translation>
    </message>
    <message>
        <location line="+87"/>
        <source>This line stood for a rung of another program: delete the line or undo the paste</source>
        <translation>Ez a sor egy másik program létrafokát jelölte: törölje a sort, vagy vonja vissza a beillesztést</translation>
    </message>
</context>
<context>
    <name>rung::model::ValueFormat</name>
    <message>
        <location filename="../model/image/value_format.cpp" line="+43"/>
        <source>Decimal</source>
        <translation>Decimális</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Signed</source>
        <translation>Előjeles</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Hexadecimal</source>
        <translation>Hexadecimális</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Binary</source>
        <translation>Bináris</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>BCD</source>
        <translation>BCD</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>%1 (not BCD)</source>
        <translation>%1 (nem BCD)</translation>
    </message>
    <message>
        <location line="+10"/>
        <location line="+64"/>
        <source>Type a value</source>
        <translation>Írjon be egy értéket</translation>
    </message>
    <message>
        <location line="-59"/>
        <source>%1 does not fit a %2-bit word (%3..%4)</source>
        <translation>%1 nem fér el egy %2 bites szóban (%3..%4)</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>&quot;%1&quot; is not a whole number (0x before a hexadecimal one)</source>
        <translation>„%1” nem egész szám (hexadecimális előtt 0x)</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>&quot;%1&quot; is not a hexadecimal value of at most %2 digits</source>
        <translation>„%1” nem legfeljebb %2 jegyű hexadecimális érték</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>&quot;%1&quot; is not a binary value of at most %2 digits</source>
        <translation>„%1” nem legfeljebb %2 jegyű bináris érték</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>&quot;%1&quot; is not a BCD value: at most %2 decimal digits</source>
        <translation>„%1” nem BCD érték: legfeljebb %2 decimális számjegy</translation>
    </message>
</context>
<context>
    <name>rung::network::Devices</name>
    <message>
        <location filename="../network/devices.cpp" line="+19"/>
        <source>%1.baud: needs a rate from 50 to 1000000</source>
        <translation>%1.baud: 50 és 1000000 közötti átviteli sebesség kell</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1.frame: &quot;%2&quot; is no character format (8N1, 7E1, ...)</source>
        <translation>%1.frame: a(z) „%2” nem karakterformátum (8N1, 7E1, ...)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1.delay: needs milliseconds from 0 to 60000</source>
        <translation>%1.delay: 0 és 60000 közötti milliszekundum kell</translation>
    </message>
    <message>
        <location line="+72"/>
        <source>%1.station: needs a MODBUS station from 1 to 247</source>
        <translation>%1.station: 1 és 247 közötti MODBUS-állomás kell</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1.mode: needs &quot;rtu&quot; or &quot;ascii&quot;</source>
        <translation>%1.mode: „rtu” vagy „ascii” kell</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1.%2.%3: needs an address 0..65535 and a value %4</source>
        <translation>%1.%2.%3: 0..65535 közötti cím és %4 érték kell</translation>
    </message>
    <message>
        <location line="+146"/>
        <source>%1: needs &quot;expect&quot; and &quot;reply&quot; as hex bytes (&quot;02 30 31&quot;), or &quot;expectText&quot; and &quot;replyText&quot; as text (&quot;\x0201&quot;)</source>
        <translation>%1: „expect” és „reply” kell hexadecimális bájtokként („02 30 31”), vagy „expectText” és „replyText” szövegként („\x0201”)</translation>
    </message>
</context>
<context>
    <name>rung::network::EngineImage</name>
    <message>
        <location filename="../network/engine_image.cpp" line="+67"/>
        <source>a station of a network keeps running: it is not stopped from its port</source>
        <translation>a hálózat állomása tovább fut: a portjáról nem állítható le</translation>
    </message>
</context>
<context>
    <name>rung::network::Network</name>
    <message>
        <location filename="../network/network.cpp" line="+80"/>
        <source>%1.ports: %2 is named twice</source>
        <translation>%1.ports: a(z) %2 kétszer szerepel</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>%1: no station &quot;%2&quot;</source>
        <translation>%1: nincs „%2” állomás</translation>
    </message>
    <message>
        <location line="+11"/>
        <location line="+31"/>
        <source>%1: no station or device &quot;%2&quot;</source>
        <translation>%1: nincs „%2” állomás vagy eszköz</translation>
    </message>
    <message>
        <location line="-29"/>
        <source>%1: %2 is on wire %3 already; a port has one wire</source>
        <translation>%1: a(z) %2 már a(z) %3 vezetéken van; egy porton egy vezeték lehet</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>%1: no wire &quot;%2&quot;</source>
        <translation>%1: nincs „%2” vezeték</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>%1: line %2: %3 drives %4, which runs %5; %3 needs %6</source>
        <extracomment>%1 station, %2 line, %3 instruction (LINK), %4 port (CP2), %5 what it runs, %6 the applications %3 takes</extracomment>
        <translation>%1: %2. sor: a(z) %3 a(z) %4 portot hajtja, amelyen %5 fut; a(z) %3 ezt igényli: %6</translation>
    </message>
    <message>
        <location line="+45"/>
        <source>silent (fault): not sent</source>
        <translation>néma (hiba): nem ment ki</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the port is on no wire</source>
        <translation>a port nincs vezetéken</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>byte %1 corrupted (fault): XOR %2h</source>
        <translation>a(z) %1. bájt elrontva (hiba): XOR %2h</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>wire cut (fault): not delivered</source>
        <translation>elvágott vezeték (hiba): nem érkezett meg</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>collision with %1: both frames garbled</source>
        <translation>ütközés ezzel: %1; mindkét keret sérült</translation>
    </message>
    <message>
        <location filename="../network/bridge.cpp" line="+43"/>
        <source>%1: no station port &quot;%2&quot;</source>
        <translation>%1: nincs „%2” állomásport</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>%1.tcp: &quot;%2&quot; is not HOST:PORT</source>
        <translation>%1.tcp: a(z) „%2” nem HOST:PORT alakú</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1.listen: &quot;%2&quot; is not ADDRESS:PORT (an IP address of this machine, 0.0.0.0 for all, or localhost)</source>
        <translation>%1.listen: a(z) „%2” nem CÍM:PORT alakú (a gép egy IP-címe, 0.0.0.0 mindegyikhez, vagy localhost)</translation>
    </message>
    <message>
        <location line="-50"/>
        <source>no station port &quot;%1&quot;</source>
        <translation>nincs „%1” állomásport</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 runs %2, whose frames the manual does not publish: it is not put on a real line</source>
        <translation>a(z) %1 portján %2 fut, amelynek kereteit a kézikönyv nem közli: nem kerül valódi vonalra</translation>
    </message>
    <message>
        <location filename="../network/network_scenario.cpp" line="+37"/>
        <source>%1: runtime error at step %2: %3</source>
        <extracomment>%1 the station, %2 the step, %3 what went wrong</extracomment>
        <translation>%1: futásidejű hiba a(z) %2. lépésnél: %3</translation>
    </message>
</context>
<context>
    <name>rung::network::NetworkCheck</name>
    <message>
        <location filename="../network/check.cpp" line="+22"/>
        <source>Computer Link</source>
        <translation>Computer Link</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>MODBUS</source>
        <translation>MODBUS</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Host Link</source>
        <translation>Host Link</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>status 2: the length is not 1..64</source>
        <translation>2-es állapot: a hossz nem 1..64</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>status 4: a wrong device type or command</source>
        <translation>4-es állapot: hibás operandustípus vagy parancs</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>status 5: a wrong device number</source>
        <translation>5-ös állapot: hibás operandusszám</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>status 6: the master&apos;s and the slave&apos;s devices differ (bits and words)</source>
        <translation>6-os állapot: a master és a slave operandusai eltérnek (bitek és szavak)</translation>
    </message>
    <message>
        <location line="+21"/>
        <location line="+54"/>
        <location line="+75"/>
        <source>%1: line %2</source>
        <translation>%1: %2. sor</translation>
    </message>
    <message>
        <location line="-123"/>
        <source>%1 drives %2, which is on no wire: every set ends in a time-out (status A)</source>
        <translation>a(z) %1 a(z) %2 portot hajtja, amely nincs vezetéken: minden készlet időtúllépéssel zárul (A állapot)</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>wire %1</source>
        <translation>%1 vezeték</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1 masters on one wire: %2; their requests collide</source>
        <translation>%1 master egy vezetéken: %2; a kéréseik ütköznek</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 and %2 both answer %3 station %4</source>
        <translation>a(z) %1 és a(z) %2 is válaszol %3 %4. állomásként</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>%1&apos;s table holds %2 sets after the first scan; it takes 1 to %3 within its area</source>
        <translation>a(z) %1 táblázata az első ciklus után %2 készletet tartalmaz; 1..%3 lehet, a területén belül</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>%1 set %2: %3</source>
        <translation>%1, %2. készlet: %3</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 set %2 names station %3, which no port or device on %4 answers with %5: the set ends in a time-out (status A)</source>
        <translation>%1, %2. készlet: a(z) %3. állomást nevezi meg, amelyként a(z) %4 vezetéken egyetlen port vagy eszköz sem válaszol %5 protokollal: a készlet időtúllépéssel zárul (A állapot)</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>%1 runs %2: the PL110 manual publishes no frames of it, so the simulation puts none on the wire and every COM / EXP query of the port times out</source>
        <translation>a(z) %1 a(z) %2 protokollt futtatja: a PL110 kézikönyve nem közli a kereteit, így a szimuláció egyet sem tesz a vezetékre, és a port minden COM / EXP lekérdezése időtúllépéssel zárul</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>SEND sends on %1, which is on no wire: the characters reach nobody</source>
        <translation>a SEND a(z) %1 porton küld, amely nincs vezetéken: a karakterek senkihez sem jutnak el</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1_%2 queries on %3, which is on no wire: every query times out</source>
        <translation>a(z) %1_%2 a(z) %3 porton kérdez le, amely nincs vezetéken: minden lekérdezés időtúllépéssel zárul</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>SEND on %1, which is not in free-port after the first scan (%2 bit 8 is OFF): the PLC ignores SEND until the program sets it</source>
        <translation>SEND a(z) %1 porton, amely az első ciklus után nincs free-port módban (a(z) %2 8. bitje KI): a PLC figyelmen kívül hagyja a SEND-et, amíg a program be nem állítja</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1_%2 queries slave %3, which no port or device on %4 answers with MODBUS: every query times out and sets its status bit</source>
        <translation>a(z) %1_%2 a(z) %3. slave-et kérdezi le, amelyként a(z) %4 vezetéken egyetlen port vagy eszköz sem válaszol MODBUS protokollal: minden lekérdezés időtúllépéssel zárul, és beállítja az állapotbitjét</translation>
    </message>
</context>
<context>
    <name>rung::network::NetworkFile</name>
    <message>
        <location filename="../network/network_file.cpp" line="+84"/>
        <source>%1: unknown key (this object takes: %2)</source>
        <translation>%1: ismeretlen kulcs (ez az objektum ezeket fogadja: %2)</translation>
    </message>
    <message>
        <location line="-48"/>
        <source>%1: missing</source>
        <translation>%1: hiányzik</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1: needs a text</source>
        <translation>%1: szöveg kell</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1: needs a whole number from %2 to %3</source>
        <translation>%1: %2 és %3 közötti egész szám kell</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1: needs a list</source>
        <translation>%1: lista kell</translation>
    </message>
    <message>
        <location line="+47"/>
        <source>%1: line %2, column %3: the file is not valid JSON (%4)</source>
        <translation>%1: %2. sor, %3. oszlop: a fájl nem érvényes JSON (%4)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1: a network file is a JSON object with &quot;stations&quot; and &quot;wires&quot;</source>
        <translation>%1: a hálózatfájl „stations” és „wires” kulcsú JSON-objektum</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>stations: a network needs at least one station</source>
        <translation>stations: a hálózathoz legalább egy állomás kell</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+43"/>
        <location line="+61"/>
        <location line="+41"/>
        <source>%1: needs an object</source>
        <translation>%1: objektum kell</translation>
    </message>
    <message>
        <location line="-127"/>
        <location line="+34"/>
        <source>%1: &quot;%2&quot; is no name (letters, digits, _ and -, at most 32)</source>
        <translation>%1: a(z) „%2” nem név (betűk, számjegyek, _ és -, legfeljebb 32)</translation>
    </message>
    <message>
        <location line="-31"/>
        <location line="+34"/>
        <source>%1: a second &quot;%2&quot;; names are unique</source>
        <translation>%1: második „%2”; a neveknek egyedinek kell lenniük</translation>
    </message>
    <message>
        <location line="-29"/>
        <source>%1: needs an object of ports</source>
        <translation>%1: portokat tartalmazó objektum kell</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1: needs an object of settings</source>
        <translation>%1: beállításokat tartalmazó objektum kell</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>%1: &quot;%2&quot; is no kind of device (modbus-slave, line)</source>
        <translation>%1: a(z) „%2” nem eszköztípus (modbus-slave, line)</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>%1: needs a list of ends, [&quot;a/CP2&quot;, &quot;b/CP2&quot;]</source>
        <translation>%1: végpontok listája kell, [&quot;a/CP2&quot;, &quot;b/CP2&quot;]</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1: a second wire &quot;%2&quot;</source>
        <translation>%1: második „%2” vezeték</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1: a wire joins at least two ends</source>
        <translation>%1: egy vezeték legalább két végpontot köt össze</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1: needs &quot;STATION/PORT&quot; or a device&apos;s name</source>
        <translation>%1: „ÁLLOMÁS/PORT” vagy egy eszköz neve kell</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>%1: a bridge goes to one of &quot;pty&quot;: true, &quot;serial&quot;: &quot;/dev/ttyUSB0&quot;, &quot;tcp&quot;: &quot;HOST:PORT&quot;, &quot;listen&quot;: &quot;HOST:PORT&quot;</source>
        <translation>%1: a híd ezek egyikéhez vezet: &quot;pty&quot;: true, &quot;serial&quot;: &quot;/dev/ttyUSB0&quot;, &quot;tcp&quot;: &quot;HOST:PORT&quot;, &quot;listen&quot;: &quot;HOST:PORT&quot;</translation>
    </message>
    <message>
        <location line="+52"/>
        <source>%1: &quot;to&quot; comes before &quot;from&quot;</source>
        <translation>%1: a „to” a „from” elé esik</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>%1: &quot;%2&quot; is no fault (cut, silent, corrupt)</source>
        <translation>%1: a(z) „%2” nem hibafajta (cut, silent, corrupt)</translation>
    </message>
    <message>
        <location filename="../network/network_write.cpp" line="+221"/>
        <source>%1: %2 items where there were %3</source>
        <translation>%1: %2 elem, holott %3 volt</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1[%2]: written differently</source>
        <translation>%1[%2]: másképp íródott ki</translation>
    </message>
    <message>
        <location line="+118"/>
        <source>%1: not saved: the file would not hold everything (%2)</source>
        <translation>%1: nincs mentve: a fájl nem őrizne meg mindent (%2)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1: cannot write the network (%2)</source>
        <translation>%1: a hálózat nem írható ki (%2)</translation>
    </message>
</context>
<context>
    <name>rung::network::NetworkSession</name>
    <message>
        <location filename="../network/network_session.cpp" line="+335"/>
        <source>a fault made in the IDE</source>
        <translation>az IDE-ben okozott hiba</translation>
    </message>
    <message>
        <location line="+60"/>
        <source>%1: line %2: %3</source>
        <extracomment>%1 station, %2 line, %3 what went wrong</extracomment>
        <translation>%1: %2. sor: %3</translation>
    </message>
    <message>
        <location line="+4"/>
        <location filename="../network/network_session_debug.cpp" line="+106"/>
        <source>%1: %2</source>
        <extracomment>%1 station, %2 why its breakpoints were not taken</extracomment>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../network/network_session_bridges.cpp" line="+120"/>
        <source>%1: the bridge did not open: %2</source>
        <extracomment>%1 the bridged port (&quot;s5/CP2&quot;), %2 why its line did not open</extracomment>
        <translation>%1: a híd nem nyílt meg: %2</translation>
    </message>
    <message>
        <location line="+44"/>
        <source>%1: the bridge&apos;s line failed: %2 (Stop opens it again)</source>
        <extracomment>%1 the bridged port (&quot;s5/CP2&quot;), %2 what happened to its line</extracomment>
        <translation>%1: a híd vonala meghibásodott: %2 (a Megállás újra megnyitja)</translation>
    </message>
</context>
<context>
    <name>rung::network::SharedLink</name>
    <message>
        <location filename="../network/shared_link.cpp" line="+252"/>
        <source>CPU Link exchange among %1 (%2 ms); no frames: the manual does not publish them</source>
        <translation>CPU Link adatcsere: %1 (%2 ms); keretek nélkül: a kézikönyv nem közli őket</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>no station</source>
        <translation>nincs állomás</translation>
    </message>
    <message>
        <location line="+86"/>
        <source>Parallel Link exchange; no frames: the manual does not publish them</source>
        <translation>Parallel Link adatcsere; keretek nélkül: a kézikönyv nem közli őket</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Parallel Link: no exchange, the other station does not answer</source>
        <translation>Parallel Link: nincs adatcsere, a másik állomás nem válaszol</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>wire %1: CPU Link and Parallel Link cannot share a wire</source>
        <translation>%1 vezeték: a CPU Link és a Parallel Link nem lehet egy vezetéken</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>wire %1: %2 and %3 are both CPU Link station %4</source>
        <translation>%1 vezeték: a(z) %2 és a(z) %3 is %4. CPU Link állomás</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>wire %1: Parallel Link joins one master and one slave</source>
        <translation>%1 vezeték: a Parallel Link egy mastert és egy slave-et köt össze</translation>
    </message>
</context>
<context>
    <name>rung::network::StationPastSource</name>
    <message>
        <location filename="../network/station_past_source.cpp" line="+38"/>
        <source>history is read-only: return to live to write, force or release</source>
        <translation>az előzmények csak olvashatók: íráshoz, kényszerítéshez vagy feloldáshoz térjen vissza az élő állapothoz</translation>
    </message>
</context>
<context>
    <name>rung::network::Trace</name>
    <message>
        <location filename="../network/net_trace.cpp" line="+18"/>
        <source>%1: name a station&apos;s device as STATION/DEVICE, e.g. %2/%3</source>
        <translation>%1: egy állomás operandusát ÁLLOMÁS/OPERANDUS alakban adja meg, pl. %2/%3</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1: no station &quot;%2&quot; (the stations: %3)</source>
        <translation>%1: nincs „%2” állomás (az állomások: %3)</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>%1 needs a value</source>
        <translation>%1 után érték kell</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unexpected argument %1</source>
        <translation>váratlan argumentum: %1</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1 needs a whole number from 1 to %2, not &quot;%3&quot;</source>
        <translation>%1 után 1 és %2 közötti egész szám kell, nem „%3”</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>--set needs STATION/DEV=VALUE@SCAN, not &quot;%1&quot;</source>
        <translation>a --set után ÁLLOMÁS/OPERANDUS=ÉRTÉK@CIKLUS kell, nem „%1”</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>unknown option %1</source>
        <translation>ismeretlen kapcsoló: %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>--scans and --trace are required</source>
        <translation>a --scans és a --trace megadása kötelező</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>--set at %1 comes after the last row: it applies once %1 rows have run, and %2 run, so it would never apply</source>
        <extracomment>--set DEV=VALUE@N applies once N (%1) rows of scans have run; %2 rows run</extracomment>
        <translation>a @%1 --set az utolsó sor utánra esik: %1 sor lefutása után érvényesülne, de csak %2 fut le, így sosem érvényesülne</translation>
    </message>
</context>
<context>
    <name>rung::network::Traffic</name>
    <message>
        <location filename="../network/traffic.cpp" line="+9"/>
        <source># traffic of %1: virtual time (ms), wire, sender, bytes, |as text|, note</source>
        <translation># %1 forgalma: virtuális idő (ms), vezeték, küldő, bájtok, |szövegként|, megjegyzés</translation>
    </message>
</context>
<context>
    <name>rung::network::TrafficDecode</name>
    <message>
        <location filename="../network/traffic_decode.cpp" line="+100"/>
        <source>read coils</source>
        <translation>tekercsek olvasása</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>read discrete inputs</source>
        <translation>bemenetek olvasása</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>read holding registers</source>
        <translation>tartóregiszterek olvasása</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>read input registers</source>
        <translation>bemeneti regiszterek olvasása</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>write single coil</source>
        <translation>egy tekercs írása</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>write single register</source>
        <translation>egy regiszter írása</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>write multiple coils</source>
        <translation>több tekercs írása</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>write multiple registers</source>
        <translation>több regiszter írása</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>unknown function</source>
        <translation>ismeretlen funkció</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>read</source>
        <translation>olvasás</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>write</source>
        <translation>írás</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>bit ON</source>
        <translation>bit BE</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>bit OFF</source>
        <translation>bit KI</translation>
    </message>
    <message>
        <location line="+2"/>
        <location filename="../network/traffic_decode_host_link.cpp" line="+57"/>
        <source>unknown command</source>
        <translation>ismeretlen parancs</translation>
    </message>
    <message>
        <location filename="../network/traffic_decode_host_link.cpp" line="-26"/>
        <source>read IR/SR words</source>
        <translation>IR/SR csatornák olvasása</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>read HR words</source>
        <translation>HR csatornák olvasása</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>read DM words</source>
        <translation>DM szavak olvasása</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>read timer/counter PVs</source>
        <translation>időzítők/számlálók aktuális értékének olvasása</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>read completion flags</source>
        <translation>lejárt-jelzők olvasása</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>read LR words</source>
        <translation>LR csatornák olvasása</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>read AR words</source>
        <translation>AR csatornák olvasása</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>write IR/SR words</source>
        <translation>IR/SR csatornák írása</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>write HR words</source>
        <translation>HR csatornák írása</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>write DM words</source>
        <translation>DM szavak írása</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>write timer/counter PVs</source>
        <translation>időzítők/számlálók aktuális értékének írása</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>write LR words</source>
        <translation>LR csatornák írása</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>write AR words</source>
        <translation>AR csatornák írása</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>read status</source>
        <translation>állapot olvasása</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>change mode</source>
        <translation>üzemmód váltása</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>read errors</source>
        <translation>hibák olvasása</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>read model</source>
        <translation>típus olvasása</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>force set</source>
        <translation>kényszerítés BE</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>force reset</source>
        <translation>kényszerítés KI</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cancel all forcing</source>
        <translation>minden kényszerítés feloldása</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>test</source>
        <translation>teszt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>command not recognised</source>
        <translation>nem felismert parancs</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>part %1 of a frame in parts: the other side answers CR for the next</source>
        <translation>részekre bontott keret %1. része: a másik fél CR-rel kéri a következőt</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>CR: the next part, please</source>
        <translation>CR: kérem a következő részt</translation>
    </message>
    <message>
        <location filename="../network/traffic_decode.cpp" line="-83"/>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message numerus="yes">
        <location line="+31"/>
        <source>the frame stops after %n byte(s): cut short or not a frame</source>
        <translation>
            <numerusform>a keret %n bájt után véget ér: csonka, vagy nem is keret</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+5"/>
        <source>%n byte(s) after the end of the frame</source>
        <translation>
            <numerusform>%n bájt a keret vége után</numerusform>
        </translation>
    </message>
    <message>
        <location line="+156"/>
        <source>MODBUS slave device</source>
        <translation>MODBUS slave eszköz</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>line device</source>
        <translation>soros vonali eszköz</translation>
    </message>
    <message>
        <location filename="../network/traffic_decode_host_link.cpp" line="+34"/>
        <location line="+130"/>
        <source>Host Link</source>
        <translation>Host Link</translation>
    </message>
    <message>
        <location line="-57"/>
        <source>wrong FCS (received %1, computed %2): the PLC answers end code 13</source>
        <translation>hibás FCS (érkezett: %1, számított: %2): a PLC 13-as befejezési kóddal válaszol</translation>
    </message>
    <message>
        <location line="+76"/>
        <source>not the CR that asks for the next part</source>
        <translation>nem a következő részt kérő CR</translation>
    </message>
    <message>
        <location filename="../network/traffic_decode.cpp" line="-57"/>
        <location line="+58"/>
        <source>real line</source>
        <translation>valódi vonal</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>no reply came before the next request (a time-out)</source>
        <translation>nem jött válasz a következő kérés előtt (időtúllépés)</translation>
    </message>
    <message>
        <location line="+50"/>
        <source>bytes</source>
        <translation>bájtok</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>free-port</source>
        <translation>free-port</translation>
    </message>
    <message>
        <location line="+85"/>
        <location line="+62"/>
        <source>Computer Link</source>
        <translation>Computer Link</translation>
    </message>
    <message>
        <location line="-55"/>
        <source>not a Computer Link request: it does not start with STX (02h)</source>
        <translation>nem Computer Link kérés: nem STX-szel (02h) kezdődik</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>wrong sum (received %1, computed %2): the slave answers error 11h</source>
        <translation>hibás összeg (érkezett: %1, számított: %2): a slave 11h hibával válaszol</translation>
    </message>
    <message>
        <location line="+6"/>
        <location filename="../network/traffic_decode_host_link.cpp" line="-179"/>
        <source>the slave refuses it: %1</source>
        <translation>a slave elutasítja: %1</translation>
    </message>
    <message>
        <location line="+73"/>
        <location line="+74"/>
        <source>MODBUS ASCII</source>
        <translation>MODBUS ASCII</translation>
    </message>
    <message>
        <location line="-74"/>
        <location line="+74"/>
        <source>MODBUS RTU</source>
        <translation>MODBUS RTU</translation>
    </message>
    <message>
        <location line="-61"/>
        <source>wrong CRC (received %1, computed %2): the slave answers nothing</source>
        <translation>hibás CRC (érkezett: %1, számított: %2): a slave nem válaszol</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>every slave (broadcast)</source>
        <translation>minden slave (körüzenet)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>not a request a slave can carry out: it answers %1</source>
        <translation>olyan kérés, amelyet a slave nem tud végrehajtani: a válasza %1</translation>
    </message>
</context>
<context>
    <name>rung::simulator::CommandInbox</name>
    <message>
        <location filename="../simulator/command_inbox.cpp" line="+15"/>
        <source>(no device)</source>
        <translation>(nincs operandus)</translation>
    </message>
    <message>
        <location line="+56"/>
        <source>the edited program is for another memory layout (another PLC): it cannot take over the running image</source>
        <translation>a módosított program más memóriafelosztású (másik PLC): nem veheti át a futó memóriaképet</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>%1 has no set value to write</source>
        <translation>%1 operandusnak nincs írható beállított értéke</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1 is not a word this PLC can write</source>
        <translation>%1 nem olyan szó, amelyet ez a PLC írni tud</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 is not a bit this PLC can write</source>
        <translation>%1 nem olyan bit, amelyet ez a PLC írni tud</translation>
    </message>
</context>
<context>
    <name>rung::simulator::Compiler</name>
    <message>
        <location filename="../simulator/compiler_detail.h" line="+117"/>
        <source>%1 needs operand %2</source>
        <translation>%1: hiányzik a(z) %2. operandus</translation>
    </message>
    <message>
        <location filename="../simulator/compile_steps.cpp" line="+177"/>
        <location filename="../simulator/compiler_detail.h" line="+17"/>
        <source>%1 is not a bit device</source>
        <translation>%1 nem bit típusú operandus</translation>
    </message>
    <message>
        <location filename="../simulator/compiler_detail.h" line="+23"/>
        <source>constant %1 is out of range</source>
        <translation>a(z) %1 konstans tartományon kívül esik</translation>
    </message>
    <message>
        <location filename="../simulator/compile_operands.cpp" line="+26"/>
        <source>%1 is not an index register</source>
        <translation>%1 nem indexregiszter</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1 is a constant; a device is expected here</source>
        <translation>%1 konstans; ide operandus kell</translation>
    </message>
    <message>
        <location line="+2"/>
        <location filename="../simulator/compiler_detail.h" line="+5"/>
        <source>%1 is not a word device or a constant</source>
        <translation>%1 nem szó típusú operandus és nem konstans</translation>
    </message>
    <message>
        <location line="+16"/>
        <location filename="../simulator/compile_steps.cpp" line="-13"/>
        <location line="+41"/>
        <location line="+220"/>
        <location filename="../simulator/compiler_detail.h" line="+24"/>
        <source>%1 cannot be written</source>
        <translation>%1 nem írható</translation>
    </message>
    <message>
        <location filename="../simulator/compile_comm.cpp" line="+61"/>
        <source>%1 needs a constant as operand %2</source>
        <translation>a(z) %1 %2. operandusa konstans kell legyen</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>%1 moves %2 digits from digit %3 to digit %4: the digits would run below digit 1</source>
        <translation>a(z) %1 %2 számjegyet mozgat a(z) %3. számjegytől a(z) %4. számjegyre: a számjegyek az 1. alá futnának</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>%1 has no variable resistor %2</source>
        <translation>a(z) %1 PLC-nek nincs %2. potenciométere</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>%1 takes a register, a 32-bit counter or a constant, not %2</source>
        <translation>a(z) %1 regisztert, 32 bites számlálót vagy konstanst fogad, nem ezt: %2</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>%1 writes four registers from %2: give a data register</source>
        <translation>a(z) %1 négy regisztert ír %2-től: adatregisztert adjon meg</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>%1 is programmed twice; the PLC allows it once only in a program</source>
        <translation>a(z) %1 kétszer szerepel a programban; a PLC csak egyszer engedi egy programban</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1 takes plain registers, not %2</source>
        <translation>a(z) %1 egyszerű regisztereket fogad, nem ezt: %2</translation>
    </message>
    <message>
        <location line="+11"/>
        <location filename="../simulator/compiler_detail.h" line="+3"/>
        <source>%1 is not a word device</source>
        <translation>%1 nem szó típusú operandus</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>%1 moves one word with %2: n must be K1</source>
        <translation>a(z) %1 egy szót mozgat ezzel: %2; n értéke K1 kell legyen</translation>
    </message>
    <message>
        <location line="+127"/>
        <source>%1_%2 is programmed twice; each index is one query of the port</source>
        <translation>a(z) %1_%2 kétszer szerepel a programban; minden index a port egy lekérdezése</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1 reads into %2, which the program cannot write</source>
        <translation>a(z) %1 a(z) %2 operandusba olvas, amelyet a program nem írhat</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>%1 needs %2 bits from %3, past the end of its area</source>
        <translation>a(z) %1 %2 bitet igényel a(z) %3 operandustól, a területe végén túl</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>%1 needs %2 words from %3, past the end of its area</source>
        <translation>a(z) %1 %2 szót igényel a(z) %3 operandustól, a területe végén túl</translation>
    </message>
    <message>
        <location line="-248"/>
        <location filename="../simulator/compile_words.cpp" line="+32"/>
        <location filename="../simulator/compiler_detail.h" line="+17"/>
        <source>%1 needs the next word too, which does not exist</source>
        <translation>%1 a következő szót is igényli, de az nem létezik</translation>
    </message>
    <message>
        <location filename="../simulator/compile_words.cpp" line="+22"/>
        <source>%1 reads a block of words: %2 is not a word device</source>
        <translation>%1 szavak blokkját olvassa: %2 nem szó típusú operandus</translation>
    </message>
    <message>
        <location filename="../simulator/compiler_detail.h" line="+29"/>
        <source>%1 needs %2 open blocks before it</source>
        <translation>%1 előtt %2 nyitott blokk kell</translation>
    </message>
    <message>
        <location filename="../simulator/compile_steps.cpp" line="-407"/>
        <source>more than %1 open blocks</source>
        <translation>több mint %1 nyitott blokk</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>%1 is not a timer</source>
        <translation>%1 nem időzítő</translation>
    </message>
    <message>
        <location line="+47"/>
        <source>%1 is not a counter</source>
        <translation>%1 nem számláló</translation>
    </message>
    <message>
        <location line="+166"/>
        <source>the simulator has no operator %1</source>
        <translation>a szimulátor nem ismeri ezt a műveleti jelet: %1</translation>
    </message>
    <message>
        <location line="+59"/>
        <source>%1 is not a number of words</source>
        <translation>%1 nem érvényes szószám</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>%1 is not a word the text can be stored from</source>
        <translation>%1 nem olyan szó, amelytől kezdve a szöveg tárolható</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>the text does not fit in the area of %1 from there on</source>
        <translation>a szöveg nem fér el %1 területén ettől a helytől kezdve</translation>
    </message>
    <message>
        <location line="+114"/>
        <source>the display has no field %1</source>
        <translation>a kijelzőnek nincs %1. mezője</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>%1 is not a variable a display field can show</source>
        <translation>%1 nem olyan változó, amelyet kijelzőmező megjeleníthet</translation>
    </message>
    <message>
        <location line="-208"/>
        <source>%1 needs a bit: a bit device, or a word and a bit number 0..15</source>
        <translation>%1 egy bitet igényel: bit típusú operandust, vagy egy szót és egy 0..15 bitszámot</translation>
    </message>
    <message>
        <location filename="../simulator/compile_words.cpp" line="+10"/>
        <source>%1 needs a count from 1 to %2</source>
        <translation>%1 darabszáma 1 és %2 között lehet</translation>
    </message>
    <message>
        <location filename="../simulator/compile_steps.cpp" line="+45"/>
        <source>the block of %1 words runs past the end of its area</source>
        <translation>a(z) %1 szavas blokk túlnyúlik a terület végén</translation>
    </message>
    <message>
        <location filename="../simulator/compiler.cpp" line="+192"/>
        <source>unknown instruction</source>
        <translation>ismeretlen utasítás</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>more than %1 nested %2</source>
        <translation>több mint %1 egymásba ágyazott %2</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 without MPS before it</source>
        <translation>%1 előtte lévő MPS nélkül</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>%1 cannot be reset</source>
        <translation>%1 nem törölhető</translation>
    </message>
    <message>
        <location filename="../simulator/compile_steps.cpp" line="-143"/>
        <location filename="../simulator/compiler.cpp" line="+5"/>
        <source>%1 is not a device</source>
        <translation>%1 nem operandus</translation>
    </message>
    <message>
        <location filename="../simulator/compiler.cpp" line="+115"/>
        <source>the program has no target</source>
        <translation>a programnak nincs célrendszere</translation>
    </message>
</context>
<context>
    <name>rung::simulator::Engine</name>
    <message>
        <location filename="../simulator/engine_execute.cpp" line="+48"/>
        <source>set value %1 is not a BCD number; the instruction is skipped</source>
        <translation>a(z) %1 beállított érték nem BCD szám; az utasítás kimarad</translation>
    </message>
    <message>
        <location line="+46"/>
        <source>%1 does not fit in BCD (0..%2); the destination is unchanged</source>
        <translation>%1 nem fér el BCD-ben (0..%2); a cél nem változik</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1 is not a BCD number; the destination is unchanged</source>
        <translation>%1 nem BCD szám; a cél nem változik</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>result %1 is outside 0..9999; %2 is written</source>
        <translation>a(z) %1 eredmény kívül esik a 0..9999 tartományon; %2 íródik be</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>subroutines nest deeper than %1 levels; the call is skipped</source>
        <translation>a szubrutinok %1 szintnél mélyebben ágyazódnak egymásba; a hívás elmarad</translation>
    </message>
    <message>
        <location filename="../simulator/engine_arith.h" line="+55"/>
        <location line="+42"/>
        <location filename="../simulator/engine_text.cpp" line="+152"/>
        <source>division by zero; the destination is unchanged</source>
        <translation>osztás nullával; a cél változatlan marad</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>MOVIND index %1 is outside 0..%2; nothing is written</source>
        <translation>a MOVIND %1 indexe kívül esik a 0..%2 tartományon; nem íródik semmi</translation>
    </message>
    <message>
        <location filename="../simulator/engine_cpm1.cpp" line="+43"/>
        <source>%1; the instruction is skipped and ER %2 is ON</source>
        <translation>%1; az utasítás nem fut le, és az ER %2 BE</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1; the instruction is skipped</source>
        <translation>%1; az utasítás nem fut le</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>%1 is not a BCD number</source>
        <translation>%1 nem BCD szám</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>bit designator %1 is not #DDSS with bits 00 to 15</source>
        <translation>a(z) %1 bitkijelölő szó nem #DDSS alakú, 00 és 15 közötti bitekkel</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>digit designator %1 is not #0DNS with digits 0 to 3</source>
        <translation>a(z) %1 számjegykijelölő szó nem #0DNS alakú, 0 és 3 közötti számjegyekkel</translation>
    </message>
    <message>
        <location line="+74"/>
        <source>division by zero</source>
        <translation>osztás nullával</translation>
    </message>
    <message>
        <location filename="../simulator/engine_debug.cpp" line="+36"/>
        <location line="+13"/>
        <source>the program has no instruction %1 to stop at</source>
        <translation>a programnak nincs %1. utasítása, amelynél meg lehetne állni</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1 is no word to compare</source>
        <translation>%1 nem összehasonlítható szó</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+10"/>
        <source>(no device)</source>
        <translation>(nincs operandus)</translation>
    </message>
    <message>
        <location line="-3"/>
        <source>%1 is no bit to watch</source>
        <translation>%1 nem figyelhető bit</translation>
    </message>
    <message>
        <location filename="../simulator/engine_operands.cpp" line="+84"/>
        <source>operation error: %1 with %2 = %3 reaches %4, which does not exist; the instruction is not executed</source>
        <translation>műveleti hiba: %1, ahol %2 = %3, a nem létező %4 operandusra mutat; az utasítás nem hajtódik végre</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>operation error: %1 reaches %2, which does not exist; the instruction is not executed</source>
        <translation>műveleti hiba: %1 a nem létező %2 operandusra mutat; az utasítás nem hajtódik végre</translation>
    </message>
    <message>
        <location filename="../simulator/engine_words.cpp" line="+15"/>
        <source>operation error: %1 bytes need %2 words from the source, past the end of its area; the instruction is not executed</source>
        <translation>műveleti hiba: %1 bájthoz %2 szó kell a forrástól, túl a terület végén; az utasítás nem hajtódik végre</translation>
    </message>
    <message>
        <location filename="../simulator/engine_comm.cpp" line="+371"/>
        <source>operation error: the communication table holds %1 sets; it takes 1 to %2</source>
        <translation>műveleti hiba: a kommunikációs táblázat %1 készletet tartalmaz; 1..%2 lehet</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>operation error: a table of %1 sets needs %2 registers, past the end of its area</source>
        <translation>műveleti hiba: egy %1 készletes táblázathoz %2 regiszter kell, ami túlnyúlik a területe végén</translation>
    </message>
    <message>
        <location line="+55"/>
        <source>operation error: another RS is active; only one may be active at a time, this one does nothing</source>
        <translation>műveleti hiba: egy másik RS aktív; egyszerre csak egy lehet aktív, ez nem csinál semmit</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>operation error: %1 data to send from a block that ends after %2 words; nothing is sent</source>
        <translation>műveleti hiba: %1 elküldendő adat egy %2 szó után véget érő blokkból; semmi sem megy ki</translation>
    </message>
    <message>
        <location line="+76"/>
        <source>operation error: %1 data received for a block that ends after %2 words; they are not stored</source>
        <translation>műveleti hiba: %1 fogadott adat egy %2 szó után véget érő blokkba; nem tárolódnak</translation>
    </message>
    <message>
        <location filename="../simulator/engine_module.cpp" line="+108"/>
        <location line="+25"/>
        <source>operation error: no special module %1 is connected (in a network a VB-1COM is the station&apos;s port MODULE%1)</source>
        <translation>műveleti hiba: nincs csatlakoztatva %1. speciális modul (hálózatban a VB-1COM az állomás MODULE%1 portja)</translation>
    </message>
    <message>
        <location line="-18"/>
        <source>operation error: buffer memory #%1..#%2 of module %3 does not exist or the block runs past its area; nothing is read</source>
        <translation>műveleti hiba: a(z) %3. modul #%1..#%2 puffermemóriája nem létezik, vagy a blokk túlnyúlik a területén; semmi sem olvasódik be</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>operation error: buffer memory #%1..#%2 of module %3 cannot be written (the module&apos;s table marks it read-only, or it does not exist); nothing is written</source>
        <translation>műveleti hiba: a(z) %3. modul #%1..#%2 puffermemóriája nem írható (a modul táblázata szerint csak olvasható, vagy nem létezik); semmi sem íródik</translation>
    </message>
    <message>
        <location filename="../simulator/engine_text.cpp" line="-111"/>
        <source>operation error: %1 characters need %2 words from the destination, past the end of its area; the instruction is not executed</source>
        <translation>műveleti hiba: %1 karakterhez %2 szó kell a céltól, ami túlnyúlik a területe végén; az utasítás nem hajtódik végre</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>operation error: %1 characters need %2 words from the source, past the end of its area; the instruction is not executed</source>
        <translation>műveleti hiba: %1 karakterhez %2 szó kell a forrástól, ami túlnyúlik a területe végén; az utasítás nem hajtódik végre</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>operation error: character %1 (%2H) is no hexadecimal digit; the destination is unchanged</source>
        <translation>műveleti hiba: a(z) %1. karakter (%2H) nem hexadecimális számjegy; a cél nem változik</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>operation error: %1 is no 4-digit BCD value (0..9999; %2 ON moves hexadecimal digits); the destination is unchanged</source>
        <extracomment>%2 the relay that makes SMOV move hexadecimal digits (Vigor M9168)</extracomment>
        <translation>műveleti hiba: a(z) %1 nem négyjegyű BCD érték (0..9999; %2 ON esetén hexadecimális számjegyek mozognak); a cél nem változik</translation>
    </message>
    <message>
        <location filename="../simulator/engine_ports.cpp" line="+55"/>
        <source>operation error: SEND of %1 characters; the transmit buffer holds 1 to %2, nothing is sent</source>
        <translation>műveleti hiba: SEND %1 karakterrel; az adási puffer 1..%2 karaktert tartalmaz, semmi sem megy el</translation>
    </message>
</context>
<context>
    <name>rung::simulator::HistorySource</name>
    <message>
        <location filename="../simulator/history_source.cpp" line="+40"/>
        <source>History: scan %1 (%2)</source>
        <extracomment>the window&apos;s mark while it shows a past scan; %1 the scan, %2 its time h:mm:ss.cc</extracomment>
        <translation>Előzmények: %1. ciklus (%2)</translation>
    </message>
    <message>
        <location line="+15"/>
        <location line="+29"/>
        <source>nothing is recorded yet: run the simulation first</source>
        <translation>még nincs semmi rögzítve: előbb futtassa a szimulációt</translation>
    </message>
    <message>
        <location line="-18"/>
        <source>history is read-only: return to live to write, force or release</source>
        <translation>az előzmények csak olvashatók: íráshoz, kényszerítéshez vagy feloldáshoz térjen vissza az élő állapothoz</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>that scan is no longer recorded</source>
        <translation>az a ciklus már nincs rögzítve</translation>
    </message>
</context>
<context>
    <name>rung::simulator::Scenario</name>
    <message>
        <location filename="../simulator/scenario_parse.cpp" line="+53"/>
        <source>%1: a number of scans is whole</source>
        <translation>%1: a ciklusok száma egész szám</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1 is more than a week of virtual time</source>
        <translation>%1 több mint egy hét virtuális idő</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 is not a whole number of milliseconds</source>
        <translation>%1 nem egész számú ezredmásodperc</translation>
    </message>
    <message>
        <location line="+46"/>
        <location line="+62"/>
        <source>%1 is no time</source>
        <translation>%1 nem időtartam</translation>
    </message>
    <message>
        <location line="-56"/>
        <source>a scenario runs one program; the first is on line %1</source>
        <translation>egy forgatókönyv egy programot futtat; az első a(z) %1. sorban van</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>unknown option %1 (--target, --model)</source>
        <translation>ismeretlen kapcsoló: %1 (--target, --model)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the period is a time of at least 1 ms</source>
        <translation>a ciklusidő legalább 1 ms</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>press names one key, then &quot;for TIME&quot; if it is held: &quot;%1&quot;</source>
        <translation>a press egy gombot nevez meg, utána „for IDŐ”, ha nyomva tartják: „%1”</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>&quot;%1&quot; is no statement (program, period, at TIME set|force|release|expect|press, within TIME expect, always expect, run TIME)</source>
        <translation>„%1” nem utasítás (program, period, at IDŐ set|force|release|expect|press, within IDŐ expect, always expect, run IDŐ)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the statement says nothing after its verb</source>
        <translation>az utasítás igéje után nincs semmi</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>no program: a scenario starts with &quot;program FILE&quot;</source>
        <translation>nincs program: a forgatókönyv „program FÁJL” sorral kezdődik</translation>
    </message>
    <message>
        <location filename="../simulator/scenario_run.cpp" line="+103"/>
        <source>&quot;%1&quot; is not understood here</source>
        <translation>„%1” itt nem értelmezhető</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1 is no device</source>
        <translation>%1 nem operandus</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: only bits are forced</source>
        <translation>%1: csak bitek kényszeríthetők</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 needs =VALUE</source>
        <translation>%1 után =ÉRTÉK kell</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 is no value (a number, ON or OFF, #hex digits)</source>
        <translation>%1 nem érték (szám, ON vagy OFF, #hexa számjegyek)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>DEVICE=VALUE is expected</source>
        <translation>OPERANDUS=ÉRTÉK várható</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>%1: only bits are forced and released</source>
        <translation>%1: csak bitek kényszeríthetők és oldhatók fel</translation>
    </message>
    <message>
        <location line="+86"/>
        <source>a device or a value is missing at the end</source>
        <translation>a végéről hiányzik egy operandus vagy érték</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a device or a value is expected at &quot;%1&quot;</source>
        <translation>operandus vagy érték várható itt: „%1”</translation>
    </message>
    <message>
        <location line="+52"/>
        <source>%1 is no device of %2: %3</source>
        <translation>%1 nem operandusa a(z) %2 PLC-nek: %3</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1: cv: and sv: name a timer&apos;s or a counter&apos;s current and set value</source>
        <translation>%1: a cv: és az sv: egy időzítő vagy számláló aktuális és beállított értékét jelöli</translation>
    </message>
    <message>
        <location line="+60"/>
        <source>a &quot;)&quot; is missing</source>
        <translation>hiányzik egy „)”</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>%1 is a word: compare it (%1=5, %1&gt;100)</source>
        <translation>%1 egy szó: hasonlítsa össze (%1=5, %1&gt;100)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 alone is no condition</source>
        <translation>%1 önmagában nem feltétel</translation>
    </message>
    <message>
        <location line="+50"/>
        <source>%1: the %2 has no keys on its front panel to press</source>
        <translation>%1: a(z) %2 előlapján nincs megnyomható gomb</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 is no key of the %2&apos;s front panel (its keys: %3)</source>
        <translation>%1 nem gombja a(z) %2 előlapjának (gombjai: %3)</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>%1: STATION/DEVICE names a device of a network&apos;s station; this scenario&apos;s program is one PLC</source>
        <translation>%1: az ÁLLOMÁS/OPERANDUS egy hálózat állomásának operandusát nevezi meg; ennek a forgatókönyvnek a programja egyetlen PLC</translation>
    </message>
    <message>
        <location line="+56"/>
        <source>at %1 comes before line %2&apos;s %3: statements stand in the order of their times</source>
        <translation>az at %1 korábbi, mint a(z) %2. sor %3 ideje: az utasítások időrendben követik egymást</translation>
    </message>
    <message>
        <location line="+158"/>
        <source>%1: the run was already at %2 (the statement before waited until then), so it applied then, not at %3</source>
        <translation>%1: a futás már %2-nál tartott (az előző utasítás addig várt), ezért akkor hajtódott végre, nem %3-kor</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>%1: the run was already at %2 (the statement before waited until then), so at %3 could not be checked</source>
        <translation>%1: a futás már %2-nál tartott (az előző utasítás addig várt), ezért az at %3 nem volt ellenőrizhető</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>at %1: expected %2, seen %3</source>
        <extracomment>A failed expectation: %1 the time, %2 what was expected, %3 the devices&apos; values then (&quot;Y0=1 Y1=0&quot;).</extracomment>
        <translation>%1-kor: elvárt %2, tapasztalt %3</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>within %1 of %2 (until %3): expected %4, seen %5</source>
        <extracomment>%1 the time allowed (&quot;2s&quot;), %2 the time it counted from, %3 until when, %4 what was expected, %5 the values seen at the end.</extracomment>
        <translation>%2 után %1-on belül (%3-ig): elvárt %4, tapasztalt %5</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>at %1: expected always %2, seen %3 (failed in %4 of %5 scans)</source>
        <extracomment>An `always` expectation that failed: %1 the first time, %2 what was expected, %3 the values then, %4 the scans it failed in, %5 the scans run.</extracomment>
        <translation>%1-kor: mindig elvárt %2, tapasztalt %3 (%5 ciklusból %4-ban nem teljesült)</translation>
    </message>
    <message>
        <location line="-296"/>
        <source>runtime error at step %1: %2</source>
        <translation>futásidejű hiba a(z) %1. lépésnél: %2</translation>
    </message>
    <message>
        <location line="+328"/>
        <source>a network&apos;s stations bring their own targets and models: --target and --model are for one program</source>
        <translation>a hálózat állomásai saját céleszközt és modellt hoznak: a --target és a --model egyetlen programhoz való</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1 is a network: rungstudio-cli test runs it</source>
        <translation>%1 egy hálózat: a rungstudio-cli test futtatja</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>the program does not start</source>
        <translation>a program nem indul el</translation>
    </message>
    <message>
        <location filename="../simulator/scenario_record.cpp" line="+38"/>
        <source>the simulation has run no scan yet: run it, work its inputs, then record</source>
        <translation>a szimuláció még egy ciklust sem futott: indítsa el, kezelje a bemeneteit, aztán rögzítsen</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the simulation&apos;s history no longer holds its start (it keeps the last hour): stop it, run it again and record sooner</source>
        <translation>a szimuláció előzménye már nem tartalmazza a kezdetét (az utolsó órát őrzi): állítsa le, indítsa újra, és rögzítsen hamarabb</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Recorded from a simulation: the inputs as they were worked, the outputs as they were seen.</source>
        <translation>Szimulációból rögzítve: a bemenetek, ahogy kezelték őket, a kimenetek, ahogy látszottak.</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>a command given while a scan was stopped inside is applied at the start of the next scan</source>
        <translation>a ciklus belsejében megállított állapotban adott parancs a következő ciklus elején érvényesül</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the period was changed during the simulation: the scenario runs at the first one, %1 ms</source>
        <translation>a ciklusidő a szimuláció közben változott: a forgatókönyv az elsővel fut, %1 ms</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>a power cycle, reset or online edit at %1 is not in the scenario</source>
        <translation>a(z) %1 időpontbeli tápciklus, alaphelyzetbe állítás vagy online szerkesztés nincs a forgatókönyvben</translation>
    </message>
    <message>
        <location filename="../simulator/scenario_trace.cpp" line="+57"/>
        <source>a scenario&apos;s run is read-only</source>
        <translation>a forgatókönyv futása csak olvasható</translation>
    </message>
    <message>
        <location filename="../simulator/scenario_record.cpp" line="+51"/>
        <source>nothing was recorded: the PLC&apos;s inputs and outputs were not read while recording</source>
        <translation>semmi sem lett rögzítve: a PLC bemeneteit és kimeneteit a rögzítés alatt nem olvasta ki az IDE</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Recorded from an online PLC: its inputs and outputs as each refresh read them.</source>
        <translation>Online PLC-ről rögzítve: a bemenetei és kimenetei, ahogy az egyes frissítések kiolvasták őket.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the PLC was read refresh by refresh: what changed between two refreshes is not in the scenario, and the scenario runs at a %1 ms scan, not the PLC&apos;s own</source>
        <translation>a PLC-t frissítésenként olvasta ki az IDE: ami két frissítés között változott, nincs a forgatókönyvben, és a forgatókönyv %1 ms-os ciklussal fut, nem a PLC sajátjával</translation>
    </message>
</context>
<context>
    <name>rung::simulator::SimulatorSession</name>
    <message>
        <location filename="../simulator/session.cpp" line="+246"/>
        <source>Line %1: %2</source>
        <translation>%1. sor: %2</translation>
    </message>
</context>
<context>
    <name>rung::simulator::Trace</name>
    <message>
        <location filename="../simulator/trace.cpp" line="+21"/>
        <source>unknown device %1: %2</source>
        <translation>ismeretlen operandus: %1: %2</translation>
    </message>
    <message>
        <location line="+93"/>
        <source>%1 needs a value</source>
        <translation>%1 után érték kell</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unexpected argument %1</source>
        <translation>váratlan argumentum: %1</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1 needs a whole number from 1 to %2, not &quot;%3&quot;</source>
        <translation>%1 után 1 és %2 közötti egész szám kell, nem „%3”</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>--scans %1 is more than the %2 scans one trace runs (a row each); run it in parts</source>
        <translation>a --scans %1 több, mint az egy nyomkövetésben futtatható %2 ciklus (mindegyik egy sor); futtassa részletekben</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>--period %1 is more than %2 ms</source>
        <translation>a --period %1 több mint %2 ms</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>--set needs DEV=VALUE@SCAN, not &quot;%1&quot;</source>
        <translation>--set formája DEV=VALUE@SCAN, nem &quot;%1&quot;</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>unknown option %1</source>
        <translation>ismeretlen kapcsoló: %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>--scans and --trace are required</source>
        <translation>a --scans és a --trace megadása kötelező</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>--set %1 comes after the last scan: it applies once %2 scans have run, and %3 run, so it would never apply</source>
        <extracomment>--set DEV=VALUE@N applies once N (%2) scans have run; %3 scans run</extracomment>
        <translation>a --set %1 az utolsó ciklus után jönne: akkor lép életbe, amikor már %2 ciklus lefutott, de csak %3 fut le, így sosem lépne életbe</translation>
    </message>
</context>
</TS>
