<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="it">
<context>
    <name>QsciScintilla</name>
    <message>
        <location filename="../editor/qscintilla_tr.h" line="+11"/>
        <source>&amp;Undo</source>
        <translation>&amp;Annulla</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>&amp;Redo</source>
        <translation>&amp;Ripeti</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cu&amp;t</source>
        <translation>&amp;Taglia</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>&amp;Copy</source>
        <translation>&amp;Copia</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Paste</source>
        <translation>&amp;Incolla</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Delete</source>
        <translation>Elimina</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Select All</source>
        <translation>Seleziona tutto</translation>
    </message>
</context>
<context>
    <name>rung::app::AboutDialog</name>
    <message>
        <location filename="../app/gui/about_dialog.cpp" line="+51"/>
        <source>About Rung Studio</source>
        <translation>Informazioni su Rung Studio</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Ladder and instruction-list editor for %1.</source>
        <translation>Editor di schemi ladder e liste istruzioni per %1.</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>User guide</source>
        <translation>Guida utente</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The user guide is not installed beside the program.</source>
        <translation>La guida utente non è installata accanto al programma.</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>GNU GPL, version 3 or later</source>
        <translation>GNU GPL, versione 3 o successiva</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>GNU LGPL, version 3</source>
        <translation>GNU LGPL, versione 3</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>GNU GPL, version 3</source>
        <translation>GNU GPL, versione 3</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>GNU LGPL, version 3 or later</source>
        <translation>GNU LGPL, versione 3 o successiva</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Built with:</source>
        <translation>Realizzato con:</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Copyright and licences</source>
        <translation>Copyright e licenze</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>About &amp;Qt</source>
        <translation>Informazioni su &amp;Qt</translation>
    </message>
</context>
<context>
    <name>rung::app::BreakpointDialog</name>
    <message>
        <location filename="../app/gui/breakpoint_dialog.cpp" line="+41"/>
        <source>Breakpoint Condition</source>
        <translation>Condizione del punto di interruzione</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Always</source>
        <translation>Sempre</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>When the bit rises</source>
        <translation>Quando il bit sale</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>When the bit falls</source>
        <translation>Quando il bit scende</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>While the bit is ON</source>
        <translation>Finché il bit è ON</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>While the bit is OFF</source>
        <translation>Finché il bit è OFF</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>When the word compares</source>
        <translation>Quando il confronto della word è vero</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Stop</source>
        <translation>&amp;Fermati</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>a device, e.g. %1 or %2</source>
        <translation>un operando, p. es. %1 o %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Device</source>
        <translation>&amp;Operando</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>&amp;Compare</source>
        <translation>&amp;Confronto</translation>
    </message>
    <message>
        <location line="+40"/>
        <source>Type the device the condition watches</source>
        <translation>Scrivere l&apos;operando che la condizione osserva</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 is no device of this PLC: %2</source>
        <translation>%1 non è un operando di questo PLC: %2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 is a bit: compare a word (D, a timer&apos;s or counter&apos;s value)</source>
        <translation>%1 è un bit: confrontare una word (D, il valore di un temporizzatore o di un contatore)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 is a word: watch a bit, or compare the word</source>
        <translation>%1 è una word: osservare un bit, o confrontare la word</translation>
    </message>
</context>
<context>
    <name>rung::app::Cli</name>
    <message>
        <location filename="../app/cli/cli.cpp" line="+61"/>
        <location line="+48"/>
        <location filename="../app/cli/cli_network.cpp" line="+147"/>
        <source>unexpected argument %1</source>
        <translation>argomento non previsto: %1</translation>
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
        <translation>uso:
  rungstudio-cli check FILE [--target %1] [--model M]
  rungstudio-cli convert FILE [--target T] [--model M] [--from il|ladder|project|plcopen] --to il|ladder|project|plcopen [-o OUT] [--force] [--map FILE]
  rungstudio-cli simulate FILE [--target T] [--model M] --scans N [--period MS] [--set DEV=VALUE@SCAN]... --trace DEV[,DEV...]
  rungstudio-cli serve FILE [--target T] [--model M] --protocol vigor|modbus|modbus-tcp|hostlink (--pty | --port NAME | --tcp HOST:PORT) [--station N] [--baud B] [--frame 8N1] [--period MS] [--fault KIND]
FILE è una lista istruzioni (.il), un testo ladder (.ladder) o un progetto (.rung).
--lang en|hu|it: la lingua dei messaggi (altrimenti quella della localizzazione, LANG).
Codice di uscita: 0 nessun errore, 1 il programma contiene errori, 2 errore di utilizzo o di I/O.</translation>
    </message>
    <message>
        <location line="+111"/>
        <source>nothing written: the list as typed would be lost</source>
        <translation>non è stato scritto nulla: la lista digitata andrebbe persa</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>nothing written: the listing would leave out the contacts above</source>
        <translation>non è stato scritto nulla: la lista istruzioni tralascerebbe i contatti sopra indicati</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>nothing written: the input does not parse or convert whole</source>
        <translation>nessun file scritto: l&apos;ingresso non si legge o non si converte per intero</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>nothing written: the input has errors (--force writes it anyway)</source>
        <translation>nessun file scritto: l&apos;ingresso contiene errori (--force lo scrive comunque)</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>cannot write %1: %2</source>
        <translation>impossibile scrivere %1: %2</translation>
    </message>
    <message>
        <location line="+49"/>
        <source>no command given</source>
        <translation>nessun comando specificato</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unknown command %1</source>
        <translation>comando sconosciuto: %1</translation>
    </message>
    <message>
        <location filename="../app/cli/cli_common.cpp" line="+98"/>
        <source>%1 needs a value</source>
        <translation>%1 richiede un valore</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>no FILE given</source>
        <translation>nessun FILE specificato</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>--from must be il, ladder or project, not %1</source>
        <translation>--from deve essere il, ladder o project, non %1</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1: which PLC? Give --target %2 or a &quot;; target: NAME&quot; first line</source>
        <translation>%1: quale PLC? Specificare --target %2 oppure una prima riga &quot;; target: NAME&quot;</translation>
    </message>
    <message>
        <location line="+74"/>
        <source>%1:rung %2:%3:%4</source>
        <extracomment>A finding&apos;s place on the ladder, after the file as a compiler writes file:line:column: %1 the file, %2 the rung&apos;s number, %3 the row, %4 the column. Keep the colons.</extracomment>
        <translation>%1:segmento %2:%3:%4</translation>
    </message>
    <message>
        <location line="-154"/>
        <source>%1 holds an instruction list typed in Rung Studio that is not in its program: the list had errors when the project was saved, and is kept as typed under the key &quot;pendingListing&quot;; the rungs are the last valid program. Open the project in Rung Studio and fix the list.</source>
        <translation>%1 contiene una lista istruzioni digitata in Rung Studio che non è nel suo programma: la lista conteneva errori quando il progetto è stato salvato, ed è conservata così come digitata sotto la chiave &quot;pendingListing&quot;; i segmenti sono l&apos;ultimo programma valido. Aprire il progetto in Rung Studio e correggere la lista.</translation>
    </message>
    <message>
        <location line="+97"/>
        <location line="+27"/>
        <location filename="../app/cli/cli_plcopen.cpp" line="+28"/>
        <source>%1 has no model %2</source>
        <translation>%1 non ha il modello %2</translation>
    </message>
    <message>
        <location line="+18"/>
        <location filename="../app/cli/cli_network.cpp" line="+52"/>
        <location filename="../app/cli/cli_plcopen.cpp" line="+36"/>
        <location line="+3"/>
        <source>error</source>
        <translation>errore</translation>
    </message>
    <message>
        <location line="+1"/>
        <location filename="../app/cli/cli_network.cpp" line="+0"/>
        <source>warning</source>
        <translation>avviso</translation>
    </message>
    <message>
        <location line="+1"/>
        <location filename="../app/cli/cli_plcopen.cpp" line="-8"/>
        <location line="+58"/>
        <source>note</source>
        <translation>nota</translation>
    </message>
    <message>
        <location filename="../app/cli/cli_language.cpp" line="+25"/>
        <source>--lang must be one of %1</source>
        <translation>--lang deve essere uno tra %1</translation>
    </message>
    <message>
        <location filename="../app/cli/cli.cpp" line="-138"/>
        <source>--to must be il, ladder, project or plcopen</source>
        <translation>--to deve essere il, ladder, project o plcopen</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>--map is for --from plcopen</source>
        <translation>--map si usa con --from plcopen</translation>
    </message>
    <message>
        <location filename="../app/cli/cli_plcopen.cpp" line="-101"/>
        <source>--from plcopen needs --target: which PLC the program is for</source>
        <translation>--from plcopen richiede --target: per quale PLC è il programma</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>unknown target %1</source>
        <translation>famiglia PLC sconosciuta: %1</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>%1: note: the file was written by Rung Studio for %2; it is read for %3</source>
        <translation>%1: nota: il file è stato scritto da Rung Studio per %2; viene letto per %3</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>variable %1 (%2) names no device of %3, and none is free for it</source>
        <translation>la variabile %1 (%2) non indica un operando di %3, e non ne resta uno libero</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>variable %1 (%2) names no device of %3; proposed: %4</source>
        <translation>la variabile %1 (%2) non indica un operando di %3; proposto: %4</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>A mapping file with the devices proposed (check them, then give it with --map FILE):</source>
        <translation>Un file di corrispondenze con gli operandi proposti (verificarli, poi indicarlo con --map FILE):</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>nothing written: the file holds no ladder to import</source>
        <translation>nulla scritto: il file non contiene uno schema ladder da importare</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>nothing written: the file holds what %1 cannot take, listed above (--force writes the rest)</source>
        <translation>nulla scritto: il file contiene ciò che %1 non può accogliere, elencato sopra (--force scrive il resto)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>written without what is listed above (--force)</source>
        <translation>scritto senza quanto elencato sopra (--force)</translation>
    </message>
</context>
<context>
    <name>rung::app::CompareWindow</name>
    <message>
        <location filename="../app/gui/compare_window.cpp" line="+46"/>
        <source>%1 is a program for %2; the open program is for %3: only programs of one PLC are compared</source>
        <translation>%1 è un programma per %2; il programma aperto è per %3: si confrontano solo programmi dello stesso PLC</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>%1, line %2, column %3: %4; a file that does not read whole is not compared</source>
        <translation>%1, riga %2, colonna %3: %4; un file che non si legge per intero non viene confrontato</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>Compare With</source>
        <translation>Confronta con</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Rung Studio projects (*.rung);;Instruction lists (*.il *.txt);;Ladder texts (*.ladder)</source>
        <translation>Progetti Rung Studio (*.rung);;Liste istruzioni (*.il *.txt);;Testi ladder (*.ladder)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Cannot compare</source>
        <translation>Impossibile confrontare</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Compare: %1 and %2</source>
        <translation>Confronto: %1 e %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>A (left): %1        B (right): %2</source>
        <translation>A (sinistra): %1        B (destra): %2</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Ladder</source>
        <translation>Ladder</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Change</source>
        <translation>Modifica</translation>
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
        <translation>Lista istruzioni</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Report</source>
        <translation>Rapporto</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&amp;Previous Change</source>
        <translation>Modifica &amp;precedente</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Next Change</source>
        <translation>Modifica &amp;successiva</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>P&amp;rint...</source>
        <translation>S&amp;tampa...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Previous change (Alt+Up)</source>
        <translation>Modifica precedente (Alt+Su)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Next change (Alt+Down)</source>
        <translation>Modifica successiva (Alt+Giù)</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>The programs are the same.</source>
        <translation>I programmi sono uguali.</translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>%n rung(s) differ.</source>
        <translation>
            <numerusform>%n segmento diverso.</numerusform>
            <numerusform>%n segmenti diversi.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+7"/>
        <source>%n difference(s) besides the rungs (symbols, set values, watch lists): see the Report.</source>
        <translation>
            <numerusform>%n differenza oltre ai segmenti (simboli, valori di preset, liste di osservazione): vedere il Rapporto.</numerusform>
            <numerusform>%n differenze oltre ai segmenti (simboli, valori di preset, liste di osservazione): vedere il Rapporto.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Alt+Down: next change, Alt+Up: previous.</source>
        <translation>Alt+Giù: modifica successiva, Alt+Su: precedente.</translation>
    </message>
    <message>
        <location line="+18"/>
        <location line="+1"/>
        <source>rung %1</source>
        <translation>segmento %1</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>~ changed</source>
        <translation>~ modificato</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>+ only in B</source>
        <translation>+ solo in B</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>- only in A</source>
        <translation>- solo in A</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>No change before this one.</source>
        <translation>Nessuna modifica prima di questa.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>No change after this one.</source>
        <translation>Nessuna modifica dopo questa.</translation>
    </message>
</context>
<context>
    <name>rung::app::ConnectionPanel</name>
    <message>
        <location filename="../app/gui/connection_panel_link.cpp" line="+50"/>
        <source>ON</source>
        <translation>ON</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>OFF</source>
        <translation>OFF</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Set %1 %2</source>
        <translation>Imposta %1 a %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Write %1 = %2</source>
        <translation>Scrivi %1 = %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Write the preset of %1 = %2</source>
        <translation>Scrivi il valore di preset di %1 = %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Force %1 %2</source>
        <translation>Forza %1 a %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Release the force on %1</source>
        <translation>Rilascia la forzatura di %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Release every force</source>
        <translation>Rilascia tutte le forzature</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>Cancelled: nothing was sent to the PLC</source>
        <translation>Annullato: nulla è stato inviato al PLC</translation>
    </message>
    <message>
        <location filename="../app/gui/connection_panel.cpp" line="+209"/>
        <source>Settings</source>
        <translation>Impostazioni</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Protocol:</source>
        <translation>Protocollo:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Serial port</source>
        <translation>Porta seriale</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>TCP</source>
        <translation>TCP</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Station:</source>
        <translation>Stazione:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Timeout (ms):</source>
        <translation>Timeout (ms):</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Retries:</source>
        <translation>Tentativi:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Test Connection</source>
        <translation>Prova connessione</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Traffic</source>
        <translation>Traffico</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Record</source>
        <translation>Registra</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Clear</source>
        <translation>Svuota</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save...</source>
        <translation>Salva...</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>PLC: %1</source>
        <translation>PLC: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PLC: %1, model %2</source>
        <translation>PLC: %1, modello %2</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The link protocol of the %1 is not published, so the IDE cannot talk to it. Instead: export the program as a console listing (File &gt; Export Instruction List) and load it with the PLC&apos;s own tool; to study the link, capture its traffic with &apos;rungstudio-cli record&apos;.</source>
        <translation>Il protocollo di comunicazione del %1 non è pubblicato, quindi l&apos;IDE non può dialogare con esso. In alternativa: esportare il programma come listato per console (File &gt; Esporta lista istruzioni) e caricarlo con lo strumento proprio del PLC; per studiare il collegamento, registrarne il traffico con &apos;rungstudio-cli record&apos;.</translation>
    </message>
    <message>
        <location filename="../app/gui/connection_panel_link.cpp" line="+23"/>
        <source>Change the PLC&apos;s Memory</source>
        <translation>Modifica della memoria del PLC</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 on %2?

This changes the memory of a real PLC, which may be driving a machine. You are asked once for each connection; later changes go at once.</source>
        <translation>%1 su %2?

Questo modifica la memoria di un PLC reale, che potrebbe comandare una macchina. La domanda viene posta una volta per connessione; le modifiche successive partono subito.</translation>
    </message>
    <message>
        <location line="+115"/>
        <source>Choose the serial port the PLC is on (or type its path)</source>
        <translation>Scegliere la porta seriale del PLC (o digitarne il percorso)</translation>
    </message>
    <message>
        <location line="-69"/>
        <source>%1: done, the PLC acknowledged it</source>
        <translation>%1: fatto, il PLC ha confermato</translation>
    </message>
    <message>
        <location line="-3"/>
        <source>A command</source>
        <translation>Un comando</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: not done: %2</source>
        <translation>%1: non eseguito: %2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>These PLCs cannot send their program back, so the IDE cannot know whether the PLC runs the program shown here. Compare by reading devices: watch them in the ladder or the watch table.</source>
        <translation>Questi PLC non possono rimandare il loro programma, quindi l&apos;IDE non può sapere se il PLC esegue il programma mostrato qui. Confrontare leggendo gli operandi: osservarli nel ladder o nella tabella di osservazione.</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>Switch to %1</source>
        <translation>Passa a %1</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>The PLC runs its program: its outputs switch as the program says.</source>
        <translation>Il PLC esegue il suo programma: le uscite commutano come dice il programma.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The PLC runs its program and takes writes from the IDE.</source>
        <translation>Il PLC esegue il suo programma e accetta le scritture dall&apos;IDE.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The PLC stops running its program.</source>
        <translation>Il PLC smette di eseguire il suo programma.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>PLC Mode</source>
        <translation>Modo del PLC</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Switch %1 to %2?

%3</source>
        <translation>Passare %1 a %2?

%3</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Type the host name or IP address of the PLC or its gateway</source>
        <translation>Digitare il nome host o l&apos;indirizzo IP del PLC o del suo gateway</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Already connected: the panel shows what the PLC reports</source>
        <translation>Già connesso: il pannello mostra ciò che il PLC riporta</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A test is under way</source>
        <translation>Un test è in corso</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Testing %1...</source>
        <translation>Test di %1...</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>The PLC answers (this protocol does not report the model)</source>
        <translation>Il PLC risponde (questo protocollo non riporta il modello)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The PLC answers: %1</source>
        <translation>Il PLC risponde: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>, version %1</source>
        <translation>, versione %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>; mode %1</source>
        <translation>; modo %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>; round trip %1 ms</source>
        <translation>; tempo di andata e ritorno %1 ms</translation>
    </message>
    <message>
        <location line="+6"/>
        <location line="+11"/>
        <source>No answer: %1</source>
        <translation>Nessuna risposta: %1</translation>
    </message>
    <message>
        <location line="-1"/>
        <source>No answer from the PLC</source>
        <translation>Nessuna risposta dal PLC</translation>
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
        <translation>Offline: nessun collegamento a questo PLC</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Connecting to %1...</source>
        <translation>Connessione a %1...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Connecting to %1: %2</source>
        <translation>Connessione a %1: %2</translation>
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
I valori mostrati sono gli ultimi letti, segnati come non aggiornati.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Cannot connect: %1</source>
        <translation>Impossibile connettersi: %1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Disconnect</source>
        <translation>Disconnetti</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Connect</source>
        <translation>Connetti</translation>
    </message>
    <message>
        <location line="+42"/>
        <source>Errors %1, retries %2, timeouts %3, refused %4, reconnects %5
Round trip %6 ms (mean %7, max %8); refresh %9 ms, %10 frame(s)</source>
        <translation>Errori %1, tentativi %2, timeout %3, rifiutati %4, riconnessioni %5
Andata e ritorno %6 ms (media %7, max %8); aggiornamento %9 ms, %10 frame</translation>
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
        <translation>Impossibile scrivere %1: %2</translation>
    </message>
    <message>
        <location filename="../app/gui/connection_panel.cpp" line="-39"/>
        <source>A serial port, or a path typed in: a pseudo-terminal such as the one
&apos;rungstudio-cli serve --pty&apos; prints, or the link that
&apos;serve --pty --link PATH&apos; keeps at PATH, which still leads to the
PLC after serve restarts</source>
        <translation>Una porta seriale, o un percorso digitato: uno pseudo-terminale come quello
stampato da &apos;rungstudio-cli serve --pty&apos;, o il collegamento che
&apos;serve --pty --link PERCORSO&apos; mantiene in PERCORSO, che porta ancora al
PLC dopo il riavvio di serve</translation>
    </message>
</context>
<context>
    <name>rung::app::DebugController</name>
    <message>
        <location filename="../app/gui/debug_controller.cpp" line="+43"/>
        <location line="+169"/>
        <source>Simulation</source>
        <translation>Simulazione</translation>
    </message>
    <message>
        <location line="-160"/>
        <location line="+161"/>
        <source>Scan Debugger</source>
        <translation>Debug scansione</translation>
    </message>
    <message>
        <location line="-98"/>
        <source>Online Edit</source>
        <translation>Modifica online</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Apply Keeping the Memory</source>
        <translation>Applica mantenendo la memoria</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Restart from Power-On</source>
        <translation>Riavvia dallo stato di accensione</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stop the Simulation</source>
        <translation>Ferma la simulazione</translation>
    </message>
    <message>
        <location line="+66"/>
        <source>Breakpoint set at %1</source>
        <translation>Punto di interruzione impostato: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Breakpoint at %1 removed</source>
        <translation>Punto di interruzione rimosso: %1</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Stop before line %1: %2</source>
        <extracomment>where the breakpoint is: %1 line, %2 the instruction</extracomment>
        <translation>Fermati prima della riga %1: %2</translation>
    </message>
</context>
<context>
    <name>rung::app::DebugEntries</name>
    <message>
        <location filename="../app/gui/debug_entries.cpp" line="+17"/>
        <source>S&amp;tep Instruction</source>
        <translation>P&amp;asso di una istruzione</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>F&amp;inish Scan</source>
        <translation>Co&amp;mpleta la scansione</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Toggle &amp;Breakpoint</source>
        <translation>Punto di interr&amp;uzione sì/no</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Breakpoint Co&amp;ndition...</source>
        <translation>Con&amp;dizione del punto di interruzione...</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Remove All Brea&amp;kpoints</source>
        <translation>Rimuovi &amp;tutti i punti di interruzione</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Return to &amp;Live</source>
        <translation>Torna a&amp;l vivo</translation>
    </message>
</context>
<context>
    <name>rung::app::DebugMarks</name>
    <message>
        <location filename="../app/gui/debug_marks.cpp" line="+35"/>
        <source>line %1</source>
        <translation>riga %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>rung %1</source>
        <translation>segmento %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>No instruction on line %1 to stop at</source>
        <translation>Nessuna istruzione alla riga %1 dove fermarsi</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Rung %1 is not in the instruction list: no breakpoint there</source>
        <translation>Il segmento %1 non è nella lista istruzioni: lì non c&apos;è punto di interruzione</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>No instruction at %1 to stop at</source>
        <translation>Nessuna istruzione in %1 dove fermarsi</translation>
    </message>
</context>
<context>
    <name>rung::app::Diff</name>
    <message>
        <location filename="../app/cli/cli_diff.cpp" line="+59"/>
        <source>%1 does not read whole, so it is not compared</source>
        <translation>%1 non si legge per intero, quindi non viene confrontato</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>  rungstudio-cli diff A B [--target T] [--model M] [--from il|ladder|project] [--format text|json]
        (exit 0 the same, 1 different, 2 error)</source>
        <translation>  rungstudio-cli diff A B [--target T] [--model M] [--from il|ladder|project] [--format text|json]
        (uscita 0 uguali, 1 diversi, 2 errore)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>  rungstudio-cli show FILE   (a project as text to read and diff: git&apos;s textconv)</source>
        <translation>  rungstudio-cli show FILE   (il progetto come testo da leggere e confrontare: il textconv di git)</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1 needs a value</source>
        <translation>%1 richiede un valore</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>unknown option %1</source>
        <translation>opzione sconosciuta: %1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>diff takes two files, A and B</source>
        <translation>diff richiede due file, A e B</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>--format must be text or json, not %1</source>
        <translation>--format deve essere text o json, non %1</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>diff needs at least one file that is not /dev/null</source>
        <translation>diff richiede almeno un file che non sia /dev/null</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1 is a program for %2 and %3 one for %4: only programs of one PLC are compared</source>
        <translation>%1 è un programma per %2 e %3 uno per %4: si confrontano solo programmi dello stesso PLC</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>usage:</source>
        <translation>uso:</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>not read as a project: %1</source>
        <translation>non letto come progetto: %1</translation>
    </message>
</context>
<context>
    <name>rung::app::ExampleTitles</name>
    <message>
        <location filename="../app/gui/example_titles.cpp" line="+21"/>
        <source>Add once a second</source>
        <translation>Somma una volta al secondo</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Timers counting down and up</source>
        <translation>Temporizzatori a decremento e a incremento</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Parts counter and reject tracking</source>
        <translation>Contapezzi e tracciamento degli scarti</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stairway light</source>
        <translation>Luce delle scale</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Setpoints on the display, set with the keys</source>
        <translation>Setpoint sul display, impostati con i tasti</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Extending a counter&apos;s range</source>
        <translation>Estensione del campo di un contatore</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Off delay</source>
        <translation>Ritardo alla disattivazione</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Flasher</source>
        <translation>Lampeggiatore</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Latch, START has priority</source>
        <translation>Autoritenuta con priorità allo START</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Latch, STOP has priority</source>
        <translation>Autoritenuta con priorità allo STOP</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Traffic light</source>
        <translation>Semaforo</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Easy Link: a master and two slaves</source>
        <translation>Easy Link: un master e due slave</translation>
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
        <translation>Master MODBUS (MBUS) e slave</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>MODBUS master with a table of requests</source>
        <translation>Master MODBUS con una tabella di richieste</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Non-protocol communication (RS)</source>
        <translation>Comunicazione senza protocollo (RS)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>VB-1COM module (FROM / TO)</source>
        <translation>Modulo VB-1COM (FROM / TO)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PL110 EXP1 MODBUS master</source>
        <translation>PL110 master MODBUS su EXP1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PL110 free-port (SEND)</source>
        <translation>PL110 free-port (SEND)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CPM1 peripheral port (Host Link) on a pseudo-terminal</source>
        <translation>Porta periferica del CPM1 (Host Link) su uno pseudo-terminale</translation>
    </message>
</context>
<context>
    <name>rung::app::FileController</name>
    <message>
        <location filename="../app/gui/file_controller.cpp" line="+72"/>
        <source>&amp;New Project...</source>
        <translation>&amp;Nuovo progetto...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>New Net&amp;work</source>
        <translation>N&amp;uova rete</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&amp;Open...</source>
        <translation>&amp;Apri...</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Open &amp;Recent</source>
        <translation>Apri &amp;recenti</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>E&amp;xamples</source>
        <translation>Ese&amp;mpi</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Save</source>
        <translation>&amp;Salva</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Save &amp;As...</source>
        <translation>Salva &amp;con nome...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Co&amp;mpare With...</source>
        <translation>Con&amp;fronta con...</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&amp;Import Instruction List...</source>
        <translation>&amp;Importa lista istruzioni...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Export Instruction List...</source>
        <translation>Es&amp;porta lista istruzioni...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Import &amp;PLCopen XML...</source>
        <translation>Importa PLCopen &amp;XML...</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Expor&amp;t PLCopen XML...</source>
        <translation>Esp&amp;orta PLCopen XML...</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The instruction list has errors, so the ladder is not the program as typed: fix the list first.</source>
        <translation>La lista istruzioni contiene errori, quindi lo schema ladder non è il programma digitato: correggere prima la lista.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Export &amp;Ladder</source>
        <translation>Esporta schema &amp;ladder</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>As &amp;PDF...</source>
        <translation>Come &amp;PDF...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>As &amp;SVG...</source>
        <translation>Come &amp;SVG...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>As P&amp;NG...</source>
        <translation>Come P&amp;NG...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Print Pre&amp;view...</source>
        <translation>Anteprima di s&amp;tampa...</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Quit</source>
        <translation>&amp;Esci</translation>
    </message>
    <message>
        <location line="+45"/>
        <source>Rung Studio was not closed properly last time. Recover the unsaved program?</source>
        <translation>Rung Studio non è stato chiuso correttamente l&apos;ultima volta. Ripristinare il programma non salvato?</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Rung Studio was not closed properly last time. Recover the unsaved changes to %1?</source>
        <translation>Rung Studio non è stato chiuso correttamente l&apos;ultima volta. Ripristinare le modifiche non salvate di %1?</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+7"/>
        <source>Recover</source>
        <translation>Ripristino</translation>
    </message>
    <message>
        <location line="+48"/>
        <source>Cannot open the file</source>
        <translation>Impossibile aprire il file</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1: networks cannot be opened here</source>
        <translation>%1: qui non si possono aprire reti</translation>
    </message>
    <message>
        <location line="+179"/>
        <source>Rung Studio projects (*.rung);;Instruction lists (*.il *.txt);;Ladder texts (*.ladder);;Scenario tests (*.rungtest);;Networks of PLCs (*.rungnet)</source>
        <translation>Progetti Rung Studio (*.rung);;Liste istruzioni (*.il *.txt);;Testi ladder (*.ladder);;Test di scenario (*.rungtest);;Reti di PLC (*.rungnet)</translation>
    </message>
    <message>
        <location line="+171"/>
        <source>Networks</source>
        <translation>Reti</translation>
    </message>
    <message>
        <location line="-323"/>
        <source>%1 names %2, but the Tests dock lists the scenarios beside the project</source>
        <translation>%1 nomina %2, ma il pannello Test elenca gli scenari accanto al progetto</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>%1, line %2, column %3: %4</source>
        <translation>%1, riga %2, colonna %3: %4</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>%1 has errors; the ladder follows once they are fixed</source>
        <translation>%1 contiene errori; lo schema ladder si aggiorna quando sono corretti</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>Cannot save</source>
        <translation>Impossibile salvare</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Saved %1</source>
        <translation>%1 salvato</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Saved %1 with the instruction list as typed; it has errors, so the ladder holds the last valid program until they are fixed</source>
        <translation>%1 salvato con la lista istruzioni così come è stata scritta; contiene errori, quindi lo schema ladder mantiene l&apos;ultimo programma valido finché non vengono corretti</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Unsaved changes</source>
        <translation>Modifiche non salvate</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save the changes to the program?</source>
        <translation>Salvare le modifiche al programma?</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>New Project</source>
        <translation>Nuovo progetto</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>PLC family:</source>
        <translation>Famiglia PLC:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Model:</source>
        <translation>Modello:</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Open</source>
        <translation>Apri</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>Replace File</source>
        <translation>Sostituisci file</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 already exists. Replace it?</source>
        <translation>%1 esiste già. Sostituirlo?</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Save As</source>
        <translation>Salva con nome</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Rung Studio projects (*.rung)</source>
        <translation>Progetti Rung Studio (*.rung)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Import Instruction List</source>
        <translation>Importa lista istruzioni</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Instruction lists (*.il *.txt);;All files (*)</source>
        <translation>Liste istruzioni (*.il *.txt);;Tutti i file (*)</translation>
    </message>
    <message>
        <location line="+12"/>
        <location line="+8"/>
        <location line="+10"/>
        <source>Cannot export</source>
        <translation>Impossibile esportare</translation>
    </message>
    <message>
        <location line="-14"/>
        <source>Export Instruction List</source>
        <translation>Esporta lista istruzioni</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Instruction lists (*.il *.txt)</source>
        <translation>Liste istruzioni (*.il *.txt)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Export Ladder</source>
        <translation>Esporta schema ladder</translation>
    </message>
    <message>
        <location line="+73"/>
        <source>Cannot open the example</source>
        <translation>Impossibile aprire l&apos;esempio</translation>
    </message>
</context>
<context>
    <name>rung::app::FrontPanelController</name>
    <message>
        <location filename="../app/gui/front_panel_controller.cpp" line="+65"/>
        <source>Front Panel</source>
        <translation>Pannello frontale</translation>
    </message>
</context>
<context>
    <name>rung::app::Gui</name>
    <message>
        <location filename="../app/gui/command_line.cpp" line="+22"/>
        <source>Ladder and instruction-list IDE for small PLCs</source>
        <translation>IDE ladder e lista istruzioni per PLC compatti</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>A project (.rung) or an instruction list to open</source>
        <translation>Progetto (.rung) o lista istruzioni da aprire</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Target of an instruction list: %1</source>
        <translation>Famiglia PLC della lista istruzioni: %1</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Unknown target %1: use %2</source>
        <translation>Famiglia PLC sconosciuta: %1; usare %2</translation>
    </message>
    <message>
        <location line="-13"/>
        <source>Save a picture of the window and quit</source>
        <translation>Salva un&apos;immagine della finestra ed esce</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Open one file at a time</source>
        <translation>Aprire un solo file alla volta</translation>
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
        <translation>Schema ladder e lista &amp;affiancati</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&amp;Reset Window Layout</source>
        <translation>Ripristina &amp;disposizione finestre</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Every panel back to its first place, closed ones shown again</source>
        <translation>Ogni pannello torna al suo posto iniziale, quelli chiusi sono mostrati di nuovo</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Ladder</source>
        <translation>Ladder</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Instruction List</source>
        <translation>Lista istruzioni</translation>
    </message>
</context>
<context>
    <name>rung::app::LineSettingsForm</name>
    <message>
        <location filename="../app/gui/line_settings_form.cpp" line="+105"/>
        <source>Port:</source>
        <translation>Porta:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Refresh</source>
        <translation>Aggiorna</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Look for serial ports again</source>
        <translation>Cerca di nuovo le porte seriali</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Baud rate:</source>
        <translation>Velocità (baud):</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Format:</source>
        <translation>Formato:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Data bits, parity (N none, E even, O odd) and stop bits</source>
        <translation>Bit di dati, parità (N nessuna, E pari, O dispari) e bit di stop</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+12"/>
        <source>Host:</source>
        <translation>Host:</translation>
    </message>
    <message>
        <location line="-11"/>
        <source>TCP port:</source>
        <translation>Porta TCP:</translation>
    </message>
    <message>
        <location line="+45"/>
        <source>No port found</source>
        <translation>Nessuna porta trovata</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Choose or type a port</source>
        <translation>Scegliere o digitare una porta</translation>
    </message>
</context>
<context>
    <name>rung::app::ListingController</name>
    <message>
        <location filename="../app/gui/listing_controller.cpp" line="+66"/>
        <source>The list as typed had errors and now shows the ladder&apos;s program; Ctrl+Z in the list brings it back</source>
        <translation>La lista digitata conteneva errori e ora mostra il programma dello schema ladder; Ctrl+Z nella lista la ripristina</translation>
    </message>
    <message>
        <location line="+94"/>
        <source>The list as typed was taken first and changed rung %1, so the ladder edit was not made: make it again on the rung as it is now.</source>
        <translation>La lista digitata è stata applicata per prima e ha cambiato il segmento %1, quindi la modifica dello schema ladder non è stata fatta: ripeterla sul segmento com&apos;è ora.</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Replace the Instruction List?</source>
        <translation>Sostituire la lista istruzioni?</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The instruction list as typed has errors (line %1: %2).</source>
        <translation>La lista istruzioni digitata contiene errori (riga %1: %2).</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>This change to the ladder replaces the list with the ladder&apos;s program; Ctrl+Z in the list brings the typed text back. Cancel keeps the list as typed and leaves the ladder as it is.</source>
        <translation>Questa modifica dello schema ladder sostituisce la lista con il programma dello schema ladder; Ctrl+Z nella lista ripristina il testo digitato. Annulla mantiene la lista digitata e lascia lo schema ladder invariato.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Replace the List</source>
        <translation>Sostituisci la lista</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>The instruction list has %1: line %2: %3. The ladder shows the last valid program.</source>
        <translation>La lista istruzioni contiene %1: riga %2: %3. Lo schema ladder mostra l&apos;ultimo programma valido.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>an error</source>
        <translation>un errore</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1 errors</source>
        <translation>%1 errori</translation>
    </message>
    <message>
        <location line="+53"/>
        <source>&amp;Redo</source>
        <translation>&amp;Ripeti</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>&amp;Undo</source>
        <translation>&amp;Annulla</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Redo %1</source>
        <extracomment>%1 is the step&apos;s label, e.g. &quot;Insert rung&quot;</extracomment>
        <translation>&amp;Ripeti %1</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>&amp;Undo %1</source>
        <translation>&amp;Annulla %1</translation>
    </message>
</context>
<context>
    <name>rung::app::MainWindow</name>
    <message>
        <location filename="../app/gui/main_window.cpp" line="+165"/>
        <source>Problems</source>
        <translation>Problemi</translation>
    </message>
    <message>
        <location line="+5"/>
        <location line="+141"/>
        <source>Project</source>
        <translation>Progetto</translation>
    </message>
    <message>
        <location line="-134"/>
        <location line="+137"/>
        <source>Symbols</source>
        <translation>Simboli</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_actions.cpp" line="+55"/>
        <source>&amp;File</source>
        <translation>&amp;File</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Main</source>
        <translation>Principale</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>&amp;Edit</source>
        <translation>&amp;Modifica</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>Normally &amp;Open Contact</source>
        <translation>Contatto normalmente &amp;aperto</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Normally &amp;Closed Contact</source>
        <translation>Contatto normalmente &amp;chiuso</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Parallel Contact</source>
        <translation>Contatto in &amp;parallelo</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Rising-Edge Contact</source>
        <translation>Contatto sul fronte di &amp;salita</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Falling-Edge Contact</source>
        <translation>Contatto sul fronte di &amp;discesa</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Parall&amp;el Normally Closed Contact</source>
        <translation>Contatto parallelo normalmente chi&amp;uso</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Parallel Ri&amp;sing-Edge Contact</source>
        <translation>Contatto pa&amp;rallelo sul fronte di salita</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Parallel Fallin&amp;g-Edge Contact</source>
        <translation>Contatto parall&amp;elo sul fronte di discesa</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Co&amp;il</source>
        <translation>&amp;Bobina</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>I&amp;nstruction</source>
        <translation>&amp;Istruzione</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Horizontal Wire</source>
        <translation>Collegamento &amp;orizzontale</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Vertical Link</source>
        <translation>Collegamento &amp;verticale</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Place &amp;Element</source>
        <translation>Posi&amp;ziona elemento</translation>
    </message>
    <message>
        <location line="+56"/>
        <source>&amp;Import Symbols (CSV)...</source>
        <translation>Importa sim&amp;boli (CSV)...</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>E&amp;xport Symbols (CSV)...</source>
        <translation>Esporta simboli (CS&amp;V)...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Add to Watc&amp;h List</source>
        <translation>Aggiungi alla lista &amp;di osservazione</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>In&amp;sert Rung</source>
        <translation>I&amp;nserisci segmento</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>De&amp;lete Rung</source>
        <translation>Elimina se&amp;gmento</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Insert R&amp;ow</source>
        <translation>Aggi&amp;ungi riga</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Delete Ro&amp;w</source>
        <translation>E&amp;limina riga</translation>
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
        <translation>F5 contatto NA, F6 contatto NC, F7 bobina, F8 istruzione
Shift+F5 / Shift+F6 gli stessi contatti in parallelo alla riga superiore
Shift+F7 / Shift+F8 contatto su fronte di salita / di discesa (Alt: in parallelo)
F9 collegamento orizzontale, Shift+F9 collegamento verticale, Ctrl+F9 / Ctrl+F10 li eliminano
Digitare un&apos;istruzione nella cella: %1
Insert: inserisce una cella, Ctrl+Insert: inserisce una riga, Shift+Insert: inserisce un segmento
Delete: cancella, Ctrl+Delete: elimina la riga, Shift+Delete: elimina il segmento
Ctrl+Z / Ctrl+Y: annulla / ripeti, Ctrl+rotellina: zoom, F4: verifica il programma</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Simulation: F10 run, F11 pause, Shift+F11 stop, F12 single scan, Ctrl+Shift+F12 power cycle</source>
        <translation>Simulazione: F10 esegui, F11 pausa, Shift+F11 stop, F12 singola scansione, Ctrl+Shift+F12 spegni e riaccendi</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Online: Ctrl+W go online / offline, Ctrl+1 STOP (PROGRAM), Ctrl+3 MONITOR, Ctrl+4 RUN</source>
        <translation>In linea: Ctrl+W vai online / offline, Ctrl+1 STOP (PROGRAM), Ctrl+3 MONITOR, Ctrl+4 RUN</translation>
    </message>
    <message>
        <location line="-162"/>
        <source>Select</source>
        <translation>Seleziona</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Select (Esc)</source>
        <translation>Seleziona (Esc)</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1 (%2): click the cells to place it</source>
        <translation>%1 (%2): fare clic sulle celle per posizionare l&apos;elemento</translation>
    </message>
    <message>
        <location line="+9"/>
        <location line="+10"/>
        <source>%1: click a cell to place it; Esc or a right click ends</source>
        <translation>%1: fare clic su una cella per posizionare l&apos;elemento; Esc o un clic destro per terminare</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Cu&amp;t Rung</source>
        <translation>&amp;Taglia segmento</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Copy Rung</source>
        <translation>&amp;Copia segmento</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Paste Rungs</source>
        <translation>&amp;Incolla segmenti</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&amp;Find Device...</source>
        <translation>Trova o&amp;perando...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Find &amp;Next</source>
        <translation>Trova &amp;successivo</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Find Pre&amp;vious</source>
        <translation>Trova pr&amp;ecedente</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Replace &amp;Device...</source>
        <translation>S&amp;ostituisci operando...</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Import Symbols</source>
        <translation>Importa simboli</translation>
    </message>
    <message>
        <location line="+0"/>
        <location filename="../app/gui/main_window_tools.cpp" line="+224"/>
        <source>CSV files (*.csv)</source>
        <translation>File CSV (*.csv)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Cannot import</source>
        <translation>Impossibile importare</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Rung Co&amp;mment...</source>
        <translation>Co&amp;mmento del segmento...</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Communic&amp;ation Ports...</source>
        <translation>Con&amp;figurazione delle porte di comunicazione...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The PLC&apos;s own port settings, kept in the project: what Ladder Master calls the 2nd COM Port Setting, CPU Link, the PL110&apos;s COM1 / EXP1 / COM2 protocols</source>
        <translation>Le impostazioni delle porte del PLC, conservate nel progetto: ciò che Ladder Master chiama 2nd COM Port Setting, CPU Link, i protocolli COM1 / EXP1 / COM2 del PL110</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>&amp;View</source>
        <translation>&amp;Visualizza</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Show Symbol &amp;Names</source>
        <translation>Mostra &amp;nomi simbolici</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Names from the symbol table in place of the addresses</source>
        <translation>Nomi della tabella dei simboli al posto degli indirizzi</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&amp;Fit Ladder to Width</source>
        <translation>Adatta schema ladder alla &amp;larghezza</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Zoom &amp;In</source>
        <translation>&amp;Ingrandisci</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Zoom &amp;Out</source>
        <translation>&amp;Riduci</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Check Program</source>
        <translation>&amp;Verifica programma</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&amp;Language</source>
        <translation>&amp;Lingua</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>&amp;Help</source>
        <translation>&amp;Aiuto</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Keyboard...</source>
        <translation>&amp;Tastiera...</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Keyboard</source>
        <translation>Tastiera</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>&amp;About Rung Studio</source>
        <translation>&amp;Informazioni su Rung Studio</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="-119"/>
        <source>Rung Comment</source>
        <translation>Commento del segmento</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Comment above rung %1:</source>
        <translation>Commento sopra il segmento %1:</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>&lt;b&gt;%1&lt;/b&gt;&lt;br&gt;Target: %2, model %3&lt;br&gt;%4, %5</source>
        <translation>&lt;b&gt;%1&lt;/b&gt;&lt;br&gt;Famiglia PLC: %2, modello %3&lt;br&gt;%4, %5</translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>%n rung(s)</source>
        <translation>
            <numerusform>%n segmento</numerusform>
            <numerusform>%n segmenti</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>%n step(s)</source>
        <translation>
            <numerusform>%n passo</numerusform>
            <numerusform>%n passi</numerusform>
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
        <translation>%1 / %2 passi</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Line %1, column %2</source>
        <translation>Riga %1, colonna %2</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Rung %1, row %2, column %3</source>
        <translation>Segmento %1, riga %2, colonna %3</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_monitor.cpp" line="+54"/>
        <source>Cannot save</source>
        <translation>Impossibile salvare</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_panels.cpp" line="+73"/>
        <location filename="../app/gui/main_window_tools.cpp" line="+4"/>
        <source>Cannot export</source>
        <translation>Impossibile esportare</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_tools.cpp" line="-157"/>
        <source>Cut rungs</source>
        <translation>Taglia segmenti</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Cannot paste the cells: %1</source>
        <translation>Impossibile incollare le celle: %1</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Line %1: %2</source>
        <translation>Riga %1: %2</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>The clipboard holds no rungs</source>
        <translation>Gli appunti non contengono segmenti</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cannot paste: %1</source>
        <translation>Impossibile incollare: %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Paste rung</source>
        <translation>Incolla segmento</translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>Paste %n rungs</source>
        <translation>
            <numerusform>Incolla %n segmento</numerusform>
            <numerusform>Incolla %n segmenti</numerusform>
        </translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Find Device</source>
        <translation>Trova operando</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Device:</source>
        <translation>Operando:</translation>
    </message>
    <message>
        <location line="+27"/>
        <location line="+3"/>
        <location line="+6"/>
        <source>Replace Device</source>
        <translation>Sostituisci operando</translation>
    </message>
    <message>
        <location line="-9"/>
        <source>Replace the device:</source>
        <translation>Sostituisci l&apos;operando:</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>with:</source>
        <translation>con:</translation>
    </message>
    <message numerus="yes">
        <location line="+8"/>
        <source>%n place(s) changed</source>
        <translation>
            <numerusform>%n occorrenza modificata</numerusform>
            <numerusform>%n occorrenze modificate</numerusform>
        </translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Replace %1 with %2</source>
        <translation>Sostituisci %1 con %2</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>(no device) %1</source>
        <translation>(nessun operando) %1</translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>%n row(s) of the symbol table name no device of this PLC and are left out of the file: %1. Export the other symbols?</source>
        <translation>
            <numerusform>%n riga della tabella dei simboli non indica un operando di questo PLC e resta fuori dal file: %1. Esportare gli altri simboli?</numerusform>
            <numerusform>%n righe della tabella dei simboli non indicano un operando di questo PLC e restano fuori dal file: %1. Esportare gli altri simboli?</numerusform>
        </translation>
    </message>
    <message>
        <location line="+19"/>
        <location line="+11"/>
        <source>Communication Ports</source>
        <translation>Porte di comunicazione</translation>
    </message>
    <message>
        <location line="-10"/>
        <source>The %1 has no port settings a program or a network uses.</source>
        <translation>Il %1 non ha impostazioni di porta usate da un programma o da una rete.</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>The communication ports are as they were</source>
        <translation>Le porte di comunicazione sono rimaste come erano</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Communication ports set: File &gt; Save keeps them in the project</source>
        <translation>Porte di comunicazione impostate: File &gt; Salva le conserva nel progetto</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="+84"/>
        <location filename="../app/gui/main_window_tools.cpp" line="-55"/>
        <source>Cross Reference</source>
        <translation>Riferimenti incrociati</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_tools.cpp" line="+22"/>
        <location line="+7"/>
        <source>Export Symbols</source>
        <translation>Esporta simboli</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_simulation.cpp" line="+32"/>
        <source>The instruction list has errors, so the ladder still shows the last program without them: correct the list (or undo) before simulating</source>
        <translation>La lista istruzioni contiene errori, quindi il ladder mostra ancora l&apos;ultimo programma senza errori: correggere la lista (o annullare) prima di simulare</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_monitor.cpp" line="+25"/>
        <source>Simulation</source>
        <translation>Simulazione</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Online PLC</source>
        <translation>PLC online</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>History (read-only)</source>
        <translation>Cronologia (sola lettura)</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>The ladder, the instruction list and the watch lists show the values of: %1</source>
        <translation>Lo schema ladder, la lista istruzioni e le liste di osservazione mostrano i valori di: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_panels.cpp" line="-9"/>
        <source>Export Timing Chart</source>
        <translation>Esporta diagramma temporale</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Timing chart exported to %1</source>
        <translation>Diagramma temporale esportato in %1</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Watch</source>
        <translation>Osservazione</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Inputs and Outputs</source>
        <translation>Ingressi e uscite</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Timing Chart</source>
        <translation>Diagramma temporale</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_monitor.cpp" line="-51"/>
        <source>Save Traffic Log</source>
        <translation>Salva il registro del traffico</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Text files (*.txt)</source>
        <translation>File di testo (*.txt)</translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_panels.cpp" line="+1"/>
        <source>Tests</source>
        <translation>Test</translation>
    </message>
</context>
<context>
    <name>rung::app::Network</name>
    <message>
        <location filename="../app/cli/cli_network.cpp" line="-176"/>
        <source>usage:</source>
        <translation>uso:</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>station %1 (%2) does not start</source>
        <translation>la stazione %1 (%2) non si avvia</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>  rungstudio-cli check NET.rungnet
  rungstudio-cli serve NET.rungnet
  rungstudio-cli simulate NET.rungnet --scans N [--period MS] [--set STATION/DEV=VALUE@SCAN]... --trace STATION/DEV[,...] [--traffic FILE]</source>
        <translation>  rungstudio-cli check NET.rungnet
  rungstudio-cli serve NET.rungnet
  rungstudio-cli simulate NET.rungnet --scans N [--period MS] [--set STAZIONE/DISP=VALORE@SCANSIONE]... --trace STAZIONE/DISP[,...] [--traffic FILE]</translation>
    </message>
    <message>
        <location line="+43"/>
        <source>--traffic needs a file</source>
        <translation>--traffic richiede un file</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1: a network file names each station&apos;s PLC</source>
        <translation>%1: il file di rete indica il PLC di ogni stazione</translation>
    </message>
    <message>
        <location line="+29"/>
        <location line="+14"/>
        <source>cannot write %1: %2</source>
        <translation>impossibile scrivere %1: %2</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1: line %2: runtime error at step %3: %4</source>
        <translation>%1: riga %2: errore di esecuzione al passo %3: %4</translation>
    </message>
    <message>
        <location line="+40"/>
        <source>%1: %2: %3</source>
        <translation>%1: %2: %3</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1: a station&apos;s program has errors; the wiring is checked once every program starts</source>
        <translation>%1: il programma di una stazione ha errori; il cablaggio si controlla quando ogni programma si avvia</translation>
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
        <translation>%1: nessun ponte: niente della rete raggiunge una linea reale (&quot;bridges&quot;, docs/network-format.md); simulate la esegue in tempo virtuale</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>%1 runs in real time; stop it with Ctrl+C</source>
        <translation>%1 è in esecuzione in tempo reale; per fermarlo Ctrl+C</translation>
    </message>
</context>
<context>
    <name>rung::app::NetworkBridgeController</name>
    <message>
        <location filename="../app/gui/network_bridge_controller.cpp" line="+30"/>
        <source>%1: pseudo-terminal</source>
        <extracomment>%1 a station&apos;s port (&quot;s5/CP2&quot;); the rest what its bridge goes to</extracomment>
        <translation>%1: pseudo-terminale</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: serial port %2</source>
        <translation>%1: porta seriale %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: TCP to %2</source>
        <translation>%1: TCP verso %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: listens on %2</source>
        <translation>%1: in ascolto su %2</translation>
    </message>
    <message>
        <location line="+74"/>
        <source>Copied %1: where %2 is reached</source>
        <translation>Copiato %1: dove si raggiunge %2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Bridges</source>
        <translation>Ponti</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>No bridge: right-click a station&apos;s port in the Network view and choose Bridge To to put it on a pseudo-terminal, a serial port or TCP.</source>
        <translation>Nessun ponte: fare clic destro sulla porta di una stazione nella vista Rete e scegliere Ponte verso per metterla su uno pseudo-terminale, una porta seriale o TCP.</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>not open</source>
        <translation>non aperto</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Copy</source>
        <translation>Copia</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Copy where the bridge is reached to the clipboard</source>
        <translation>Copia negli appunti dove si raggiunge il ponte</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Edit...</source>
        <translation>Modifica...</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Remove</source>
        <translation>Rimuovi</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Not running: the network is not built (the status bar says why)</source>
        <translation>Non in funzione: la rete non è costruita (la barra di stato dice perché)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Changed: Stop builds the network again with this bridge</source>
        <translation>Modificato: Stop ricostruisce la rete con questo ponte</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Open: give this path to a master on this computer</source>
        <translation>Aperto: date questo percorso a un master su questo computer</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Open: %1</source>
        <translation>Aperto: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Opening...</source>
        <translation>Apertura...</translation>
    </message>
</context>
<context>
    <name>rung::app::NetworkBridgeDialog</name>
    <message>
        <location filename="../app/gui/network_bridge_dialog.cpp" line="+43"/>
        <source>Bridge of %1</source>
        <extracomment>%1 a station&apos;s port, &quot;s5/CP2&quot;</extracomment>
        <translation>Ponte di %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>While the network runs, %1 is put on a real line: a master on this computer or the network reaches the simulated station, or the station reaches a real device.</source>
        <translation>Mentre la rete è in funzione, %1 viene messa su una linea reale: un master su questo computer o in rete raggiunge la stazione simulata, oppure la stazione raggiunge un dispositivo reale.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&amp;Pseudo-terminal (a master on this computer)</source>
        <translation>&amp;Pseudo-terminale (un master su questo computer)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Serial port</source>
        <translation>Porta &amp;seriale</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>TCP: &amp;connect to a serial device server</source>
        <translation>TCP: &amp;connessione a un device server seriale</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>TCP: &amp;listen for a master</source>
        <translation>TCP: in &amp;ascolto di un master</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>The serial port the real line is on (a USB adapter: /dev/ttyUSB0)</source>
        <translation>La porta seriale su cui si trova la linea reale (un adattatore USB: /dev/ttyUSB0)</translation>
    </message>
    <message>
        <location line="+63"/>
        <source>Listen on:</source>
        <translation>In ascolto su:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>any free port</source>
        <translation>qualsiasi porta libera</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>An IP address of this computer, 0.0.0.0 for all of them, or localhost</source>
        <translation>Un indirizzo IP di questo computer, 0.0.0.0 per tutti, oppure localhost</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The serial device server&apos;s host name or IP address</source>
        <translation>Il nome host o l&apos;indirizzo IP del device server seriale</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>A new pseudo-terminal (/dev/pts/N) opens when the network window builds the network, and stays while the window is open (Stop keeps it). Its path is shown on the port and in the Bridges dock, with a Copy button: give it to the master (mbpoll, an HMI, another Rung Studio&apos;s Connection dock).</source>
        <translation>Un nuovo pseudo-terminale (/dev/pts/N) si apre quando la finestra della rete costruisce la rete e resta finché la finestra è aperta (Stop lo mantiene). Il suo percorso è mostrato sulla porta e nel pannello Ponti, con un pulsante Copia: datelo al master (mbpoll, un HMI, il pannello Connessione di un altro Rung Studio).</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The serial port opens at the port&apos;s own rate and format, so that the simulated station and the real line agree: changing them here changes the port&apos;s settings.</source>
        <translation>La porta seriale si apre alla velocità e al formato della porta stessa, perché la stazione simulata e la linea reale concordino: cambiarli qui cambia le impostazioni della porta.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>A serial device server in TCP server mode passes the bytes to its serial line: the simulated station reaches the real device behind it.</source>
        <translation>Un device server seriale in modalità server TCP passa i byte alla sua linea seriale: la stazione simulata raggiunge il dispositivo reale collegato a esso.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>A master connects over TCP and sends the serial line&apos;s bytes (RTU over TCP, not Modbus TCP), one master at a time.</source>
        <translation>Un master si collega via TCP e invia i byte della linea seriale (RTU su TCP, non Modbus TCP), un master alla volta.</translation>
    </message>
    <message>
        <location line="+44"/>
        <source>Choose the serial port, or type its name</source>
        <translation>Scegliere la porta seriale o digitarne il nome</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Type the device server&apos;s host name or IP address</source>
        <translation>Digitare il nome host o l&apos;indirizzo IP del device server</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Type the address to listen on (0.0.0.0 for all of them)</source>
        <translation>Digitare l&apos;indirizzo su cui ascoltare (0.0.0.0 per tutti)</translation>
    </message>
</context>
<context>
    <name>rung::app::NetworkChart</name>
    <message>
        <location filename="../app/gui/network_chart.cpp" line="+107"/>
        <source>Follow</source>
        <translation>Segui</translation>
    </message>
    <message>
        <location line="-1"/>
        <source>Add station/device, e.g. %1</source>
        <translation>Aggiungi stazione/operando, ad es. %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Type a station&apos;s device above (%1) to draw it</source>
        <translation>Scrivere sopra un operando di una stazione (%1) per disegnarlo</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Trigger: %1 rises, %2 &gt; 100</source>
        <translation>Trigger: %1 rises, %2 &gt; 100</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A condition on one station&apos;s device, checked after each of its scans: STATION/DEVICE rises, falls, or = &lt;&gt; &lt; &lt;= &gt; &gt;= VALUE (the same as Simulation &gt; Stop When...)</source>
        <translation>Una condizione sull&apos;operando di una stazione, verificata dopo ogni sua scansione: STAZIONE/OPERANDO rises (fronte di salita), falls (fronte di discesa), oppure = &lt;&gt; &lt; &lt;= &gt; &gt;= VALORE (come Simulazione &gt; Fermati quando...)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Stop the network</source>
        <translation>Ferma la rete</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Only mark</source>
        <translation>Solo segna</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stop the network: every station pauses at the end of its scan when the condition becomes true</source>
        <translation>Ferma la rete: quando la condizione diventa vera, ogni stazione si ferma alla fine della sua scansione</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Arm</source>
        <translation>Arma</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Watch for the trigger (Enter in its field does the same)</source>
        <translation>Attende il trigger (Invio nel suo campo fa lo stesso)</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Armed: stops the network when %1</source>
        <translation>Armato: la rete si ferma quando %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Armed: marks when %1</source>
        <translation>Armato: segna quando %1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1 at %2 (scan %3)</source>
        <extracomment>%1 the condition, %2 the virtual time, %3 the scan of its station</extracomment>
        <translation>%1 a %2 (scansione %3)</translation>
    </message>
    <message>
        <location line="+54"/>
        <source>%1: write STATION/DEVICE, e.g. %2 (stations: %3)</source>
        <translation>%1: scrivere STAZIONE/OPERANDO, ad es. %2 (stazioni: %3)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Not added to the timing chart: %1</source>
        <translation>Non aggiunto al diagramma temporale: %1</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1 keeps no history of %2</source>
        <translation>%1 non conserva la storia di %2</translation>
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
        <translation>%1 si è fermata al punto di interruzione della riga %2; le altre stazioni attendono alla fine della loro scansione</translation>
    </message>
    <message>
        <location line="+43"/>
        <source>Stop &amp;When...</source>
        <translation>Fermati &amp;quando...</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>No network is running</source>
        <translation>Nessuna rete in esecuzione</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Stop the network after the scan in which a station&apos;s condition becomes true,
written STATION/CONDITION, e.g. %1/%2 &gt; 100 or %1/%3 rises (empty: never):</source>
        <extracomment>%1 a station&apos;s name, %2 a word of it, %3 a bit of it</extracomment>
        <translation>Ferma la rete dopo la scansione in cui la condizione di una stazione diventa vera,
scritta STAZIONE/CONDIZIONE, per es. %1/%2 &gt; 100 o %1/%3 rises (vuoto: mai):</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Stop When</source>
        <translation>Fermati quando</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Scan Debugger</source>
        <translation>Debug scansione</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Instruction List</source>
        <translation>Lista istruzioni</translation>
    </message>
    <message>
        <location line="+110"/>
        <source>no station</source>
        <translation>nessuna stazione</translation>
    </message>
    <message>
        <location line="+79"/>
        <source>Stopped: %1 became true</source>
        <extracomment>the status bar while the network&apos;s trigger holds it: %1 the condition (&quot;s2/D10 &gt; 100&quot;)</extracomment>
        <translation>Fermata: %1 è diventata vera</translation>
    </message>
    <message>
        <location line="-63"/>
        <source>Breakpoint set at %1 of %2</source>
        <extracomment>%1 the place (&quot;line 3&quot;, &quot;rung 2&quot;), %2 the station</extracomment>
        <translation>Punto di interruzione impostato: %2, %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Breakpoint at %1 of %2 removed</source>
        <translation>Punto di interruzione rimosso: %2, %1</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Stop %1 before line %2: %3</source>
        <extracomment>where the breakpoint is: %1 station, %2 line, %3 the instruction</extracomment>
        <translation>Ferma %1 prima della riga %2: %3</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>%1 stopped before line %2</source>
        <extracomment>the status bar while a station&apos;s scan is stopped inside: %1 station, %2 line</extracomment>
        <translation>%1 ferma prima della riga %2</translation>
    </message>
    <message>
        <location filename="../app/gui/network_debug_stop.cpp" line="+25"/>
        <source>No stop condition</source>
        <translation>Nessuna condizione di arresto</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The network stops when %1 becomes true</source>
        <translation>La rete si ferma quando %1 diventa vera</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The timing chart marks when %1 becomes true</source>
        <translation>Il diagramma temporale segna quando %1 diventa vera</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>%1: write STATION/CONDITION with a station of the network (%2)</source>
        <extracomment>%1 what was typed, %2 the stations&apos; names</extracomment>
        <translation>%1: scrivere STAZIONE/CONDIZIONE con una stazione della rete (%2)</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>%1 cannot be watched in %2</source>
        <translation>%1 non si può osservare in %2</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1 became true after scan %2 (%3): the network stopped there</source>
        <extracomment>%1 the condition (&quot;s2/D10 &gt; 100&quot;), %2 scan number, %3 virtual time</extracomment>
        <translation>%1 è diventata vera dopo la scansione %2 (%3): la rete si è fermata lì</translation>
    </message>
</context>
<context>
    <name>rung::app::NetworkDocument</name>
    <message>
        <location filename="../app/gui/network_document.cpp" line="+49"/>
        <source>pseudo-terminal</source>
        <translation>pseudo-terminale</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>serial port</source>
        <translation>porta seriale</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>TCP connection</source>
        <translation>connessione TCP</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>TCP listener</source>
        <translation>ascolto TCP</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>The network has no file yet: use Save As</source>
        <translation>La rete non ha ancora un file: usare Salva con nome</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>Untitled network</source>
        <translation>Rete senza nome</translation>
    </message>
    <message>
        <location line="+54"/>
        <source>%1: cannot read the program (%2)</source>
        <translation>%1: impossibile leggere il programma (%2)</translation>
    </message>
    <message>
        <location line="+101"/>
        <source>&quot;%1&quot; is no station name (letters, digits, _ and -, at most 32)</source>
        <translation>&quot;%1&quot; non è un nome di stazione (lettere, cifre, _ e -, al massimo 32)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>A station or device is already named &quot;%1&quot;</source>
        <translation>Esiste già una stazione o un dispositivo di nome &quot;%1&quot;</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: no such program</source>
        <translation>%1: programma inesistente</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+29"/>
        <source>&quot;%1&quot; is no target</source>
        <translation>&quot;%1&quot; non è una famiglia PLC</translation>
    </message>
    <message>
        <location line="-20"/>
        <source>Add Station %1</source>
        <translation>Aggiungi stazione %1</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>%1 has no model &quot;%2&quot;</source>
        <translation>%1 non ha il modello &quot;%2&quot;</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1 exists already: choose another name</source>
        <translation>%1 esiste già: scegliere un altro nome</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>wire %1 (%2) goes: fewer than two ends are left</source>
        <translation>il cavo %1 (%2) viene rimosso: gli restano meno di due estremi</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the fault %1 on wire %2 goes</source>
        <translation>il guasto %1 sul cavo %2 viene rimosso</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 comes off wire %2</source>
        <translation>%1 viene staccato dal cavo %2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the bridge of %1 (%2) goes</source>
        <translation>il ponte di %1 (%2) viene rimosso</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the fault %1 (silent) goes</source>
        <translation>il guasto %1 (silenzio) viene rimosso</translation>
    </message>
    <message>
        <location line="+6"/>
        <location line="+32"/>
        <location line="+93"/>
        <source>No station is named &quot;%1&quot;</source>
        <translation>Nessuna stazione si chiama &quot;%1&quot;</translation>
    </message>
    <message>
        <location line="-108"/>
        <source>Remove Station %1</source>
        <translation>Rimuovi stazione %1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>No station port or device is named &quot;%1&quot;</source>
        <translation>Nessuna porta di stazione o dispositivo si chiama &quot;%1&quot;</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1 (%2 %3) has no port %4</source>
        <translation>%1 (%2 %3) non ha la porta %4</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>A wire joins two different ends</source>
        <translation>Un cavo collega due estremi diversi</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1 and %2 are on wire %3 already</source>
        <translation>%1 e %2 sono già sul cavo %3</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>Connect %1 to %2</source>
        <translation>Collega %1 a %2</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Disconnect %1</source>
        <translation>Scollega %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 is on no wire</source>
        <translation>%1 non è su alcun cavo</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Remove Wire %1</source>
        <translation>Rimuovi cavo %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>No wire is named &quot;%1&quot;</source>
        <translation>Nessun cavo si chiama &quot;%1&quot;</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>Port Settings of %1/%2</source>
        <translation>Impostazioni della porta %1/%2</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>A bridge goes from a station&apos;s port (STATION/PORT), not from &quot;%1&quot;</source>
        <translation>Un ponte parte dalla porta di una stazione (STAZIONE/PORTA), non da &quot;%1&quot;</translation>
    </message>
    <message>
        <location line="-9"/>
        <source>%1 has a bridge already</source>
        <translation>%1 ha già un ponte</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>A %1 bridge needs where it goes</source>
        <translation>Un ponte (%1) ha bisogno della destinazione</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&quot;%1&quot; is not HOST:PORT</source>
        <translation>&quot;%1&quot; non è HOST:PORTA</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>%1 runs %2, whose frames are not published: it cannot be bridged</source>
        <translation>%1 usa %2, i cui frame non sono pubblicati: non può avere un ponte</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Add Bridge %1</source>
        <translation>Aggiungi ponte %1</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Change Bridge %1</source>
        <translation>Modifica ponte %1</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1 has no bridge</source>
        <translation>%1 non ha un ponte</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Remove Bridge %1</source>
        <translation>Rimuovi ponte %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The period is 1 to 1000000 ms, not %1</source>
        <translation>Il periodo va da 1 a 1000000 ms, non %1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Network Period %1 ms</source>
        <translation>Periodo della rete %1 ms</translation>
    </message>
</context>
<context>
    <name>rung::app::NetworkHistoryController</name>
    <message>
        <location filename="../app/gui/network_history_controller.cpp" line="+90"/>
        <source>The network is stopped: run it, then pause it to see any instant of its past</source>
        <translation>La rete è fermata: eseguirla, poi metterla in pausa per vedere qualsiasi istante del suo passato</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Pause the network to see every station at the cursor&apos;s time</source>
        <translation>Mettere in pausa la rete per vedere ogni stazione all&apos;istante del cursore</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>That instant is no longer recorded: the history starts at %1</source>
        <extracomment>%1 the oldest virtual time still recorded, h:mm:ss.hh</extracomment>
        <translation>Quell&apos;istante non è più registrato: la cronologia inizia a %1</translation>
    </message>
    <message>
        <location line="+50"/>
        <source>History: %1, every station (read-only)</source>
        <extracomment>%1 the virtual time shown, h:mm:ss.hh; every station of the network shows that instant</extracomment>
        <translation>Cronologia: %1, tutte le stazioni (sola lettura)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Every station&apos;s ladder, inputs and outputs, front panel and watched values show this instant. Run, Single Scan, Stop or Return to Live (Ctrl+Shift+L) go back to the present</source>
        <translation>Il ladder, gli ingressi e le uscite, il pannello frontale e i valori osservati di ogni stazione mostrano questo istante. Esegui, Singola scansione, Fermati o Torna al vivo (Ctrl+Shift+L) riportano al presente</translation>
    </message>
</context>
<context>
    <name>rung::app::NetworkPortDialog</name>
    <message>
        <location filename="../app/gui/network_port_dialog.cpp" line="+61"/>
        <source>Port Settings: %1</source>
        <translation>Impostazioni porta: %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 %2: %3</source>
        <translation>%1 %2: %3</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 %2, port %3</source>
        <translation>%1 %2, porta %3</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>&amp;Application:</source>
        <translation>&amp;Applicazione:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Station number:</source>
        <translation>Numero di &amp;stazione:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Baud rate:</source>
        <translation>&amp;Baud rate:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Format:</source>
        <translation>&amp;Formato:</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>CPU Link master (station 0)</source>
        <translation>Master CPU Link (stazione 0)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source> x 10 ms</source>
        <translation> x 10 ms</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Total s&amp;laves (%1..%2):</source>
        <translation>Numero di s&amp;lave (%1..%2):</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Transfer range mode (%1..%2):</source>
        <translation>Modo dell&apos;area di &amp;trasferimento (%1..%2):</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Retries (%1..%2):</source>
        <translation>&amp;Ritentativi (%1..%2):</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>T&amp;ime-out (%1..%2):</source>
        <translation>T&amp;ime-out (%1..%2):</translation>
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
        <translation>Bassa velocità</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>High speed</source>
        <translation>Alta velocità</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>R&amp;ole:</source>
        <translation>R&amp;uolo:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>S&amp;peed (the master&apos;s decides):</source>
        <translation>&amp;Velocità (decide quella del master):</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>MODBUS</source>
        <translation>MODBUS</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&amp;Mode:</source>
        <translation>&amp;Modo:</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Start and end characters</source>
        <translation>Caratteri di inizio e di fine</translation>
    </message>
    <message>
        <location line="+5"/>
        <location line="+1"/>
        <source>none</source>
        <translation>nessuno</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Start c&amp;haracter (%1..%2):</source>
        <translation>Carattere di &amp;inizio (%1..%2):</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;End character (%1..%2):</source>
        <translation>Carattere di &amp;fine (%1..%2):</translation>
    </message>
    <message>
        <location line="+25"/>
        <location line="+88"/>
        <location line="+10"/>
        <source>%1 (default)</source>
        <translation>%1 (predefinito)</translation>
    </message>
    <message>
        <location line="-37"/>
        <source>%1 %2 has no such port</source>
        <translation>%1 %2 non ha questa porta</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>default: %1</source>
        <translation>predefinito: %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1..%2, default %3</source>
        <translation>%1..%2, predefinito %3</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1 (not a rate of %2)</source>
        <translation>%1 (non è una velocità di %2)</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1 always uses %2</source>
        <translation>%1 usa sempre %2</translation>
    </message>
    <message>
        <location line="+62"/>
        <source>the project&apos;s settings</source>
        <translation>le impostazioni del progetto</translation>
    </message>
    <message>
        <location line="+47"/>
        <source>Port Settings</source>
        <translation>Impostazioni porta</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The %1 %2&apos;s port:</source>
        <translation>La porta del %1 %2:</translation>
    </message>
</context>
<context>
    <name>rung::app::NetworkStationDialog</name>
    <message>
        <location filename="../app/gui/network_station_dialog.cpp" line="+25"/>
        <source>Add New Project Station</source>
        <translation>Aggiungi stazione con nuovo progetto</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>&amp;Browse...</source>
        <translation>&amp;Sfoglia...</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Name:</source>
        <translation>&amp;Nome:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;PLC:</source>
        <translation>&amp;PLC:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Model:</source>
        <translation>&amp;Modello:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Project &amp;file:</source>
        <translation>&amp;File del progetto:</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>New Project</source>
        <translation>Nuovo progetto</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Rung Studio projects (*.rung)</source>
        <translation>Progetti Rung Studio (*.rung)</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>A name is letters, digits, _ and -, at most 32</source>
        <translation>Un nome è fatto di lettere, cifre, _ e -, al massimo 32</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>A station or device is already named &quot;%1&quot;</source>
        <translation>Esiste già una stazione o un dispositivo di nome &quot;%1&quot;</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Choose where the project is saved</source>
        <translation>Scegliere dove salvare il progetto</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 exists already: a new project never overwrites a file</source>
        <translation>%1 esiste già: un nuovo progetto non sovrascrive mai un file</translation>
    </message>
</context>
<context>
    <name>rung::app::NetworkTrafficModel</name>
    <message>
        <location filename="../app/gui/network_traffic_model.cpp" line="+203"/>
        <source>Request: %1</source>
        <translation>Richiesta: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Reply: %1</source>
        <translation>Risposta: %1</translation>
    </message>
    <message>
        <location line="+54"/>
        <source>When the frame&apos;s first byte left: virtual time, seconds.milliseconds.microseconds</source>
        <translation>Quando è partito il primo byte del frame: tempo virtuale, secondi.millisecondi.microsecondi</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The station or device the frame is for; a reply&apos;s is the master</source>
        <translation>La stazione o il dispositivo a cui è destinato il frame; per una risposta, il master</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The address as the receiving PLC&apos;s device, with the address on the wire</source>
        <translation>L&apos;indirizzo come operando del PLC che riceve, con l&apos;indirizzo sul cavo</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Bytes (Computer Link), registers or bits (MODBUS), words, present values or flags (Host Link), characters (text)</source>
        <translation>Byte (Computer Link), registri o bit (MODBUS), parole, valori correnti o flag (Host Link), caratteri (testo)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The PLC&apos;s error or exception code, or what is wrong with the frame</source>
        <translation>Il codice di errore o di eccezione del PLC, o che cosa non va nel frame</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>A fault or a collision that changed the frame</source>
        <translation>Un guasto o una collisione che ha alterato il frame</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Time (s)</source>
        <translation>Tempo (s)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Wire</source>
        <translation>Cavo</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Sender</source>
        <translation>Mittente</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Receiver</source>
        <translation>Destinatario</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Protocol</source>
        <translation>Protocollo</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Station</source>
        <translation>Stazione</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Command</source>
        <translation>Comando</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Address</source>
        <translation>Indirizzo</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Count</source>
        <translation>Quantità</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Data</source>
        <translation>Dati</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Error</source>
        <translation>Errore</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Note</source>
        <translation>Nota</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Bytes</source>
        <translation>Byte</translation>
    </message>
</context>
<context>
    <name>rung::app::NetworkTrafficView</name>
    <message>
        <location filename="../app/gui/network_traffic_view.cpp" line="+171"/>
        <source>&amp;Errors only</source>
        <translation>Solo &amp;errori</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Save...</source>
        <translation>&amp;Salva...</translation>
    </message>
    <message>
        <location line="-2"/>
        <source>Only the frames with an error code, a problem (a wrong sum or CRC, a frame cut short) or a fault&apos;s note</source>
        <translation>Solo i frame con un codice di errore, un problema (somma o CRC errati, frame troncato) o la nota di un guasto</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Save the frames shown as CSV or as text</source>
        <translation>Salva i frame visualizzati come CSV o come testo</translation>
    </message>
    <message>
        <location line="-7"/>
        <source>&amp;Wire:</source>
        <translation>&amp;Cavo:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>S&amp;tation:</source>
        <translation>S&amp;tazione:</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>All wires</source>
        <translation>Tutti i cavi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>All stations</source>
        <translation>Tutte le stazioni</translation>
    </message>
    <message numerus="yes">
        <location line="+129"/>
        <source>%n frame(s)</source>
        <translation>
            <numerusform>%n frame</numerusform>
            <numerusform>%n frame</numerusform>
        </translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 of %2 frames</source>
        <translation>%1 di %2 frame</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 older frames were let go (the view keeps the last %2)</source>
        <translation>%1 frame più vecchi scartati (la vista conserva gli ultimi %2)</translation>
    </message>
    <message>
        <location line="+9"/>
        <location line="+22"/>
        <location line="+9"/>
        <location line="+27"/>
        <source>Cannot write %1: %2</source>
        <translation>Impossibile scrivere %1: %2</translation>
    </message>
    <message>
        <location line="-19"/>
        <source>%1 older frames were let go before these (the view keeps the last %2)</source>
        <translation>%1 frame più vecchi scartati prima di questi (la vista conserva gli ultimi %2)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 of %2 frames: wire %3, station %4%5</source>
        <translation>%1 di %2 frame: cavo %3, stazione %4%5</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+1"/>
        <source>all</source>
        <translation>tutti</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>, errors only</source>
        <translation>, solo errori</translation>
    </message>
    <message>
        <location line="+19"/>
        <location line="+9"/>
        <location line="+10"/>
        <source>Save Traffic</source>
        <translation>Salva il traffico</translation>
    </message>
    <message>
        <location line="-18"/>
        <source>CSV (*.csv);;Text, as rungstudio-cli writes it (*.txt)</source>
        <translation>CSV (*.csv);;Testo, come lo scrive rungstudio-cli (*.txt)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 already exists. Replace it?</source>
        <translation>%1 esiste già. Sostituirlo?</translation>
    </message>
</context>
<context>
    <name>rung::app::NetworkView</name>
    <message>
        <location filename="../app/gui/network_canvas.cpp" line="+59"/>
        <source>%1: scan period %2 ms</source>
        <translation>%1: periodo di scansione %2 ms</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>scan period %1 ms</source>
        <translation>periodo di scansione %1 ms</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>program not readable</source>
        <translation>programma non leggibile</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>station %1, %2 %3</source>
        <translation>stazione %1, %2 %3</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>, %1 slaves, range %2</source>
        <translation>, %1 slave, area %2</translation>
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
        <translation>impostazioni rifiutate</translation>
    </message>
    <message>
        <location filename="../app/gui/network_view.cpp" line="+209"/>
        <source>bridge: failed (%1)</source>
        <extracomment>a bridge whose line did not open; the tooltip says why</extracomment>
        <translation>ponte: guasto (%1)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>pseudo-terminal</source>
        <translation>pseudo-terminale</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>bridge: pseudo-terminal</source>
        <extracomment>%1 the pseudo-terminal&apos;s path while the network runs</extracomment>
        <translation>ponte: pseudo-terminale</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>bridge: pseudo-terminal %1</source>
        <translation>ponte: pseudo-terminale %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>bridge: serial %1</source>
        <translation>ponte: seriale %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>bridge: TCP to %1</source>
        <translation>ponte: TCP verso %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>bridge: listens on %1</source>
        <translation>ponte: in ascolto su %1</translation>
    </message>
    <message>
        <location filename="../app/gui/network_canvas.cpp" line="+20"/>
        <source>MODBUS slave (simulated)</source>
        <translation>Slave MODBUS (simulato)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>serial line (simulated)</source>
        <translation>linea seriale (simulata)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>station %1, %2</source>
        <translation>stazione %1, %2</translation>
    </message>
    <message>
        <location line="+154"/>
        <source>dashed: no frames on the wire (the manual does not publish them)</source>
        <translation>tratteggiato: nessun frame sul cavo (il manuale non li pubblica)</translation>
    </message>
    <message>
        <location filename="../app/gui/network_view.cpp" line="-103"/>
        <source>Network</source>
        <translation>Rete</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>%1 is a simulated device: edit it in the network file</source>
        <translation>%1 è un dispositivo simulato: si modifica nel file di rete</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Remove Station</source>
        <translation>Rimuovi stazione</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Remove station %1? With it:
%2
(Edit &gt; Undo brings it back.)</source>
        <translation>Rimuovere la stazione %1? Con essa:
%2
(Modifica &gt; Annulla la ripristina.)</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>Add Station from Program</source>
        <translation>Aggiungi stazione da programma</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Programs (*.rung *.il *.ladder);;All files (*)</source>
        <translation>Programmi (*.rung *.il *.ladder);;Tutti i file (*)</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Network Period</source>
        <translation>Periodo della rete</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Scan period of the stations that give none (ms):</source>
        <translation>Periodo di scansione delle stazioni che non ne indicano uno (ms):</translation>
    </message>
    <message>
        <location line="+84"/>
        <source>&amp;Pseudo-terminal</source>
        <translation>&amp;Pseudo-terminale</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&amp;Serial Port...</source>
        <translation>Porta &amp;seriale...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>TCP &amp;Listen...</source>
        <translation>&amp;Ascolto TCP...</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Port &amp;Settings...</source>
        <translation>&amp;Impostazioni porta...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Disconnect</source>
        <translation>&amp;Scollega</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>Add New Pro&amp;ject Station...</source>
        <translation>Aggiungi stazione con nuovo pro&amp;getto...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Network Period...</source>
        <translation>Periodo della &amp;rete...</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Zoom O&amp;ut</source>
        <translation>Rim&amp;picciolisci</translation>
    </message>
    <message>
        <location line="+51"/>
        <location line="+10"/>
        <source>Save Network</source>
        <translation>Salva rete</translation>
    </message>
    <message>
        <location line="-9"/>
        <source>%1 cannot hold everything in this network:
%2

Save anyway, leaving this out of the file?</source>
        <translation>%1 non può contenere tutto ciò che c&apos;è in questa rete:
%2

Salvare comunque, lasciando fuori questo dal file?</translation>
    </message>
    <message>
        <location line="-67"/>
        <source>Remove &amp;Wire</source>
        <translation>Rimuovi &amp;cavo</translation>
    </message>
    <message>
        <location line="-47"/>
        <source>&amp;Bridge To</source>
        <translation>Pon&amp;te verso</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>&amp;TCP Device Server...</source>
        <translation>Device server &amp;TCP...</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>Edit &amp;Bridge...</source>
        <translation>Modifica p&amp;onte...</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Copy %1</source>
        <translation>&amp;Copia %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Remove Brid&amp;ge</source>
        <translation>Rimuovi pon&amp;te</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>&amp;Open Program</source>
        <translation>&amp;Apri programma</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Remove Station %1...</source>
        <translation>&amp;Rimuovi stazione %1...</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Add Station from &amp;Program...</source>
        <translation>Aggiungi stazione da &amp;programma...</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Zoom &amp;In</source>
        <translation>&amp;Ingrandisci</translation>
    </message>
</context>
<context>
    <name>rung::app::NetworkWatchModel</name>
    <message>
        <location filename="../app/gui/network_watch_model.cpp" line="+49"/>
        <source>No network is open</source>
        <translation>Nessuna rete aperta</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1: write STATION/DEVICE, e.g. %2 (stations: %3)</source>
        <extracomment>%1 what was typed, %2 the stations, e.g. &quot;master, s5, s2&quot;</extracomment>
        <translation>%1: scrivere STAZIONE/OPERANDO, ad es. %2 (stazioni: %3)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1: no station &quot;%2&quot; (stations: %3)</source>
        <translation>%1: nessuna stazione «%2» (stazioni: %3)</translation>
    </message>
    <message>
        <location line="+71"/>
        <location line="+42"/>
        <source>ON</source>
        <translation>ON</translation>
    </message>
    <message>
        <location line="-42"/>
        <source>OFF</source>
        <translation>OFF</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Station/Device</source>
        <translation>Stazione/operando</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Value</source>
        <translation>Valore</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Model</source>
        <extracomment>the PLC model of the row&apos;s station (&quot;VB&quot;, &quot;PL110-2A&quot;)</extracomment>
        <translation>Modello</translation>
    </message>
</context>
<context>
    <name>rung::app::NetworkWindow</name>
    <message>
        <location filename="../app/gui/network_window.cpp" line="+263"/>
        <location line="+222"/>
        <source>Network</source>
        <translation>Rete</translation>
    </message>
    <message>
        <location line="-219"/>
        <source>&amp;Network</source>
        <translation>&amp;Rete</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Edit Station Program</source>
        <translation>&amp;Modifica il programma della stazione</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&amp;Save Network</source>
        <translation>&amp;Salva la rete</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Save Network &amp;As...</source>
        <translation>Salva la rete c&amp;ome...</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Close Network</source>
        <translation>&amp;Chiudi la rete</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Edit</source>
        <translation>&amp;Modifica</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Undo</source>
        <translation>&amp;Annulla</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Redo</source>
        <translation>&amp;Ripeti</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Add Station From a &amp;Program...</source>
        <translation>Aggiungi stazione da un &amp;programma...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Add Station as a &amp;New Project...</source>
        <translation>Aggiungi stazione come &amp;nuovo progetto...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Network Peri&amp;od...</source>
        <translation>Peri&amp;odo della rete...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Simulation</source>
        <translation>&amp;Simulazione</translation>
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
        <translation>&amp;Esegui</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&amp;Pause</source>
        <translation>&amp;Pausa</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Stop</source>
        <translation>&amp;Fermati</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Single S&amp;can</source>
        <translation>Singola s&amp;cansione</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Run &amp;For...</source>
        <translation>Esegui pe&amp;r...</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Run For</source>
        <extracomment>the virtual time to run the network for, in seconds</extracomment>
        <translation>Esegui per</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Virtual time to run the network for (seconds):</source>
        <translation>Tempo virtuale per cui eseguire la rete (secondi):</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Power C&amp;ycle</source>
        <translation>&amp;Spegni e riaccendi</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Spee&amp;d</source>
        <translation>&amp;Velocità</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>x%1 Real Time</source>
        <translation>x%1 tempo reale</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>As &amp;Fast as Possible</source>
        <translation>Il più &amp;veloce possibile</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Station:</source>
        <translation>Stazione:</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>F&amp;aults</source>
        <translation>&amp;Guasti</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&amp;View</source>
        <translation>&amp;Visualizza</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>No network is open</source>
        <translation>Nessuna rete aperta</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Cut Wire %1 (%2)</source>
        <extracomment>%1 a wire&apos;s name, %2 its ends (&quot;master/CP2, s5/CP2&quot;)</extracomment>
        <translation>Taglia il collegamento %1 (%2)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Wire %1 is cut: nothing it carries arrives</source>
        <translation>Il collegamento %1 è tagliato: non arriva nulla di ciò che trasporta</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Wire %1 is joined again</source>
        <translation>Il collegamento %1 è di nuovo unito</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Corrupt the Next Frame on %1</source>
        <translation>Altera il prossimo frame su %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The next frame on %1 will arrive with its second byte changed</source>
        <translation>Il prossimo frame su %1 arriverà con il secondo byte cambiato</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Baud Rate of %1: %2 (changed)...</source>
        <extracomment>%1 a station&apos;s port (&quot;s5/CP2&quot;); %2 the rate set by hand, if any</extracomment>
        <translation>Velocità di %1: %2 (cambiata)...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Change the Baud Rate of %1...</source>
        <translation>Cambia la velocità di %1...</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Baud Rate</source>
        <translation>Velocità di trasmissione</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 sends and reads at (the other ends keep theirs):</source>
        <translation>%1 trasmette e riceve a (gli altri capi mantengono la propria):</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Silence %1</source>
        <translation>Ammutolisci %1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Stop ends every fault made here</source>
        <translation>Fermati annulla ogni guasto creato qui</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Stations</source>
        <translation>Stazioni</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Inputs and Outputs</source>
        <translation>Ingressi e uscite</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Front Panel</source>
        <translation>Pannello frontale</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Network Watch</source>
        <translation>Osservazione rete</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Station/device, e.g. %1</source>
        <translation>Stazione/operando, ad es. %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Watch</source>
        <translation>&amp;Osserva</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Remove From Watch</source>
        <translation>Rimuovi dall&apos;osservazione</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Add to the Timing Chart</source>
        <translation>Aggiungi al diagramma temporale</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Timing Chart</source>
        <translation>Diagramma temporale</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Traffic</source>
        <translation>Traffico</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Double-click a station to edit its program</source>
        <translation>Doppio clic su una stazione per modificarne il programma</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Ladder</source>
        <translation>Ladder</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Close Network</source>
        <translation>Chiudi la rete</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 has edits that are not saved. Save them?</source>
        <translation>%1 ha modifiche non salvate. Salvarle?</translation>
    </message>
    <message>
        <location filename="../app/gui/network_window_session.cpp" line="+73"/>
        <source>%1: the listing does not draw as a ladder</source>
        <translation>%1: la lista istruzioni non si disegna come ladder</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>An empty network: add stations from the Network view&apos;s menu (right click)</source>
        <translation>Una rete vuota: aggiungere stazioni dal menu della vista Rete (clic destro)</translation>
    </message>
    <message>
        <location line="+41"/>
        <source>The network has no station yet: add one from the Network view&apos;s menu</source>
        <translation>La rete non ha ancora stazioni: aggiungerne una dal menu della vista Rete</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>A station&apos;s program is edited in the main window: Network &gt; Edit Station Program; Stop reads it again</source>
        <translation>Il programma di una stazione si modifica nella finestra principale: Rete &gt; Modifica il programma della stazione; Fermati lo rilegge</translation>
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
        <translation>La rete è stata modificata: Fermati la ricostruisce con la modifica</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>%1%2 - Network - Rung Studio</source>
        <extracomment>the window&apos;s title: the network file&apos;s name, * when it has unsaved edits</extracomment>
        <translation>%1%2 - Rete - Rung Studio</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Save Network</source>
        <translation>Salva la rete</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Networks of PLCs (*.rungnet)</source>
        <translation>Reti di PLC (*.rungnet)</translation>
    </message>
    <message>
        <location line="+72"/>
        <source>No network</source>
        <translation>Nessuna rete</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Running</source>
        <translation>In esecuzione</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Stepping</source>
        <translation>Passo passo</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Paused</source>
        <translation>In pausa</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Stopped</source>
        <translation>Fermata</translation>
    </message>
    <message numerus="yes">
        <location line="+4"/>
        <source>%1, %2, %n station(s)</source>
        <extracomment>%1 run state, %2 virtual time, %3 number of stations</extracomment>
        <translation>
            <numerusform>%1, %2, %n stazione</numerusform>
            <numerusform>%1, %2, %n stazioni</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>rung::app::Online</name>
    <message>
        <location filename="../app/cli/cli_online.cpp" line="+17"/>
        <source>usage:</source>
        <translation>uso:</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>%1 needs a value</source>
        <translation>%1 richiede un valore</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>unknown option %1</source>
        <translation>opzione sconosciuta: %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>--target and --protocol are needed</source>
        <translation>servono --target e --protocol</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>unknown target %1</source>
        <translation>famiglia PLC sconosciuta: %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>unknown protocol %1: vigor, modbus, modbus-tcp or hostlink</source>
        <translation>protocollo sconosciuto %1: vigor, modbus, modbus-tcp o hostlink</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>give exactly one of --port, --tcp and --pty</source>
        <translation>indicare esattamente uno tra --port, --tcp e --pty</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>modbus-tcp needs --tcp HOST:PORT (for RTU frames on a port: modbus)</source>
        <translation>modbus-tcp richiede --tcp HOST:PORTA (per frame RTU su una porta: modbus)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>--tcp needs HOST:PORT, e.g. 127.0.0.1:502; got %1</source>
        <translation>--tcp richiede HOST:PORTA, ad es. 127.0.0.1:502; ricevuto %1</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>%1 must be a number from %2 to %3; got %4</source>
        <translation>%1 deve essere un numero da %2 a %3; ricevuto %4</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>--frame must be data bits, parity and stop bits, e.g. 8N1 or 7E2; got %1</source>
        <translation>--frame indica bit di dati, parità e bit di stop, ad es. 8N1 o 7E2; ricevuto %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>no device given</source>
        <translation>nessun operando indicato</translation>
    </message>
    <message>
        <location line="+74"/>
        <source>  rungstudio-cli read  --target T --protocol vigor|modbus|modbus-tcp|hostlink
        (--port NAME | --tcp HOST:PORT | --pty PATH) [--station N] [--baud B]
        [--frame 8N1] [--timeout MS] [--retries N] DEVICE...
  rungstudio-cli write (the same options) DEVICE=VALUE...
Exit status of read and write: 0 done, 1 the PLC did not answer or refused, 2 usage, device, value or port error.</source>
        <translation>  rungstudio-cli read  --target T --protocol vigor|modbus|modbus-tcp|hostlink
        (--port NOME | --tcp HOST:PORTA | --pty PERCORSO) [--station N] [--baud B]
        [--frame 8N1] [--timeout MS] [--retries N] OPERANDO...
  rungstudio-cli write (le stesse opzioni) OPERANDO=VALORE...
Codice di uscita di read e write: 0 fatto, 1 il PLC non ha risposto o ha rifiutato, 2 errore di uso, di operando, di valore o di porta.</translation>
    </message>
    <message>
        <location line="+69"/>
        <source>%1: write DEVICE=VALUE</source>
        <translation>%1: scrivere OPERANDO=VALORE</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1: %2 is not a value for %3 (a bit takes 0 or 1, ON or OFF; a word a number, 0x for hexadecimal)</source>
        <translation>%1: %2 non è un valore per %3 (un bit vale 0 o 1, ON o OFF; una word un numero, 0x per l&apos;esadecimale)</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>note: %1</source>
        <translation>nota: %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>not written: %1</source>
        <translation>non scritto: %1</translation>
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
        <translation>Vai online</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The simulation is running. Going online pauses it: the views then show the PLC&apos;s values. Go online?</source>
        <translation>La simulazione è in esecuzione. Andare online la mette in pausa: le viste mostrano poi i valori del PLC. Andare online?</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Simulate</source>
        <translation>Simula</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>The IDE is online to %1. Go offline to simulate?</source>
        <translation>L&apos;IDE è online con %1. Andare offline per simulare?</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The simulation stays paused while the IDE is online</source>
        <translation>La simulazione resta in pausa finché l&apos;IDE è online</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>Connection</source>
        <translation>Connessione</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Online</source>
        <translation>&amp;In linea</translation>
    </message>
    <message>
        <location line="+7"/>
        <location line="+73"/>
        <source>Go &amp;Online</source>
        <translation>Vai &amp;online</translation>
    </message>
    <message>
        <location line="-63"/>
        <source>&amp;Test Connection</source>
        <translation>&amp;Prova connessione</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>PLC to &amp;STOP / PROGRAM</source>
        <translation>PLC in &amp;STOP / PROGRAM</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>PLC to &amp;MONITOR</source>
        <translation>PLC in &amp;MONITOR</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>PLC to &amp;RUN</source>
        <translation>PLC in &amp;RUN</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Release All &amp;Forces in the PLC</source>
        <translation>Rilascia tutte le &amp;forzature nel PLC</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Online: %1</source>
        <translation>Online: %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Going online. The IDE cannot know whether the PLC runs the program shown: compare by reading devices</source>
        <translation>Connessione online. L&apos;IDE non può sapere se il PLC esegue il programma mostrato: confrontare leggendo gli operandi</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Offline</source>
        <translation>Offline</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1 cannot switch the PLC between RUN and STOP: use the switch on the PLC</source>
        <translation>%1 non può commutare il PLC tra RUN e STOP: usare il selettore sul PLC</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Go &amp;Offline</source>
        <translation>Vai &amp;offline</translation>
    </message>
</context>
<context>
    <name>rung::app::PlcopenImportDialog</name>
    <message>
        <location filename="../app/gui/plcopen_exchange.cpp" line="+34"/>
        <location line="+16"/>
        <source>Cannot export</source>
        <translation>Impossibile esportare</translation>
    </message>
    <message>
        <location line="-11"/>
        <location line="+17"/>
        <source>Export PLCopen XML</source>
        <translation>Esporta PLCopen XML</translation>
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
        <translation>Importa PLCopen XML</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PLCopen XML (*.xml);;All files (*)</source>
        <translation>PLCopen XML (*.xml);;Tutti i file (*)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Cannot open the file</source>
        <translation>Impossibile aprire il file</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Import PLCopen XML: %1</source>
        <translation>Importa PLCopen XML: %1</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>PLC family:</source>
        <translation>Famiglia PLC:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Model:</source>
        <translation>Modello:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Variables without a device: a free one is proposed; change it where the program needs another.</source>
        <translation>Variabili senza operando: ne viene proposto uno libero; cambiarlo dove il programma ne richiede un altro.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Variable</source>
        <translation>Variabile</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Type</source>
        <translation>Tipo</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Line</source>
        <translation>Riga</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Device</source>
        <translation>Operando</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Not imported (element, line and why):</source>
        <translation>Non importato (elemento, riga e motivo):</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Import the rest and leave out what is listed</source>
        <translation>Importa il resto e tralascia quanto elencato</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>&amp;Import</source>
        <translation>&amp;Importa</translation>
    </message>
    <message>
        <location line="+23"/>
        <location line="+53"/>
        <source>(no such device)</source>
        <translation>(operando inesistente)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>line %1: %2: %3</source>
        <translation>riga %1: %2: %3</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The file holds no ladder to import.</source>
        <translation>Il file non contiene uno schema ladder da importare.</translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>Everything in the file is imported: %n rung(s).</source>
        <translation>
            <numerusform>Tutto il contenuto del file viene importato: %n segmento.</numerusform>
            <numerusform>Tutto il contenuto del file viene importato: %n segmenti.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>%n item(s) of the file are not imported; %1 variable(s) have no device yet.</source>
        <translation>
            <numerusform>%n elemento del file non viene importato; %1 variabili non hanno ancora un operando.</numerusform>
            <numerusform>%n elementi del file non vengono importati; %1 variabili non hanno ancora un operando.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+31"/>
        <source>Some variables still have no device: give each one a device of %1.</source>
        <translation>Alcune variabili non hanno ancora un operando: assegnare a ciascuna un operando di %1.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The file holds what %1 cannot take, listed here. Tick &quot;%2&quot; to import the rest.</source>
        <translation>Il file contiene ciò che %1 non può accogliere, elencato qui. Spuntare &quot;%2&quot; per importare il resto.</translation>
    </message>
    <message>
        <location line="-198"/>
        <source>%1 is written. Other tools will read it, with these notes:

%2</source>
        <translation>%1 è scritto. Altri strumenti lo leggeranno, con queste note:

%2</translation>
    </message>
    <message>
        <location line="+168"/>
        <source>Imported, but working otherwise than in the file:</source>
        <translation>Importato, ma funziona diversamente che nel file:</translation>
    </message>
</context>
<context>
    <name>rung::app::PortOptions</name>
    <message>
        <location filename="../app/cli/cli_port_options.cpp" line="+16"/>
        <source>unexpected argument %1</source>
        <translation>argomento inatteso %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 needs a value</source>
        <translation>%1 richiede un valore</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>--baud must be a number from 50 to 4000000; got %1</source>
        <translation>--baud deve essere un numero da 50 a 4000000; ricevuto %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>--frame must be data bits, parity and stop bits, e.g. 8N1 or 7E2; got %1</source>
        <translation>--frame indica bit di dati, parità e bit di stop, ad es. 8N1 o 7E2; ricevuto %1</translation>
    </message>
</context>
<context>
    <name>rung::app::ProgramExport</name>
    <message>
        <location filename="../app/gui/ladder_export.cpp" line="+82"/>
        <source>%1 could not be written</source>
        <translation>Impossibile scrivere %1</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>%1: the ladder can be exported as PDF, SVG or PNG</source>
        <translation>%1: lo schema ladder può essere esportato in PDF, SVG o PNG</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>%1    page %2 of %3</source>
        <translation>%1    pagina %2 di %3</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Instruction list, line %1: %2</source>
        <translation>Lista istruzioni, riga %1: %2</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+7"/>
        <source>Rung %1: %2</source>
        <translation>Segmento %1: %2</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Rung %1 is not in the list: %2</source>
        <translation>Il segmento %1 non è nella lista: %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Nothing was written: the instruction list would not hold the whole program.
%1</source>
        <translation>Non è stato scritto nulla: la lista istruzioni non conterrebbe l&apos;intero programma.
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
        [--seconds S]   (PORT: una porta seriale, un percorso /dev/pts, o pty per uno nuovo)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>usage:</source>
        <translation>uso:</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>--pc and --plc are needed: the two ports to join</source>
        <translation>servono --pc e --plc: le due porte da collegare</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>--seconds must be a positive number; got %1</source>
        <translation>--seconds deve essere un numero positivo; ricevuto %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the PC&apos;s side: %1</source>
        <translation>lato PC: %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the PLC&apos;s side: %1</source>
        <translation>lato PLC: %1</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>cannot write %1: %2</source>
        <translation>impossibile scrivere %1: %2</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Passing bytes between %1 (PC) and %2 (PLC); stop with Ctrl+C</source>
        <translation>Inoltro dei byte tra %1 (PC) e %2 (PLC); fermare con Ctrl+C</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>%1 bytes from the PC, %2 bytes from the PLC, in %3 records</source>
        <translation>%1 byte dal PC, %2 byte dal PLC, in %3 registrazioni</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 records were lost: the capture was not written as fast as they came</source>
        <translation>%1 registrazioni perse: la cattura non è stata scritta alla velocità con cui arrivavano</translation>
    </message>
</context>
<context>
    <name>rung::app::RecoveryFile</name>
    <message>
        <location filename="../app/gui/recovery.cpp" line="+84"/>
        <source>The recovery file could not be written: %1</source>
        <translation>Impossibile scrivere il file di recupero: %1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The recovery file could not be written: %1: %2</source>
        <translation>Impossibile scrivere il file di recupero: %1: %2</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>%1 could not be read and is kept: %2</source>
        <translation>%1 non è leggibile ed è stato conservato: %2</translation>
    </message>
</context>
<context>
    <name>rung::app::ScanDebuggerView</name>
    <message>
        <location filename="../app/gui/scan_debugger_view.cpp" line="+23"/>
        <source>ON</source>
        <translation>ON</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>OFF</source>
        <translation>OFF</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1: %2 (top)</source>
        <extracomment>a stack entry: %1 depth (1 = bottom), %2 ON/OFF</extracomment>
        <translation>%1: %2 (cima)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>(empty)</source>
        <translation>(vuoto)</translation>
    </message>
    <message>
        <location line="+151"/>
        <source>Logic result:</source>
        <translation>Risultato logico:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Step Instruction</source>
        <translation>Passo di una istruzione</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Finish Scan</source>
        <translation>Completa la scansione</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Continue</source>
        <translation>Continua</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Breakpoints:</source>
        <translation>Punti di interruzione:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Where</source>
        <translation>Dove</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Stops</source>
        <translation>Si ferma</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Condition...</source>
        <translation>Condizione...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Remove</source>
        <translation>Rimuovi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Remove All</source>
        <translation>Rimuovi tutti</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>Block stack (%1 / %2):</source>
        <translation>Stack dei blocchi (%1 / %2):</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 stack:</source>
        <translation>Stack %1:</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Not stopped inside a scan. Step Instruction starts a scan and stops before its first instruction; a breakpoint stops a running scan.</source>
        <translation>Non fermo dentro una scansione. Passo di una istruzione avvia una scansione e si ferma prima della sua prima istruzione; un punto di interruzione ferma una scansione in corso.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The simulation is off.</source>
        <translation>La simulazione è spenta.</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Stopped before step %1 (line %2, rung %3): %4</source>
        <extracomment>%1 step, %2 line, %3 rung, %4 the instruction, e.g. &quot;OUT Y0&quot;</extracomment>
        <translation>Fermo prima del passo %1 (riga %2, segmento %3): %4</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Stopped at the end of the program</source>
        <translation>Fermo alla fine del programma</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>A breakpoint stopped the scan.</source>
        <translation>Un punto di interruzione ha fermato la scansione.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stepping one instruction at a time.</source>
        <translation>Avanzamento di una istruzione alla volta.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Inside an interlock (IL/MC) whose condition is OFF</source>
        <translation>Dentro un interblocco (IL/MC) la cui condizione è OFF</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Inside a step (STL) that is not active</source>
        <translation>Dentro un passo (STL) non attivo</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Rung %1 (no longer there)</source>
        <translation>Segmento %1 (non esiste più)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Rung %1, line %2: %3</source>
        <extracomment>%1 rung, %2 line, %3 the instruction</extracomment>
        <translation>Segmento %1, riga %2: %3</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>No breakpoint is set: Ctrl+B sets one where the cursor is</source>
        <translation>Nessun punto di interruzione: Ctrl+B ne imposta uno dove si trova il cursore</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Choose a breakpoint in the list first</source>
        <translation>Scegliere prima un punto di interruzione nell&apos;elenco</translation>
    </message>
</context>
<context>
    <name>rung::app::Serve</name>
    <message>
        <location filename="../app/cli/cli_serve.cpp" line="+188"/>
        <source>unexpected argument %1</source>
        <translation>argomento inatteso %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 needs a valid value</source>
        <translation>%1 richiede un valore valido</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>no FILE given</source>
        <translation>nessun FILE indicato</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>--protocol is required</source>
        <translation>--protocol è obbligatorio</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unknown protocol %1 (vigor, modbus, modbus-tcp, hostlink)</source>
        <translation>protocollo sconosciuto %1 (vigor, modbus, modbus-tcp, hostlink)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>give one of --pty, --port NAME and --tcp HOST:PORT</source>
        <translation>indicare uno solo tra --pty, --port NAME e --tcp HOST:PORT</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>--protocol modbus-tcp is served over --tcp HOST:PORT</source>
        <translation>--protocol modbus-tcp si serve con --tcp HOST:PORT</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>--tcp needs HOST:PORT with a numeric address, e.g. 127.0.0.1:1502, not %1</source>
        <translation>--tcp richiede HOST:PORT con un indirizzo numerico, ad es. 127.0.0.1:1502, non %1</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>--frame needs data bits, parity and stop bits, e.g. 8N1 or 7E2, not %1</source>
        <translation>--frame richiede bit di dati, parità e bit di stop, ad es. 8N1 o 7E2, non %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>--station %1 is outside %2..%3, the stations of %4</source>
        <translation>--station %1 è fuori da %2..%3, le stazioni di %4</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>unknown fault %1 (%2)</source>
        <translation>guasto sconosciuto %1 (%2)</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>%1 does not speak %2; it speaks %3</source>
        <translation>%1 non parla %2; parla %3</translation>
    </message>
    <message>
        <location line="+45"/>
        <source>%1 serves %2 (%3, %4, station %5) on %6; stop it with Ctrl+C</source>
        <translation>%1 serve %2 (%3, %4, stazione %5) su %6; per fermarlo Ctrl+C</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>%1 requests answered, %2 refused with an error, %3 for other stations or broadcast, %4 frames dropped; %5 writes</source>
        <translation>%1 richieste con risposta, %2 rifiutate con un errore, %3 per altre stazioni o broadcast, %4 frame scartati; %5 scritture</translation>
    </message>
    <message>
        <location line="-304"/>
        <source>usage: rungstudio-cli serve FILE [--target T] [--model M] --protocol vigor|modbus|modbus-tcp|hostlink (--pty [--link PATH] | --port NAME | --tcp HOST:PORT) [--station N] [--baud B] [--frame 8N1|7E1|7E2|...] [--period MS] [--fault bad-checksum|silent|wrong-station|garbage|truncated|split]</source>
        <translation>uso: rungstudio-cli serve FILE [--target T] [--model M] --protocol vigor|modbus|modbus-tcp|hostlink (--pty [--link PATH] | --port NAME | --tcp HOST:PORT) [--station N] [--baud B] [--frame 8N1|7E1|7E2|...] [--period MS] [--fault bad-checksum|silent|wrong-station|garbage|truncated|split]</translation>
    </message>
    <message>
        <location line="+46"/>
        <source>--link %1: %2</source>
        <translation>--link %1: %2</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>--link %1: something that is not a link to a pseudo-terminal is there already; it is left as it is: remove it or give another path</source>
        <translation>--link %1: lì c&apos;è già qualcosa che non è un collegamento a uno pseudo-terminale; resta com&apos;è: rimuoverlo o indicare un altro percorso</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>--link %1: the link cannot be made: %2</source>
        <translation>--link %1: impossibile creare il collegamento: %2</translation>
    </message>
    <message>
        <location line="+108"/>
        <source>--link names the pseudo-terminal of --pty (a port keeps its own name, a TCP address is given)</source>
        <translation>--link dà un nome allo pseudo-terminale di --pty (una porta ha già il suo nome, un indirizzo TCP è dato)</translation>
    </message>
    <message>
        <location line="+114"/>
        <source>%1 (a link to %2, removed at the end)</source>
        <translation>%1 (un collegamento a %2, rimosso alla fine)</translation>
    </message>
    <message>
        <location line="-54"/>
        <source>%1 has no published protocol to serve (its manual gives none)</source>
        <translation>%1 non ha un protocollo pubblicato da servire (il suo manuale non ne riporta)</translation>
    </message>
</context>
<context>
    <name>rung::app::Simulate</name>
    <message>
        <location filename="../app/cli/cli_simulate.cpp" line="+17"/>
        <source>usage: rungstudio-cli simulate FILE [--target T] [--model M] --scans N [--period MS] [--set DEV=VALUE@SCAN]... --trace DEV[,DEV...]
FILE is a listing (.il), a ladder text (.ladder) or a project (.rung).</source>
        <translation>uso: rungstudio-cli simulate FILE [--target T] [--model M] --scans N [--period MS] [--set OPERANDO=VALORE@SCANSIONE]... --trace OPERANDO[,OPERANDO...]
FILE è una lista istruzioni (.il), un testo ladder (.ladder) o un progetto (.rung).</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>%1 needs a value</source>
        <translation>%1 richiede un valore</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>unexpected argument %1</source>
        <translation>argomento non previsto: %1</translation>
    </message>
    <message>
        <location filename="../app/cli/cli_load_program.cpp" line="+47"/>
        <location line="+7"/>
        <location line="+33"/>
        <source>the program does not start</source>
        <translation>il programma non si avvia</translation>
    </message>
    <message>
        <location filename="../app/cli/cli_simulate.cpp" line="+29"/>
        <source>runtime error at step %1: %2</source>
        <translation>errore di esecuzione al passo %1: %2</translation>
    </message>
</context>
<context>
    <name>rung::app::SimulationController</name>
    <message numerus="yes">
        <location filename="../app/gui/simulation_controller.cpp" line="+101"/>
        <source>The program has %n error(s): the simulation does not start; the Problems list shows them</source>
        <translation>
            <numerusform>Il programma ha %n errore: la simulazione non parte; l&apos;elenco Problemi lo mostra</numerusform>
            <numerusform>Il programma ha %n errori: la simulazione non parte; l&apos;elenco Problemi li mostra</numerusform>
        </translation>
    </message>
    <message>
        <location line="+83"/>
        <source>The edited program has errors: the simulation goes on with the program before the edit (stop it to simulate what is shown)</source>
        <translation>Il programma modificato ha errori: la simulazione continua con il programma di prima della modifica (fermarla per simulare quello mostrato)</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>The program was edited: the simulation stopped. Run starts the edited program from power-on</source>
        <translation>Il programma è stato modificato: la simulazione si è fermata. Esegui avvia il programma modificato dallo stato di accensione</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Online edit: the edited program restarted from power-on</source>
        <translation>Modifica online: il programma modificato è ripartito dallo stato di accensione</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Online edit: the edited program takes over when the stopped scan ends; the memory is kept</source>
        <translation>Modifica online: il programma modificato subentra alla fine della scansione fermata; la memoria è mantenuta</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Online edit: the edited program runs from the next scan on; the memory is kept</source>
        <translation>Modifica online: il programma modificato gira dalla prossima scansione; la memoria è mantenuta</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The edited program is for another memory layout: the running memory cannot be kept. Restart it from power-on, or stop the simulation?</source>
        <translation>Il programma modificato ha un&apos;altra disposizione della memoria: la memoria in uso non si può mantenere. Riavviarlo dallo stato di accensione o fermare la simulazione?</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>no longer uses %1 (their values stay as they are)</source>
        <translation>non usa più %1 (i loro valori restano come sono)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>now uses %1 (they start from the values the memory holds)</source>
        <translation>ora usa %1 (partono dai valori che la memoria contiene)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The edited program %1. Apply it keeping the memory, restart it from power-on, or stop the simulation?</source>
        <extracomment>%1 what changed, e.g. &quot;no longer uses T0 (...); now uses T5 (...)&quot;</extracomment>
        <translation>Il programma modificato %1. Applicarlo mantenendo la memoria, riavviarlo dallo stato di accensione o fermare la simulazione?</translation>
    </message>
    <message>
        <location line="+82"/>
        <source> | the program before the edit</source>
        <translation> | il programma di prima della modifica</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Simulation off</source>
        <translation>Simulazione spenta</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Stopped</source>
        <translation>Fermata</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Paused</source>
        <translation>In pausa</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Running x%1</source>
        <translation>In esecuzione x%1</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Running at full speed</source>
        <translation>In esecuzione alla massima velocità</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Stepping</source>
        <translation>Passo passo</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 | %2 | %3 scans | scan %4 ms</source>
        <extracomment>%1 run state, %2 simulated time h:mm:ss.cc, %3 scans, %4 scan period in ms</extracomment>
        <translation>%1 | %2 | %3 scansioni | scansione %4 ms</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Evaluation of a scan on this computer: %1 µs (%2..%3)</source>
        <extracomment>the time the last scan took to evaluate on this computer: current, minimum, maximum</extracomment>
        <translation>Valutazione di una scansione su questo computer: %1 µs (%2..%3)</translation>
    </message>
    <message>
        <location filename="../app/gui/simulation_debug.cpp" line="+117"/>
        <source>always</source>
        <translation>sempre</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>when %1 rises</source>
        <translation>quando %1 sale</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>when %1 falls</source>
        <translation>quando %1 scende</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>while %1 is ON</source>
        <translation>finché %1 è ON</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>while %1 is OFF</source>
        <translation>finché %1 è OFF</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>when %1 %2 %3</source>
        <extracomment>a breakpoint&apos;s condition, e.g. &quot;when D10 &gt; 100&quot;</extracomment>
        <translation>quando %1 %2 %3</translation>
    </message>
    <message>
        <location filename="../app/gui/simulation_history.cpp" line="+66"/>
        <source>History: rebuilding...</source>
        <translation>Cronologia: ricostruzione...</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>No history: the simulation is off</source>
        <translation>Nessuna cronologia: la simulazione è spenta</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>No history yet: run the simulation</source>
        <translation>Ancora nessuna cronologia: eseguire la simulazione</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Recorded: the last %1 of simulated time (scans %2..%3, %4 MB); at least the last hour is kept</source>
        <extracomment>%1 h:mm:ss of simulated time, %2 %3 first and last scan, %4 memory in MB</extracomment>
        <translation>Registrato: gli ultimi %1 di tempo simulato (scansioni %2..%3, %4 MB); si conserva almeno l&apos;ultima ora</translation>
    </message>
</context>
<context>
    <name>rung::app::SimulationMenu</name>
    <message>
        <location filename="../app/gui/simulation_menu.cpp" line="+46"/>
        <source>&amp;Simulation</source>
        <translation>&amp;Simulazione</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>&amp;Run</source>
        <translation>&amp;Esegui</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Pause</source>
        <translation>&amp;Pausa</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Stop (Back to Power-On)</source>
        <translation>&amp;Stop (stato di accensione)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Single S&amp;can</source>
        <translation>Singola s&amp;cansione</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Po&amp;wer Cycle</source>
        <translation>Spegni e &amp;riaccendi</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Run Sc&amp;ans...</source>
        <translation>Esegui scansio&amp;ni...</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Run Scans</source>
        <translation>Esegui scansioni</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Scans to run:</source>
        <translation>Scansioni da eseguire:</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>R&amp;un For...</source>
        <translation>Esegu&amp;i per...</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Run For</source>
        <translation>Esegui per</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Simulated time to run, in seconds:</source>
        <translation>Tempo simulato da eseguire, in secondi:</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Spee&amp;d</source>
        <translation>&amp;Velocità</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>x%1 Real Time</source>
        <translation>x%1 tempo reale</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>As &amp;Fast as Possible</source>
        <translation>Il più &amp;veloce possibile</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Scan Peri&amp;od</source>
        <translation>Peri&amp;odo di scansione</translation>
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
        <translation>Rilascia tutte le &amp;forzature</translation>
    </message>
</context>
<context>
    <name>rung::app::SimulationPanel</name>
    <message>
        <location filename="../app/gui/simulation_panel.cpp" line="+161"/>
        <source>Run</source>
        <translation>Esecuzione</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Scans:</source>
        <translation>Scansioni:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Run Scans</source>
        <translation>Esegui scansioni</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Simulated time:</source>
        <translation>Tempo simulato:</translation>
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
        <translation>Esegui per</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Speed:</source>
        <translation>Velocità:</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>x%1 real time</source>
        <translation>x%1 tempo reale</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>As fast as possible</source>
        <translation>Il più veloce possibile</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Scan period:</source>
        <translation>Periodo di scansione:</translation>
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
        <translation>Spegni e riaccendi</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Off and on again: the retentive areas keep their values, the rest starts as at power-on</source>
        <translation>Spegnere e riaccendere: le aree ritentive conservano i valori, il resto riparte come all&apos;accensione</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Statistics</source>
        <translation>Statistiche</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>History</source>
        <translation>Cronologia</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Show scan:</source>
        <translation>Mostra scansione:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Return to Live</source>
        <translation>Torna al vivo</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>The simulation is off: Run, Single Scan or Run Scans starts it.</source>
        <translation>La simulazione è spenta: Esegui, Singola scansione o Esegui scansioni la avviano.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Simulated time: %1
Scans: %2
Scan period: %3 ms
Evaluation: %4 µs (%5..%6)</source>
        <extracomment>the statistics block: simulated time, scans, the scan period, the evaluation time of the last scan on this computer (current, minimum..maximum)</extracomment>
        <translation>Tempo simulato: %1
Scansioni: %2
Periodo di scansione: %3 ms
Valutazione: %4 µs (%5..%6)</translation>
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
        <translation>%1, riga %2: %3</translation>
    </message>
</context>
<context>
    <name>rung::app::Terminal</name>
    <message>
        <location filename="../app/cli/cli_terminal.cpp" line="+103"/>
        <source>  rungstudio-cli terminal --port PORT [--baud B] [--frame 8N1] [--wait MS]
        (each line of stdin: hex bytes, &quot;text\r&quot;, or a capture line)</source>
        <translation>  rungstudio-cli terminal --port PORT [--baud B] [--frame 8N1] [--wait MS]
        (ogni riga dello standard input: byte esadecimali, &quot;testo\r&quot; o una riga di una cattura)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>usage:</source>
        <translation>uso:</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>--port is needed</source>
        <translation>serve --port</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>--wait must be a number from 1 to 60000; got %1</source>
        <translation>--wait deve essere un numero da 1 a 60000; ricevuto %1</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>line %1: &quot;%2&quot; is neither hex bytes (02 30 31), a quoted text (&quot;@00RD\r&quot;) nor a capture line</source>
        <translation>riga %1: &quot;%2&quot; non è né byte esadecimali (02 30 31), né un testo tra virgolette (&quot;@00RD\r&quot;), né una riga di una cattura</translation>
    </message>
</context>
<context>
    <name>rung::app::Test</name>
    <message>
        <location filename="../app/cli/cli_test.cpp" line="+46"/>
        <source>  rungstudio-cli test FILE|DIR... [--junit OUT.xml]   (scenario tests, .rungtest)</source>
        <translation>  rungstudio-cli test FILE|DIR... [--junit OUT.xml]   (test di scenario, .rungtest)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>--junit needs a value</source>
        <translation>--junit richiede un valore</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>unknown option %1</source>
        <translation>opzione sconosciuta: %1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>no scenario given</source>
        <translation>nessuno scenario indicato</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1: no .%2 file in the folder</source>
        <translation>%1: nessun file .%2 nella cartella</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1: no such file or folder</source>
        <translation>%1: file o cartella inesistente</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>error</source>
        <translation>errore</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>note</source>
        <translation>nota</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1 scenario(s), %2 expectation(s): %3 failed; %4 scenario(s) did not pass</source>
        <extracomment>The summary of a test run: %1 scenario files, %2 expectations, %3 failed expectations, %4 scenarios that failed or did not run.</extracomment>
        <translation>%1 scenari, %2 attese: %3 non soddisfatte; %4 scenari non superati</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>cannot write %1: %2</source>
        <translation>impossibile scrivere %1: %2</translation>
    </message>
</context>
<context>
    <name>rung::app::TestsPanel</name>
    <message>
        <location filename="../app/gui/tests_panel.cpp" line="+52"/>
        <source>unknown target %1</source>
        <translation>famiglia PLC sconosciuta: %1</translation>
    </message>
    <message>
        <location line="+94"/>
        <source>Run All</source>
        <translation>Esegui tutti</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Run</source>
        <translation>Esegui</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Refresh</source>
        <translation>Aggiorna</translation>
    </message>
    <message>
        <location filename="../app/gui/tests_panel_record.cpp" line="+70"/>
        <source>Record...</source>
        <translation>Registra...</translation>
    </message>
    <message>
        <location filename="../app/gui/tests_panel.cpp" line="+2"/>
        <source>Runs the selected scenario</source>
        <translation>Esegue lo scenario selezionato</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Scenario / expectation</source>
        <translation>Scenario / attesa</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Result</source>
        <translation>Risultato</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Save the project: its scenario tests (.rungtest) are the files beside it that name it</source>
        <translation>Salvare il progetto: i suoi test di scenario (.rungtest) sono i file accanto che lo indicano</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Scenario tests (.rungtest) that name this project, in %1 and below</source>
        <translation>Test di scenario (.rungtest) che nominano questo progetto, in %1 e nelle sottocartelle</translation>
    </message>
    <message>
        <location line="+53"/>
        <source>%1 names no program: its first statement is `program FILE`</source>
        <translation>%1 non nomina alcun programma: la sua prima istruzione è `program FILE`</translation>
    </message>
    <message>
        <location line="+44"/>
        <source>the open program has errors: %1</source>
        <translation>il programma aperto contiene errori: %1</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>No scenario test names this project</source>
        <translation>Nessun test di scenario indica questo progetto</translation>
    </message>
    <message>
        <location line="+69"/>
        <source>not run</source>
        <translation>non eseguito</translation>
    </message>
    <message numerus="yes">
        <location line="+8"/>
        <source>passed: %n expectation(s)</source>
        <translation>
            <numerusform>superato: %n attesa</numerusform>
            <numerusform>superato: %n attese</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+5"/>
        <source>FAILED: %n expectation(s)</source>
        <translation>
            <numerusform>FALLITO: %n attesa</numerusform>
            <numerusform>FALLITO: %n attese</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2"/>
        <source>did not run</source>
        <translation>non è stato eseguito</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>line %1</source>
        <translation>riga %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>error: %1</source>
        <translation>errore: %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <location line="+46"/>
        <source>line %1: %2</source>
        <translation>riga %1: %2</translation>
    </message>
    <message>
        <location line="-41"/>
        <source>ok</source>
        <translation>ok</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>FAILED: %1 (double-click: the timing chart)</source>
        <translation>FALLITO: %1 (doppio clic: il diagramma temporale)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Scenario tests: %1 passed, %2 failed</source>
        <translation>Test di scenario: %1 superati, %2 falliti</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Timing chart of %1, line %2</source>
        <translation>Diagramma temporale di %1, riga %2</translation>
    </message>
    <message>
        <location filename="../app/gui/tests_panel_record.cpp" line="+80"/>
        <source>Nothing to record: start a simulation and work its inputs first</source>
        <translation>Niente da registrare: avviare prima una simulazione e azionarne gli ingressi</translation>
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
        <translation>Registra uno scenario</translation>
    </message>
    <message>
        <location line="-38"/>
        <source>Save the project first: a scenario names the project&apos;s file.</source>
        <translation>Salvare prima il progetto: uno scenario indica il file del progetto.</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Scenario tests (*.rungtest)</source>
        <translation>Test di scenario (*.rungtest)</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>Recorded %1</source>
        <translation>Registrato %1</translation>
    </message>
    <message>
        <location line="-142"/>
        <source>Offline: the recording ends here; Stop Recording... writes it</source>
        <translation>Non in linea: la registrazione finisce qui; Ferma registrazione... la scrive</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Stop Recording...</source>
        <translation>Ferma registrazione...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Writes the scenario of what the PLC did since Record...: its inputs and outputs as each refresh read them</source>
        <translation>Scrive lo scenario di ciò che il PLC ha fatto da Registra...: i suoi ingressi e uscite come li ha letti ogni aggiornamento</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Writes a scenario of the simulation so far: the inputs as you worked them, the outputs as they were seen; online, records what the PLC&apos;s inputs and outputs do until Stop Recording...</source>
        <translation>Scrive uno scenario della simulazione finora: gli ingressi come sono stati azionati, le uscite come sono state viste; in linea, registra ciò che fanno gli ingressi e le uscite del PLC fino a Ferma registrazione...</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Not online: go online to record what a PLC does</source>
        <translation>Non in linea: andare in linea per registrare ciò che fa un PLC</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>The program reads no input and drives no output: nothing to record</source>
        <translation>Il programma non legge ingressi e non comanda uscite: niente da registrare</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>This PLC&apos;s session keeps no history: it cannot be recorded</source>
        <translation>La sessione di questo PLC non conserva la cronologia: non può essere registrata</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Recording the PLC&apos;s inputs and outputs: Stop Recording... writes the scenario</source>
        <translation>Registrazione degli ingressi e delle uscite del PLC: Ferma registrazione... scrive lo scenario</translation>
    </message>
    <message>
        <location line="+107"/>
        <source>%1 is written. What it does not hold:</source>
        <translation>%1 è stato scritto. Ciò che non contiene:</translation>
    </message>
</context>
<context>
    <name>rung::app::VirtualPlc</name>
    <message>
        <location filename="../app/virtual_plc/virtual_plc.cpp" line="+98"/>
        <location line="+10"/>
        <source>the virtual PLC is stopping</source>
        <translation>il PLC virtuale si sta arrestando</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>the simulation did not take the write within the time allowed</source>
        <translation>la simulazione non ha eseguito la scrittura entro il tempo consentito</translation>
    </message>
    <message>
        <location line="+71"/>
        <source>The virtual PLC needs a QCoreApplication for its simulation thread</source>
        <translation>Il PLC virtuale richiede una QCoreApplication per il thread di simulazione</translation>
    </message>
</context>
<context>
    <name>rung::comms::Driver</name>
    <message>
        <location filename="../comms/driver/driver.cpp" line="+42"/>
        <source>station 0 is the Modbus broadcast address: no PLC answers it, so nothing could be read and no write acknowledged; give the PLC&apos;s own station (1..247, or 255 for any PL110)</source>
        <translation>la stazione 0 è l&apos;indirizzo broadcast Modbus: nessun PLC risponde, quindi nulla potrebbe essere letto né alcuna scrittura confermata; indicare la stazione del PLC (1..247, o 255 per qualsiasi PL110)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>station %1 is outside %2&apos;s %3..%4</source>
        <translation>la stazione %1 è fuori dall&apos;intervallo %3..%4 di %2</translation>
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
        <translation>%1 non ha un indirizzo in %2, quindi non può essere letto con esso</translation>
    </message>
    <message>
        <location line="+48"/>
        <source>%1 and %2 more</source>
        <translation>%1 e altri %2</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+33"/>
        <source>reading %1 from %2</source>
        <translation>lettura di %1 da %2</translation>
    </message>
    <message>
        <location filename="../comms/driver/driver_commands.cpp" line="+19"/>
        <source>ON</source>
        <translation>ON</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>OFF</source>
        <translation>OFF</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>%1: %2 has no word address in %3</source>
        <translation>%1: %2 non ha un indirizzo di word in %3</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>%1: %2 does not fit %3 (%4..%5)</source>
        <translation>%1: %2 non rientra in %3 (%4..%5)</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>%1: %2 is not a bit in %3</source>
        <translation>%1: %2 non è un bit in %3</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>setting %1 %2 on %3</source>
        <translation>impostazione di %1 a %2 su %3</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>writing %1 = %2 to %3</source>
        <translation>scrittura di %1 = %2 su %3</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>writing the set value of %1 = %2 to %3</source>
        <translation>scrittura del valore di preset di %1 = %2 su %3</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>%1: the set value of %2 is a constant of the program in the PLC; %3 cannot change it (change the program, or make the set value a register)</source>
        <translation>%1: il valore di preset di %2 è una costante del programma nel PLC; %3 non può cambiarlo (modificare il programma, o mettere il preset in un registro)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>forcing %1 %2 on %3</source>
        <translation>forzatura di %1 a %2 su %3</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>releasing %1 on %2</source>
        <translation>rilascio della forzatura di %1 su %2</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: %2 has no command that releases one bit; release all forced bits instead (KC)</source>
        <translation>%1: %2 non ha un comando che rilascia un solo bit; rilasciare invece tutti i bit forzati (KC)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>releasing every forced bit on %1</source>
        <translation>rilascio di tutti i bit forzati su %1</translation>
    </message>
    <message>
        <location line="+34"/>
        <location filename="../comms/driver/host_link_driver.cpp" line="+154"/>
        <source>switching %1 to %2</source>
        <translation>commutazione di %1 in %2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: the PLC has RUN and STOP only</source>
        <translation>%1: il PLC ha solo RUN e STOP</translation>
    </message>
    <message>
        <location filename="../comms/driver/host_link_driver.cpp" line="-131"/>
        <location filename="../comms/driver/modbus_driver.cpp" line="+29"/>
        <source>%1 unit %2 on %3</source>
        <translation>%1 unità %2 su %3</translation>
    </message>
    <message>
        <location line="+68"/>
        <source>%1: the completion flags of timers and counters are read-only over Host Link (RG)</source>
        <translation>%1: i flag di completamento di temporizzatori e contatori sono in sola lettura con Host Link (RG)</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>Host Link forces bits of the IR / SR channels (CIO) only</source>
        <translation>Host Link forza solo i bit dei canali IR / SR (CIO)</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>reading the mode of %1</source>
        <translation>lettura del modo di %1</translation>
    </message>
    <message>
        <location line="+40"/>
        <source>%1 was in RUN mode: switched to MONITOR, where Host Link writes are accepted (the program goes on running)</source>
        <translation>%1 era in modo RUN: commutato in MONITOR, dove le scritture Host Link sono accettate (il programma continua a girare)</translation>
    </message>
    <message>
        <location line="+12"/>
        <location filename="../comms/driver/modbus_driver.cpp" line="+105"/>
        <source>reading the model of %1</source>
        <translation>lettura del modello di %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>model code %1h</source>
        <translation>codice modello %1h</translation>
    </message>
    <message>
        <location filename="../comms/driver/link.cpp" line="+59"/>
        <source>%1 is not open</source>
        <translation>%1 non è aperto</translation>
    </message>
    <message>
        <location line="+50"/>
        <source>cancelled</source>
        <translation>annullato</translation>
    </message>
    <message>
        <location line="+40"/>
        <location line="+9"/>
        <source>%1 (%2 attempts)</source>
        <translation>%1 (%2 tentativi)</translation>
    </message>
    <message>
        <location filename="../comms/driver/modbus_driver.cpp" line="-45"/>
        <source>%1: Modbus has no function that writes discrete inputs</source>
        <translation>%1: Modbus non ha una funzione che scrive gli ingressi discreti</translation>
    </message>
    <message>
        <location line="+54"/>
        <source>device type %1</source>
        <translation>tipo di dispositivo %1</translation>
    </message>
    <message>
        <location filename="../comms/driver/online_session.cpp" line="+116"/>
        <source>%1 is not connected: nothing was sent</source>
        <translation>%1 non è connesso: non è stato inviato nulla</translation>
    </message>
    <message>
        <location line="+230"/>
        <source>Connection lost: %1. Trying again.</source>
        <translation>Connessione persa: %1. Nuovo tentativo in corso.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Connection to %1 lost: %2. Trying again.</source>
        <translation>Connessione con %1 persa: %2. Nuovo tentativo in corso.</translation>
    </message>
    <message>
        <location line="-7"/>
        <source>Cannot reach %1: %2. Trying again.</source>
        <translation>Impossibile raggiungere %1: %2. Nuovo tentativo in corso.</translation>
    </message>
    <message>
        <location line="-246"/>
        <source>%1 cannot force bits: its protocol has no force command. Set the bit instead (the program may overwrite it).</source>
        <translation>%1 non può forzare i bit: il suo protocollo non ha un comando di forzatura. Impostare invece il bit (il programma può sovrascriverlo).</translation>
    </message>
    <message>
        <location line="+305"/>
        <source>Cannot connect to %1: %2</source>
        <translation>Impossibile connettersi a %1: %2</translation>
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
        <translation>modo sconosciuto</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>cannot force over %1: the protocol has no force command; write the bit instead (the program may overwrite it)</source>
        <translation>impossibile forzare con %1: il protocollo non ha un comando di forzatura; scrivere invece il bit (il programma può sovrascriverlo)</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>%1 has no command to change RUN / STOP</source>
        <translation>%1 non ha un comando per cambiare RUN / STOP</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>%1 does not speak %2</source>
        <translation>%1 non supporta %2</translation>
    </message>
    <message>
        <location filename="../comms/driver/vigor_driver.cpp" line="+19"/>
        <source>%1 station %2 on %3</source>
        <translation>%1 stazione %2 su %3</translation>
    </message>
    <message>
        <location filename="../comms/driver/driver.cpp" line="+83"/>
        <source>%1 does not fit %2 (0..9999)</source>
        <translation>%1 non rientra in %2 (0..9999)</translation>
    </message>
    <message>
        <location filename="../comms/driver/driver_commands.cpp" line="-153"/>
        <source>%1: %2 holds four BCD digits (#0000..#9999); %3h is not one</source>
        <translation>%1: %2 contiene quattro cifre BCD (#0000..#9999); %3h non lo è</translation>
    </message>
</context>
<context>
    <name>rung::comms::Protocol</name>
    <message>
        <location filename="../comms/protocol/host_link.cpp" line="+99"/>
        <source>normal completion (end code %1)</source>
        <translation>completamento normale (codice di fine %1)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>not executable in RUN mode (end code %1): switch the PLC to MONITOR to write</source>
        <translation>non eseguibile in modo RUN (codice di fine %1): per scrivere portare il PLC in MONITOR</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>not executable in MONITOR mode (end code %1)</source>
        <translation>non eseguibile in modo MONITOR (codice di fine %1)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the PLC&apos;s memory is write-protected (end code %1)</source>
        <translation>la memoria del PLC è protetta da scrittura (codice di fine %1)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>address over: the area ends before the last word asked for (end code %1)</source>
        <translation>indirizzo oltre il limite: l&apos;area finisce prima dell&apos;ultima parola richiesta (codice di fine %1)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>not executable in PROGRAM mode (end code %1)</source>
        <translation>non eseguibile in modo PROGRAM (codice di fine %1)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the PLC received the command with a wrong FCS (end code %1): noise on the line or a wrong parity setting</source>
        <translation>il PLC ha ricevuto il comando con FCS errato (codice di fine %1): disturbi sulla linea o parità impostata male</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the PLC found the command&apos;s format wrong (end code %1)</source>
        <translation>il PLC ha trovato errato il formato del comando (codice di fine %1)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>a number in the command is out of range (end code %1)</source>
        <translation>un numero nel comando è fuori campo (codice di fine %1)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the PLC does not support the command (end code %1)</source>
        <translation>il PLC non supporta il comando (codice di fine %1)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the command&apos;s frame is too long (end code %1)</source>
        <translation>il frame del comando è troppo lungo (codice di fine %1)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>end code %1</source>
        <translation>codice di fine %1</translation>
    </message>
    <message>
        <location filename="../comms/protocol/host_link_master.cpp" line="+91"/>
        <source>Host Link: the reply starts with byte %1 instead of &quot;@&quot;: not a Host Link answer</source>
        <translation>Host Link: la risposta inizia con il byte %1 invece di &quot;@&quot;: non è una risposta Host Link</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Host Link: %1 characters without the end of a frame (CR)</source>
        <translation>Host Link: %1 caratteri senza fine del frame (CR)</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Host Link: a frame too short to hold an FCS: %1</source>
        <translation>Host Link: frame troppo corto per contenere un FCS: %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Host Link: wrong FCS in the reply (received %1, computed %2): noise on the line or a wrong parity setting</source>
        <translation>Host Link: FCS errato nella risposta (ricevuto %1, calcolato %2): disturbi sulla linea o parità impostata male</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Host Link: the reply has no unit number and header: %1</source>
        <translation>Host Link: la risposta non ha numero di unità e intestazione: %1</translation>
    </message>
    <message>
        <location line="+10"/>
        <location line="+65"/>
        <source>Host Link: unit %1 answered, unit %2 was asked</source>
        <translation>Host Link: ha risposto l&apos;unità %1, era interrogata l&apos;unità %2</translation>
    </message>
    <message>
        <location line="-59"/>
        <source>Host Link: the PLC did not recognise the command %1 (IC)</source>
        <translation>Host Link: il PLC non ha riconosciuto il comando %1 (IC)</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Host Link: the reply has no end code: %1</source>
        <translation>Host Link: la risposta non ha codice di fine: %1</translation>
    </message>
    <message>
        <location line="+51"/>
        <source>Host Link: the reply is for %1, the command was %2</source>
        <translation>Host Link: la risposta è per %1, il comando era %2</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Host Link: TEST returned &quot;%1&quot;, not the &quot;%2&quot; that was sent</source>
        <translation>Host Link: TEST ha restituito &quot;%1&quot;, non i caratteri &quot;%2&quot; inviati</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Host Link: %1 refused: %2</source>
        <translation>Host Link: %1 rifiutato: %2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Host Link: the reply to %1 holds %2 characters of data that do not fit the command</source>
        <translation>Host Link: la risposta a %1 contiene %2 caratteri di dati che non corrispondono al comando</translation>
    </message>
    <message>
        <location line="+47"/>
        <source>Host Link: no reply from unit %1 within %2 ms</source>
        <translation>Host Link: nessuna risposta dall&apos;unità %1 entro %2 ms</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Host Link: the reply stopped after %1 parts and %2 characters (%3) within %4 ms</source>
        <translation>Host Link: la risposta si è interrotta dopo %1 parti e %2 caratteri (%3) entro %4 ms</translation>
    </message>
    <message>
        <location filename="../comms/protocol/modbus.cpp" line="+50"/>
        <source>Modbus ASCII: a frame of %1 characters: %2</source>
        <translation>Modbus ASCII: un frame di %1 caratteri: %2</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Modbus ASCII: &quot;%1&quot; is no hex digit pair</source>
        <translation>Modbus ASCII: &quot;%1&quot; non è una coppia di cifre esadecimali</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Modbus ASCII: wrong LRC (received %1, computed %2): noise on the line or a wrong baud rate or parity</source>
        <translation>Modbus ASCII: LRC errato (ricevuto %1, calcolato %2): disturbi sulla linea o velocità o parità errate</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>illegal function (exception %1h): the device does not support this function code</source>
        <translation>funzione non valida (eccezione %1h): il dispositivo non supporta questo codice funzione</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>illegal data address (exception %1h): the address or the count is outside the device&apos;s map</source>
        <translation>indirizzo dati non valido (eccezione %1h): l&apos;indirizzo o il numero è fuori dalla mappa del dispositivo</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>illegal data value (exception %1h)</source>
        <translation>valore dati non valido (eccezione %1h)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>server device failure (exception %1h); the PL110 manual uses this code for an illegal data value</source>
        <translation>guasto del dispositivo server (eccezione %1h); il manuale del PL110 usa questo codice per un valore dati non valido</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>acknowledge (exception %1h): the device accepted a long task</source>
        <translation>conferma (eccezione %1h): il dispositivo ha accettato un&apos;operazione lunga</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>server device busy (exception %1h)</source>
        <translation>dispositivo server occupato (eccezione %1h)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>memory parity error (exception %1h)</source>
        <translation>errore di parità della memoria (eccezione %1h)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>gateway path unavailable (exception %1h)</source>
        <translation>percorso del gateway non disponibile (eccezione %1h)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>gateway target device failed to respond (exception %1h)</source>
        <translation>il dispositivo dietro il gateway non ha risposto (eccezione %1h)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>unknown exception code %1h</source>
        <translation>codice di eccezione sconosciuto %1h</translation>
    </message>
    <message>
        <location filename="../comms/protocol/modbus_master.cpp" line="+82"/>
        <source>Modbus RTU: the reply starts %1, not an answer to function %2h</source>
        <translation>Modbus RTU: la risposta inizia con %1, non è una risposta alla funzione %2h</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Modbus RTU: %1 bytes more than the %2-byte reply: %3</source>
        <translation>Modbus RTU: %1 byte in più della risposta di %2 byte: %3</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Modbus RTU: wrong CRC in the reply (received %1, computed %2): noise on the line or a wrong baud rate or parity</source>
        <translation>Modbus RTU: CRC errato nella risposta (ricevuto %1, calcolato %2): disturbi sulla linea o velocità o parità impostate male</translation>
    </message>
    <message>
        <location line="+15"/>
        <location filename="../comms/protocol/modbus_slave.cpp" line="+210"/>
        <source>Modbus TCP: not a Modbus header (protocol %1, length %2): %3</source>
        <translation>Modbus TCP: non è un&apos;intestazione Modbus (protocollo %1, lunghezza %2): %3</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Modbus TCP: %1 bytes more than the reply&apos;s length</source>
        <translation>Modbus TCP: %1 byte in più della lunghezza della risposta</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Modbus TCP: the reply is for transaction %1, the request was %2</source>
        <translation>Modbus TCP: la risposta è per la transazione %1, la richiesta era %2</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Modbus ASCII: no CR LF within %1 characters of the colon</source>
        <translation>Modbus ASCII: nessun CR LF entro %1 caratteri dai due punti</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Modbus ASCII: %1 characters after the reply&apos;s CR LF</source>
        <translation>Modbus ASCII: %1 caratteri dopo il CR LF della risposta</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Modbus ASCII: a reply without a function code</source>
        <translation>Modbus ASCII: una risposta senza codice funzione</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Modbus: unit %1 answered, unit %2 was asked</source>
        <translation>Modbus: ha risposto l&apos;unità %1, era interrogata l&apos;unità %2</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Modbus: an exception reply of %1 bytes</source>
        <translation>Modbus: risposta di eccezione di %1 byte</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Modbus: function %1h refused: %2</source>
        <translation>Modbus: funzione %1h rifiutata: %2</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Modbus: the reply is for function %1h, the request was %2h</source>
        <translation>Modbus: la risposta è per la funzione %1h, la richiesta era %2h</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Modbus: the reply to function %1h does not match the request: %2</source>
        <translation>Modbus: la risposta alla funzione %1h non corrisponde alla richiesta: %2</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>Modbus: no reply from unit %1 within %2 ms</source>
        <translation>Modbus: nessuna risposta dall&apos;unità %1 entro %2 ms</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Modbus: the reply stopped after %1 bytes (%2) within %3 ms</source>
        <translation>Modbus: la risposta si è interrotta dopo %1 byte (%2) entro %3 ms</translation>
    </message>
    <message>
        <location filename="../comms/protocol/vigor_link.cpp" line="+32"/>
        <source>no error (error 00h)</source>
        <translation>nessun errore (errore 00h)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the PLC could not read the request&apos;s characters as hexadecimal (ASCII conversion error %1h)</source>
        <translation>il PLC non ha potuto leggere i caratteri della richiesta come esadecimali (errore di conversione ASCII %1h)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the PLC received the request with a wrong sum (sum check error %1h): noise on the line or a wrong parity setting</source>
        <translation>il PLC ha ricevuto la richiesta con somma errata (errore di controllo somma %1h): disturbi sulla linea o parità impostata male</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the PLC does not know the command (error %1h)</source>
        <translation>il PLC non conosce il comando (errore %1h)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>communication error (error %1h): the PLC may be in STOP or the parity does not match</source>
        <translation>errore di comunicazione (errore %1h): il PLC potrebbe essere in STOP o la parità non corrisponde</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>address out of range (error %1h)</source>
        <translation>indirizzo fuori campo (errore %1h)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>unknown error code %1h</source>
        <translation>codice di errore sconosciuto %1h</translation>
    </message>
    <message>
        <location filename="../comms/protocol/vigor_link_master.cpp" line="+43"/>
        <source>Vigor link: the reply starts with byte %1 instead of ACK (06h): not a Computer Link answer</source>
        <translation>Vigor link: la risposta inizia con il byte %1 invece di ACK (06h): non è una risposta Computer Link</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Vigor link: %1 bytes without the end of a frame (ETX)</source>
        <translation>Vigor link: %1 byte senza fine del frame (ETX)</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Vigor link: wrong sum in the reply (received %1, computed %2): noise on the line or a wrong parity setting</source>
        <translation>Vigor link: somma errata nella risposta (ricevuta %1, calcolata %2): disturbi sulla linea o parità impostata male</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Vigor link: a reply of %1 bytes is too short or has an odd number of hex digits: %2</source>
        <translation>Vigor link: una risposta di %1 byte è troppo corta o ha un numero dispari di cifre esadecimali: %2</translation>
    </message>
    <message>
        <location line="+10"/>
        <location line="+9"/>
        <source>Vigor link: the reply holds characters that are not upper-case hexadecimal: %1</source>
        <translation>Vigor link: la risposta contiene caratteri che non sono esadecimali maiuscoli: %1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Vigor link: station %1 answered, station %2 was asked</source>
        <translation>Vigor link: ha risposto la stazione %1, era interrogata la stazione %2</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Vigor link: the reply is for command %1h, the request was %2h</source>
        <translation>Vigor link: la risposta è per il comando %1h, la richiesta era %2h</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Vigor link: %1</source>
        <translation>Vigor link: %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Vigor link: the reply carries %1 data bytes, %2 expected</source>
        <translation>Vigor link: la risposta porta %1 byte di dati, ne erano attesi %2</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Vigor link: no reply from station %1 within %2 ms</source>
        <translation>Vigor link: nessuna risposta dalla stazione %1 entro %2 ms</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Vigor link: the reply stopped after %1 bytes (%2) within %3 ms</source>
        <translation>Vigor link: la risposta si è interrotta dopo %1 byte (%2) entro %3 ms</translation>
    </message>
    <message>
        <location filename="../comms/transport/pty_transport.cpp" line="+39"/>
        <source>Cannot create a pseudo-terminal: %1</source>
        <translation>Impossibile creare uno pseudo-terminale: %1</translation>
    </message>
    <message>
        <location line="+45"/>
        <location line="+7"/>
        <location filename="../comms/transport/serial_transport.cpp" line="+85"/>
        <location line="+8"/>
        <location line="+12"/>
        <source>Cannot open %1: %2</source>
        <translation>Impossibile aprire %1: %2</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Cannot open %1: it is not a terminal</source>
        <translation>Impossibile aprire %1: non è un terminale</translation>
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
        <translation>%1 non è aperto</translation>
    </message>
    <message>
        <location line="-22"/>
        <location filename="../comms/transport/serial_transport.cpp" line="-13"/>
        <location filename="../comms/transport/tcp_transport.cpp" line="-24"/>
        <source>Writing to %1 failed: %2</source>
        <translation>Scrittura su %1 non riuscita: %2</translation>
    </message>
    <message>
        <location line="+6"/>
        <location filename="../comms/transport/serial_transport.cpp" line="+2"/>
        <location filename="../comms/transport/tcp_transport.cpp" line="+8"/>
        <source>Writing to %1 did not finish in time</source>
        <translation>La scrittura su %1 non è terminata in tempo</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>%1 was closed by the other side: %2</source>
        <translation>%1 è stato chiuso dall&apos;altro lato: %2</translation>
    </message>
    <message>
        <location line="+14"/>
        <location filename="../comms/transport/tcp_transport.cpp" line="+22"/>
        <source>%1 was closed by the other side</source>
        <translation>%1 è stato chiuso dall&apos;altro lato</translation>
    </message>
    <message>
        <location filename="../comms/transport/serial_transport.cpp" line="-138"/>
        <source>permission denied: add your user to the group that owns %1 (usually &quot;dialout&quot;: sudo usermod -aG dialout $USER, then log in again)</source>
        <translation>permesso negato: aggiungere l&apos;utente al gruppo proprietario di %1 (di solito &quot;dialout&quot;: sudo usermod -aG dialout $USER, poi accedere di nuovo)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the port is busy: another program has it open</source>
        <translation>la porta è occupata: un altro programma la tiene aperta</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>no such port (unplugged?)</source>
        <translation>porta inesistente (scollegata?)</translation>
    </message>
    <message>
        <location line="+93"/>
        <source>%1 does not accept the line settings: %2</source>
        <translation>%1 non accetta le impostazioni di linea: %2</translation>
    </message>
    <message>
        <location line="+54"/>
        <source>%1 failed while reading (unplugged?): %2</source>
        <translation>%1 ha dato errore durante la lettura (scollegata?): %2</translation>
    </message>
    <message>
        <location line="+11"/>
        <location line="+11"/>
        <source>%1 is gone (unplugged?)</source>
        <translation>%1 non c&apos;è più (scollegata?)</translation>
    </message>
    <message>
        <location filename="../comms/transport/tcp_transport.cpp" line="-83"/>
        <source>Cannot take the TCP connection: %1</source>
        <translation>Impossibile prendere in carico la connessione TCP: %1</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Cannot connect to %1: %2</source>
        <translation>Impossibile connettersi a %1: %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Cannot connect to %1 within %2 ms</source>
        <translation>Impossibile connettersi a %1 entro %2 ms</translation>
    </message>
    <message>
        <location line="+87"/>
        <source>Cannot listen on %1:%2: %3</source>
        <translation>Impossibile restare in ascolto su %1:%2: %3</translation>
    </message>
    <message>
        <location filename="../comms/protocol/host_link_master.cpp" line="-111"/>
        <source>Host Link: the reply to %1 goes on past the %2 characters of data the command asks for (part %3): not the answer to this command</source>
        <translation>Host Link: la risposta a %1 va oltre i %2 caratteri di dati chiesti dal comando (parte %3): non è la risposta a questo comando</translation>
    </message>
    <message>
        <location filename="../comms/protocol/host_link_slave.cpp" line="+45"/>
        <source>Host Link: %1 characters arrived before the command was answered; the %2 beyond the first %3 were dropped</source>
        <translation>Host Link: sono arrivati %1 caratteri prima della risposta al comando; i %2 oltre i primi %3 sono stati scartati</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Host Link: a new command began where part %1 of the %2 command was due; the unfinished command was dropped</source>
        <translation>Host Link: è iniziato un nuovo comando al posto della parte %1 del comando %2; il comando incompleto è stato scartato</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Host Link: %1 characters without a CR (a part holds at most %2): dropped, waiting for the next &quot;@&quot;</source>
        <translation>Host Link: %1 caratteri senza CR (una parte ne contiene al massimo %2): scartati, in attesa del prossimo &quot;@&quot;</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>Host Link: the %1 command goes on past %2 characters in %3 parts, longer than any command; answered with end code 18</source>
        <translation>Host Link: il comando %1 va oltre %2 caratteri in %3 parti, più lungo di qualsiasi comando; risposto con codice di fine 18</translation>
    </message>
    <message>
        <location filename="../comms/protocol/modbus_slave.cpp" line="-63"/>
        <source>Modbus: %1 bytes arrived before the request was answered; the %2 beyond the first %3 were dropped</source>
        <translation>Modbus: sono arrivati %1 byte prima della risposta alla richiesta; i %2 oltre i primi %3 sono stati scartati</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>Modbus ASCII: no CR LF within %1 characters of the colon: dropped</source>
        <translation>Modbus ASCII: nessun CR LF entro %1 caratteri dai due punti: scartato</translation>
    </message>
    <message>
        <location line="+72"/>
        <source>Modbus RTU: a frame of function %1h runs past %2 bytes, the longest an RTU frame can be: dropped with what follows until the line is quiet</source>
        <translation>Modbus RTU: un frame della funzione %1h supera %2 byte, la lunghezza massima di un frame RTU: scartato con ciò che segue finché la linea tace</translation>
    </message>
    <message>
        <location filename="../comms/protocol/vigor_link_slave.cpp" line="+53"/>
        <source>Vigor link: %1 bytes arrived before the request was answered; the %2 beyond the first %3 were dropped</source>
        <translation>Vigor link: sono arrivati %1 byte prima della risposta alla richiesta; i %2 oltre i primi %3 sono stati scartati</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>Vigor link: %1 bytes from STX without ETX (a request holds at most %2): dropped up to the next STX</source>
        <translation>Vigor link: %1 byte da STX senza ETX (una richiesta ne contiene al massimo %2): scartati fino al prossimo STX</translation>
    </message>
    <message>
        <location filename="../comms/transport/fd_waiter.cpp" line="+15"/>
        <source>no wake-up pipe for cancelling a read: %1</source>
        <translation>nessuna pipe di risveglio per annullare una lettura: %1</translation>
    </message>
    <message>
        <location filename="../comms/transport/pty_transport.cpp" line="-100"/>
        <source>Cannot open %1 again: the pseudo-terminal this program made ended when it was closed; make a new one and give its path to the peer</source>
        <translation>Impossibile aprire di nuovo %1: lo pseudo-terminale creato da questo programma è terminato alla chiusura; crearne uno nuovo e darne il percorso all&apos;altra parte</translation>
    </message>
    <message>
        <location filename="../comms/slave/memory_image.cpp" line="+86"/>
        <source>%1 cannot be written in this PLC&apos;s memory</source>
        <translation>%1 non si può scrivere nella memoria di questo PLC</translation>
    </message>
    <message>
        <location filename="../comms/slave/slave_server.cpp" line="+87"/>
        <location line="+29"/>
        <source>%1 does not speak this protocol</source>
        <translation>%1 non parla questo protocollo</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The slave listens already</source>
        <translation>Lo slave è già in ascolto</translation>
    </message>
    <message>
        <location line="+88"/>
        <source>The slave has been stopped</source>
        <translation>Lo slave è stato arrestato</translation>
    </message>
    <message>
        <location line="+124"/>
        <source>A TCP client was refused: %1 clients are served already</source>
        <translation>Un client TCP è stato rifiutato: sono già serviti %1 client</translation>
    </message>
</context>
<context>
    <name>rung::comms::Relay</name>
    <message>
        <location filename="../comms/driver/relay.cpp" line="+32"/>
        <location line="+14"/>
        <location line="+5"/>
        <source>the PC&apos;s side</source>
        <translation>il lato PC</translation>
    </message>
    <message>
        <location line="-18"/>
        <location line="+14"/>
        <location line="+3"/>
        <source>the PLC&apos;s side</source>
        <translation>il lato PLC</translation>
    </message>
    <message>
        <location line="-13"/>
        <source>%1 (%2) cannot be opened: %3</source>
        <translation>impossibile aprire %1 (%2): %3</translation>
    </message>
    <message>
        <location line="+61"/>
        <source>%1 (%2) stopped taking bytes: %3</source>
        <translation>%1 (%2) non accetta più byte: %3</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 (%2) failed: %3</source>
        <translation>%1 (%2) non funziona più: %3</translation>
    </message>
</context>
<context>
    <name>rung::editor::CompareView</name>
    <message>
        <location filename="../editor/compare_view.cpp" line="+49"/>
        <source>the same</source>
        <translation>uguale</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>moved</source>
        <translation>spostato</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>changed</source>
        <translation>modificato</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>moved and changed</source>
        <translation>spostato e modificato</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>inserted</source>
        <translation>inserito</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>deleted</source>
        <translation>eliminato</translation>
    </message>
    <message>
        <location line="+161"/>
        <source>Both programs are empty.</source>
        <translation>Entrambi i programmi sono vuoti.</translation>
    </message>
    <message>
        <location line="+47"/>
        <source>A: rung %1</source>
        <translation>A: segmento %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>B: rung %1</source>
        <translation>B: segmento %1</translation>
    </message>
    <message>
        <location line="+46"/>
        <source>(not in A)</source>
        <translation>(non in A)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>(not in B)</source>
        <translation>(non in B)</translation>
    </message>
</context>
<context>
    <name>rung::editor::CrossReferenceModel</name>
    <message>
        <location filename="../editor/cross_reference_model.cpp" line="+120"/>
        <source>contact</source>
        <translation>contatto</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>coil</source>
        <translation>bobina</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>box</source>
        <translation>blocco funzione</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>rung %1</source>
        <translation>segmento %1</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>The first %1 uses; type a device or a prefix for the rest</source>
        <translation>Primi %1 utilizzi; digitare un operando o un prefisso per vedere gli altri</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>Device</source>
        <translation>Operando</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Step</source>
        <translation>Passo</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Use</source>
        <translation>Uso</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Instruction</source>
        <translation>Istruzione</translation>
    </message>
</context>
<context>
    <name>rung::editor::CrossReferenceView</name>
    <message>
        <location filename="../editor/cross_reference_view.cpp" line="+36"/>
        <source>Device or prefix (%1, %2)</source>
        <translation>Operando o prefisso (%1, %2)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Device or prefix (%1, %2); empty: every device</source>
        <translation>Operando o prefisso (%1, %2); vuoto: tutti gli operandi</translation>
    </message>
</context>
<context>
    <name>rung::editor::Document</name>
    <message>
        <location filename="../editor/commands/document_commands.cpp" line="+26"/>
        <source>Edit symbols</source>
        <translation>Modifica simboli</translation>
    </message>
    <message>
        <location filename="../editor/document.cpp" line="+77"/>
        <source>Untitled</source>
        <translation>Senza titolo</translation>
    </message>
    <message>
        <location line="+73"/>
        <source>Insert rung</source>
        <translation>Inserisci segmento</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Delete rung</source>
        <translation>Elimina segmento</translation>
    </message>
    <message numerus="yes">
        <location line="+0"/>
        <source>Delete %n rungs</source>
        <translation>
            <numerusform>Elimina %n segmento</numerusform>
            <numerusform>Elimina %n segmenti</numerusform>
        </translation>
    </message>
    <message>
        <location line="+46"/>
        <source>Edit instruction list</source>
        <translation>Modifica lista istruzioni</translation>
    </message>
    <message>
        <location line="+50"/>
        <source>Rung %1: %2 (row %3, column %4) is on no path to an output, so the list leaves it out; the ladder keeps it while this line stays.</source>
        <translation>Segmento %1: %2 (riga %3, colonna %4) non è su alcun percorso verso un&apos;uscita, quindi la lista lo omette; il ladder lo conserva finché resta questa riga.</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>it has nothing to list yet</source>
        <translation>non contiene ancora nulla da elencare</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Rung %1 is not in the list: %2. Edit it in the ladder; this line keeps its place.</source>
        <translation>Il segmento %1 non è nella lista: %2. Modificalo nel ladder; questa riga ne tiene il posto.</translation>
    </message>
</context>
<context>
    <name>rung::editor::FrontPanel</name>
    <message>
        <location filename="../editor/front_panel.cpp" line="+376"/>
        <source>%1: %2 (key %3; held down, %4 is 1)</source>
        <translation>%1: %2 (tasto %3; tenuto premuto, %4 vale 1)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: %2 (writes %3)</source>
        <translation>%1: %2 (scrive %3)</translation>
    </message>
    <message>
        <location line="+51"/>
        <source>This PLC has no front panel that its manual describes</source>
        <translation>Il manuale di questo PLC non descrive un pannello frontale</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Run the simulation (F10) to see the PLC&apos;s front panel</source>
        <translation>Avviare la simulazione (F10) per vedere il pannello frontale del PLC</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>Display mode %1 (%2)</source>
        <translation>Modo di visualizzazione %1 (%2)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Page %1 (%2)</source>
        <translation>Pagina %1 (%2)</translation>
    </message>
</context>
<context>
    <name>rung::editor::IlEditor</name>
    <message>
        <location filename="../editor/il_editor.cpp" line="+104"/>
        <location line="+386"/>
        <source>Instruction list</source>
        <translation>Lista istruzioni</translation>
    </message>
</context>
<context>
    <name>rung::editor::IlLexer</name>
    <message>
        <location filename="../editor/il_lexer.cpp" line="+22"/>
        <source>Default</source>
        <translation>Predefinito</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Instruction</source>
        <translation>Istruzione</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Device</source>
        <translation>Operando</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Constant</source>
        <translation>Costante</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Comment</source>
        <translation>Commento</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Step number</source>
        <translation>Numero di passo</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Unknown word</source>
        <translation>Parola sconosciuta</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Rung not in the list</source>
        <translation>Segmento non presente nella lista</translation>
    </message>
</context>
<context>
    <name>rung::editor::IoPanel</name>
    <message>
        <location filename="../editor/io_panel.cpp" line="+83"/>
        <source>Inputs are switches</source>
        <translation>Ingressi come interruttori</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Inputs are push buttons</source>
        <translation>Ingressi come pulsanti</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A switch stays where it is put; a push button is ON only while held (mouse, or Space on the focused button). The right button sets one input on its own</source>
        <translation>Un interruttore resta dove lo si mette; un pulsante è ON solo finché è premuto (mouse, o Spazio sul pulsante selezionato). Il tasto destro imposta un solo ingresso</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+229"/>
        <source>Inputs take effect at the next scan</source>
        <translation>Gli ingressi valgono dalla scansione successiva</translation>
    </message>
    <message>
        <location line="-228"/>
        <location line="+229"/>
        <source>Run the simulation (F10) to work the inputs</source>
        <translation>Avviare la simulazione (F10) per agire sugli ingressi</translation>
    </message>
    <message>
        <location line="-146"/>
        <source>Further inputs the program uses</source>
        <translation>Altri ingressi usati dal programma</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Further outputs the program uses</source>
        <translation>Altre uscite usate dal programma</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Inputs</source>
        <translation>Ingressi</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Outputs</source>
        <translation>Uscite</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Analog inputs</source>
        <translation>Ingressi analogici</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Analog outputs</source>
        <translation>Uscite analogiche</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>This model has no terminals to show</source>
        <translation>Questo modello non ha morsetti da mostrare</translation>
    </message>
    <message>
        <location line="+51"/>
        <source>Switch</source>
        <translation>Interruttore</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Push Button</source>
        <translation>Pulsante</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Force ON</source>
        <translation>Forza ON</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Force OFF</source>
        <translation>Forza OFF</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Release</source>
        <translation>Rilascia</translation>
    </message>
</context>
<context>
    <name>rung::editor::LadderView</name>
    <message>
        <location filename="../editor/ladder_view.cpp" line="+41"/>
        <location line="+503"/>
        <source>Ladder diagram</source>
        <translation>Schema ladder</translation>
    </message>
    <message>
        <location line="-407"/>
        <source>Edit rung comment</source>
        <translation>Modifica commento del segmento</translation>
    </message>
    <message>
        <location line="+215"/>
        <source>Type one instruction, for example &quot;%1 %2&quot;</source>
        <translation>Digitare una sola istruzione, ad esempio &quot;%1 %2&quot;</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>%1 is drawn with vertical links, not typed into a cell</source>
        <translation>%1 si disegna con i collegamenti verticali, non si digita in una cella</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Contacts go in the grid; the right-hand column holds coils and boxes</source>
        <translation>I contatti vanno nella griglia; la colonna di destra contiene bobine e blocchi funzione</translation>
    </message>
    <message>
        <location line="+24"/>
        <location line="+13"/>
        <source>Place %1</source>
        <translation>Posiziona %1</translation>
    </message>
    <message>
        <location line="+22"/>
        <location filename="../editor/ladder_view_mouse.cpp" line="+157"/>
        <source>Draw a wire</source>
        <translation>Disegna collegamento orizzontale</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Toggle a vertical link</source>
        <translation>Attiva/disattiva un collegamento verticale</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Delete</source>
        <translation>Elimina</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Insert a cell</source>
        <translation>Inserisci una cella</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Insert a row</source>
        <translation>Inserisci una riga</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Delete a row</source>
        <translation>Elimina una riga</translation>
    </message>
    <message>
        <location filename="../editor/ladder_view_mouse.cpp" line="+12"/>
        <source>Draw a vertical link</source>
        <translation>Traccia un collegamento verticale</translation>
    </message>
    <message>
        <location filename="../editor/ladder_view_keys.cpp" line="+154"/>
        <source>%1 has no such contact</source>
        <translation>%1 non ha un contatto di questo tipo</translation>
    </message>
    <message>
        <location line="+78"/>
        <source>There is no wire under the cursor</source>
        <translation>Non c&apos;è un collegamento orizzontale sotto il cursore</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Delete a wire</source>
        <translation>Elimina un collegamento orizzontale</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>There is no vertical link at the cursor</source>
        <translation>Non c&apos;è un collegamento verticale al cursore</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Delete a vertical link</source>
        <translation>Elimina un collegamento verticale</translation>
    </message>
    <message>
        <location filename="../editor/ladder_view_selection.cpp" line="+85"/>
        <source>Delete cells</source>
        <translation>Elimina celle</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Paste cells</source>
        <translation>Incolla celle</translation>
    </message>
    <message>
        <location filename="../editor/ladder_view_find.cpp" line="+45"/>
        <source>%1 is not used in the program</source>
        <translation>%1 non è usato nel programma</translation>
    </message>
    <message>
        <location filename="../editor/ladder_view_monitor.cpp" line="+241"/>
        <source>current %1, set %2, %3</source>
        <extracomment>a timer&apos;s or counter&apos;s live state in a tooltip: current value, set value, done bit</extracomment>
        <translation>corrente %1, preset %2, %3</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>ON</source>
        <translation>ON</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>OFF</source>
        <translation>OFF</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1 (forced)</source>
        <translation>%1 (forzato)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The last values known: the source is offline</source>
        <translation>Gli ultimi valori noti: la sorgente è offline</translation>
    </message>
</context>
<context>
    <name>rung::editor::MonitorCommands</name>
    <message>
        <location filename="../editor/monitor_commands.cpp" line="+131"/>
        <source>Force %1 O&amp;N</source>
        <translation>Forza %1 O&amp;N</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Force %1 O&amp;FF</source>
        <translation>Forza %1 O&amp;FF</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Release %1</source>
        <translation>&amp;Rilascia %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Set %1 &amp;ON</source>
        <translation>Imposta %1 &amp;ON</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Set %1 OFF</source>
        <translation>Imposta %1 OFF</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&amp;Write %1...</source>
        <translation>&amp;Scrivi %1...</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Write &amp;Preset of %1...</source>
        <translation>Scrivi il valore di &amp;preset di %1...</translation>
    </message>
    <message>
        <location line="+7"/>
        <location line="+99"/>
        <source>The preset of %1 is the constant %2 of the program: change it in the program</source>
        <translation>Il valore di preset di %1 è la costante %2 del programma: modificarlo nel programma</translation>
    </message>
    <message>
        <location line="-86"/>
        <source>%1 forced ON</source>
        <translation>%1 forzato ON</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1 forced OFF</source>
        <translation>%1 forzato OFF</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 released</source>
        <translation>%1 rilasciato</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1 set ON</source>
        <translation>%1 impostato ON</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1 set OFF</source>
        <translation>%1 impostato OFF</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>Write %1</source>
        <translation>Scrivi %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>New value of %1 (a whole number, 0x before a hexadecimal one):</source>
        <translation>Nuovo valore di %1 (un numero intero, 0x davanti a uno esadecimale):</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>&quot;%1&quot; is no value for %2: type a whole number (0x before a hexadecimal one)</source>
        <translation>&quot;%1&quot; non è un valore per %2: scrivere un numero intero (0x davanti a uno esadecimale)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 written: %2</source>
        <translation>%1 scritto: %2</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Write Preset of %1</source>
        <translation>Scrivi il valore di preset di %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>New preset of %1:</source>
        <translation>Nuovo valore di preset di %1:</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>&quot;%1&quot; is no preset for %2: type a whole number from 0</source>
        <translation>&quot;%1&quot; non è un valore di preset per %2: scrivere un numero intero da 0</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Preset of %1 written: %2</source>
        <translation>Valore di preset di %1 scritto: %2</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>&quot;%1&quot; is no preset for %2: the preset is 0..9999 (BCD)</source>
        <translation>&quot;%1&quot; non è un valore di preset per %2: il valore di preset è 0..9999 (BCD)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Preset of %1 written: %2 (in %3)</source>
        <translation>Valore di preset di %1 scritto: %2 (in %3)</translation>
    </message>
</context>
<context>
    <name>rung::editor::ProblemsView</name>
    <message>
        <location filename="../editor/problems_view.cpp" line="+52"/>
        <source>Severity</source>
        <translation>Gravità</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Code</source>
        <translation>Codice</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Place</source>
        <translation>Posizione</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Message</source>
        <translation>Messaggio</translation>
    </message>
    <message>
        <location line="+68"/>
        <location line="+47"/>
        <source>Problems</source>
        <translation>Problemi</translation>
    </message>
    <message>
        <location line="-97"/>
        <source>Error</source>
        <translation>Errore</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+68"/>
        <source>Warning</source>
        <translation>Avviso</translation>
    </message>
    <message>
        <location line="-67"/>
        <source>Note</source>
        <translation>Nota</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>line %1</source>
        <translation>riga %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+53"/>
        <source>rung %1, row %2</source>
        <translation>segmento %1, riga %2</translation>
    </message>
    <message>
        <location line="-52"/>
        <source>rung %1</source>
        <translation>segmento %1</translation>
    </message>
    <message>
        <location line="-11"/>
        <source>%1 (fix available)</source>
        <translation>%1 (correzione disponibile)</translation>
    </message>
    <message>
        <location line="+86"/>
        <source>1 error</source>
        <translation>1 errore</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1 errors</source>
        <translation>%1 errori</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>1 warning</source>
        <translation>1 avviso</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1 warnings</source>
        <translation>%1 avvisi</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Problems (%1)</source>
        <translation>Problemi (%1)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>, </source>
        <translation>, </translation>
    </message>
    <message>
        <location line="+10"/>
        <source>No problems found</source>
        <translation>Nessun problema trovato</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Show</source>
        <translation>Mostra</translation>
    </message>
</context>
<context>
    <name>rung::editor::SymbolTableModel</name>
    <message>
        <location filename="../editor/symbol_table_model.cpp" line="+34"/>
        <source>No device yet: the row becomes a symbol when it names one</source>
        <translation>Nessun operando: la riga diventa un simbolo quando ne indica uno</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>No symbol yet: edit the row to make it one</source>
        <translation>Non ancora un simbolo: modificare la riga per renderla tale</translation>
    </message>
    <message>
        <location line="+122"/>
        <source>Device</source>
        <translation>Operando</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Name</source>
        <translation>Nome</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Comment</source>
        <translation>Commento</translation>
    </message>
</context>
<context>
    <name>rung::editor::TimingChart</name>
    <message>
        <location filename="../editor/timing_chart.cpp" line="+181"/>
        <source>Devices and ranges to draw, with commas; they can also be dragged here from the ladder or the watch table</source>
        <translation>Operandi e intervalli da tracciare, separati da virgole; si possono anche trascinare qui dal ladder o dalla tabella di osservazione</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Zoom in (+, Ctrl+wheel)</source>
        <translation>Ingrandisci (+, Ctrl+rotellina)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Zoom out (-, Ctrl+wheel)</source>
        <translation>Riduci (-, Ctrl+rotellina)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Whole History</source>
        <translation>Tutta la cronologia</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Show everything recorded</source>
        <translation>Mostra tutto ciò che è registrato</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Follow</source>
        <translation>Segui</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Keep the newest scan at the right edge</source>
        <translation>L&apos;ultima scansione resta sul bordo destro</translation>
    </message>
    <message>
        <location line="-15"/>
        <source>Add: %1, %2, then Enter</source>
        <translation>Aggiungi: %1, %2, poi Invio</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Type devices above (%1, %2) or drag them here from the ladder or the watch table</source>
        <translation>Digitare sopra gli operandi (%1, %2) o trascinarli qui dal ladder o dalla tabella di osservazione</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Trigger: %1 rises, %2 &gt; 100</source>
        <translation>Trigger: %1 rises, %2 &gt; 100</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A condition checked after every scan: DEVICE rises, DEVICE falls, or DEVICE = &lt;&gt; &lt; &lt;= &gt; &gt;= VALUE</source>
        <translation>Una condizione verificata dopo ogni scansione: OPERANDO rises (fronte di salita), OPERANDO falls (fronte di discesa), oppure OPERANDO = &lt;&gt; &lt; &lt;= &gt; &gt;= VALORE</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Stop the simulation</source>
        <translation>Ferma la simulazione</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Only mark</source>
        <translation>Solo segna</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Arm</source>
        <translation>Arma</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Watch for the trigger (Enter in its field does the same)</source>
        <translation>Attende il trigger (Invio nel suo campo fa lo stesso)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Export</source>
        <translation>Esporta</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save the chart as CSV (every change), PNG or SVG</source>
        <translation>Salva il diagramma come CSV (ogni cambiamento), PNG o SVG</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Click: cursor A; Shift+click or right click: cursor B; wheel: scroll; Ctrl+wheel: zoom; right click on a name: its format</source>
        <translation>Clic: cursore A; Maiusc+clic o clic destro: cursore B; rotellina: scorrimento; Ctrl+rotellina: zoom; clic destro su un nome: il suo formato</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>The trigger could not be armed on this source</source>
        <translation>Il trigger non può essere armato su questa sorgente</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>This source keeps no history of some devices: the chart cannot draw them</source>
        <translation>Questa sorgente non conserva la cronologia di alcuni operandi: il diagramma non può tracciarli</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Not added to the timing chart: %1</source>
        <translation>Non aggiunto al diagramma temporale: %1</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>The timing chart draws at most %1 devices</source>
        <translation>Il diagramma temporale traccia al massimo %1 operandi</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>Show As</source>
        <translation>Mostra come</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Remove</source>
        <translation>Rimuovi</translation>
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
            <numerusform>B − A: %1 (%n scansione)</numerusform>
            <numerusform>B − A: %1 (%n scansioni)</numerusform>
        </translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Click the chart for cursor A, Shift+click for cursor B</source>
        <translation>Clic sul diagramma per il cursore A, Maiusc+clic per il cursore B</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Trigger not armed: %1</source>
        <translation>Trigger non armato: %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Trigger not armed: this source cannot watch %1</source>
        <translation>Trigger non armato: questa sorgente non può osservare %1</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Armed: stops when %1</source>
        <translation>Armato: si ferma quando %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Armed: marks when %1</source>
        <translation>Armato: segna quando %1</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>%1 at %2 (scan %3)</source>
        <translation>%1 a %2 (scansione %3)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Trigger: %1 at %2 (scan %3); the simulation is paused there</source>
        <translation>Trigger: %1 a %2 (scansione %3); la simulazione è in pausa lì</translation>
    </message>
    <message>
        <location line="+12"/>
        <location line="+8"/>
        <source>Cannot write %1: %2</source>
        <translation>Impossibile scrivere %1: %2</translation>
    </message>
    <message>
        <location line="+15"/>
        <location line="+13"/>
        <location line="+7"/>
        <source>Cannot write %1</source>
        <translation>Impossibile scrivere %1</translation>
    </message>
    <message>
        <location line="-10"/>
        <source>Timing chart</source>
        <translation>Diagramma temporale</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1 is no export format (CSV, PNG, SVG)</source>
        <translation>%1 non è un formato di esportazione (CSV, PNG, SVG)</translation>
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
        <translation>ON</translation>
    </message>
    <message>
        <location line="-239"/>
        <location line="+10"/>
        <location line="+52"/>
        <location line="+7"/>
        <location line="+173"/>
        <source>OFF</source>
        <translation>OFF</translation>
    </message>
    <message>
        <location line="-236"/>
        <source>%1 of %2, %3</source>
        <translation>%1 di %2, %3</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1 (forced)</source>
        <translation>%1 (forzato)</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Watch list %1</source>
        <translation>Lista di osservazione %1</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>not a device</source>
        <translation>non è un operando</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Not forced</source>
        <translation>Non forzato</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Forced %1</source>
        <translation>Forzato %1</translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+32"/>
        <source>Forced</source>
        <translation>Forzato</translation>
    </message>
    <message>
        <location line="-8"/>
        <source>Device</source>
        <translation>Operando</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Symbol</source>
        <translation>Simbolo</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Value</source>
        <translation>Valore</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Format</source>
        <translation>Formato</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Double-click or F2: write a value; a bit flips</source>
        <translation>Doppio clic o F2: scrive un valore; un bit si inverte</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Double-click: show the word in decimal, signed, hexadecimal, binary or BCD</source>
        <translation>Doppio clic: mostra la word in decimale, con segno, esadecimale, binario o BCD</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Double-click: force a bit ON or OFF, or release it</source>
        <translation>Doppio clic: forza un bit ON o OFF, o lo rilascia</translation>
    </message>
    <message>
        <location filename="../editor/watch_list_model_rows.cpp" line="+218"/>
        <source>Not added to the watch list: %1</source>
        <translation>Non aggiunto alla lista di osservazione: %1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Watch 1</source>
        <translation>Osservazione 1</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Add %1 to the watch list</source>
        <translation>Aggiungi %1 alla lista di osservazione</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Remove %1 from the watch list</source>
        <translation>Rimuovi %1 dalla lista di osservazione</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Show %1 as %2</source>
        <translation>Mostra %1 come %2</translation>
    </message>
    <message>
        <location filename="../editor/watch_list_model.cpp" line="+82"/>
        <source>%1 is a timer or counter: its current value follows the program and cannot be written here</source>
        <translation>%1 è un temporizzatore o un contatore: il suo valore corrente segue il programma e qui non si può scrivere</translation>
    </message>
    <message>
        <location line="+47"/>
        <source>&quot;%1&quot; is no value for %2: type ON or OFF (1 or 0)</source>
        <translation>&quot;%1&quot; non è un valore per %2: scrivere ON o OFF (1 o 0)</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>type a whole number (0x before a hexadecimal one)</source>
        <translation>digitare un numero intero (0x prima di uno esadecimale)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>type up to %1 hexadecimal digits</source>
        <translation>digitare al massimo %1 cifre esadecimali</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>type up to %1 binary digits (0 and 1)</source>
        <translation>digitare al massimo %1 cifre binarie (0 e 1)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>type up to %1 decimal digits (BCD)</source>
        <translation>digitare al massimo %1 cifre decimali (BCD)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>a %1-bit word holds %2..%3</source>
        <translation>una word a %1 bit contiene %2..%3</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&quot;%1&quot; is no value for %2: %3</source>
        <translation>&quot;%1&quot; non è un valore per %2: %3</translation>
    </message>
</context>
<context>
    <name>rung::editor::WatchListView</name>
    <message>
        <location filename="../editor/watch_list_view.cpp" line="+49"/>
        <location line="+41"/>
        <source>Watch lists</source>
        <translation>Liste di osservazione</translation>
    </message>
    <message>
        <location line="+71"/>
        <location line="+20"/>
        <source>Set ON</source>
        <translation>Imposta ON</translation>
    </message>
    <message>
        <location line="-20"/>
        <location line="+24"/>
        <source>Set OFF</source>
        <translation>Imposta OFF</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Force ON</source>
        <translation>Forza ON</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Force OFF</source>
        <translation>Forza OFF</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Release</source>
        <translation>Rilascia</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Write Value...</source>
        <translation>Scrivi valore...</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Show As</source>
        <translation>Mostra come</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Remove</source>
        <translation>Rimuovi</translation>
    </message>
</context>
<context>
    <name>rung::editor::WatchPanel</name>
    <message>
        <location filename="../editor/watch_panel.cpp" line="+41"/>
        <source>Add: a device or a range (%1), then Enter</source>
        <translation>Aggiungi: un operando o un intervallo (%1), poi Invio</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Several at once with commas: %1, %2, %3. Devices can also be dragged here from the ladder or the cross reference</source>
        <translation>Più di uno con le virgole: %1, %2, %3. Gli operandi si possono anche trascinare qui dal ladder o dai riferimenti incrociati</translation>
    </message>
</context>
<context>
    <name>rung::model::Address</name>
    <message>
        <location filename="../model/target/address.cpp" line="+137"/>
        <source>A device is missing</source>
        <translation>Manca un operando</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1: a number is expected after %2</source>
        <translation>%1: dopo %2 è atteso un numero</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 is not a device of %2</source>
        <translation>%1 non è un operando di %2</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1: the number is too large</source>
        <translation>%1: il numero è troppo grande</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: %2 is numbered in octal</source>
        <translation>%1: %2 è numerato in ottale</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1: a bit number is expected after the point</source>
        <translation>%1: dopo il punto è atteso un numero di bit</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+16"/>
        <source>%1: bit %2 is beyond 00..15</source>
        <translation>%1: il bit %2 è oltre 00..15</translation>
    </message>
    <message>
        <location line="-10"/>
        <source>%1: unexpected &apos;%2&apos; after the device</source>
        <translation>%1: &apos;%2&apos; inatteso dopo l&apos;operando</translation>
    </message>
    <message>
        <location line="+49"/>
        <source>%1: %2 has no bit numbers</source>
        <translation>%1: %2 non ha numeri di bit</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+28"/>
        <source>%1: %2 has no %3</source>
        <translation>%1: %2 non ha %3</translation>
    </message>
    <message>
        <location line="-11"/>
        <location line="+14"/>
        <source>%1 is beyond %2&apos;s %3 %4</source>
        <translation>%1 è fuori campo (%3 di %2: %4)</translation>
    </message>
    <message>
        <location line="-12"/>
        <source>%1 is beyond %2&apos;s %3</source>
        <translation>%1 è fuori campo (%3 di %2)</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>A constant is missing</source>
        <translation>Manca una costante</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>%1: %2 writes constants without K or H</source>
        <translation>%1: %2 scrive le costanti senza K o H</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>write a constant as K (decimal) or H (hexadecimal)</source>
        <translation>scrivere una costante come K (decimale) o H (esadecimale)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>write a constant with # (e.g. #0150)</source>
        <translation>scrivere una costante con # (ad es. #0150)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>write a constant as a plain number (e.g. 150)</source>
        <translation>scrivere una costante come numero semplice (ad es. 150)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: %2 has no # constants; %3</source>
        <translation>%1: %2 non ha costanti con #; %3</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location line="+128"/>
        <source>%1: both ends of a range must be devices of one kind (D0..D15)</source>
        <translation>%1: entrambi gli estremi di un intervallo devono essere operandi dello stesso tipo (D0..D15)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1: the range runs backwards</source>
        <translation>%1: l&apos;intervallo va all&apos;indietro</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: %2 devices; a range holds at most %3</source>
        <translation>%1: %2 operandi; un intervallo ne contiene al massimo %3</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>%1: the PLC has no %2 inside this range</source>
        <translation>%1: il PLC non ha %2 in questo intervallo</translation>
    </message>
    <message>
        <location line="-152"/>
        <source>%1: digits are expected</source>
        <translation>%1: sono attese delle cifre</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1: &apos;%2&apos; is not a digit</source>
        <translation>%1: &apos;%2&apos; non è una cifra</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1: the constant is too large</source>
        <translation>%1: la costante è troppo grande</translation>
    </message>
</context>
<context>
    <name>rung::model::Checks</name>
    <message>
        <location filename="../model/checks/checks_ladder.cpp" line="+68"/>
        <source>Reverse current: power would cross an element right to left to reach row %1</source>
        <translation>Corrente inversa: la corrente attraverserebbe un elemento da destra a sinistra per raggiungere la riga %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Duplicate the shared contact into each branch</source>
        <translation>Duplica il contatto condiviso in ogni ramo</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Open branch: row %1 is not connected to the left rail</source>
        <translation>Ramo aperto: la riga %1 non è collegata alla barra sinistra</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1 has no condition: it is wired straight to the left rail</source>
        <translation>%1 non ha condizione: è collegato direttamente alla barra sinistra</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>%1 (row %2, column %3) is not on any path from the left rail to an output: the list leaves it out</source>
        <translation>%1 (riga %2, colonna %3) non si trova su alcun percorso dalla barra sinistra a un&apos;uscita: la lista lo omette</translation>
    </message>
    <message>
        <location line="+58"/>
        <location filename="../model/checks/checks_list.cpp" line="+55"/>
        <source>Append %1</source>
        <translation>Aggiungi %1 in fondo</translation>
    </message>
    <message>
        <location filename="../model/checks/checks_blocks_and_stack.cpp" line="+59"/>
        <source>Rewrite the rung in the canonical form</source>
        <translation>Riscrivi il segmento nella forma canonica</translation>
    </message>
    <message>
        <location line="+47"/>
        <source>More than %1 %2 in a row: the PLC rejects the program</source>
        <translation>Più di %1 %2 consecutivi: il PLC rifiuta il programma</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>Stacked %1: combine each block with %1 as soon as it is complete</source>
        <translation>%1 impilati: combinare ogni blocco con %1 appena è completo</translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>Stacked %1: %n blocks are open; an OR chain needs less stack</source>
        <translation>
            <numerusform>%1 impilati: %n blocco è aperto; una catena OR richiede meno stack</numerusform>
            <numerusform>%1 impilati: %n blocchi sono aperti; una catena OR richiede meno stack</numerusform>
        </translation>
    </message>
    <message>
        <location line="+7"/>
        <source>A single contact joined with %1 is simpler as %2</source>
        <translation>Un singolo contatto unito con %1 è più semplice come %2</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>The block after a single contact can be written shorter; the contact stays in front of the %1</source>
        <translation>Il blocco dopo un singolo contatto si può scrivere più breve; il contatto resta davanti a %1</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>A single device in parallel with a block belongs on the lower row: the block first, then an OR, drops the %1</source>
        <translation>Un singolo operando in parallelo a un blocco va sulla riga inferiore: prima il blocco, poi un OR, senza %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Contacts in series need no %1: each can follow the one before it as %2</source>
        <translation>I contatti in serie non richiedono %1: ognuno può seguire il precedente come %2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The block after a single contact can move to the front and drop the %1</source>
        <translation>Il blocco dopo un singolo contatto può essere spostato in testa, senza %1</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Put the single device below the block and drop the %1</source>
        <translation>Metti il singolo operando sotto il blocco ed elimina %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Join the contacts in series and drop the %1</source>
        <translation>Collega i contatti in serie ed elimina %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Move the block to the front and drop the %1</source>
        <translation>Sposta il blocco in testa ed elimina %1</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>MPS nests more than %1 deep</source>
        <translation>MPS annidati oltre %1 livelli</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 without a matching MPS</source>
        <translation>%1 senza un MPS corrispondente</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>An output with no contacts of its own belongs on top of the branch and needs no %1</source>
        <translation>Un&apos;uscita senza contatti propri va in cima alla diramazione e non richiede %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Put the output on top and drop the %1</source>
        <translation>Metti l&apos;uscita in cima ed elimina %1</translation>
    </message>
    <message numerus="yes">
        <location line="+12"/>
        <source>%n MPS left without MPP at the end of the rung</source>
        <translation>
            <numerusform>%n MPS senza MPP alla fine del segmento</numerusform>
            <numerusform>%n MPS senza MPP alla fine del segmento</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/checks/checks_operands.cpp" line="+160"/>
        <source>%1 cannot be written: the program only reads it (%2)</source>
        <translation>%1 non può essere scritto: il programma lo legge soltanto (%2)</translation>
    </message>
    <message>
        <location filename="../model/checks/checks_duplicates.cpp" line="+20"/>
        <source>%1 is programmed twice; the PLC allows it once only in a program (the first is on line %2)</source>
        <translation>%1 è programmata due volte; il PLC la ammette una sola volta in un programma (la prima è alla riga %2)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 is programmed twice; the PLC allows it once only in a program (the first is in rung %2)</source>
        <translation>%1 è programmata due volte; il PLC la ammette una sola volta in un programma (la prima è nel segmento %2)</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>%1 is driven twice; a coil may be driven only once (the first is on line %2)</source>
        <translation>%1 è comandato due volte; una bobina può essere comandata una volta sola (il primo è alla riga %2)</translation>
    </message>
    <message>
        <location line="+10"/>
        <location filename="../model/listing/structure.cpp" line="+19"/>
        <source>%1 (the PLC says &quot;%2&quot;)</source>
        <translation>%1 (il PLC segnala &quot;%2&quot;)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 is driven twice; a coil may be driven only once (the first is in rung %2)</source>
        <translation>%1 è comandato due volte; una bobina può essere comandata una volta sola (il primo è nel segmento %2)</translation>
    </message>
    <message>
        <location filename="../model/checks/checks_nesting.cpp" line="+51"/>
        <source>END is missing</source>
        <translation>Manca END</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Instructions after END are never executed</source>
        <translation>Le istruzioni dopo END non vengono mai eseguite</translation>
    </message>
    <message>
        <location filename="../model/listing/structure.cpp" line="+222"/>
        <source>IL inside IL: close the first with ILC</source>
        <translation>IL dentro IL: chiudere il primo con ILC</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>Jump number %1 is beyond 00..%2</source>
        <translation>Il numero di salto %1 è oltre 00..%2</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>JMP inside JMP: close the first jump</source>
        <translation>JMP dentro JMP: chiudere il primo salto</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>A second %1 %2: several JMP may share a number, only one JME</source>
        <translation>Un secondo %1 %2: più JMP possono condividere un numero, un solo JME</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1 %2 without a JMP before it</source>
        <translation>%1 %2 senza un JMP prima</translation>
    </message>
    <message>
        <location line="-221"/>
        <source>%1 cannot stand inside a step (STEP(08) .. STEP(08))</source>
        <translation>%1 non può stare dentro una fase (STEP(08) .. STEP(08))</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1 %2 inside subroutine %3: close that one with %4 first</source>
        <translation>%1 %2 dentro la subroutine %3: chiudere prima quella con %4</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>A second %1 %2: each subroutine number is defined once</source>
        <translation>Una seconda %1 %2: ogni numero di subroutine si definisce una volta sola</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1 without %2 before it</source>
        <translation>%1 senza %2 prima</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1 without a control bit ends the steps, but no step is open</source>
        <translation>%1 senza bit di controllo chiude le fasi, ma nessuna fase è aperta</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>%1 is after the main program and outside the subroutines: it never runs</source>
        <translation>%1 è dopo il programma principale e fuori dalle subroutine: non viene mai eseguita</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1 %2 is not closed with %3</source>
        <translation>%1 %2 non è chiusa con %3</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The steps are not closed with %1 without a control bit</source>
        <translation>Le fasi non sono chiuse con %1 senza bit di controllo</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 %2: there is no %3 %2 before END</source>
        <translation>%1 %2: prima di END non c&apos;è %3 %2</translation>
    </message>
    <message>
        <location line="+101"/>
        <location line="+51"/>
        <source>%1 without %2</source>
        <translation>%1 senza %2</translation>
    </message>
    <message>
        <location line="-45"/>
        <source>IL and JMP overlap: the jump opened inside the interlock is still open</source>
        <translation>IL e JMP si sovrappongono: il salto aperto dentro l&apos;interblocco è ancora aperto</translation>
    </message>
    <message>
        <location line="+52"/>
        <source>IL and JMP overlap: the interlock opened inside the jump is still open</source>
        <translation>IL e JMP si sovrappongono: l&apos;interblocco aperto dentro il salto è ancora aperto</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>IL without ILC</source>
        <translation>IL senza ILC</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>JMP without its end (%1)</source>
        <translation>JMP senza la sua fine (%1)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>JMP %1 has no JME %1</source>
        <translation>JMP %1 non ha JME %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>JMP %1 has no JME %1 after it</source>
        <translation>JMP %1 non ha JME %1 dopo di sé</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The step ladder is not closed with RET</source>
        <translation>Lo step ladder non è chiuso con RET</translation>
    </message>
    <message>
        <location filename="../model/checks/checks_operands.cpp" line="-20"/>
        <source>Set value %1 is out of range</source>
        <translation>Il valore di preset %1 è fuori campo</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>%1 cannot be written: the PLC drives it (%2)</source>
        <translation>%1 non è scrivibile: lo gestisce il PLC (%2)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1 cannot drive %2: %3 are not relays</source>
        <translation>%1 non può comandare %2: %3 non sono relè</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Number %1 is used as a timer and as a counter; they share one bank</source>
        <translation>Il numero %1 è usato come temporizzatore e come contatore; condividono un banco</translation>
    </message>
    <message>
        <location filename="../model/checks/checks_duplicates.cpp" line="-11"/>
        <source>%1 is driven twice; the later one wins (first on line %2)</source>
        <translation>%1 è comandato due volte; prevale l&apos;ultimo (il primo alla riga %2)</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1 is driven twice; the later one wins (first in rung %2)</source>
        <translation>%1 è comandato due volte; prevale l&apos;ultimo (il primo nel segmento %2)</translation>
    </message>
    <message>
        <location filename="../model/checks/checks_length.cpp" line="+15"/>
        <source>The program needs %1 steps; %2 holds %3</source>
        <translation>Il programma richiede %1 passi; %2 ne contiene %3</translation>
    </message>
    <message>
        <location filename="../model/checks/operand_rules.cpp" line="+17"/>
        <source>operand %1</source>
        <translation>operando %1</translation>
    </message>
    <message>
        <location line="+53"/>
        <source>the %1 of %2 must be #DDSS with bits DD and SS from 00 to 15, not %3</source>
        <translation>il %1 di %2 deve essere #DDSS con i bit DD e SS da 00 a 15, non %3</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the %1 of %2 must be #0DNS with digits D, N and S from 0 to 3, not %3</source>
        <translation>il %1 di %2 deve essere #0DNS con le cifre D, N e S da 0 a 3, non %3</translation>
    </message>
    <message>
        <location line="+157"/>
        <source>the %1 of %2 must be BCD (#0000..#9999), not %3</source>
        <translation>il %1 di %2 deve essere BCD (#0000..#9999), non %3</translation>
    </message>
    <message>
        <location line="-46"/>
        <source>%1 or %2</source>
        <translation>%1 o %2</translation>
    </message>
    <message>
        <location line="-95"/>
        <source>%1 uses %2..%3, which runs from %4 into %5: a block stays in one</source>
        <translation>%1 usa %2..%3, che passa da %4 a %5: un blocco resta in un&apos;area sola</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1 uses %2..%3, but %4 does not exist</source>
        <translation>%1 usa %2..%3, ma %4 non esiste</translation>
    </message>
    <message>
        <location line="+113"/>
        <location line="+38"/>
        <source>the %1 of %2 must be %3, not %4</source>
        <translation>il %1 di %2 deve essere %3, non %4</translation>
    </message>
    <message>
        <location line="-33"/>
        <location line="+80"/>
        <source>%1 takes its %2 from %3 only, not %4</source>
        <translation>%1 prende il suo %2 solo da %3, non da %4</translation>
    </message>
    <message>
        <location line="-72"/>
        <source>the %1 of %2 must be a device, not %3</source>
        <translation>il %1 di %2 deve essere un operando, non %3</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>the %1 of %2 must be at least %3, not %4</source>
        <translation>il %1 di %2 deve essere almeno %3, non %4</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the %1 of %2 must be from %3 to %4, not %5</source>
        <translation>il %1 di %2 deve essere da %3 a %4, non %5</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>the %1 of %2 must be a number, not %3</source>
        <translation>il %1 di %2 deve essere un numero, non %3</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>%1 moves whole words: %2 cannot be its %3</source>
        <translation>%1 sposta word intere: %2 non può essere il suo %3</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1 takes its %2 from a constant or from %3, not %4</source>
        <translation>%1 prende il suo %2 da una costante o da %3, non da %4</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>%1 takes only %2..%3, not %4</source>
        <translation>%1 accetta solo %2..%3, non %4</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>the %1 of %2 is a word: %3 is a single bit</source>
        <translation>il %1 di %2 è una word: %3 è un singolo bit</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>the %1 of %2 is a word: %3 starts no word of 16 bits (%4 and %5 do)</source>
        <translation>il %1 di %2 è una word: %3 non è l&apos;inizio di una word di 16 bit (%4 e %5 lo sono)</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>the %1 of %2 is a bit: %3 is a whole channel (%4 is its first bit)</source>
        <translation>il %1 di %2 è un bit: %3 è un canale intero (il suo primo bit è %4)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the %1 of %2 is a bit: %3 is a whole word (%4 is its first bit)</source>
        <translation>il %1 di %2 è un bit: %3 è una word intera (il suo primo bit è %4)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the %1 of %2 is a bit: %3 is a whole word</source>
        <translation>il %1 di %2 è un bit: %3 è una word intera</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>the %1 of %2 must be a channel with bits (IR, HR, LR), not %3</source>
        <translation>il %1 di %2 deve essere un canale con bit (IR, HR, LR), non %3</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1 %2 %3: the last device must be of the kind of the first and not before it</source>
        <translation>%1 %2 %3: l&apos;ultimo operando deve essere dello stesso tipo del primo e non precederlo</translation>
    </message>
    <message>
        <location line="+47"/>
        <source>%1 cannot write %2: %3 are written only by %4</source>
        <translation>%1 non può scrivere %2: %3 sono scritti solo da %4</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1 is not simulated: it does nothing in the simulator</source>
        <translation>%1 non è simulato: nel simulatore non fa nulla</translation>
    </message>
    <message>
        <location filename="../model/checks/checks_switched.cpp" line="+64"/>
        <source>%1 runs only while %2 is ON, and no instruction sets %2</source>
        <translation>%1 funziona solo mentre %2 è ON, e nessuna istruzione imposta %2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 stops while %2 is ON, and line %3 writes %2</source>
        <translation>%1 si ferma mentre %2 è ON, e la riga %3 scrive %2</translation>
    </message>
    <message>
        <location filename="../model/checks/unmodelled.cpp" line="+53"/>
        <source>%1 is not simulated: %2</source>
        <translation>%1 non è simulato: %2</translation>
    </message>
    <message>
        <location filename="../model/checks/operand_rules.cpp" line="-307"/>
        <source>the %1 of %2 holds %3 (character %4), which does not fit a byte: a character is stored as its Latin-1 code, 0..255</source>
        <translation>il %1 di %2 contiene %3 (carattere %4), che non sta in un byte: un carattere è salvato come il suo codice Latin-1, 0..255</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1 stores two characters a word, but %2 holds %3 bits a word: write 1 character per word</source>
        <translation>%1 salva due caratteri per word, ma %2 ha word di %3 bit: scrivere 1 carattere per word</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>the %1 of %2 (length %3) is stored in %4..%5, but %6 does not exist: the text is too long for its place</source>
        <translation>il %1 di %2 (lunghezza %3) è salvato in %4..%5, ma %6 non esiste: il testo è troppo lungo per la sua posizione</translation>
    </message>
    <message>
        <location line="+333"/>
        <source>the display shows %1 of the %2 of %3 as a space: it draws the character codes %4</source>
        <translation>il display mostra %1 del %2 di %3 come uno spazio: visualizza i codici di carattere %4</translation>
    </message>
</context>
<context>
    <name>rung::model::Compare</name>
    <message>
        <location filename="../model/compare/compare_report.cpp" line="+21"/>
        <source>the same</source>
        <translation>uguale</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>moved</source>
        <translation>spostato</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>changed</source>
        <translation>modificato</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>moved and changed</source>
        <translation>spostato e modificato</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>inserted</source>
        <translation>inserito</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>deleted</source>
        <translation>eliminato</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>contact</source>
        <translation>contatto</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>output</source>
        <translation>uscita</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>branches</source>
        <translation>rami</translation>
    </message>
    <message>
        <location line="+41"/>
        <source>name</source>
        <translation>nome</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>comment</source>
        <translation>commento</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>- rung %1 of A: %2</source>
        <extracomment>A rung only in the first program (A): %1 its number there, %2 &quot;deleted&quot;.</extracomment>
        <translation>- segmento %1 di A: %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>+ rung %1 of B: %2</source>
        <extracomment>A rung only in the second program (B): %1 its number there, %2 &quot;inserted&quot;.</extracomment>
        <translation>+ segmento %1 di B: %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>rung %1: %2</source>
        <translation>segmento %1: %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>rung %1 -&gt; %2: %3</source>
        <extracomment>A rung of A (number %1) that is rung %2 of B, and what happened to it (%3).</extracomment>
        <translation>segmento %1 -&gt; %2: %3</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>+ %1 added: %2</source>
        <translation>+ %1 aggiunto: %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>- %1 removed: %2</source>
        <translation>- %1 rimosso: %2</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>* the branches joining the contacts changed</source>
        <translation>* i rami che uniscono i contatti sono cambiati</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>* %1 changed: %2 -&gt; %3</source>
        <translation>* %1 modificato: %2 -&gt; %3</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>operand %1: %2 -&gt; %3</source>
        <extracomment>An operand that changed: %1 its number (1 = the first), %2 and %3 the old and the new operand.</extracomment>
        <translation>operando %1: %2 -&gt; %3</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>* comment changed: %1 -&gt; %2</source>
        <translation>* commento modificato: %1 -&gt; %2</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>+ %1 added: %2 %3</source>
        <extracomment>%1 what (&quot;symbol X0&quot;, &quot;set value T0&quot;), %2 the field (&quot;name&quot;, &quot;comment&quot;, &quot;value&quot;).</extracomment>
        <translation>+ %1 aggiunto: %2 %3</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>- %1 removed: %2 %3</source>
        <translation>- %1 rimosso: %2 %3</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>* %1 changed: %2 %3 -&gt; %4</source>
        <translation>* %1 modificato: %2 %3 -&gt; %4</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>+ watch list %1 added: %2</source>
        <translation>+ lista di osservazione %1 aggiunta: %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>- watch list %1 removed: %2</source>
        <translation>- lista di osservazione %1 rimossa: %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>+ watch list %1: %2 added</source>
        <translation>+ lista di osservazione %1: %2 aggiunto</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>- watch list %1: %2 removed</source>
        <translation>- lista di osservazione %1: %2 rimosso</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>* watch list %1: the order changed: %2 -&gt; %3</source>
        <translation>* lista di osservazione %1: l&apos;ordine è cambiato: %2 -&gt; %3</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>* watch list %1: %2 shown as %3 -&gt; %4</source>
        <extracomment>A watch list row shown in another format: %1 the list, %2 the device, %3 and %4 the formats (dec, signed, hex, bin, bcd).</extracomment>
        <translation>* lista di osservazione %1: %2 mostrato come %3 -&gt; %4</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>+ B holds an instruction list typed with errors that is not in its rungs (pendingListing)</source>
        <translation>+ B contiene una lista istruzioni digitata con errori che non è nei suoi segmenti (pendingListing)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>- A holds an instruction list typed with errors that is not in its rungs (pendingListing)</source>
        <translation>- A contiene una lista istruzioni digitata con errori che non è nei suoi segmenti (pendingListing)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>* the instruction lists typed with errors that are not in the rungs differ (pendingListing)</source>
        <translation>* le liste istruzioni digitate con errori che non sono nei segmenti differiscono (pendingListing)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>+ symbol row not yet a symbol: %1</source>
        <translation>+ riga non ancora simbolo: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>- symbol row not yet a symbol: %1</source>
        <translation>- riga non ancora simbolo: %1</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>* model changed: %1 -&gt; %2</source>
        <translation>* modello modificato: %1 -&gt; %2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>symbol %1</source>
        <translation>simbolo %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>set value %1</source>
        <translation>valore di preset %1</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>The programs are the same (rungs: %1).</source>
        <translation>I programmi sono uguali (segmenti: %1).</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Rungs: %1 in A, %2 in B; %3 the same, %4 moved, %5 changed, %6 moved and changed, %7 inserted, %8 deleted.</source>
        <extracomment>The summary of a comparison: %1 rungs in A, %2 in B, then how many of each kind.</extracomment>
        <translation>Segmenti: %1 in A, %2 in B; %3 uguali, %4 spostati, %5 modificati, %6 spostati e modificati, %7 inseriti, %8 eliminati.</translation>
    </message>
</context>
<context>
    <name>rung::model::Convert</name>
    <message>
        <location filename="../model/convert/convert_to_ladder.cpp" line="+216"/>
        <source>%1 joins the condition of a branch point in parallel with another block; the ladder cannot draw this: repeat the shared contacts in this branch instead</source>
        <translation>%1 collega la condizione di un punto di diramazione in parallelo a un altro blocco; lo schema ladder non può disegnarlo: ripeti invece i contatti comuni in questo ramo</translation>
    </message>
    <message>
        <location line="+77"/>
        <source>%1 has no block to continue; start the rung with a load</source>
        <translation>%1 non ha un blocco da continuare; iniziare il segmento con un caricamento</translation>
    </message>
    <message>
        <location line="+8"/>
        <location line="+18"/>
        <source>%1 has no block to join in parallel</source>
        <translation>%1 non ha un blocco da collegare in parallelo</translation>
    </message>
    <message numerus="yes">
        <location line="-9"/>
        <source>%1 needs two blocks, but %n is open</source>
        <translation>
            <numerusform>%1 richiede due blocchi, ma %n è aperto</numerusform>
            <numerusform>%1 richiede due blocchi, ma %n sono aperti</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+19"/>
        <source>MPS needs exactly one open block, but %n is open</source>
        <translation>
            <numerusform>MPS richiede esattamente un blocco aperto, ma %n è aperto</numerusform>
            <numerusform>MPS richiede esattamente un blocco aperto, ma %n sono aperti</numerusform>
        </translation>
    </message>
    <message>
        <location line="+12"/>
        <source>%1 without a matching MPS</source>
        <translation>%1 senza un MPS corrispondente</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>%1 needs %2 input blocks, but %3 are open</source>
        <translation>%1 richiede %2 blocchi di ingresso, ma %3 sono aperti</translation>
    </message>
    <message>
        <location line="+9"/>
        <location filename="../model/convert/convert_to_list.cpp" line="+48"/>
        <source>%1 has an input with no condition</source>
        <translation>%1 ha un ingresso senza condizione</translation>
    </message>
    <message>
        <location line="+15"/>
        <location line="+4"/>
        <location line="+6"/>
        <location filename="../model/convert/convert_to_list.cpp" line="+12"/>
        <source>%1 has no condition</source>
        <translation>%1 non ha condizione</translation>
    </message>
    <message>
        <location line="-5"/>
        <source>%1 needs one block, but %2 are open</source>
        <translation>%1 richiede un blocco, ma %2 sono aperti</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>The rung starting on line %1 ends without an output</source>
        <translation>Il segmento che inizia alla riga %1 termina senza un&apos;uscita</translation>
    </message>
    <message numerus="yes">
        <location line="+4"/>
        <source>The rung starting on line %1 leaves %n MPS without MPP</source>
        <translation>
            <numerusform>Il segmento che inizia alla riga %1 lascia %n MPS senza MPP</numerusform>
            <numerusform>Il segmento che inizia alla riga %1 lascia %n MPS senza MPP</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/convert/convert_to_list.cpp" line="+33"/>
        <source>%1 has no INV element</source>
        <translation>%1 non ha un elemento INV</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 has no such contact</source>
        <translation>%1 non ha un contatto di questo tipo</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>%1 has no branch stack</source>
        <translation>%1 non ha uno stack delle diramazioni</translation>
    </message>
    <message>
        <location line="+80"/>
        <source>A block cannot start with INV</source>
        <translation>Un blocco non può iniziare con INV</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>An output has no condition</source>
        <translation>Un&apos;uscita non ha condizione</translation>
    </message>
    <message>
        <location line="+97"/>
        <source>A branch reads a device that an earlier branch of the same rung writes, and %1 cannot hold this branch point (IL does not nest); draw the branches as separate rungs</source>
        <translation>Un ramo legge un operando che un ramo precedente dello stesso segmento scrive, e %1 non può mantenere questo punto di diramazione (IL non si annida); disegna i rami come segmenti separati</translation>
    </message>
    <message>
        <location line="+98"/>
        <source>A box with several inputs must stand alone in its rung</source>
        <translation>Un blocco funzione con più ingressi deve stare da solo nel suo segmento</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Row %1 is not connected to the left rail</source>
        <translation>La riga %1 non è collegata alla barra sinistra</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Reverse current: the network feeding row %1 can only close through an element crossed right to left</source>
        <translation>Corrente inversa: la rete che alimenta la riga %1 può chiudersi solo attraverso un elemento percorso da destra a sinistra</translation>
    </message>
</context>
<context>
    <name>rung::model::InstructionList</name>
    <message>
        <location filename="../model/listing/il_parse.cpp" line="+164"/>
        <source>Too many errors; the rest of the listing was not read</source>
        <translation>Troppi errori; il resto della lista non è stato letto</translation>
    </message>
    <message>
        <location line="+158"/>
        <source>Program sections such as &apos;%1&apos; are not supported: a listing is one main program, run at every scan</source>
        <translation>Le sezioni di programma come &apos;%1&apos; non sono supportate: una lista istruzioni è un solo programma principale, eseguito a ogni scansione</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Program sections such as &apos;%1&apos; are not supported: a listing is one main program, run at every scan; put what runs once under LD %2 (ON in the first scan). Interrupt programs are not supported</source>
        <translation>Le sezioni di programma come &apos;%1&apos; non sono supportate: una lista istruzioni è un solo programma principale, eseguito a ogni scansione; mettere ciò che va eseguito una volta sotto LD %2 (ON nella prima scansione). I programmi di interrupt non sono supportati</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>Unknown instruction &apos;%1&apos; for %2</source>
        <translation>Istruzione sconosciuta &apos;%1&apos; per %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Unknown instruction &apos;%1&apos; for %2; did you mean %3?</source>
        <translation>Istruzione sconosciuta &apos;%1&apos; per %2; forse intendevi %3?</translation>
    </message>
    <message>
        <location line="+41"/>
        <source>%1 cannot compare values</source>
        <translation>%1 non può confrontare valori</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>A second operand is missing after &apos;%1&apos;</source>
        <translation>Manca un secondo operando dopo &apos;%1&apos;</translation>
    </message>
    <message>
        <location line="+19"/>
        <location line="+210"/>
        <source>&apos;%1...&apos; is too long for an operand</source>
        <translation>&apos;%1...&apos; è troppo lungo per un operando</translation>
    </message>
    <message numerus="yes">
        <location line="-135"/>
        <source>%1 needs %n operand(s): %2</source>
        <translation>
            <numerusform>%1 richiede %n operando: %2</numerusform>
            <numerusform>%1 richiede %n operandi: %2</numerusform>
        </translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 takes no operand</source>
        <translation>%1 non accetta operandi</translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>Unexpected &apos;%1&apos;: %2 takes %n operand(s)</source>
        <translation>
            <numerusform>&apos;%1&apos; inatteso: %2 accetta %n operando</numerusform>
            <numerusform>&apos;%1&apos; inatteso: %2 accetta %n operandi</numerusform>
        </translation>
    </message>
    <message>
        <location line="+34"/>
        <source>%1: a set value is a BCD constant #0000..#9999 or a channel</source>
        <translation>%1: un valore di preset è una costante BCD #0000..#9999 o un canale</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>%1 is out of range: %2..%3 fit here</source>
        <translation>%1 è fuori campo: qui sono ammessi %2..%3</translation>
    </message>
    <message>
        <location line="+73"/>
        <source>%1: a label number is expected</source>
        <translation>%1: è atteso un numero di etichetta</translation>
    </message>
    <message>
        <location line="+43"/>
        <location line="+46"/>
        <source>%1 is a constant; a device is expected here</source>
        <translation>%1 è una costante; qui è atteso un operando</translation>
    </message>
    <message>
        <location line="-32"/>
        <source>%1: %2 is expected here</source>
        <translation>%1: qui è atteso %2</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>%1 is a word (%2 bits); a single device is expected here</source>
        <translation>%1 è una word (%2 bit); qui è atteso un singolo operando</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1: an index register modifies only the word operands of application instructions and set values</source>
        <translation>%1: un registro indice modifica solo gli operandi word delle istruzioni applicative e i valori di preset</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>a timer</source>
        <translation>un temporizzatore</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>a counter</source>
        <translation>un contatore</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>a step relay</source>
        <translation>un relè di passo</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>a bit device</source>
        <translation>un operando a bit</translation>
    </message>
    <message>
        <location filename="../model/listing/operand_text.cpp" line="+159"/>
        <source>%1: K%2 is no digit count here; K1..K%3 (groups of 4 bits) fit a word</source>
        <translation>%1: K%2 non è un numero di cifre valido; in una word stanno K1..K%3 (gruppi di 4 bit)</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1: K%2 takes a bit device (the first of its bits), not %3</source>
        <translation>%1: K%2 richiede un operando a bit (il primo dei suoi bit), non %3</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1 takes the %2 bits %3..%4, but %5 does not exist</source>
        <translation>%1 occupa i %2 bit %3..%4, ma %5 non esiste</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1: an index register cannot be indexed</source>
        <translation>%1: un registro indice non può essere indicizzato</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: index registers modify words (D0E0, K4M0E0) and K constants, not the bit %2</source>
        <translation>%1: i registri indice modificano word (D0E0, K4M0E0) e costanti K, non il bit %2</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1: index registers modify K constants, not %2</source>
        <translation>%1: i registri indice modificano costanti K, non %2</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1: %2 is not an index register (%3)</source>
        <translation>%1: %2 non è un registro indice (%3)</translation>
    </message>
    <message>
        <location filename="../model/listing/il_parse.cpp" line="-344"/>
        <source>The text &quot;%1&quot; has no closing quote; a quote inside a text is written twice (&quot;&quot;)</source>
        <translation>Il testo &quot;%1&quot; non ha le virgolette di chiusura; le virgolette dentro un testo si scrivono due volte (&quot;&quot;)</translation>
    </message>
    <message>
        <location line="+198"/>
        <source>&quot;%1&quot;: a text in quotes is not expected here</source>
        <translation>&quot;%1&quot;: qui non è atteso un testo tra virgolette</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1: a text in double quotes is expected here, as &quot;%2&quot;</source>
        <translation>%1: qui è atteso un testo tra virgolette doppie, come &quot;%2&quot;</translation>
    </message>
</context>
<context>
    <name>rung::model::Ladder</name>
    <message>
        <location filename="../model/ladder/replace_device.cpp" line="+22"/>
        <source>%1 cannot replace %2 in rung %3: %4 is expected there.</source>
        <translation>%1 non può sostituire %2 nel segmento %3: lì serve %4.</translation>
    </message>
</context>
<context>
    <name>rung::model::LadderText</name>
    <message>
        <location filename="../model/ladder/ladder_text.cpp" line="+195"/>
        <source>A ladder text starts with &quot;LADDER &lt;target&gt; WIDTH &lt;n&gt;&quot;</source>
        <translation>Un testo ladder inizia con &quot;LADDER &lt;target&gt; WIDTH &lt;n&gt;&quot;</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>This ladder is for %1, not %2</source>
        <translation>Questo ladder è per %1, non per %2</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The cell width must be a number from 5 to 200</source>
        <translation>La larghezza delle celle deve essere un numero da 5 a 200</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Expected &quot;RUNG &lt;n&gt; ROWS &lt;rows&gt; COLUMNS &lt;columns&gt;&quot;</source>
        <translation>Atteso &quot;RUNG &lt;n&gt; ROWS &lt;rows&gt; COLUMNS &lt;columns&gt;&quot;</translation>
    </message>
    <message>
        <location line="+18"/>
        <location line="+9"/>
        <source>The rung has fewer rows than its header says</source>
        <translation>Il segmento ha meno righe di quante ne dichiari l&apos;intestazione</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>A row starts with the left rail &apos;|&apos;</source>
        <translation>Una riga inizia con la barra sinistra &apos;|&apos;</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>A cell is empty, a wire, or a contact &quot;-[ %1 ]-&quot;</source>
        <translation>Una cella è vuota, un collegamento o un contatto &quot;-[ %1 ]-&quot;</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>An output is written in parentheses: (%1 %2)</source>
        <translation>Un&apos;uscita si scrive tra parentesi: (%1 %2)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>(^) marks a further input of a box above it</source>
        <translation>(^) indica un ulteriore ingresso del blocco funzione soprastante</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>One output instruction is expected</source>
        <translation>È attesa un&apos;istruzione di uscita</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>&apos;~%1&apos;: a power-flow element is ~, ~P or ~N</source>
        <translation>&apos;~%1&apos;: un elemento sul flusso di corrente è ~, ~P o ~N</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>&apos;%1&apos; is not a contact mark (&apos; &apos;, &apos;/&apos;, &apos;P&apos;, &apos;N&apos;, &apos;~&apos;)</source>
        <translation>&apos;%1&apos; non è un segno di contatto (&apos; &apos;, &apos;/&apos;, &apos;P&apos;, &apos;N&apos;, &apos;~&apos;)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The contact has no device</source>
        <translation>Il contatto non ha un operando</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>%1 is a word; a contact takes a bit device</source>
        <translation>%1 è una word; un contatto richiede un operando a bit</translation>
    </message>
    <message>
        <location line="+69"/>
        <source>&apos;%1&apos; is not a contact</source>
        <translation>&apos;%1&apos; non è un contatto</translation>
    </message>
</context>
<context>
    <name>rung::model::PanelView</name>
    <message>
        <location filename="../model/image/panel_view.cpp" line="+131"/>
        <source>Display mode %1: the manual describes mode %2 (one %3-digit value) and mode %4 (two %5-digit values)</source>
        <translation>Modo di visualizzazione %1: il manuale descrive il modo %2 (un valore di %3 cifre) e il modo %4 (due valori di %5 cifre)</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>The register named by %1 (%2) does not exist</source>
        <translation>Il registro indicato da %1 (%2) non esiste</translation>
    </message>
    <message>
        <location line="+110"/>
        <source>Application &quot;%1&quot;; the ports&apos; protocols as their settings give them</source>
        <translation>Applicazione «%1»; i protocolli delle porte secondo le loro impostazioni</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The application&apos;s name and the ports&apos; protocols are not known here: shown as dashes</source>
        <translation>Il nome dell&apos;applicazione e i protocolli delle porte qui non sono noti: indicati con un trattino</translation>
    </message>
    <message>
        <location line="+154"/>
        <source>No page is shown: the program enables none</source>
        <translation>Nessuna pagina visualizzata: il programma non ne abilita alcuna</translation>
    </message>
    <message>
        <location filename="../model/target/target_pl110_panel.cpp" line="+139"/>
        <source>System info: the simulator has no BOOT or firmware version (shown as a dash); the slave address is SMW4, changed with the keys after the system password 1357</source>
        <translation>System info: il simulatore non ha versione del programma di BOOT né del firmware (indicate con un trattino); l&apos;indirizzo slave è SMW4, modificabile con i tasti previa immissione della password di sistema 1357</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Date and time: the simulator&apos;s clock does not count; SM9..SM15 keep what the program or the keys write</source>
        <translation>Data e ora: l&apos;orologio interno del simulatore non conta; SM9..SM15 mantengono quanto scritto dal programma o dai tasti</translation>
    </message>
</context>
<context>
    <name>rung::model::Plcopen</name>
    <message>
        <location filename="../model/exchange/plcopen_import.cpp" line="+128"/>
        <source>not a PLCopen TC6 XML 2.01 project (the root is &lt;%1&gt; in &quot;%2&quot;, &lt;project&gt; in &quot;%3&quot; is expected)</source>
        <translation>non è un progetto PLCopen TC6 XML 2.01 (la radice è &lt;%1&gt; in &quot;%2&quot;, è atteso &lt;project&gt; in &quot;%3&quot;)</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>a %1 is not imported: %2 runs one ladder, with no user functions or function blocks</source>
        <translation>un %1 non viene importato: %2 esegue un solo schema ladder, senza funzioni né blocchi funzione dell&apos;utente</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the file has no program</source>
        <translation>il file non contiene un programma</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>a body in %1 is not imported: only ladder (LD) is</source>
        <translation>un corpo in %1 non viene importato: solo il ladder (LD)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the program has no ladder (LD) body</source>
        <translation>il programma non ha un corpo ladder (LD)</translation>
    </message>
    <message>
        <location line="+159"/>
        <source>the mapping file gives %1: %2</source>
        <translation>il file di corrispondenze indica %1: %2</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>%1 at %2: %3 has no such device (docs/plcopen.md, located variables); give one in a mapping file</source>
        <translation>%1 in %2: %3 non ha un tale operando (docs/plcopen.md, variabili allocate); indicarne uno in un file di corrispondenze</translation>
    </message>
    <message>
        <location line="+159"/>
        <source>input %1 is not a variable or a literal</source>
        <translation>l&apos;ingresso %1 non è una variabile né un letterale</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>line %1: &quot;%2&quot; is not NAME = DEVICE</source>
        <translation>riga %1: &quot;%2&quot; non è NOME = OPERANDO</translation>
    </message>
    <message>
        <location filename="../model/exchange/plcopen_power.cpp" line="+66"/>
        <source>its input is connected to nothing: not imported</source>
        <translation>il suo ingresso non è collegato a nulla: non importato</translation>
    </message>
    <message>
        <location line="+98"/>
        <source>it is connected to element %1, which the file does not have</source>
        <translation>è collegato all&apos;elemento %1, che il file non contiene</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the power flow runs in a loop: not imported</source>
        <translation>il flusso di potenza gira in un anello: non importato</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>a contact both negated and on an edge is not imported</source>
        <translation>un contatto insieme negato e sul fronte non viene importato</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 has no such contact</source>
        <translation>%1 non ha un tale contatto</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>no connector is named %1</source>
        <translation>nessun connettore si chiama %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>a %1 carries no power flow %2 can take</source>
        <translation>un %1 non porta un flusso di potenza che %2 possa accogliere</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>a comparison needs IN1 and IN2</source>
        <translation>un confronto richiede IN1 e IN2</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>%1 has no compare contact %2</source>
        <translation>%1 non ha un contatto di confronto %2</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>%1 has no element for %2 in the power flow</source>
        <translation>%1 non ha un elemento per %2 nel flusso di potenza</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>output %1 of %2 as power flow is not imported</source>
        <translation>l&apos;uscita %1 di %2 come flusso di potenza non viene importata</translation>
    </message>
    <message>
        <location filename="../model/exchange/plcopen_outputs.cpp" line="+22"/>
        <source>one instruction is expected</source>
        <translation>è attesa un&apos;istruzione</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>a negated coil that also sets, resets or pulses is not imported</source>
        <translation>una bobina negata che anche imposta, resetta o dà un impulso non viene importata</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 has no such coil</source>
        <translation>%1 non ha una tale bobina</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>PT must be a time literal (T#1s) to be a set value: not imported</source>
        <translation>PT deve essere un letterale di tempo (T#1s) per essere un valore di preset: non importato</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1 has no pulse timer (TP)</source>
        <translation>%1 non ha un temporizzatore a impulso (TP)</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>%1 has no %2 timer that times %3 ms on %4</source>
        <translation>%1 non ha un temporizzatore %2 che misuri %3 ms su %4</translation>
    </message>
    <message>
        <location line="+117"/>
        <source>MOVE&apos;s OUT goes to no variable: not imported</source>
        <translation>l&apos;OUT di MOVE non va a una variabile: non importato</translation>
    </message>
    <message>
        <location line="-17"/>
        <source>%1 has no move instruction</source>
        <translation>%1 non ha un&apos;istruzione di trasferimento</translation>
    </message>
    <message>
        <location filename="../model/exchange/plcopen_rungs.cpp" line="+256"/>
        <source>the ladder does not use it and it names no device: not imported</source>
        <translation>lo schema ladder non la usa e non indica un operando: non importata</translation>
    </message>
    <message>
        <location line="+115"/>
        <source>IEC jumps, labels and returns are not imported: %1&apos;s own jumps work otherwise; write them in Rung Studio</source>
        <translation>i salti, le etichette e i ritorni IEC non vengono importati: i salti propri di %1 funzionano diversamente; scriverli in Rung Studio</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>its power comes from %1 (line %2), which is not imported</source>
        <translation>il suo flusso viene da %1 (riga %2), che non viene importato</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>its power goes to %1 (line %2), which is not imported</source>
        <translation>il suo flusso va a %1 (riga %2), che non viene importato</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>no output uses it: not imported</source>
        <translation>nessuna uscita lo usa: non importato</translation>
    </message>
    <message>
        <location filename="../model/exchange/plcopen_write.cpp" line="+96"/>
        <source>%1 is written as a block of %2&apos;s own: other tools read the file but do not know this block</source>
        <translation>%1 viene scritto come blocco proprio di %2: altri strumenti leggono il file ma non conoscono questo blocco</translation>
    </message>
    <message>
        <location filename="../model/exchange/plcopen_xml.cpp" line="+25"/>
        <source>line %1: the XML nests deeper than %2 levels</source>
        <translation>riga %1: l&apos;XML è annidato oltre %2 livelli</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>line %1, column %2: the file is not well-formed XML (%3)</source>
        <translation>riga %1, colonna %2: il file non è XML ben formato (%3)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the file holds no XML element</source>
        <translation>il file non contiene elementi XML</translation>
    </message>
    <message>
        <location filename="../model/exchange/plcopen_import.cpp" line="-379"/>
        <source>a second program is not imported: a project is one ladder (the program %1 is)</source>
        <translation>un secondo programma non viene importato: un progetto è un solo schema ladder (viene importato il programma %1)</translation>
    </message>
    <message>
        <location line="+254"/>
        <source>%1 is not imported: %2 keeps a counter&apos;s present value as BCD digits</source>
        <translation>%1 non viene importato: %2 tiene il valore corrente di un contatore in cifre BCD</translation>
    </message>
    <message>
        <location filename="../model/exchange/plcopen_power.cpp" line="-288"/>
        <source>%1 as a contact is not imported: only a timer&apos;s or counter&apos;s bit (Q) is</source>
        <translation>%1 come contatto non viene importato: solo il bit (Q) di un temporizzatore o di un contatore</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1 is not imported: the bit of %2 %3 is %4</source>
        <translation>%1 non viene importato: il bit di %2 %3 è %4</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>its input %1 is negated: not imported</source>
        <translation>il suo ingresso %1 è negato: non importato</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>its input %1 on a %2 edge is not imported</source>
        <translation>il suo ingresso %1 con edge=&quot;%2&quot; non viene importato</translation>
    </message>
    <message>
        <location line="+274"/>
        <source>%1 has no contact that is never ON for an input left FALSE</source>
        <translation>%1 non ha un contatto mai ON per un ingresso lasciato a FALSE</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>its EN has a condition: while EN is OFF an IEC block stops where it stands, which %1&apos;s timers and counters do not; not imported</source>
        <translation>il suo EN ha una condizione: mentre EN è OFF un blocco IEC si ferma dove si trova, i temporizzatori e i contatori di %1 no; non importato</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>input %1 is %2, not power: not imported</source>
        <translation>l&apos;ingresso %1 è %2, non flusso di potenza: non importato</translation>
    </message>
    <message>
        <location filename="../model/exchange/plcopen_outputs.cpp" line="-1"/>
        <source>%1 has no instruction to make a BCD value binary</source>
        <translation>%1 non ha un&apos;istruzione per rendere binario un valore BCD</translation>
    </message>
    <message>
        <location filename="../model/exchange/plcopen_rungs.cpp" line="-210"/>
        <source>the instruction list in the file differs from its ladder (another tool changed the ladder?): the ladder is imported</source>
        <translation>la lista istruzioni nel file differisce dal suo schema ladder (un altro strumento ha modificato lo schema?): viene importato lo schema ladder</translation>
    </message>
    <message>
        <location line="+196"/>
        <source>this block is not imported: contacts, coils, TON, TOF, CTU, CTD, CTUD, MOVE, the comparisons, NOT, R_TRIG and F_TRIG are (docs/plcopen.md)</source>
        <translation>questo blocco non viene importato: lo sono contatti, bobine, TON, TOF, CTU, CTD, CTUD, MOVE, i confronti, NOT, R_TRIG e F_TRIG (docs/plcopen.md)</translation>
    </message>
    <message>
        <location filename="../model/exchange/plcopen_write.cpp" line="+3"/>
        <source>%1 is written as a block of %2&apos;s own (%3): other tools read the file but do not know this block</source>
        <translation>%1 viene scritto come blocco proprio di %2 (%3): altri strumenti leggono il file ma non conoscono questo blocco</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>the instruction list is not written beside the ladder: rung %1 does not convert (%2)</source>
        <translation>la lista istruzioni non viene scritta accanto allo schema ladder: il segmento %1 non si converte (%2)</translation>
    </message>
    <message>
        <location filename="../model/exchange/plcopen_counters.cpp" line="+26"/>
        <source>%1&apos;s %2 stops counting at its set value, where CV counts on past PV (Q is the same); its reset is an RST, which acts where it stands in the program, not when the counter runs as R does</source>
        <translation>il %2 di %1 smette di contare al valore di preset, mentre CV continua oltre PV (Q è lo stesso); il suo reset è un RST, che agisce dove si trova nel programma, non quando il contatore viene eseguito come fa R</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1&apos;s %2 stops counting at 0, where CV counts on below 0 (Q is the same), and it is OFF until it has counted down, where a CTD is ON until LD first loads PV</source>
        <translation>il %2 di %1 smette di contare a 0, mentre CV continua sotto 0 (Q è lo stesso), ed è OFF finché non ha contato fino in fondo, mentre un CTD è ON finché LD non carica PV la prima volta</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1&apos;s %2 stops counting at its set value, where CV counts on past PV (Q is the same)</source>
        <translation>il %2 di %1 smette di contare al valore di preset, mentre CV continua oltre PV (Q è lo stesso)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1&apos;s %2 stops counting at 0, where CV counts on below 0, and %1 compares the count at the end of the scan, where a CTUD sets QD when it runs</source>
        <translation>il %2 di %1 smette di contare a 0, mentre CV continua sotto 0, e %1 confronta il conteggio alla fine della scansione, mentre un CTUD imposta QD quando viene eseguito</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1 compares the count of %2 with PV at the end of the scan, where a CTUD sets QU when it runs</source>
        <translation>%1 confronta il conteggio di %2 con PV alla fine della scansione, mentre un CTUD imposta QU quando viene eseguito</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1&apos;s %2 wraps around at its limits, where IEC&apos;s CTUD stops</source>
        <translation>il %2 di %1 ricomincia da capo ai suoi limiti, mentre il CTUD IEC si ferma</translation>
    </message>
    <message>
        <location filename="../model/exchange/plcopen_export.cpp" line="+139"/>
        <source>%1 reads a set value in a word as BCD digits, where PV is a number</source>
        <translation>%1 legge un valore di preset in una word come cifre BCD, mentre PV è un numero</translation>
    </message>
    <message>
        <location line="+287"/>
        <source>%1 is written as an IEC %2: %3</source>
        <translation>%1 viene scritto come %2 IEC: %3</translation>
    </message>
    <message>
        <location filename="../model/exchange/plcopen_import_counters.cpp" line="+59"/>
        <source>%1 is no counter of %2: give %3 a counter in the mapping file</source>
        <translation>%1 non è un contatore di %2: assegnare a %3 un contatore nel file di corrispondenze</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>%1 has no counter that counts as %2 does on %3</source>
        <translation>%1 non ha un contatore che conti come %2 su %3</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>it uses %1 together, which no counter of %2 has</source>
        <translation>usa insieme %1, che nessun contatore di %2 ha</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>PV is not given: not imported</source>
        <translation>PV non è indicato: non importato</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>PV %1 is a variable: %2 reads a set value in a word as BCD digits; not imported</source>
        <translation>PV %1 è una variabile: %2 legge un valore di preset in una word come cifre BCD; non importato</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>PV %1 is a variable: %2 keeps a counter&apos;s set value in the PLC, a number; not imported</source>
        <translation>PV %1 è una variabile: %2 tiene il valore di preset di un contatore nel PLC, un numero; non importato</translation>
    </message>
    <message>
        <location line="+62"/>
        <source>%1 (%2) is imported as %3&apos;s %4: %5</source>
        <translation>%1 (%2) viene importato come %4 di %3: %5</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 (%2) is imported as %3&apos;s %4, which counts the other way: its bit is %1&apos;s Q once %5 has been ON, and its present value is not CV</source>
        <translation>%1 (%2) viene importato come %4 di %3, che conta nell&apos;altro verso: il suo bit è il Q di %1 dopo che %5 è stato ON, e il suo valore corrente non è CV</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1.CV is not imported: %2 counts the other way, its present value is not CV</source>
        <translation>%1.CV non viene importato: %2 conta nell&apos;altro verso, il suo valore corrente non è CV</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>%1 of %2 to a variable is not imported: only a counter&apos;s CV is</source>
        <translation>%1 di %2 verso una variabile non viene importato: solo il CV di un contatore</translation>
    </message>
</context>
<context>
    <name>rung::model::PortConfig</name>
    <message>
        <location filename="../model/comm/port_config.cpp" line="+56"/>
        <source>%1: needs a whole number from %2 to %3</source>
        <translation>%1: richiede un numero intero da %2 a %3</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>%1: needs &quot;%2&quot; or &quot;%3&quot;</source>
        <translation>%1: richiede &quot;%2&quot; o &quot;%3&quot;</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>%1: %2 has no serial port a network can use</source>
        <translation>%1: %2 non ha una porta seriale utilizzabile in una rete</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: %2 has no port %3 (its ports: %4)</source>
        <translation>%1: %2 non ha la porta %3 (le sue porte: %4)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: the %2 %3 has no port %4</source>
        <translation>%1: il %2 %3 non ha la porta %4</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1: needs the name of an application</source>
        <translation>%1: richiede il nome di un&apos;applicazione</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1: %2 is no application of %3 (%4)</source>
        <translation>%1: %2 non è un&apos;applicazione di %3 (%4)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1: the %2 %3 has no %4 on %5 (it has: %6)</source>
        <translation>%1: il %2 %3 non ha %4 su %5 (ha: %6)</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1: %2 takes no setting &quot;%3&quot;</source>
        <translation>%1: %2 non accetta l&apos;impostazione &quot;%3&quot;</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1: %2 is not a rate of %3 (%4)</source>
        <translation>%1: %2 non è una velocità di %3 (%4)</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1: &quot;%2&quot; is no character format (data bits 7 or 8, parity N, E or O, stop bits 1 or 2: 8N1, 7E1)</source>
        <translation>%1: &quot;%2&quot; non è un formato di carattere (bit di dati 7 o 8, parità N, E o O, bit di stop 1 o 2: 8N1, 7E1)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1: %2 always uses %3</source>
        <translation>%1: %2 usa sempre %3</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>%1: needs an object of settings</source>
        <translation>%1: richiede un oggetto di impostazioni</translation>
    </message>
</context>
<context>
    <name>rung::model::PowerFlow</name>
    <message>
        <location filename="../model/image/power_flow.cpp" line="+416"/>
        <source>ON</source>
        <translation>ON</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>OFF</source>
        <translation>OFF</translation>
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
        <translation>Riga %1, colonna %2 (byte %3): il file non è JSON valido (%4)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The file is JSON but not a Rung Studio project (no top-level object)</source>
        <translation>Il file è JSON ma non è un progetto Rung Studio (nessun oggetto al livello superiore)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The file is JSON but not a Rung Studio project (&quot;format&quot; is not &quot;%1&quot;)</source>
        <translation>Il file è JSON ma non è un progetto Rung Studio (&quot;format&quot; non è &quot;%1&quot;)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The project was written by a newer Rung Studio (schema %1); this version reads schema %2 and older</source>
        <translation>Il progetto è stato scritto da una versione più recente di Rung Studio (schema %1); questa versione legge lo schema %2 e precedenti</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&quot;schema&quot; must be a positive number</source>
        <translation>&quot;schema&quot; deve essere un numero positivo</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>&quot;target&quot;: unknown PLC family &quot;%1&quot;</source>
        <translation>&quot;target&quot;: famiglia PLC sconosciuta &quot;%1&quot;</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&quot;model&quot;: %1 has no model &quot;%2&quot;</source>
        <translation>&quot;model&quot;: %1 non ha il modello &quot;%2&quot;</translation>
    </message>
    <message>
        <location line="+22"/>
        <location line="+67"/>
        <source>%1: an object with &quot;device&quot; and &quot;name&quot; is expected</source>
        <translation>%1: è atteso un oggetto con &quot;device&quot; e &quot;name&quot;</translation>
    </message>
    <message>
        <location line="-43"/>
        <source>setValues.%1: a whole number between -%2 and %2 is expected</source>
        <translation>setValues.%1: è atteso un numero intero tra -%2 e %2</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1: an object with &quot;name&quot; and &quot;devices&quot; is expected</source>
        <translation>%1: è atteso un oggetto con &quot;name&quot; e &quot;devices&quot;</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>%1.devices[%2]: a device name is expected</source>
        <translation>%1.devices[%2]: è atteso il nome di un operando</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1.formats.%2: &quot;%3&quot; is no format (dec, signed, hex, bin, bcd)</source>
        <translation>%1.formats.%2: &quot;%3&quot; non è un formato (dec, signed, hex, bin, bcd)</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>a string</source>
        <translation>una stringa</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>an array</source>
        <translation>un array</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>an object</source>
        <translation>un oggetto</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>a number</source>
        <translation>un numero</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>another value</source>
        <translation>un altro valore</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1: %2 is expected</source>
        <translation>%1: il valore deve essere %2</translation>
    </message>
    <message>
        <location line="+104"/>
        <source>%1.outputs: [row, &quot;instruction&quot;] with a row inside the rung is expected</source>
        <translation>%1.outputs: è atteso [riga, &quot;istruzione&quot;] con una riga interna al segmento</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1.outputs: row %2 has two outputs</source>
        <translation>%1.outputs: la riga %2 ha due uscite</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>%1.outputs: &quot;%2&quot; takes up to %3 input rows, one box per rung</source>
        <translation>%1.outputs: &quot;%2&quot; accetta fino a %3 righe di ingresso, un blocco funzione per segmento</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1.outputs: the input rows of &quot;%2&quot; start at its own row and go down inside the rung</source>
        <translation>%1.outputs: le righe di ingresso di &quot;%2&quot; partono dalla sua riga e scendono all&apos;interno del segmento</translation>
    </message>
    <message>
        <location line="-125"/>
        <source>%1: a rung object is expected</source>
        <translation>%1: è atteso un oggetto segmento</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>%1: &quot;rows&quot; must be 1..1000 and &quot;columns&quot; 0..1000</source>
        <translation>%1: &quot;rows&quot; deve essere 1..1000 e &quot;columns&quot; 0..1000</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1.cells: %2 rows are expected, the file has %3</source>
        <translation>%1.cells: sono attese %2 righe, il file ne ha %3</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1.cells[%2]: an array of cells is expected</source>
        <translation>%1.cells[%2]: è atteso un array di celle</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1.cells[%2]: %3 cells are expected, the file has %4</source>
        <translation>%1.cells[%2]: sono attese %3 celle, il file ne ha %4</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1.cells[%2][%3]: a cell is a string (&quot;&quot;, &quot;-&quot; or a contact)</source>
        <translation>%1.cells[%2][%3]: una cella è una stringa (&quot;&quot;, &quot;-&quot; o un contatto)</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>%1.links: [%2, %3] is outside the rung</source>
        <translation>%1.links: [%2, %3] è fuori dal segmento</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>one instruction is expected</source>
        <translation>è attesa una sola istruzione</translation>
    </message>
    <message>
        <location filename="../model/project/file_read.cpp" line="+13"/>
        <source>%1: cannot open the file (%2)</source>
        <translation>%1: impossibile aprire il file (%2)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: the file is %2 MB; the most Rung Studio reads is %3 MB</source>
        <translation>%1: il file è di %2 MB; Rung Studio legge al massimo %3 MB</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: the file is larger than %2 MB, the most Rung Studio reads</source>
        <translation>%1: il file supera %2 MB, il massimo che Rung Studio legge</translation>
    </message>
    <message>
        <location filename="../model/project/project.cpp" line="+165"/>
        <source>%1: cannot write the file (%2)</source>
        <translation>%1: impossibile scrivere il file (%2)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1: saving failed (%2); the previous file is unchanged</source>
        <translation>%1: salvataggio non riuscito (%2); il file precedente è invariato</translation>
    </message>
    <message>
        <location filename="../model/project/program_file.cpp" line="+30"/>
        <source>unknown target %1 (%2)</source>
        <translation>famiglia PLC sconosciuta: %1 (%2)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1: unknown target %2 (%3)</source>
        <translation>%1: famiglia PLC sconosciuta: %2 (%3)</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1 is a %2 project, not %3</source>
        <translation>%1 è un progetto %2, non %3</translation>
    </message>
</context>
<context>
    <name>rung::model::SymbolsCsv</name>
    <message>
        <location filename="../model/project/symbols_csv.cpp" line="+113"/>
        <source>a symbol without a device</source>
        <translation>un simbolo senza operando</translation>
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
        <translation>la porta periferica dell&apos;unità CPU (Host Link, 9600 bps 7E2, unità 0)</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>input channels</source>
        <translation>canali di ingresso</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>output channels</source>
        <translation>canali di uscita</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>work channels</source>
        <translation>canali di lavoro</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>special channels</source>
        <translation>canali speciali</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>holding relays</source>
        <translation>relè di mantenimento</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>link relays</source>
        <translation>relè di collegamento</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>temporary relays</source>
        <translation>relè temporanei</translation>
    </message>
    <message>
        <location line="+4"/>
        <location filename="../model/target/target_pl110.cpp" line="+87"/>
        <location filename="../model/target/target_vpc.cpp" line="+61"/>
        <source>timers</source>
        <translation>temporizzatori</translation>
    </message>
    <message>
        <location line="+8"/>
        <location filename="../model/target/target_pl110.cpp" line="+5"/>
        <location filename="../model/target/target_vigor.cpp" line="+241"/>
        <location filename="../model/target/target_vpc.cpp" line="+5"/>
        <source>counters</source>
        <translation>contatori</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>data memory</source>
        <translation>memoria dati</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>read-only data memory</source>
        <translation>memoria dati di sola lettura</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>always ON</source>
        <translation>sempre ON</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>always OFF</source>
        <translation>sempre OFF</translation>
    </message>
    <message>
        <location line="+2"/>
        <location filename="../model/target/target_pl110.cpp" line="+73"/>
        <location filename="../model/target/target_vigor.cpp" line="+43"/>
        <source>ON for the first scan</source>
        <translation>ON per la prima scansione</translation>
    </message>
    <message>
        <location line="+2"/>
        <location filename="../model/target/target_vigor.cpp" line="+8"/>
        <source>1 min clock</source>
        <translation>clock da 1 min</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>0.02 s clock</source>
        <translation>clock da 0,02 s</translation>
    </message>
    <message>
        <location line="+2"/>
        <location filename="../model/target/target_vpc.cpp" line="+58"/>
        <source>0.1 s clock</source>
        <translation>clock da 0,1 s</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>0.2 s clock</source>
        <translation>clock da 0,2 s</translation>
    </message>
    <message>
        <location line="+2"/>
        <location filename="../model/target/target_vigor.cpp" line="-2"/>
        <location filename="../model/target/target_vpc.cpp" line="+2"/>
        <source>1 s clock</source>
        <translation>clock da 1 s</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>ER: instruction execution error</source>
        <translation>ER: errore di esecuzione dell&apos;istruzione</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>CY: carry</source>
        <translation>CY: riporto</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>GR: greater than</source>
        <translation>GR: maggiore</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>EQ: equal</source>
        <translation>EQ: uguale</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>LE: less than</source>
        <translation>LE: minore</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>ON for one cycle when a step starts</source>
        <translation>ON per un ciclo quando una fase inizia</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>FAL number of a non-fatal error in 253.00..253.07 (BCD)</source>
        <translation>numero FAL di un errore non grave in 253.00..253.07 (BCD)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>analog setting 0 (BCD 0..200)</source>
        <translation>impostazione analogica 0 (BCD 0..200)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>analog setting 1 (BCD 0..200)</source>
        <translation>impostazione analogica 1 (BCD 0..200)</translation>
    </message>
    <message>
        <location line="+5"/>
        <location filename="../model/target/target_pl110.cpp" line="+87"/>
        <location filename="../model/target/target_vigor.cpp" line="+95"/>
        <location filename="../model/target/target_vpc.cpp" line="+5"/>
        <source>Start a block with a normally open contact</source>
        <translation>Inizia un blocco con un contatto normalmente aperto</translation>
    </message>
    <message>
        <location line="+3"/>
        <location filename="../model/target/target_pl110.cpp" line="+1"/>
        <location filename="../model/target/target_vigor.cpp" line="+3"/>
        <location filename="../model/target/target_vpc.cpp" line="+1"/>
        <source>Start a block with a normally closed contact</source>
        <translation>Inizia un blocco con un contatto normalmente chiuso</translation>
    </message>
    <message>
        <location line="+3"/>
        <location filename="../model/target/target_pl110.cpp" line="+2"/>
        <location filename="../model/target/target_vigor.cpp" line="+9"/>
        <location filename="../model/target/target_vpc.cpp" line="+2"/>
        <source>Normally open contact in series</source>
        <translation>Contatto normalmente aperto in serie</translation>
    </message>
    <message>
        <location line="+2"/>
        <location filename="../model/target/target_pl110.cpp" line="+1"/>
        <location filename="../model/target/target_vigor.cpp" line="+3"/>
        <location filename="../model/target/target_vpc.cpp" line="+1"/>
        <source>Normally closed contact in series</source>
        <translation>Contatto normalmente chiuso in serie</translation>
    </message>
    <message>
        <location line="+2"/>
        <location filename="../model/target/target_pl110.cpp" line="+3"/>
        <location filename="../model/target/target_vigor.cpp" line="+9"/>
        <location filename="../model/target/target_vpc.cpp" line="+2"/>
        <source>Normally open contact in parallel</source>
        <translation>Contatto normalmente aperto in parallelo</translation>
    </message>
    <message>
        <location line="+2"/>
        <location filename="../model/target/target_pl110.cpp" line="+1"/>
        <location filename="../model/target/target_vigor.cpp" line="+3"/>
        <location filename="../model/target/target_vpc.cpp" line="+1"/>
        <source>Normally closed contact in parallel</source>
        <translation>Contatto normalmente chiuso in parallelo</translation>
    </message>
    <message>
        <location line="+4"/>
        <location filename="../model/target/target_pl110.cpp" line="+5"/>
        <location filename="../model/target/target_vigor.cpp" line="+18"/>
        <location filename="../model/target/target_vpc.cpp" line="+2"/>
        <source>Connect the last two blocks in series</source>
        <translation>Collega in serie gli ultimi due blocchi</translation>
    </message>
    <message>
        <location line="+2"/>
        <location filename="../model/target/target_pl110.cpp" line="+2"/>
        <location filename="../model/target/target_vigor.cpp" line="+3"/>
        <location filename="../model/target/target_vpc.cpp" line="+2"/>
        <source>Connect the last two blocks in parallel</source>
        <translation>Collega in parallelo gli ultimi due blocchi</translation>
    </message>
    <message>
        <location line="+2"/>
        <location filename="../model/target/target_pl110.cpp" line="+33"/>
        <location filename="../model/target/target_vigor.cpp" line="+12"/>
        <location filename="../model/target/target_vpc.cpp" line="+2"/>
        <source>Output coil</source>
        <translation>Bobina di uscita</translation>
    </message>
    <message>
        <location line="+2"/>
        <location filename="../model/target/target_vpc.cpp" line="+3"/>
        <source>Inverted output coil</source>
        <translation>Bobina di uscita negata</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Set (latch) a bit</source>
        <translation>Imposta (memorizza) un bit</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Reset a bit</source>
        <translation>Resetta un bit</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Keep: set = last but one block, reset = last block; reset wins</source>
        <translation>Keep: set = penultimo blocco, reset = ultimo blocco; prevale il reset</translation>
    </message>
    <message>
        <location line="+6"/>
        <location filename="../model/target/target_vigor.cpp" line="+9"/>
        <source>ON for one scan on a rising edge</source>
        <translation>ON per una scansione su un fronte di salita</translation>
    </message>
    <message>
        <location line="+4"/>
        <location filename="../model/target/target_vigor.cpp" line="+3"/>
        <source>ON for one scan on a falling edge</source>
        <translation>ON per una scansione su un fronte di discesa</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Timer, 0.1 s, counts down from the BCD set value</source>
        <translation>Temporizzatore, 0,1 s, conta all&apos;indietro dal valore di preset BCD</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>High-speed timer, 0.01 s, counts down from the BCD set value</source>
        <translation>Temporizzatore veloce, 0,01 s, conta all&apos;indietro dal valore di preset BCD</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Down counter: count = last but one block, reset = last block</source>
        <translation>Contatore all&apos;indietro: conteggio = penultimo blocco, reset = ultimo blocco</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Reversible counter: up, down and reset inputs; wraps at the limits</source>
        <translation>Contatore reversibile: ingressi avanti, indietro e reset; ricomincia ai limiti</translation>
    </message>
    <message>
        <location line="+7"/>
        <location filename="../model/target/target_vpc.cpp" line="+41"/>
        <source>Interlock: what follows runs under this condition</source>
        <translation>Interblocco: ciò che segue viene eseguito sotto questa condizione</translation>
    </message>
    <message>
        <location line="+4"/>
        <location filename="../model/target/target_vpc.cpp" line="+3"/>
        <source>Clear the interlock</source>
        <translation>Chiude l&apos;interblocco</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Jump: while OFF, skip to the JME with the same number</source>
        <translation>Salto: mentre è OFF, salta al JME con lo stesso numero</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>End of the jump with this number</source>
        <translation>Fine del salto con questo numero</translation>
    </message>
    <message>
        <location line="+42"/>
        <source>analog settings</source>
        <translation>regolazioni analogiche</translation>
    </message>
    <message>
        <location filename="../model/target/target_cpm1_instructions.cpp" line="+70"/>
        <source>subroutine number</source>
        <translation>numero di subroutine</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>FAL number</source>
        <translation>numero FAL</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>start word</source>
        <translation>word iniziale</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>end word</source>
        <translation>word finale</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>result</source>
        <translation>risultato</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>bit designator</source>
        <translation>selettore di bit</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>digit designator</source>
        <translation>selettore di cifre</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+2"/>
        <source>control bit</source>
        <translation>bit di controllo</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Move a channel or a constant</source>
        <translation>Sposta un canale o una costante</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Move the inverse of S to D</source>
        <translation>Copia l&apos;inverso di S in D</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Move one bit: Bi = #DDSS, destination bit DD, source bit SS</source>
        <translation>Copia un bit: Bi = #DDSS, bit di destinazione DD, bit sorgente SS</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Move digits: Di = #0DNS, first destination digit D, N+1 digits, first source digit S</source>
        <translation>Copia cifre: Di = #0DNS, prima cifra di destinazione D, N+1 cifre, prima cifra sorgente S</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Shift register: data, shift pulse and reset inputs; St..E</source>
        <translation>Registro a scorrimento: ingressi dato, impulso di scorrimento e reset; St..E</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Shift the words St..E up by one word, #0000 into St</source>
        <translation>Sposta le word St..E di una word verso l&apos;alto, #0000 in St</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Compare two words: GR 255.05, EQ 255.06, LE 255.07</source>
        <translation>Confronta due word: GR 255.05, EQ 255.06, LE 255.07</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>R = the value of the BCD digits of S</source>
        <translation>R = il valore delle cifre BCD di S</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>R = S as BCD digits</source>
        <translation>R = S in cifre BCD</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Invert every bit of a channel</source>
        <translation>Inverte ogni bit di un canale</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>R = I1 AND I2, bit by bit</source>
        <translation>R = I1 AND I2, bit per bit</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>R = I1 OR I2, bit by bit</source>
        <translation>R = I1 OR I2, bit per bit</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>R = I1 XOR I2, bit by bit</source>
        <translation>R = I1 XOR I2, bit per bit</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Add 1 to a BCD channel (9999 -&gt; 0000)</source>
        <translation>Aggiunge 1 a un canale BCD (9999 -&gt; 0000)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Subtract 1 from a BCD channel (0000 -&gt; 9999)</source>
        <translation>Sottrae 1 da un canale BCD (0000 -&gt; 9999)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Set the carry flag CY (255.04)</source>
        <translation>Imposta il flag di riporto CY (255.04)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Clear the carry flag CY (255.04)</source>
        <translation>Azzera il flag di riporto CY (255.04)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>R = Au + Ad + CY in BCD; CY on a carry</source>
        <translation>R = Au + Ad + CY in BCD; CY in caso di riporto</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>R = Mi - Su - CY in BCD; below zero: the 10&apos;s complement and CY</source>
        <translation>R = Mi - Su - CY in BCD; sotto zero: il complemento a 10 e CY</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>R+1, R = Md x Mr in BCD (8 digits)</source>
        <translation>R+1, R = Md x Mr in BCD (8 cifre)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>R = Dd / Dr in BCD, R+1 = the remainder</source>
        <translation>R = Dd / Dr in BCD, R+1 = il resto</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>R = Au + Ad + CY in binary; CY above FFFF</source>
        <translation>R = Au + Ad + CY in binario; CY oltre FFFF</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>R = Mi - Su - CY in binary; below zero: the 2&apos;s complement and CY</source>
        <translation>R = Mi - Su - CY in binario; sotto zero: il complemento a 2 e CY</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Run subroutine N, then go on after SBS</source>
        <translation>Esegue la subroutine N, poi prosegue dopo SBS</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Start of subroutine N (after the main program; ends the main program)</source>
        <translation>Inizio della subroutine N (dopo il programma principale, che termina qui)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>End of the subroutine: back after its SBS</source>
        <translation>Fine della subroutine: ritorno dopo la sua SBS</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Non-fatal error N: N into 253.00..253.07, the program goes on; FAL 00 clears it</source>
        <translation>Errore non grave N: N in 253.00..253.07, il programma prosegue; FAL 00 lo cancella</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Start of the step of control bit B; without B: end of the steps</source>
        <translation>Inizio della fase con bit di controllo B; senza B: fine delle fasi</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>End the current step and start the step of control bit B</source>
        <translation>Termina la fase corrente e avvia la fase con bit di controllo B</translation>
    </message>
    <message>
        <location filename="../model/target/target_cpm1.cpp" line="-37"/>
        <location filename="../model/target/target_vigor.cpp" line="+25"/>
        <source>No operation</source>
        <translation>Nessuna operazione</translation>
    </message>
    <message>
        <location line="+3"/>
        <location filename="../model/target/target_pl110.cpp" line="+199"/>
        <location filename="../model/target/target_vigor.cpp" line="-1"/>
        <location filename="../model/target/target_vpc.cpp" line="+5"/>
        <source>End of the program</source>
        <translation>Fine del programma</translation>
    </message>
    <message>
        <location filename="../model/target/target_pl110.cpp" line="-457"/>
        <source>IF contact: ON while S1 ? S2 is true</source>
        <translation>Contatto IF: ON mentre S1 ? S2 è vero</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>digital inputs</source>
        <translation>ingressi digitali</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>digital outputs</source>
        <translation>uscite digitali</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>bistable relays</source>
        <translation>relè bistabili</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>markers</source>
        <translation>marker</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>timers (with SM0.13 ON)</source>
        <translation>temporizzatori (con SM0.13 ON)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>variables</source>
        <translation>variabili</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>special markers</source>
        <translation>marker speciali</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>variables, double words</source>
        <translation>variabili, doppie word</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>special markers, double words</source>
        <translation>special marker, doppie word</translation>
    </message>
    <message>
        <location line="+6"/>
        <location filename="../model/target/target_vpc.cpp" line="-106"/>
        <source>analog inputs</source>
        <translation>ingressi analogici</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>trimmers</source>
        <translation>trimmer</translation>
    </message>
    <message>
        <location line="+4"/>
        <location filename="../model/target/target_vpc.cpp" line="+5"/>
        <source>analog outputs</source>
        <translation>uscite analogiche</translation>
    </message>
    <message>
        <location line="+5"/>
        <location line="+3"/>
        <source>timer presets</source>
        <translation>preset dei temporizzatori</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>counter presets</source>
        <translation>preset dei contatori</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>EEPROM words</source>
        <translation>word EEPROM</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>MMC words</source>
        <translation>word MMC</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>display characters</source>
        <translation>caratteri del display</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>RUN/STOP (1 = RUN)</source>
        <translation>RUN/STOP (1 = RUN)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>60 s clock (30 s ON, 30 s OFF)</source>
        <translation>clock da 60 s (30 s ON, 30 s OFF)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>1 s clock (0.5 s ON, 0.5 s OFF)</source>
        <translation>clock da 1 s (0,5 s ON, 0,5 s OFF)</translation>
    </message>
    <message>
        <location line="+2"/>
        <location filename="../model/target/target_vpc.cpp" line="+25"/>
        <source>toggles every scan</source>
        <translation>commuta a ogni scansione</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>TEST: inputs are taken from SM37</source>
        <translation>TEST: gli ingressi sono presi da SM37</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>inputs I1..I8 in TEST mode (bit 0 = I1), cleared at power-on</source>
        <translation>ingressi I1..I8 in modalità TEST (bit 0 = I1), azzerata all&apos;accensione</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>counters C1..C16 off, timers T49..T64 on</source>
        <translation>contatori C1..C16 disattivati, temporizzatori T49..T64 attivi</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>last scan time (0.1 ms)</source>
        <translation>tempo dell&apos;ultima scansione (0,1 ms)</translation>
    </message>
    <message>
        <location line="+2"/>
        <location filename="../model/target/target_vigor.cpp" line="-174"/>
        <source>minimum scan time (0.1 ms)</source>
        <translation>tempo di scansione minimo (0,1 ms)</translation>
    </message>
    <message>
        <location line="+2"/>
        <location filename="../model/target/target_vigor.cpp" line="+2"/>
        <source>maximum scan time (0.1 ms)</source>
        <translation>tempo di scansione massimo (0,1 ms)</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>the encoders&apos; load bits and the stepper motor output on AQ1 are not modelled; the word is plain memory</source>
        <translation>i bit di caricamento degli encoder e l&apos;uscita AQ1 del motore passo passo non sono modellati; la word è semplice memoria</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the protocol address (the offset and the rotary switch) is not modelled; the word is plain memory</source>
        <translation>l&apos;indirizzo di protocollo (l&apos;offset e il rotary-switch) non è modellato; la word è semplice memoria</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the real-time clock is not modelled: the word keeps what the program writes and does not count</source>
        <translation>l&apos;orologio interno non è modellato: la word mantiene ciò che il programma scrive e non avanza</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>the encoders are not modelled: no count, no load, no rate; the word is plain memory</source>
        <translation>gli encoder non sono modellati: nessun conteggio, caricamento o frequenza; la word è semplice memoria</translation>
    </message>
    <message>
        <location line="-4"/>
        <source>the timed interrupts and the stepper ramp are not modelled (interrupt programs are not supported)</source>
        <translation>gli interrupt a tempo e la rampa del motore passo passo non sono modellati (i programmi di interrupt non sono supportati)</translation>
    </message>
    <message>
        <location filename="../model/target/target_pl110_comm.cpp" line="+38"/>
        <source>MODBUS RTU slave</source>
        <translation>Slave MODBUS RTU</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>MODBUS RTU master (COM / EXP)</source>
        <translation>Master MODBUS RTU (COM / EXP)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>NAIS MATSUSHITA-MASTER (COM / EXP, no frames)</source>
        <translation>NAIS MATSUSHITA-MASTER (COM / EXP, senza frame)</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>COM1, the RS-485 port</source>
        <translation>COM1, la porta RS-485</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>EXP1, the expansion port</source>
        <translation>EXP1, la porta di espansione</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>COM2, the USB programming port (57600 8N1)</source>
        <translation>COM2, la porta USB di programmazione (57600 8N1)</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>COM1 transmit buffer (bytes)</source>
        <translation>buffer di trasmissione COM1 (byte)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>COM1 receive buffer (bytes)</source>
        <translation>buffer di ricezione COM1 (byte)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>EXP1 transmit buffer (bytes)</source>
        <translation>buffer di trasmissione EXP1 (byte)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>EXP1 receive buffer (bytes)</source>
        <translation>buffer di ricezione EXP1 (byte)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>COM2 transmit buffer (bytes)</source>
        <translation>buffer di trasmissione COM2 (byte)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>COM2 receive buffer (bytes)</source>
        <translation>buffer di ricezione COM2 (byte)</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>serial port</source>
        <translation>porta seriale</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>number of characters</source>
        <translation>numero di caratteri</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Send n characters of the port&apos;s transmit buffer (free-port mode)</source>
        <translation>Trasmette n caratteri del buffer di trasmissione della porta (modalità free-port)</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>index</source>
        <translation>indice</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>operation</source>
        <translation>operazione</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>slave</source>
        <translation>slave</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>data type</source>
        <translation>tipo di dato</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>data number</source>
        <translation>numero del dato</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>PL110 area</source>
        <translation>area del PL110</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>number of words or bits</source>
        <translation>numero di word o bit</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>COM1 master query COM_1..COM_16: read or write a slave&apos;s words or bits while ON</source>
        <translation>Interrogazione master COM1 COM_1..COM_16: legge o scrive word o bit di uno slave finché è attiva</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>EXP1 master query EXP_1..EXP_16: read or write a slave&apos;s words or bits while ON</source>
        <translation>Interrogazione master EXP1 EXP_1..EXP_16: legge o scrive word o bit di uno slave finché è attiva</translation>
    </message>
    <message>
        <location filename="../model/target/target_pl110.cpp" line="+8"/>
        <source>the input filters and analog settings are not modelled: an analog input reads the value set in the simulator</source>
        <translation>i filtri degli ingressi e le impostazioni analogiche non sono modellati: un ingresso analogico legge il valore impostato nel simulatore</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>not in the manual&apos;s table of special markers: 4.2.19 names SM32..SM34 for free-port and SM35..SM37 for the characters received, the table (2.1.2) has SM78 / SM88 / SM98 and SM79 / SM89 / SM99, which the simulator follows; the word is plain memory</source>
        <translation>non è nella tabella degli special marker del manuale: il 4.2.19 indica SM32..SM34 per il free-port e SM35..SM37 per i caratteri ricevuti, la tabella (2.1.2) ha SM78 / SM88 / SM98 e SM79 / SM89 / SM99, che il simulatore segue; la word è semplice memoria</translation>
    </message>
    <message>
        <location line="+6"/>
        <location line="+5"/>
        <source>the protocol&apos;s baud rate and format come from the port&apos;s settings (project or network file), not from the program; the word is plain memory</source>
        <translation>il baud-rate e il formato del protocollo vengono dalle impostazioni della porta (progetto o file di rete), non dal programma; la word è semplice memoria</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>COM2 runs the MODBUS slave only: its status, reply delay, supervision time and counters are not modelled; the word is plain memory</source>
        <translation>COM2 funziona solo da slave MODBUS: il suo stato, il ritardo di risposta, il tempo di controllo e i contatori non sono modellati; la word è semplice memoria</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>NOT contact: invert the power flow</source>
        <translation>Contatto NOT: inverte il flusso di corrente</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>P contact: power flows for one scan when it turns ON</source>
        <translation>Contatto P: la corrente passa per una scansione quando si attiva</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>N contact: power flows for one scan when it turns OFF</source>
        <translation>Contatto N: la corrente passa per una scansione quando si disattiva</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Start a block with an immediate input contact</source>
        <translation>Inizia un blocco con un contatto di ingresso immediato</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Start a block with a normally closed immediate input contact</source>
        <translation>Inizia un blocco con un contatto di ingresso immediato normalmente chiuso</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Immediate input contact in series</source>
        <translation>Contatto di ingresso immediato in serie</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Normally closed immediate input contact in series</source>
        <translation>Contatto di ingresso immediato normalmente chiuso in serie</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Immediate input contact in parallel</source>
        <translation>Contatto di ingresso immediato in parallelo</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Normally closed immediate input contact in parallel</source>
        <translation>Contatto di ingresso immediato normalmente chiuso in parallelo</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Immediate output coil: writes the terminal at once</source>
        <translation>Bobina di uscita immediata: scrive subito il morsetto</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Bistable relay coil: each activation toggles the relay</source>
        <translation>Bobina di relè bistabile: ogni attivazione commuta il relè</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>bit number</source>
        <translation>numero del bit</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Set a bit (0..15) of a word to 1</source>
        <translation>Porta a 1 un bit (0..15) di una word</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Reset a bit (0..15) of a word to 0</source>
        <translation>Porta a 0 un bit (0..15) di una word</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>preset</source>
        <translation>preset</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>time base (ms)</source>
        <translation>base tempi (ms)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>On-delay timer: T ON once the time reaches PT; OFF resets</source>
        <translation>Temporizzatore all&apos;eccitazione: T ON quando il tempo raggiunge PT; OFF lo azzera</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Off-delay timer: T ON at once, OFF when PT has elapsed after OFF</source>
        <translation>Temporizzatore alla diseccitazione: T ON subito, OFF quando è trascorso PT dopo l&apos;OFF</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Accumulating on-delay timer: keeps its time while OFF</source>
        <translation>Temporizzatore all&apos;eccitazione a ritenzione: conserva il tempo mentre è OFF</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Up counter: UP, DOWN and RESET inputs; C ON while the count &gt;= PV</source>
        <translation>Contatore avanti: ingressi UP, DOWN e RESET; C ON mentre il conteggio è &gt;= PV</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Down counter from PV: UP, DOWN and RESET (load PV) inputs; C ON at 0</source>
        <translation>Contatore all&apos;indietro da PV: ingressi UP, DOWN e RESET (carica PV); C ON a 0</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>operator</source>
        <translation>operatore</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Math formula: D = S1 op S2, op one of + - * / | &amp; ^ &lt;&lt; &gt;&gt;</source>
        <translation>Formula matematica: D = S1 op S2, op uno tra + - * / | &amp; ^ &lt;&lt; &gt;&gt;</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Move a value or a word to D</source>
        <translation>Sposta un valore o una word in D</translation>
    </message>
    <message>
        <location line="+11"/>
        <location filename="../model/target/target_vigor.cpp" line="+204"/>
        <location line="+74"/>
        <location line="+102"/>
        <source>number of words</source>
        <translation>numero di word</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Move n words from S (or the value S) to D</source>
        <translation>Sposta n word da S (o il valore S) a D</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Indexed move: D[index] = S, the area used as a vector</source>
        <translation>Spostamento indicizzato: D[indice] = S, l&apos;area usata come vettore</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Set the range of an AI, TR, AQ or PID output</source>
        <translation>Imposta il campo di un&apos;uscita AI, TR, AQ o PID</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Tune an on/off positioner</source>
        <translation>Taratura di un posizionatore on/off</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>On/off positioner</source>
        <translation>Posizionatore on/off</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Start a PID loop</source>
        <translation>Avvia un regolatore PID</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PID control loop</source>
        <translation>Regolatore PID</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Set the output of a PID loop</source>
        <translation>Imposta l&apos;uscita di un regolatore PID</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Setpoint generator with acceleration and deceleration ramps</source>
        <translation>Generatore di setpoint con rampe di accelerazione e decelerazione</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Convert a value</source>
        <translation>Converte un valore</translation>
    </message>
    <message>
        <location line="+59"/>
        <source>row</source>
        <translation>riga</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>column</source>
        <translation>colonna</translation>
    </message>
    <message>
        <location line="-20"/>
        <source>state (0 disabled, 1 shown, 2 editable)</source>
        <translation>stato (0 disabilitato, 1 visualizzato, 2 modificabile)</translation>
    </message>
    <message>
        <location line="-8"/>
        <source>variable shown</source>
        <translation>variabile visualizzata</translation>
    </message>
    <message>
        <location line="-6"/>
        <source>display field</source>
        <translation>campo del display</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>minimum</source>
        <translation>minimo</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>maximum</source>
        <translation>massimo</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Set a display field: its state, variable and limits</source>
        <translation>Imposta un campo del display: stato, variabile e limiti</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>type (0 16 bit signed, 1 16 bit unsigned, 2 32 bit signed)</source>
        <translation>tipo (0 16 bit con segno, 1 16 bit senza segno, 2 32 bit con segno)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>total digits</source>
        <translation>numero totale di cifre</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>decimals</source>
        <translation>cifre decimali</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>fill (0 spaces, 1 zeros)</source>
        <translation>riempimento (0 spazi, 1 zeri)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Format a display field: type, digits, decimals, fill</source>
        <translation>Formatta un campo del display: tipo, cifre, decimali, riempimento</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>access (0 free, 1 password)</source>
        <translation>accesso (0 libero, 1 con password)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Place a display field: row, column and access</source>
        <translation>Posiziona un campo del display: riga, colonna e accesso</translation>
    </message>
    <message>
        <location filename="../model/target/target_vigor.cpp" line="-656"/>
        <source>Compare contact: ON while S1 ? S2</source>
        <translation>Contatto di confronto: ON mentre S1 ? S2</translation>
    </message>
    <message>
        <location line="+162"/>
        <location filename="../model/target/target_vpc.cpp" line="-68"/>
        <source>inputs</source>
        <translation>ingressi</translation>
    </message>
    <message>
        <location line="+5"/>
        <location filename="../model/target/target_vpc.cpp" line="+5"/>
        <source>outputs</source>
        <translation>uscite</translation>
    </message>
    <message>
        <location line="+4"/>
        <location filename="../model/target/target_vpc.cpp" line="+14"/>
        <source>auxiliary relays</source>
        <translation>relè ausiliari</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>latched auxiliary relays</source>
        <translation>relè ausiliari ritentivi</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>special relays</source>
        <translation>relè speciali</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>step relays</source>
        <translation>relè di passo</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>latched step relays</source>
        <translation>relè di passo ritentivi</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>timers (100 ms)</source>
        <translation>temporizzatori (100 ms)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>timers (10 ms)</source>
        <translation>temporizzatori (10 ms)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>accumulating timers (1 ms)</source>
        <translation>temporizzatori a ritenzione (1 ms)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>accumulating timers (100 ms)</source>
        <translation>temporizzatori a ritenzione (100 ms)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>latched counters</source>
        <translation>contatori ritentivi</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>32-bit counters</source>
        <translation>contatori a 32 bit</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>data registers</source>
        <translation>registri dati</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>latched data registers</source>
        <translation>registri dati ritentivi</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>special registers</source>
        <translation>registri speciali</translation>
    </message>
    <message>
        <location line="+9"/>
        <location line="+4"/>
        <source>index registers</source>
        <translation>registri indice</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>ON while the PLC runs</source>
        <translation>ON mentre il PLC è in RUN</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>10 ms clock</source>
        <translation>clock da 10 ms</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>100 ms clock</source>
        <translation>clock da 100 ms</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>SMOV works on hexadecimal digits</source>
        <translation>SMOV opera su cifre esadecimali</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>current scan time (0.1 ms)</source>
        <translation>tempo di scansione attuale (0,1 ms)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>parallel operation or RS communication error, PLC keeps running</source>
        <translation>errore di funzionamento parallelo o di comunicazione RS, il PLC continua a funzionare</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>parallel link: this unit is the master</source>
        <translation>collegamento parallelo: questa unità è il master</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>parallel link: this unit is a slave</source>
        <translation>collegamento parallelo: questa unità è uno slave</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>parallel operation normal</source>
        <translation>funzionamento parallelo normale</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>CP2 modem: start dialing (OFF to ON)</source>
        <translation>modem CP2: avvio composizione (da OFF a ON)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>CP2 modem: dialing failed</source>
        <translation>modem CP2: composizione non riuscita</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>RS instruction send flag</source>
        <translation>flag di invio dell&apos;istruzione RS</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>RS instruction receive done</source>
        <translation>ricezione dell&apos;istruzione RS completata</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>CP2 modem CD signal</source>
        <translation>segnale CD del modem CP2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>time-out during RS</source>
        <translation>time-out durante RS</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>parallel operation high-speed transfer</source>
        <translation>trasferimento ad alta velocità del funzionamento parallelo</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>CPU link communication failed (master); M9184..M9190 slaves 1..7</source>
        <translation>comunicazione del collegamento CPU non riuscita (master); M9184..M9190 slave 1..7</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>RS communication error code</source>
        <translation>codice di errore della comunicazione RS</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>display mode of the display screen</source>
        <translation>modo di visualizzazione dello schermo</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>number of the D register shown in mode 3</source>
        <translation>numero del registro D visualizzato nel modo 3</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>computer link station number</source>
        <translation>numero di stazione del collegamento al computer</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>RS: number of data left to send</source>
        <translation>RS: numero di dati ancora da inviare</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>RS: number of data received</source>
        <translation>RS: numero di dati ricevuti</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>RS, LINK and MBUS time-out, x 10 ms (0: 100 ms)</source>
        <translation>time-out di RS, LINK e MBUS, x 10 ms (0: 100 ms)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>CPU link communication time-out time</source>
        <translation>collegamento CPU: tempo di time-out della comunicazione</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>CPU link: number of slave stations</source>
        <translation>collegamento CPU: numero di stazioni slave</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>CPU link: transfer range mode</source>
        <translation>collegamento CPU: modo del campo di trasferimento</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>CPU link: communication retries</source>
        <translation>collegamento CPU: tentativi di comunicazione</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>current network scan time</source>
        <translation>tempo di scansione attuale della rete</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>maximum network scan time</source>
        <translation>tempo di scansione massimo della rete</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>CPU link: communication errors of the master; D9204..D9210 slaves 1..7</source>
        <translation>collegamento CPU: errori di comunicazione del master; D9204..D9210 slave 1..7</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>CPU link: error code of slave 1 (D9213..D9218: slaves 2..7): 00H none, 01H time-out, 05H sum error</source>
        <translation>collegamento CPU: codice di errore dello slave 1 (D9213..D9218: slave 2..7): 00H nessuno, 01H time-out, 05H errore di somma</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Start a block with a rising-edge contact</source>
        <translation>Inizia un blocco con un contatto sul fronte di salita</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Start a block with a falling-edge contact</source>
        <translation>Inizia un blocco con un contatto sul fronte di discesa</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Rising-edge contact in series</source>
        <translation>Contatto sul fronte di salita in serie</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Falling-edge contact in series</source>
        <translation>Contatto sul fronte di discesa in serie</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Rising-edge contact in parallel</source>
        <translation>Contatto sul fronte di salita in parallelo</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Falling-edge contact in parallel</source>
        <translation>Contatto sul fronte di discesa in parallelo</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Push the result onto the branch stack</source>
        <translation>Salva il risultato nello stack delle diramazioni</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Read the top of the branch stack</source>
        <translation>Legge la cima dello stack delle diramazioni</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Pop the branch stack</source>
        <translation>Preleva dallo stack delle diramazioni</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Invert the result</source>
        <translation>Inverte il risultato</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Set (latch) a device</source>
        <translation>Imposta (memorizza) un operando</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Reset a device, a timer or a counter</source>
        <translation>Resetta un operando, un temporizzatore o un contatore</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>On-delay timer: T0..T199 100 ms, T200..T245 10 ms units; T246..T249 1 ms, T250..T255 100 ms accumulating (reset with RST)</source>
        <translation>Temporizzatore di ritardo all&apos;inserzione: T0..T199 in unità di 100 ms, T200..T245 di 10 ms; T246..T249 1 ms, T250..T255 100 ms a ritenzione (azzerati con RST)</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>Move 32 bits: S (S, S+1) to D (low word), D+1 (high word)</source>
        <translation>Sposta 32 bit: S (S, S+1) in D (word bassa), D+1 (word alta)</translation>
    </message>
    <message>
        <location line="+88"/>
        <source>module number</source>
        <translation>numero del modulo</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>buffer memory word</source>
        <translation>word della memoria buffer</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>Write n words to special module m1, at m2, once on a rising edge</source>
        <translation>Scrive n word nel modulo speciale m1, da m2, una volta sul fronte di salita</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Check code: the sum of n bytes from S into D, their parity into D+1 (M9161 ON: one byte a word)</source>
        <translation>Codice di controllo: la somma di n byte da S in D, la loro parità in D+1 (M9161 ON: un byte per word)</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>first input or output</source>
        <translation>primo ingresso o uscita</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>number of digits</source>
        <translation>numero di cifre</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Convert n ASCII characters from S to hexadecimal in D</source>
        <translation>Converte n caratteri ASCII da S in esadecimale in D</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Convert n hexadecimal digits from S to ASCII in D</source>
        <translation>Converte n cifre esadecimali da S in ASCII in D</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>first word to send</source>
        <translation>primo registro da inviare</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>first word received</source>
        <translation>primo registro ricevuto</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Serial communication on CP2: send m words from S, receive n words into D</source>
        <translation>Comunicazione seriale su CP2: invia m word da S, riceve n word in D</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>table</source>
        <translation>inizio tabella</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>working area</source>
        <translation>blocco di lavoro</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Easy Link between PLCs: table from S1, working area S2</source>
        <translation>Easy Link tra PLC: tabella da S1, area di lavoro S2</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>MODBUS master: table from S1, working area S2</source>
        <translation>Master MODBUS: tabella da S1, area di lavoro S2</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>variable resistor</source>
        <translation>potenziometro</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Read the variable resistor (volume) VRn into D</source>
        <translation>Legge il potenziometro VRn in D</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Swap the high and low bytes of D</source>
        <translation>Scambia il byte alto e il byte basso di D</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>digit position</source>
        <translation>posizione della cifra</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Move m2 digits of S from digit m1 to D from digit n</source>
        <translation>Sposta m2 cifre di S dalla cifra m1 in D dalla cifra n</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>32 bits: D, D+1 = (S1, S1+1) / (S2, S2+1), D+2, D+3 = remainder</source>
        <translation>32 bit: D, D+1 = (S1, S1+1) / (S2, S2+1), D+2, D+3 = resto</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Alternate: D changes state at each rising edge of the input</source>
        <translation>Alterna: D cambia stato a ogni fronte di salita dell&apos;ingresso</translation>
    </message>
    <message>
        <location line="-319"/>
        <source>Counter: counts rising edges, reset with RST</source>
        <translation>Contatore: conta i fronti di salita, reset con RST</translation>
    </message>
    <message>
        <location line="-391"/>
        <source>Computer Link</source>
        <translation>Computer Link</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>CP1, the main unit&apos;s RS-232 port (Computer Link, 19200 bps, station 0)</source>
        <translation>CP1, la porta RS-232 dell&apos;unità base (Computer Link, 19200 bps, stazione 0)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>CP2, the second communication port (a card or a module)</source>
        <translation>CP2, la seconda porta di comunicazione (una scheda o un modulo)</translation>
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
        <translation>Non Protocol (senza protocollo)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>CP3, the VB-CADP&apos;s RS-485 port (Computer Link, 19200 bps, station 0..99)</source>
        <translation>CP3, la porta RS-485 del VB-CADP (Computer Link, 19200 bps, stazione 0..99)</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>VB-1COM serial module</source>
        <translation>modulo seriale VB-1COM</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>a VB-1COM serial module, numbered as FROM / TO name it</source>
        <translation>un modulo seriale VB-1COM, numerato come lo indicano FROM / TO</translation>
    </message>
    <message>
        <location line="+100"/>
        <source>variable resistors (panel)</source>
        <translation>potenziometri (pannello)</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>RS, CCD, ASCI, HEX: 8-bit mode, one byte a word (OFF: 16-bit)</source>
        <translation>RS, CCD, ASCI, HEX: modalità a 8 bit, un byte per word (OFF: 16 bit)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>ON for one scan when LINK or MBUS completed its table</source>
        <translation>ON per una scansione quando LINK o MBUS ha completato la sua tabella</translation>
    </message>
    <message>
        <location line="+174"/>
        <source>Step ladder: start of step S</source>
        <translation>Step ladder: inizio del passo S</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>End of the step ladder</source>
        <translation>Fine dello step ladder</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Move S to D</source>
        <translation>Sposta S in D</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>Move n words from S to D</source>
        <translation>Sposta n word da S a D</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Compare S1 with S2: D, D+1, D+2 = &gt;, =, &lt;</source>
        <translation>Confronta S1 con S2: D, D+1, D+2 = &gt;, =, &lt;</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Reset every device from D1 to D2</source>
        <translation>Resetta tutti gli operandi da D1 a D2</translation>
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
        <translation>D, D+1 = S1 x S2 (prodotto a 32 bit)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>D = S1 / S2, D+1 = remainder</source>
        <translation>D = S1 / S2, D+1 = resto</translation>
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
        <translation>D = S1 AND S2, bit per bit</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>D = S1 OR S2, bit by bit</source>
        <translation>D = S1 OR S2, bit per bit</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>D = S1 XOR S2, bit by bit</source>
        <translation>D = S1 XOR S2, bit per bit</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>D = every bit of S inverted</source>
        <translation>D = ogni bit di S invertito</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>D = S as BCD digits</source>
        <translation>D = S in cifre BCD</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>D = the value of the BCD digits S</source>
        <translation>D = il valore delle cifre BCD di S</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>Read n words of special module m1, from m2</source>
        <translation>Legge n word dal modulo speciale m1, da m2</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Write n words to special module m1, at m2</source>
        <translation>Scrive n word nel modulo speciale m1, a m2</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>Refresh n inputs or outputs now</source>
        <translation>Aggiorna subito n ingressi o uscite</translation>
    </message>
    <message>
        <location filename="../model/target/target_vpc.cpp" line="-41"/>
        <source>Compare contact between two decimal operands</source>
        <translation>Contatto di confronto tra due operandi decimali</translation>
    </message>
    <message>
        <location line="+44"/>
        <source>retentive auxiliary relays</source>
        <translation>relè ausiliari ritentivi</translation>
    </message>
    <message>
        <location line="+7"/>
        <location line="+4"/>
        <source>system relays</source>
        <translation>relè di sistema</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>registers</source>
        <translation>registri</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>parallel output (o00..o11)</source>
        <translation>uscita parallela (o00..o11)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>parallel input (i00..i11)</source>
        <translation>ingresso parallelo (i00..i11)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>RUN: always ON</source>
        <translation>RUN: sempre ON</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>ERR: program error</source>
        <translation>ERR: errore di programma</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>CON: PC connected</source>
        <translation>CON: PC collegato</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>VPCIO connected</source>
        <translation>VPCIO collegato</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>0.01 s clock</source>
        <translation>clock da 0,01 s</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>Transfer while the condition is OFF: d,s  d+s  d-s</source>
        <translation>Trasferimento mentre la condizione è OFF: d,s  d+s  d-s</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Transfer while the condition is ON: d,s  d+s  d-s</source>
        <translation>Trasferimento mentre la condizione è ON: d,s  d+s  d-s</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Latching relay: set = last but one block, reset = last block</source>
        <translation>Relè con ritenuta: set = penultimo blocco, reset = ultimo blocco</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Timer: 00..15 count down, 16..31 count up, 0.01 s</source>
        <translation>Temporizzatore: 00..15 contano all&apos;indietro, 16..31 in avanti, 0,01 s</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Counter: count = last but one block, reset = last block</source>
        <translation>Contatore: conteggio = penultimo blocco, reset = ultimo blocco</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Jump: skip up to JPE while the condition is OFF</source>
        <translation>Salto: salta fino a JPE mentre la condizione è OFF</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>End of a jump</source>
        <translation>Fine di un salto</translation>
    </message>
    <message>
        <location line="+65"/>
        <source>input LED: lit while the input is ON</source>
        <translation>LED d&apos;ingresso: acceso finché l&apos;ingresso è ON</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>output LED: lit while the output is ON</source>
        <translation>LED d&apos;uscita: acceso finché l&apos;uscita è ON</translation>
    </message>
    <message>
        <location filename="../model/target/target_cpm1_maps.cpp" line="+20"/>
        <source>Omron Host Link (C-mode)</source>
        <translation>Omron Host Link (modo C)</translation>
    </message>
    <message>
        <location filename="../model/target/target_pl110_maps.cpp" line="+22"/>
        <source>PL110 MODBUS slave</source>
        <translation>PL110 slave MODBUS</translation>
    </message>
    <message>
        <location filename="../model/target/target_vigor_maps.cpp" line="+15"/>
        <source>Vigor Computer Link</source>
        <translation>Vigor Computer Link</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>Vigor CP2 MODBUS slave</source>
        <translation>Vigor CP2 slave MODBUS</translation>
    </message>
    <message>
        <location filename="../model/target/target_cpm1.cpp" line="+76"/>
        <source>lit while the PLC has power</source>
        <translation>acceso finché il PLC è alimentato</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>lit in RUN or MONITOR mode; dark in PROGRAM mode or on an error</source>
        <translation>acceso in modo RUN o MONITOR; spento in modo PROGRAM o in caso di errore</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>lit on a fatal error: the CPU stopped; blinks on a non-fatal error the CPU goes on after (FAL 01..99 in 253.00..253.07, an instruction skipped with ER 255.03)</source>
        <translation>acceso per un errore grave: la CPU si è fermata; lampeggia per un errore non grave dopo il quale la CPU prosegue (FAL 01..99 in 253.00..253.07, un&apos;istruzione saltata con ER 255.03)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>lit while the PLC communicates: a byte sent or received on its peripheral port within the last 0.2 s</source>
        <translation>acceso mentre il PLC comunica: un byte inviato o ricevuto sulla sua porta periferica negli ultimi 0,2 s</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>analog setting: 0..200 as BCD into its channel</source>
        <translation>impostazione analogica: 0..200 in BCD nel suo canale</translation>
    </message>
    <message>
        <location filename="../model/target/target_vigor.cpp" line="+203"/>
        <source>variable resistor read by VRRD, 0..255</source>
        <translation>potenziometro letto da VRRD, 0..255</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>lit while the program runs</source>
        <translation>acceso mentre il programma è in esecuzione</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>lit when a program error stopped the PLC</source>
        <translation>acceso quando un errore di programma ha fermato il PLC</translation>
    </message>
    <message>
        <location filename="../model/target/target_pl110_panel.cpp" line="-124"/>
        <source>steady: the PLC is in RUN; slow blink (0.5 s on, 0.5 s off): no ladder program runs</source>
        <translation>acceso fisso: il PLC è in RUN; lampeggio lento (0,5 s on / 0,5 s off): nessun applicativo ladder in esecuzione</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+2"/>
        <location line="+2"/>
        <source>lit while the port transmits a packet</source>
        <translation>acceso durante la trasmissione di un pacchetto di dati sulla porta</translation>
    </message>
    <message>
        <location line="+58"/>
        <source>increments the field being edited</source>
        <translation>incrementa il campo in modifica</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>decrements the field being edited</source>
        <translation>decrementa il campo in modifica</translation>
    </message>
    <message>
        <location filename="../model/target/target_pl110.cpp" line="-84"/>
        <source>characters per word</source>
        <translation>caratteri per word</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>text</source>
        <translation>testo</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Store a text from D: 1 or 2 characters per word, high byte first</source>
        <translation>Salva un testo a partire da D: 1 o 2 caratteri per word, iniziando dalla parte alta</translation>
    </message>
    <message>
        <location filename="../model/target/target_pl110_panel.cpp" line="-8"/>
        <source>scrolls through the pages the program enables; while a value is entered, switches between steps of one and editing digit by digit</source>
        <translation>scorre le pagine abilitate dal programma; durante l&apos;immissione di un valore passa dalla modifica incrementale alla modifica a cifre</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>edits the page&apos;s fields in turn, storing each value; held for 2 s, opens the password page</source>
        <translation>abilita in sequenza la modifica dei campi della pagina, salvando ogni valore; tenuto premuto per 2 s, apre la pagina della password</translation>
    </message>
</context>
<context>
    <name>rung::model::Trigger</name>
    <message>
        <location filename="../model/image/trigger.cpp" line="+39"/>
        <source>Type a condition: &quot;%1 rises&quot;, &quot;%1 falls&quot; or &quot;%2 &gt; 100&quot;</source>
        <translation>Digitare una condizione: &quot;%1 rises&quot;, &quot;%1 falls&quot; o &quot;%2 &gt; 100&quot;</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>&quot;%1&quot; is not a whole number (0x before a hexadecimal one)</source>
        <translation>&quot;%1&quot; non è un numero intero (0x prima di uno esadecimale)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&quot;%1&quot; is no condition: write &quot;%2 rises&quot;, &quot;%2 falls&quot; or &quot;%3 &gt; 100&quot;</source>
        <translation>&quot;%1&quot; non è una condizione: scrivere &quot;%2 rises&quot;, &quot;%2 falls&quot; o &quot;%3 &gt; 100&quot;</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1 is a word: compare it with a value (&quot;%1 &gt; 100&quot;)</source>
        <translation>%1 è una word: confrontarla con un valore (&quot;%1 &gt; 100&quot;)</translation>
    </message>
</context>
<context>
    <name>rung::model::TypedListing</name>
    <message>
        <location filename="../model/convert/typed_listing.cpp" line="+79"/>
        <source>This line keeps %1 (row %2, column %3) of rung %4, but no rung follows it: delete the line to let the contact go, or undo</source>
        <translation>Questa riga conserva %1 (riga %2, colonna %3) del segmento %4, ma nessun segmento la segue: elimina la riga per lasciar andare il contatto, oppure annulla</translation>
    </message>
    <message>
        <location line="+48"/>
        <source>%1 (row %2, column %3) of rung %4 finds no place in the rung typed below this line: delete the line to let it go, or undo</source>
        <translation>%1 (riga %2, colonna %3) del segmento %4 non trova posto nel segmento scritto sotto questa riga: elimina la riga per lasciarlo andare, oppure annulla</translation>
    </message>
    <message>
        <location line="+87"/>
        <source>This line stood for a rung of another program: delete the line or undo the paste</source>
        <translation>Questa riga rappresentava un segmento di un altro programma: elimina la riga o annulla l&apos;incolla</translation>
    </message>
</context>
<context>
    <name>rung::model::ValueFormat</name>
    <message>
        <location filename="../model/image/value_format.cpp" line="+43"/>
        <source>Decimal</source>
        <translation>Decimale</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Signed</source>
        <translation>Con segno</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Hexadecimal</source>
        <translation>Esadecimale</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Binary</source>
        <translation>Binario</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>BCD</source>
        <translation>BCD</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>%1 (not BCD)</source>
        <translation>%1 (non BCD)</translation>
    </message>
    <message>
        <location line="+10"/>
        <location line="+64"/>
        <source>Type a value</source>
        <translation>Digitare un valore</translation>
    </message>
    <message>
        <location line="-59"/>
        <source>%1 does not fit a %2-bit word (%3..%4)</source>
        <translation>%1 non sta in una word a %2 bit (%3..%4)</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>&quot;%1&quot; is not a whole number (0x before a hexadecimal one)</source>
        <translation>&quot;%1&quot; non è un numero intero (0x prima di uno esadecimale)</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>&quot;%1&quot; is not a hexadecimal value of at most %2 digits</source>
        <translation>&quot;%1&quot; non è un valore esadecimale di al massimo %2 cifre</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>&quot;%1&quot; is not a binary value of at most %2 digits</source>
        <translation>&quot;%1&quot; non è un valore binario di al massimo %2 cifre</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>&quot;%1&quot; is not a BCD value: at most %2 decimal digits</source>
        <translation>&quot;%1&quot; non è un valore BCD: al massimo %2 cifre decimali</translation>
    </message>
</context>
<context>
    <name>rung::network::Devices</name>
    <message>
        <location filename="../network/devices.cpp" line="+19"/>
        <source>%1.baud: needs a rate from 50 to 1000000</source>
        <translation>%1.baud: richiede una velocità da 50 a 1000000</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1.frame: &quot;%2&quot; is no character format (8N1, 7E1, ...)</source>
        <translation>%1.frame: &quot;%2&quot; non è un formato di carattere (8N1, 7E1, ...)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1.delay: needs milliseconds from 0 to 60000</source>
        <translation>%1.delay: richiede millisecondi da 0 a 60000</translation>
    </message>
    <message>
        <location line="+72"/>
        <source>%1.station: needs a MODBUS station from 1 to 247</source>
        <translation>%1.station: richiede una stazione MODBUS da 1 a 247</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1.mode: needs &quot;rtu&quot; or &quot;ascii&quot;</source>
        <translation>%1.mode: richiede &quot;rtu&quot; o &quot;ascii&quot;</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1.%2.%3: needs an address 0..65535 and a value %4</source>
        <translation>%1.%2.%3: richiede un indirizzo 0..65535 e un valore %4</translation>
    </message>
    <message>
        <location line="+146"/>
        <source>%1: needs &quot;expect&quot; and &quot;reply&quot; as hex bytes (&quot;02 30 31&quot;), or &quot;expectText&quot; and &quot;replyText&quot; as text (&quot;\x0201&quot;)</source>
        <translation>%1: richiede &quot;expect&quot; e &quot;reply&quot; come byte esadecimali (&quot;02 30 31&quot;), o &quot;expectText&quot; e &quot;replyText&quot; come testo (&quot;\x0201&quot;)</translation>
    </message>
</context>
<context>
    <name>rung::network::EngineImage</name>
    <message>
        <location filename="../network/engine_image.cpp" line="+67"/>
        <source>a station of a network keeps running: it is not stopped from its port</source>
        <translation>una stazione di una rete continua a funzionare: non si ferma dalla sua porta</translation>
    </message>
</context>
<context>
    <name>rung::network::Network</name>
    <message>
        <location filename="../network/network.cpp" line="+80"/>
        <source>%1.ports: %2 is named twice</source>
        <translation>%1.ports: %2 è indicata due volte</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>%1: no station &quot;%2&quot;</source>
        <translation>%1: nessuna stazione &quot;%2&quot;</translation>
    </message>
    <message>
        <location line="+11"/>
        <location line="+31"/>
        <source>%1: no station or device &quot;%2&quot;</source>
        <translation>%1: nessuna stazione o dispositivo &quot;%2&quot;</translation>
    </message>
    <message>
        <location line="-29"/>
        <source>%1: %2 is on wire %3 already; a port has one wire</source>
        <translation>%1: %2 è già sul cavo %3; una porta ha un solo cavo</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>%1: no wire &quot;%2&quot;</source>
        <translation>%1: nessun cavo &quot;%2&quot;</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>%1: line %2: %3 drives %4, which runs %5; %3 needs %6</source>
        <extracomment>%1 station, %2 line, %3 instruction (LINK), %4 port (CP2), %5 what it runs, %6 the applications %3 takes</extracomment>
        <translation>%1: riga %2: %3 usa %4, che esegue %5; %3 richiede %6</translation>
    </message>
    <message>
        <location line="+45"/>
        <source>silent (fault): not sent</source>
        <translation>muto (guasto): non inviato</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the port is on no wire</source>
        <translation>la porta non è su alcun cavo</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>byte %1 corrupted (fault): XOR %2h</source>
        <translation>byte %1 alterato (guasto): XOR %2h</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>wire cut (fault): not delivered</source>
        <translation>cavo tagliato (guasto): non consegnato</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>collision with %1: both frames garbled</source>
        <translation>collisione con %1: entrambi i frame alterati</translation>
    </message>
    <message>
        <location filename="../network/bridge.cpp" line="+43"/>
        <source>%1: no station port &quot;%2&quot;</source>
        <translation>%1: nessuna porta di stazione &quot;%2&quot;</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>%1.tcp: &quot;%2&quot; is not HOST:PORT</source>
        <translation>%1.tcp: &quot;%2&quot; non è HOST:PORTA</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1.listen: &quot;%2&quot; is not ADDRESS:PORT (an IP address of this machine, 0.0.0.0 for all, or localhost)</source>
        <translation>%1.listen: &quot;%2&quot; non è INDIRIZZO:PORTA (un indirizzo IP di questa macchina, 0.0.0.0 per tutti, oppure localhost)</translation>
    </message>
    <message>
        <location line="-50"/>
        <source>no station port &quot;%1&quot;</source>
        <translation>nessuna porta di stazione &quot;%1&quot;</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 runs %2, whose frames the manual does not publish: it is not put on a real line</source>
        <translation>%1 esegue %2, i cui frame il manuale non pubblica: non viene messa su una linea reale</translation>
    </message>
    <message>
        <location filename="../network/network_scenario.cpp" line="+37"/>
        <source>%1: runtime error at step %2: %3</source>
        <extracomment>%1 the station, %2 the step, %3 what went wrong</extracomment>
        <translation>%1: errore di esecuzione al passo %2: %3</translation>
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
        <translation>stato 2: la lunghezza non è 1..64</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>status 4: a wrong device type or command</source>
        <translation>stato 4: tipo di operando o comando errato</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>status 5: a wrong device number</source>
        <translation>stato 5: numero di operando errato</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>status 6: the master&apos;s and the slave&apos;s devices differ (bits and words)</source>
        <translation>stato 6: gli operandi del master e dello slave differiscono (bit e word)</translation>
    </message>
    <message>
        <location line="+21"/>
        <location line="+54"/>
        <location line="+75"/>
        <source>%1: line %2</source>
        <translation>%1: riga %2</translation>
    </message>
    <message>
        <location line="-123"/>
        <source>%1 drives %2, which is on no wire: every set ends in a time-out (status A)</source>
        <translation>%1 usa %2, che non è su alcun cavo: ogni set termina in time-out (stato A)</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>wire %1</source>
        <translation>cavo %1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1 masters on one wire: %2; their requests collide</source>
        <translation>%1 master su un cavo: %2; le loro richieste collidono</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 and %2 both answer %3 station %4</source>
        <translation>%1 e %2 rispondono entrambi come stazione %3 %4</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>%1&apos;s table holds %2 sets after the first scan; it takes 1 to %3 within its area</source>
        <translation>la tabella di %1 contiene %2 set dopo la prima scansione; ne accetta da 1 a %3 entro la sua area</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>%1 set %2: %3</source>
        <translation>%1 set %2: %3</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 set %2 names station %3, which no port or device on %4 answers with %5: the set ends in a time-out (status A)</source>
        <translation>%1 set %2 indica la stazione %3, a cui nessuna porta o dispositivo su %4 risponde con %5: il set termina in time-out (stato A)</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>%1 runs %2: the PL110 manual publishes no frames of it, so the simulation puts none on the wire and every COM / EXP query of the port times out</source>
        <translation>%1 usa %2: il manuale del PL110 non ne pubblica i frame, quindi la simulazione non ne mette alcuno sul cavo e ogni interrogazione COM / EXP della porta va in time-out</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>SEND sends on %1, which is on no wire: the characters reach nobody</source>
        <translation>SEND trasmette su %1, che non è su alcun cavo: i caratteri non raggiungono nessuno</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1_%2 queries on %3, which is on no wire: every query times out</source>
        <translation>%1_%2 interroga su %3, che non è su alcun cavo: ogni interrogazione va in time-out</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>SEND on %1, which is not in free-port after the first scan (%2 bit 8 is OFF): the PLC ignores SEND until the program sets it</source>
        <translation>SEND su %1, che dopo la prima scansione non è in free-port (il bit 8 di %2 è OFF): il PLC ignora SEND finché il programma non lo imposta</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1_%2 queries slave %3, which no port or device on %4 answers with MODBUS: every query times out and sets its status bit</source>
        <translation>%1_%2 interroga lo slave %3, a cui nessuna porta o dispositivo su %4 risponde con MODBUS: ogni interrogazione va in time-out e imposta il suo bit di stato</translation>
    </message>
</context>
<context>
    <name>rung::network::NetworkFile</name>
    <message>
        <location filename="../network/network_file.cpp" line="+84"/>
        <source>%1: unknown key (this object takes: %2)</source>
        <translation>%1: chiave sconosciuta (questo oggetto accetta: %2)</translation>
    </message>
    <message>
        <location line="-48"/>
        <source>%1: missing</source>
        <translation>%1: manca</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1: needs a text</source>
        <translation>%1: richiede un testo</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1: needs a whole number from %2 to %3</source>
        <translation>%1: richiede un numero intero da %2 a %3</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1: needs a list</source>
        <translation>%1: richiede una lista</translation>
    </message>
    <message>
        <location line="+47"/>
        <source>%1: line %2, column %3: the file is not valid JSON (%4)</source>
        <translation>%1: riga %2, colonna %3: il file non è JSON valido (%4)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1: a network file is a JSON object with &quot;stations&quot; and &quot;wires&quot;</source>
        <translation>%1: un file di rete è un oggetto JSON con &quot;stations&quot; e &quot;wires&quot;</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>stations: a network needs at least one station</source>
        <translation>stations: una rete richiede almeno una stazione</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+43"/>
        <location line="+61"/>
        <location line="+41"/>
        <source>%1: needs an object</source>
        <translation>%1: richiede un oggetto</translation>
    </message>
    <message>
        <location line="-127"/>
        <location line="+34"/>
        <source>%1: &quot;%2&quot; is no name (letters, digits, _ and -, at most 32)</source>
        <translation>%1: &quot;%2&quot; non è un nome (lettere, cifre, _ e -, al massimo 32)</translation>
    </message>
    <message>
        <location line="-31"/>
        <location line="+34"/>
        <source>%1: a second &quot;%2&quot;; names are unique</source>
        <translation>%1: un secondo &quot;%2&quot;; i nomi sono unici</translation>
    </message>
    <message>
        <location line="-29"/>
        <source>%1: needs an object of ports</source>
        <translation>%1: richiede un oggetto di porte</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1: needs an object of settings</source>
        <translation>%1: richiede un oggetto di impostazioni</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>%1: &quot;%2&quot; is no kind of device (modbus-slave, line)</source>
        <translation>%1: &quot;%2&quot; non è un tipo di dispositivo (modbus-slave, line)</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>%1: needs a list of ends, [&quot;a/CP2&quot;, &quot;b/CP2&quot;]</source>
        <translation>%1: richiede una lista di estremi, [&quot;a/CP2&quot;, &quot;b/CP2&quot;]</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1: a second wire &quot;%2&quot;</source>
        <translation>%1: un secondo cavo &quot;%2&quot;</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1: a wire joins at least two ends</source>
        <translation>%1: un cavo collega almeno due estremi</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1: needs &quot;STATION/PORT&quot; or a device&apos;s name</source>
        <translation>%1: richiede &quot;STAZIONE/PORTA&quot; o il nome di un dispositivo</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>%1: a bridge goes to one of &quot;pty&quot;: true, &quot;serial&quot;: &quot;/dev/ttyUSB0&quot;, &quot;tcp&quot;: &quot;HOST:PORT&quot;, &quot;listen&quot;: &quot;HOST:PORT&quot;</source>
        <translation>%1: un ponte va a uno tra &quot;pty&quot;: true, &quot;serial&quot;: &quot;/dev/ttyUSB0&quot;, &quot;tcp&quot;: &quot;HOST:PORT&quot;, &quot;listen&quot;: &quot;HOST:PORT&quot;</translation>
    </message>
    <message>
        <location line="+52"/>
        <source>%1: &quot;to&quot; comes before &quot;from&quot;</source>
        <translation>%1: &quot;to&quot; viene prima di &quot;from&quot;</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>%1: &quot;%2&quot; is no fault (cut, silent, corrupt)</source>
        <translation>%1: &quot;%2&quot; non è un guasto (cut, silent, corrupt)</translation>
    </message>
    <message>
        <location filename="../network/network_write.cpp" line="+221"/>
        <source>%1: %2 items where there were %3</source>
        <translation>%1: %2 elementi dove ce n&apos;erano %3</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1[%2]: written differently</source>
        <translation>%1[%2]: scritto diversamente</translation>
    </message>
    <message>
        <location line="+118"/>
        <source>%1: not saved: the file would not hold everything (%2)</source>
        <translation>%1: non salvato: il file non conterrebbe tutto (%2)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1: cannot write the network (%2)</source>
        <translation>%1: impossibile scrivere la rete (%2)</translation>
    </message>
</context>
<context>
    <name>rung::network::NetworkSession</name>
    <message>
        <location filename="../network/network_session.cpp" line="+335"/>
        <source>a fault made in the IDE</source>
        <translation>un guasto creato nell&apos;IDE</translation>
    </message>
    <message>
        <location line="+60"/>
        <source>%1: line %2: %3</source>
        <extracomment>%1 station, %2 line, %3 what went wrong</extracomment>
        <translation>%1: riga %2: %3</translation>
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
        <translation>%1: il ponte non si è aperto: %2</translation>
    </message>
    <message>
        <location line="+44"/>
        <source>%1: the bridge&apos;s line failed: %2 (Stop opens it again)</source>
        <extracomment>%1 the bridged port (&quot;s5/CP2&quot;), %2 what happened to its line</extracomment>
        <translation>%1: la linea del ponte si è guastata: %2 (Stop la riapre)</translation>
    </message>
</context>
<context>
    <name>rung::network::SharedLink</name>
    <message>
        <location filename="../network/shared_link.cpp" line="+252"/>
        <source>CPU Link exchange among %1 (%2 ms); no frames: the manual does not publish them</source>
        <translation>scambio CPU Link tra %1 (%2 ms); nessun frame: il manuale non li pubblica</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>no station</source>
        <translation>nessuna stazione</translation>
    </message>
    <message>
        <location line="+86"/>
        <source>Parallel Link exchange; no frames: the manual does not publish them</source>
        <translation>scambio Parallel Link; nessun frame: il manuale non li pubblica</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Parallel Link: no exchange, the other station does not answer</source>
        <translation>Parallel Link: nessuno scambio, l&apos;altra stazione non risponde</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>wire %1: CPU Link and Parallel Link cannot share a wire</source>
        <translation>cavo %1: CPU Link e Parallel Link non possono condividere un cavo</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>wire %1: %2 and %3 are both CPU Link station %4</source>
        <translation>cavo %1: %2 e %3 sono entrambe la stazione CPU Link %4</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>wire %1: Parallel Link joins one master and one slave</source>
        <translation>cavo %1: Parallel Link collega un master e uno slave</translation>
    </message>
</context>
<context>
    <name>rung::network::StationPastSource</name>
    <message>
        <location filename="../network/station_past_source.cpp" line="+38"/>
        <source>history is read-only: return to live to write, force or release</source>
        <translation>la cronologia è di sola lettura: tornare al vivo per scrivere, forzare o rilasciare</translation>
    </message>
</context>
<context>
    <name>rung::network::Trace</name>
    <message>
        <location filename="../network/net_trace.cpp" line="+18"/>
        <source>%1: name a station&apos;s device as STATION/DEVICE, e.g. %2/%3</source>
        <translation>%1: indicare un operando di una stazione come STAZIONE/OPERANDO, ad es. %2/%3</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1: no station &quot;%2&quot; (the stations: %3)</source>
        <translation>%1: nessuna stazione &quot;%2&quot; (le stazioni: %3)</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>%1 needs a value</source>
        <translation>%1 richiede un valore</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unexpected argument %1</source>
        <translation>argomento inatteso %1</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1 needs a whole number from 1 to %2, not &quot;%3&quot;</source>
        <translation>%1 richiede un numero intero da 1 a %2, non &quot;%3&quot;</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>--set needs STATION/DEV=VALUE@SCAN, not &quot;%1&quot;</source>
        <translation>--set richiede STAZIONE/DISP=VALORE@SCANSIONE, non &quot;%1&quot;</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>unknown option %1</source>
        <translation>opzione sconosciuta %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>--scans and --trace are required</source>
        <translation>--scans e --trace sono obbligatori</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>--set at %1 comes after the last row: it applies once %1 rows have run, and %2 run, so it would never apply</source>
        <extracomment>--set DEV=VALUE@N applies once N (%1) rows of scans have run; %2 rows run</extracomment>
        <translation>--set a %1 viene dopo l&apos;ultima riga: vale dopo %1 righe, e ne vengono eseguite %2, quindi non varrebbe mai</translation>
    </message>
</context>
<context>
    <name>rung::network::Traffic</name>
    <message>
        <location filename="../network/traffic.cpp" line="+9"/>
        <source># traffic of %1: virtual time (ms), wire, sender, bytes, |as text|, note</source>
        <translation># traffico di %1: tempo virtuale (ms), cavo, mittente, byte, |come testo|, nota</translation>
    </message>
</context>
<context>
    <name>rung::network::TrafficDecode</name>
    <message>
        <location filename="../network/traffic_decode.cpp" line="+100"/>
        <source>read coils</source>
        <translation>lettura bobine</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>read discrete inputs</source>
        <translation>lettura ingressi</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>read holding registers</source>
        <translation>lettura holding register</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>read input registers</source>
        <translation>lettura registri di ingresso</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>write single coil</source>
        <translation>scrittura di una bobina</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>write single register</source>
        <translation>scrittura di un registro</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>write multiple coils</source>
        <translation>scrittura di più bobine</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>write multiple registers</source>
        <translation>scrittura di più registri</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>unknown function</source>
        <translation>funzione sconosciuta</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>read</source>
        <translation>lettura</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>write</source>
        <translation>scrittura</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>bit ON</source>
        <translation>bit ON</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>bit OFF</source>
        <translation>bit OFF</translation>
    </message>
    <message>
        <location line="+2"/>
        <location filename="../network/traffic_decode_host_link.cpp" line="+57"/>
        <source>unknown command</source>
        <translation>comando sconosciuto</translation>
    </message>
    <message>
        <location filename="../network/traffic_decode_host_link.cpp" line="-26"/>
        <source>read IR/SR words</source>
        <translation>lettura canali IR/SR</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>read HR words</source>
        <translation>lettura canali HR</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>read DM words</source>
        <translation>lettura parole DM</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>read timer/counter PVs</source>
        <translation>lettura valori correnti di temporizzatori/contatori</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>read completion flags</source>
        <translation>lettura flag di completamento</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>read LR words</source>
        <translation>lettura canali LR</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>read AR words</source>
        <translation>lettura canali AR</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>write IR/SR words</source>
        <translation>scrittura canali IR/SR</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>write HR words</source>
        <translation>scrittura canali HR</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>write DM words</source>
        <translation>scrittura parole DM</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>write timer/counter PVs</source>
        <translation>scrittura valori correnti di temporizzatori/contatori</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>write LR words</source>
        <translation>scrittura canali LR</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>write AR words</source>
        <translation>scrittura canali AR</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>read status</source>
        <translation>lettura stato</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>change mode</source>
        <translation>cambio modo</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>read errors</source>
        <translation>lettura errori</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>read model</source>
        <translation>lettura modello</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>force set</source>
        <translation>forza ON</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>force reset</source>
        <translation>forza OFF</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cancel all forcing</source>
        <translation>rilascio di tutte le forzature</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>test</source>
        <translation>test</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>command not recognised</source>
        <translation>comando non riconosciuto</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>part %1 of a frame in parts: the other side answers CR for the next</source>
        <translation>parte %1 di un frame in parti: l&apos;altro lato risponde CR per la successiva</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>CR: the next part, please</source>
        <translation>CR: la parte successiva, prego</translation>
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
            <numerusform>il frame si ferma dopo %n byte: troncato o non è un frame</numerusform>
            <numerusform>il frame si ferma dopo %n byte: troncato o non è un frame</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+5"/>
        <source>%n byte(s) after the end of the frame</source>
        <translation>
            <numerusform>%n byte dopo la fine del frame</numerusform>
            <numerusform>%n byte dopo la fine del frame</numerusform>
        </translation>
    </message>
    <message>
        <location line="+156"/>
        <source>MODBUS slave device</source>
        <translation>dispositivo slave MODBUS</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>line device</source>
        <translation>dispositivo di linea</translation>
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
        <translation>FCS errato (ricevuto %1, calcolato %2): il PLC risponde con il codice di fine 13</translation>
    </message>
    <message>
        <location line="+76"/>
        <source>not the CR that asks for the next part</source>
        <translation>non è il CR che chiede la parte successiva</translation>
    </message>
    <message>
        <location filename="../network/traffic_decode.cpp" line="-57"/>
        <location line="+58"/>
        <source>real line</source>
        <translation>linea reale</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>no reply came before the next request (a time-out)</source>
        <translation>nessuna risposta prima della richiesta successiva (timeout)</translation>
    </message>
    <message>
        <location line="+50"/>
        <source>bytes</source>
        <translation>byte</translation>
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
        <translation>non è una richiesta Computer Link: non inizia con STX (02h)</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>wrong sum (received %1, computed %2): the slave answers error 11h</source>
        <translation>somma errata (ricevuta %1, calcolata %2): lo slave risponde con l&apos;errore 11h</translation>
    </message>
    <message>
        <location line="+6"/>
        <location filename="../network/traffic_decode_host_link.cpp" line="-179"/>
        <source>the slave refuses it: %1</source>
        <translation>lo slave la rifiuta: %1</translation>
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
        <translation>CRC errato (ricevuto %1, calcolato %2): lo slave non risponde</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>every slave (broadcast)</source>
        <translation>tutti gli slave (broadcast)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>not a request a slave can carry out: it answers %1</source>
        <translation>non è una richiesta che uno slave possa eseguire: risponde %1</translation>
    </message>
</context>
<context>
    <name>rung::simulator::CommandInbox</name>
    <message>
        <location filename="../simulator/command_inbox.cpp" line="+15"/>
        <source>(no device)</source>
        <translation>(nessun operando)</translation>
    </message>
    <message>
        <location line="+56"/>
        <source>the edited program is for another memory layout (another PLC): it cannot take over the running image</source>
        <translation>il programma modificato ha un&apos;altra disposizione della memoria (un altro PLC): non può subentrare all&apos;immagine in uso</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>%1 has no set value to write</source>
        <translation>%1 non ha un valore di preset da scrivere</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1 is not a word this PLC can write</source>
        <translation>%1 non è una parola che questo PLC può scrivere</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 is not a bit this PLC can write</source>
        <translation>%1 non è un bit che questo PLC può scrivere</translation>
    </message>
</context>
<context>
    <name>rung::simulator::Compiler</name>
    <message>
        <location filename="../simulator/compiler_detail.h" line="+117"/>
        <source>%1 needs operand %2</source>
        <translation>%1 richiede l&apos;operando %2</translation>
    </message>
    <message>
        <location filename="../simulator/compile_steps.cpp" line="+177"/>
        <location filename="../simulator/compiler_detail.h" line="+17"/>
        <source>%1 is not a bit device</source>
        <translation>%1 non è un operando a bit</translation>
    </message>
    <message>
        <location filename="../simulator/compiler_detail.h" line="+23"/>
        <source>constant %1 is out of range</source>
        <translation>la costante %1 è fuori campo</translation>
    </message>
    <message>
        <location filename="../simulator/compile_operands.cpp" line="+26"/>
        <source>%1 is not an index register</source>
        <translation>%1 non è un registro indice</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1 is a constant; a device is expected here</source>
        <translation>%1 è una costante; qui è atteso un operando</translation>
    </message>
    <message>
        <location line="+2"/>
        <location filename="../simulator/compiler_detail.h" line="+5"/>
        <source>%1 is not a word device or a constant</source>
        <translation>%1 non è un operando word né una costante</translation>
    </message>
    <message>
        <location line="+16"/>
        <location filename="../simulator/compile_steps.cpp" line="-13"/>
        <location line="+41"/>
        <location line="+220"/>
        <location filename="../simulator/compiler_detail.h" line="+24"/>
        <source>%1 cannot be written</source>
        <translation>%1 non può essere scritto</translation>
    </message>
    <message>
        <location filename="../simulator/compile_comm.cpp" line="+61"/>
        <source>%1 needs a constant as operand %2</source>
        <translation>%1 richiede una costante come operando %2</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>%1 moves %2 digits from digit %3 to digit %4: the digits would run below digit 1</source>
        <translation>%1 sposta %2 cifre dalla cifra %3 alla cifra %4: le cifre andrebbero sotto la cifra 1</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>%1 has no variable resistor %2</source>
        <translation>%1 non ha il potenziometro %2</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>%1 takes a register, a 32-bit counter or a constant, not %2</source>
        <translation>%1 accetta un registro, un contatore a 32 bit o una costante, non %2</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>%1 writes four registers from %2: give a data register</source>
        <translation>%1 scrive quattro registri da %2: indicare un registro dati</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>%1 is programmed twice; the PLC allows it once only in a program</source>
        <translation>%1 è programmata due volte; il PLC la ammette una sola volta in un programma</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1 takes plain registers, not %2</source>
        <translation>%1 accetta registri semplici, non %2</translation>
    </message>
    <message>
        <location line="+11"/>
        <location filename="../simulator/compiler_detail.h" line="+3"/>
        <source>%1 is not a word device</source>
        <translation>%1 non è un operando word</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>%1 moves one word with %2: n must be K1</source>
        <translation>%1 sposta una word con %2: n deve essere K1</translation>
    </message>
    <message>
        <location line="+127"/>
        <source>%1_%2 is programmed twice; each index is one query of the port</source>
        <translation>%1_%2 è programmata due volte; ogni indice è una sola interrogazione della porta</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1 reads into %2, which the program cannot write</source>
        <translation>%1 legge in %2, che il programma non può scrivere</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>%1 needs %2 bits from %3, past the end of its area</source>
        <translation>%1 richiede %2 bit da %3, oltre la fine della sua area</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>%1 needs %2 words from %3, past the end of its area</source>
        <translation>%1 richiede %2 word da %3, oltre la fine della sua area</translation>
    </message>
    <message>
        <location line="-248"/>
        <location filename="../simulator/compile_words.cpp" line="+32"/>
        <location filename="../simulator/compiler_detail.h" line="+17"/>
        <source>%1 needs the next word too, which does not exist</source>
        <translation>%1 richiede anche la word successiva, che non esiste</translation>
    </message>
    <message>
        <location filename="../simulator/compile_words.cpp" line="+22"/>
        <source>%1 reads a block of words: %2 is not a word device</source>
        <translation>%1 legge un blocco di word: %2 non è un operando word</translation>
    </message>
    <message>
        <location filename="../simulator/compiler_detail.h" line="+29"/>
        <source>%1 needs %2 open blocks before it</source>
        <translation>%1 richiede %2 blocchi aperti prima di sé</translation>
    </message>
    <message>
        <location filename="../simulator/compile_steps.cpp" line="-407"/>
        <source>more than %1 open blocks</source>
        <translation>più di %1 blocchi aperti</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>%1 is not a timer</source>
        <translation>%1 non è un temporizzatore</translation>
    </message>
    <message>
        <location line="+47"/>
        <source>%1 is not a counter</source>
        <translation>%1 non è un contatore</translation>
    </message>
    <message>
        <location line="+166"/>
        <source>the simulator has no operator %1</source>
        <translation>il simulatore non ha l&apos;operatore %1</translation>
    </message>
    <message>
        <location line="+59"/>
        <source>%1 is not a number of words</source>
        <translation>%1 non è un numero di word</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>%1 is not a word the text can be stored from</source>
        <translation>%1 non è una word da cui memorizzare il testo</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>the text does not fit in the area of %1 from there on</source>
        <translation>il testo non entra nell&apos;area di %1 da lì in poi</translation>
    </message>
    <message>
        <location line="+114"/>
        <source>the display has no field %1</source>
        <translation>il display non ha il campo %1</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>%1 is not a variable a display field can show</source>
        <translation>%1 non è una variabile che un campo del display può visualizzare</translation>
    </message>
    <message>
        <location line="-208"/>
        <source>%1 needs a bit: a bit device, or a word and a bit number 0..15</source>
        <translation>%1 richiede un bit: un operando a bit, o una word e un numero di bit 0..15</translation>
    </message>
    <message>
        <location filename="../simulator/compile_words.cpp" line="+10"/>
        <source>%1 needs a count from 1 to %2</source>
        <translation>%1 richiede un numero da 1 a %2</translation>
    </message>
    <message>
        <location filename="../simulator/compile_steps.cpp" line="+45"/>
        <source>the block of %1 words runs past the end of its area</source>
        <translation>il blocco di %1 word va oltre la fine della sua area</translation>
    </message>
    <message>
        <location filename="../simulator/compiler.cpp" line="+192"/>
        <source>unknown instruction</source>
        <translation>istruzione sconosciuta</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>more than %1 nested %2</source>
        <translation>più di %1 %2 annidati</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 without MPS before it</source>
        <translation>%1 senza MPS prima</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>%1 cannot be reset</source>
        <translation>%1 non può essere resettato</translation>
    </message>
    <message>
        <location filename="../simulator/compile_steps.cpp" line="-143"/>
        <location filename="../simulator/compiler.cpp" line="+5"/>
        <source>%1 is not a device</source>
        <translation>%1 non è un operando</translation>
    </message>
    <message>
        <location filename="../simulator/compiler.cpp" line="+115"/>
        <source>the program has no target</source>
        <translation>il programma non ha una famiglia PLC</translation>
    </message>
</context>
<context>
    <name>rung::simulator::Engine</name>
    <message>
        <location filename="../simulator/engine_execute.cpp" line="+48"/>
        <source>set value %1 is not a BCD number; the instruction is skipped</source>
        <translation>il valore di preset %1 non è un numero BCD; l&apos;istruzione viene saltata</translation>
    </message>
    <message>
        <location line="+46"/>
        <source>%1 does not fit in BCD (0..%2); the destination is unchanged</source>
        <translation>%1 non sta in BCD (0..%2); la destinazione resta invariata</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1 is not a BCD number; the destination is unchanged</source>
        <translation>%1 non è un numero BCD; la destinazione resta invariata</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>result %1 is outside 0..9999; %2 is written</source>
        <translation>il risultato %1 è fuori da 0..9999; viene scritto %2</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>subroutines nest deeper than %1 levels; the call is skipped</source>
        <translation>le subroutine sono annidate oltre %1 livelli; la chiamata non viene eseguita</translation>
    </message>
    <message>
        <location filename="../simulator/engine_arith.h" line="+55"/>
        <location line="+42"/>
        <location filename="../simulator/engine_text.cpp" line="+152"/>
        <source>division by zero; the destination is unchanged</source>
        <translation>divisione per zero; la destinazione resta invariata</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>MOVIND index %1 is outside 0..%2; nothing is written</source>
        <translation>l&apos;indice %1 di MOVIND è fuori da 0..%2; non viene scritto nulla</translation>
    </message>
    <message>
        <location filename="../simulator/engine_cpm1.cpp" line="+43"/>
        <source>%1; the instruction is skipped and ER %2 is ON</source>
        <translation>%1; l&apos;istruzione non viene eseguita e ER %2 è ON</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1; the instruction is skipped</source>
        <translation>%1; l&apos;istruzione non viene eseguita</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>%1 is not a BCD number</source>
        <translation>%1 non è un numero BCD</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>bit designator %1 is not #DDSS with bits 00 to 15</source>
        <translation>il selettore di bit %1 non è #DDSS con bit da 00 a 15</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>digit designator %1 is not #0DNS with digits 0 to 3</source>
        <translation>il selettore di cifre %1 non è #0DNS con cifre da 0 a 3</translation>
    </message>
    <message>
        <location line="+74"/>
        <source>division by zero</source>
        <translation>divisione per zero</translation>
    </message>
    <message>
        <location filename="../simulator/engine_debug.cpp" line="+36"/>
        <location line="+13"/>
        <source>the program has no instruction %1 to stop at</source>
        <translation>il programma non ha un&apos;istruzione %1 dove fermarsi</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1 is no word to compare</source>
        <translation>%1 non è una word da confrontare</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+10"/>
        <source>(no device)</source>
        <translation>(nessun operando)</translation>
    </message>
    <message>
        <location line="-3"/>
        <source>%1 is no bit to watch</source>
        <translation>%1 non è un bit da osservare</translation>
    </message>
    <message>
        <location filename="../simulator/engine_operands.cpp" line="+84"/>
        <source>operation error: %1 with %2 = %3 reaches %4, which does not exist; the instruction is not executed</source>
        <translation>errore operativo: %1 con %2 = %3 raggiunge %4, che non esiste; l&apos;istruzione non viene eseguita</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>operation error: %1 reaches %2, which does not exist; the instruction is not executed</source>
        <translation>errore operativo: %1 raggiunge %2, che non esiste; l&apos;istruzione non viene eseguita</translation>
    </message>
    <message>
        <location filename="../simulator/engine_words.cpp" line="+15"/>
        <source>operation error: %1 bytes need %2 words from the source, past the end of its area; the instruction is not executed</source>
        <translation>errore operativo: %1 byte richiedono %2 word dalla sorgente, oltre la fine della sua area; l&apos;istruzione non viene eseguita</translation>
    </message>
    <message>
        <location filename="../simulator/engine_comm.cpp" line="+371"/>
        <source>operation error: the communication table holds %1 sets; it takes 1 to %2</source>
        <translation>errore operativo: la tabella di comunicazione contiene %1 set; ne accetta da 1 a %2</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>operation error: a table of %1 sets needs %2 registers, past the end of its area</source>
        <translation>errore operativo: una tabella di %1 set richiede %2 registri, oltre la fine della sua area</translation>
    </message>
    <message>
        <location line="+55"/>
        <source>operation error: another RS is active; only one may be active at a time, this one does nothing</source>
        <translation>errore operativo: un altro RS è attivo; ne può essere attivo uno solo alla volta, questo non fa nulla</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>operation error: %1 data to send from a block that ends after %2 words; nothing is sent</source>
        <translation>errore operativo: %1 dati da inviare da un blocco che finisce dopo %2 word; non viene inviato nulla</translation>
    </message>
    <message>
        <location line="+76"/>
        <source>operation error: %1 data received for a block that ends after %2 words; they are not stored</source>
        <translation>errore operativo: %1 dati ricevuti per un blocco che finisce dopo %2 word; non vengono memorizzati</translation>
    </message>
    <message>
        <location filename="../simulator/engine_module.cpp" line="+108"/>
        <location line="+25"/>
        <source>operation error: no special module %1 is connected (in a network a VB-1COM is the station&apos;s port MODULE%1)</source>
        <translation>errore operativo: nessun modulo speciale %1 collegato (in una rete un VB-1COM è la porta MODULE%1 della stazione)</translation>
    </message>
    <message>
        <location line="-18"/>
        <source>operation error: buffer memory #%1..#%2 of module %3 does not exist or the block runs past its area; nothing is read</source>
        <translation>errore operativo: la memoria buffer #%1..#%2 del modulo %3 non esiste o il blocco va oltre la sua area; non viene letto nulla</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>operation error: buffer memory #%1..#%2 of module %3 cannot be written (the module&apos;s table marks it read-only, or it does not exist); nothing is written</source>
        <translation>errore operativo: la memoria buffer #%1..#%2 del modulo %3 non si può scrivere (la tabella del modulo la indica di sola lettura, o non esiste); non viene scritto nulla</translation>
    </message>
    <message>
        <location filename="../simulator/engine_text.cpp" line="-111"/>
        <source>operation error: %1 characters need %2 words from the destination, past the end of its area; the instruction is not executed</source>
        <translation>errore operativo: %1 caratteri richiedono %2 word dalla destinazione, oltre la fine della sua area; l&apos;istruzione non viene eseguita</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>operation error: %1 characters need %2 words from the source, past the end of its area; the instruction is not executed</source>
        <translation>errore operativo: %1 caratteri richiedono %2 word dalla sorgente, oltre la fine della sua area; l&apos;istruzione non viene eseguita</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>operation error: character %1 (%2H) is no hexadecimal digit; the destination is unchanged</source>
        <translation>errore operativo: il carattere %1 (%2H) non è una cifra esadecimale; la destinazione non cambia</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>operation error: %1 is no 4-digit BCD value (0..9999; %2 ON moves hexadecimal digits); the destination is unchanged</source>
        <extracomment>%2 the relay that makes SMOV move hexadecimal digits (Vigor M9168)</extracomment>
        <translation>errore operativo: %1 non è un valore BCD di 4 cifre (0..9999; con %2 ON si spostano cifre esadecimali); la destinazione non cambia</translation>
    </message>
    <message>
        <location filename="../simulator/engine_ports.cpp" line="+55"/>
        <source>operation error: SEND of %1 characters; the transmit buffer holds 1 to %2, nothing is sent</source>
        <translation>errore operativo: SEND di %1 caratteri; il buffer di trasmissione ne contiene da 1 a %2, non viene trasmesso nulla</translation>
    </message>
</context>
<context>
    <name>rung::simulator::HistorySource</name>
    <message>
        <location filename="../simulator/history_source.cpp" line="+40"/>
        <source>History: scan %1 (%2)</source>
        <extracomment>the window&apos;s mark while it shows a past scan; %1 the scan, %2 its time h:mm:ss.cc</extracomment>
        <translation>Cronologia: scansione %1 (%2)</translation>
    </message>
    <message>
        <location line="+15"/>
        <location line="+29"/>
        <source>nothing is recorded yet: run the simulation first</source>
        <translation>non è ancora registrato nulla: eseguire prima la simulazione</translation>
    </message>
    <message>
        <location line="-18"/>
        <source>history is read-only: return to live to write, force or release</source>
        <translation>la cronologia è di sola lettura: tornare al vivo per scrivere, forzare o rilasciare</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>that scan is no longer recorded</source>
        <translation>quella scansione non è più registrata</translation>
    </message>
</context>
<context>
    <name>rung::simulator::Scenario</name>
    <message>
        <location filename="../simulator/scenario_parse.cpp" line="+53"/>
        <source>%1: a number of scans is whole</source>
        <translation>%1: il numero di scansioni è intero</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1 is more than a week of virtual time</source>
        <translation>%1 supera una settimana di tempo virtuale</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 is not a whole number of milliseconds</source>
        <translation>%1 non è un numero intero di millisecondi</translation>
    </message>
    <message>
        <location line="+46"/>
        <location line="+62"/>
        <source>%1 is no time</source>
        <translation>%1 non è un tempo</translation>
    </message>
    <message>
        <location line="-56"/>
        <source>a scenario runs one program; the first is on line %1</source>
        <translation>uno scenario esegue un solo programma; il primo è alla riga %1</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>unknown option %1 (--target, --model)</source>
        <translation>opzione sconosciuta: %1 (--target, --model)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the period is a time of at least 1 ms</source>
        <translation>il periodo è un tempo di almeno 1 ms</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>press names one key, then &quot;for TIME&quot; if it is held: &quot;%1&quot;</source>
        <translation>press indica un solo tasto, poi &quot;for TEMPO&quot; se è tenuto premuto: &quot;%1&quot;</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>&quot;%1&quot; is no statement (program, period, at TIME set|force|release|expect|press, within TIME expect, always expect, run TIME)</source>
        <translation>&quot;%1&quot; non è un&apos;istruzione (program, period, at TEMPO set|force|release|expect|press, within TEMPO expect, always expect, run TEMPO)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the statement says nothing after its verb</source>
        <translation>l&apos;istruzione non dice nulla dopo il verbo</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>no program: a scenario starts with &quot;program FILE&quot;</source>
        <translation>nessun programma: uno scenario inizia con &quot;program FILE&quot;</translation>
    </message>
    <message>
        <location filename="../simulator/scenario_run.cpp" line="+103"/>
        <source>&quot;%1&quot; is not understood here</source>
        <translation>&quot;%1&quot; non è comprensibile qui</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1 is no device</source>
        <translation>%1 non è un operando</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: only bits are forced</source>
        <translation>%1: si forzano solo i bit</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 needs =VALUE</source>
        <translation>%1 richiede =VALORE</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 is no value (a number, ON or OFF, #hex digits)</source>
        <translation>%1 non è un valore (un numero, ON o OFF, #cifre esadecimali)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>DEVICE=VALUE is expected</source>
        <translation>è atteso OPERANDO=VALORE</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>%1: only bits are forced and released</source>
        <translation>%1: si forzano e rilasciano solo i bit</translation>
    </message>
    <message>
        <location line="+86"/>
        <source>a device or a value is missing at the end</source>
        <translation>manca un operando o un valore alla fine</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a device or a value is expected at &quot;%1&quot;</source>
        <translation>è atteso un operando o un valore in &quot;%1&quot;</translation>
    </message>
    <message>
        <location line="+52"/>
        <source>%1 is no device of %2: %3</source>
        <translation>%1 non è un operando di %2: %3</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1: cv: and sv: name a timer&apos;s or a counter&apos;s current and set value</source>
        <translation>%1: cv: e sv: indicano il valore corrente e di preset di un temporizzatore o contatore</translation>
    </message>
    <message>
        <location line="+60"/>
        <source>a &quot;)&quot; is missing</source>
        <translation>manca una &quot;)&quot;</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>%1 is a word: compare it (%1=5, %1&gt;100)</source>
        <translation>%1 è una word: confrontala (%1=5, %1&gt;100)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 alone is no condition</source>
        <translation>%1 da solo non è una condizione</translation>
    </message>
    <message>
        <location line="+50"/>
        <source>%1: the %2 has no keys on its front panel to press</source>
        <translation>%1: il %2 non ha tasti da premere sul frontale</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 is no key of the %2&apos;s front panel (its keys: %3)</source>
        <translation>%1 non è un tasto del frontale del %2 (i suoi tasti: %3)</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>%1: STATION/DEVICE names a device of a network&apos;s station; this scenario&apos;s program is one PLC</source>
        <translation>%1: STAZIONE/OPERANDO indica un operando di una stazione di una rete; il programma di questo scenario è un solo PLC</translation>
    </message>
    <message>
        <location line="+56"/>
        <source>at %1 comes before line %2&apos;s %3: statements stand in the order of their times</source>
        <translation>at %1 viene prima di %3 della riga %2: le istruzioni seguono l&apos;ordine dei loro tempi</translation>
    </message>
    <message>
        <location line="+158"/>
        <source>%1: the run was already at %2 (the statement before waited until then), so it applied then, not at %3</source>
        <translation>%1: l&apos;esecuzione era già a %2 (l&apos;istruzione precedente ha atteso fin lì), quindi è stata applicata allora, non a %3</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>%1: the run was already at %2 (the statement before waited until then), so at %3 could not be checked</source>
        <translation>%1: l&apos;esecuzione era già a %2 (l&apos;istruzione precedente ha atteso fin lì), quindi at %3 non si è potuto verificare</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>at %1: expected %2, seen %3</source>
        <extracomment>A failed expectation: %1 the time, %2 what was expected, %3 the devices&apos; values then (&quot;Y0=1 Y1=0&quot;).</extracomment>
        <translation>a %1: atteso %2, visto %3</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>within %1 of %2 (until %3): expected %4, seen %5</source>
        <extracomment>%1 the time allowed (&quot;2s&quot;), %2 the time it counted from, %3 until when, %4 what was expected, %5 the values seen at the end.</extracomment>
        <translation>entro %1 da %2 (fino a %3): atteso %4, visto %5</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>at %1: expected always %2, seen %3 (failed in %4 of %5 scans)</source>
        <extracomment>An `always` expectation that failed: %1 the first time, %2 what was expected, %3 the values then, %4 the scans it failed in, %5 the scans run.</extracomment>
        <translation>a %1: atteso sempre %2, visto %3 (non soddisfatto in %4 di %5 scansioni)</translation>
    </message>
    <message>
        <location line="-296"/>
        <source>runtime error at step %1: %2</source>
        <translation>errore di esecuzione al passo %1: %2</translation>
    </message>
    <message>
        <location line="+328"/>
        <source>a network&apos;s stations bring their own targets and models: --target and --model are for one program</source>
        <translation>le stazioni di una rete portano i propri target e modelli: --target e --model valgono per un solo programma</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1 is a network: rungstudio-cli test runs it</source>
        <translation>%1 è una rete: la esegue rungstudio-cli test</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>the program does not start</source>
        <translation>il programma non si avvia</translation>
    </message>
    <message>
        <location filename="../simulator/scenario_record.cpp" line="+38"/>
        <source>the simulation has run no scan yet: run it, work its inputs, then record</source>
        <translation>la simulazione non ha ancora eseguito alcuna scansione: avviarla, azionarne gli ingressi, poi registrare</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the simulation&apos;s history no longer holds its start (it keeps the last hour): stop it, run it again and record sooner</source>
        <translation>la cronologia della simulazione non ne contiene più l&apos;inizio (conserva l&apos;ultima ora): fermarla, riavviarla e registrare prima</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Recorded from a simulation: the inputs as they were worked, the outputs as they were seen.</source>
        <translation>Registrato da una simulazione: gli ingressi come sono stati azionati, le uscite come sono state viste.</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>a command given while a scan was stopped inside is applied at the start of the next scan</source>
        <translation>un comando dato mentre una scansione era ferma al suo interno viene applicato all&apos;inizio della scansione successiva</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the period was changed during the simulation: the scenario runs at the first one, %1 ms</source>
        <translation>il periodo è cambiato durante la simulazione: lo scenario usa il primo, %1 ms</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>a power cycle, reset or online edit at %1 is not in the scenario</source>
        <translation>un ciclo di alimentazione, un reset o una modifica online a %1 non è nello scenario</translation>
    </message>
    <message>
        <location filename="../simulator/scenario_trace.cpp" line="+57"/>
        <source>a scenario&apos;s run is read-only</source>
        <translation>l&apos;esecuzione di uno scenario è di sola lettura</translation>
    </message>
    <message>
        <location filename="../simulator/scenario_record.cpp" line="+51"/>
        <source>nothing was recorded: the PLC&apos;s inputs and outputs were not read while recording</source>
        <translation>non è stato registrato nulla: gli ingressi e le uscite del PLC non sono stati letti durante la registrazione</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Recorded from an online PLC: its inputs and outputs as each refresh read them.</source>
        <translation>Registrato da un PLC in linea: i suoi ingressi e uscite come li ha letti ogni aggiornamento.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the PLC was read refresh by refresh: what changed between two refreshes is not in the scenario, and the scenario runs at a %1 ms scan, not the PLC&apos;s own</source>
        <translation>il PLC è stato letto aggiornamento per aggiornamento: ciò che è cambiato tra due aggiornamenti non è nello scenario, e lo scenario gira con una scansione di %1 ms, non quella del PLC</translation>
    </message>
</context>
<context>
    <name>rung::simulator::SimulatorSession</name>
    <message>
        <location filename="../simulator/session.cpp" line="+246"/>
        <source>Line %1: %2</source>
        <translation>Riga %1: %2</translation>
    </message>
</context>
<context>
    <name>rung::simulator::Trace</name>
    <message>
        <location filename="../simulator/trace.cpp" line="+21"/>
        <source>unknown device %1: %2</source>
        <translation>operando sconosciuto %1: %2</translation>
    </message>
    <message>
        <location line="+93"/>
        <source>%1 needs a value</source>
        <translation>%1 richiede un valore</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unexpected argument %1</source>
        <translation>argomento inatteso %1</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1 needs a whole number from 1 to %2, not &quot;%3&quot;</source>
        <translation>%1 richiede un numero intero da 1 a %2, non &quot;%3&quot;</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>--scans %1 is more than the %2 scans one trace runs (a row each); run it in parts</source>
        <translation>--scans %1 supera le %2 scansioni che una traccia esegue (una riga ciascuna); eseguirla a parti</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>--period %1 is more than %2 ms</source>
        <translation>--period %1 supera %2 ms</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>--set needs DEV=VALUE@SCAN, not &quot;%1&quot;</source>
        <translation>--set richiede DEV=VALUE@SCAN, non &quot;%1&quot;</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>unknown option %1</source>
        <translation>opzione sconosciuta %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>--scans and --trace are required</source>
        <translation>--scans e --trace sono obbligatori</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>--set %1 comes after the last scan: it applies once %2 scans have run, and %3 run, so it would never apply</source>
        <extracomment>--set DEV=VALUE@N applies once N (%2) scans have run; %3 scans run</extracomment>
        <translation>--set %1 viene dopo l&apos;ultima scansione: si applica dopo %2 scansioni, e se ne eseguono %3, quindi non si applicherebbe mai</translation>
    </message>
</context>
</TS>
