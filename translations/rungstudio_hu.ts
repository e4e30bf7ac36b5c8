<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="hu">
<context>
    <name>Tr</name>
    <message>
        <location filename="../simulator/compiler.cpp" line="74"/>
        <source>%1 needs operand %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../simulator/compiler.cpp" line="125"/>
        <source>%1 cannot be written</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../simulator/compiler.cpp" line="127"/>
        <source>%1 is not a word device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../simulator/compiler.cpp" line="140"/>
        <source>%1 needs the next word too, which does not exist</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rung::app::Cli</name>
    <message>
        <location filename="../app/cli/cli.cpp" line="22"/>
        <source>usage:
  rungstudio-cli check FILE [--target vpc|vigor|cpm1|pl110] [--model M]
  rungstudio-cli convert FILE [--target T] [--from il|ladder|project] --to il|ladder|project [-o OUT]
  rungstudio-cli simulate FILE [--target T] --scans N [--period MS] [--set DEV=VALUE@SCAN]... --trace DEV[,DEV...]
FILE is a listing (.il), a ladder text (.ladder) or a project (.rung).
Exit status: 0 no error, 1 the program has errors, 2 usage or I/O error.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/cli/cli.cpp" line="39"/>
        <location filename="../app/cli/cli.cpp" line="80"/>
        <source>unexpected argument %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/cli/cli.cpp" line="86"/>
        <source>--to must be il, ladder or project</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/cli/cli.cpp" line="97"/>
        <source>nothing written: the input has errors</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/cli/cli.cpp" line="115"/>
        <source>cannot write %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/cli/cli.cpp" line="141"/>
        <source>no command given</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/cli/cli.cpp" line="142"/>
        <source>unknown command %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/cli/cli_common.cpp" line="51"/>
        <source>%1 needs a value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/cli/cli_common.cpp" line="76"/>
        <source>no FILE given</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/cli/cli_common.cpp" line="97"/>
        <source>--from must be il, ladder or project, not %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/cli/cli_common.cpp" line="111"/>
        <source>%1 is a %2 project, not %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/cli/cli_common.cpp" line="121"/>
        <source>cannot read %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/cli/cli_common.cpp" line="125"/>
        <source>%1 is %2 MB; the limit is %3 MB</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/cli/cli_common.cpp" line="138"/>
        <source>%1: which PLC? Give --target vpc|vigor|cpm1|pl110 or a &quot;; target: NAME&quot; first line</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/cli/cli_common.cpp" line="145"/>
        <source>unknown target %1 (vpc, vigor, cpm1, pl110)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/cli/cli_common.cpp" line="152"/>
        <location filename="../app/cli/cli_common.cpp" line="179"/>
        <source>%1 has no model %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/cli/cli_common.cpp" line="197"/>
        <source>error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/cli/cli_common.cpp" line="198"/>
        <source>warning</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/cli/cli_common.cpp" line="199"/>
        <source>note</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rung::app::Gui</name>
    <message>
        <location filename="../app/gui/application.cpp" line="36"/>
        <source>Ladder and instruction-list IDE for small PLCs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/application.cpp" line="42"/>
        <source>A project (.rung) or an instruction list to open</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/application.cpp" line="46"/>
        <source>Target of an instruction list: vpc, vigor, cpm1, pl110</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/application.cpp" line="51"/>
        <source>Save a picture of the window and quit</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rung::app::MainWindow</name>
    <message>
        <location filename="../app/gui/main_window.cpp" line="115"/>
        <source>Problems</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="120"/>
        <source>Project</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="127"/>
        <source>Symbols</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="130"/>
        <source>Device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="130"/>
        <source>Name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="130"/>
        <source>Comment</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="164"/>
        <source>&amp;File</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="165"/>
        <source>Main</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="168"/>
        <source>&amp;New Project...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="171"/>
        <source>&amp;Open...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="173"/>
        <source>Open &amp;Recent</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="174"/>
        <source>E&amp;xamples</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="175"/>
        <source>&amp;Save</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="178"/>
        <source>Save &amp;As...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="181"/>
        <source>&amp;Import Instruction List...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="182"/>
        <source>&amp;Export Instruction List...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="183"/>
        <source>Export &amp;Ladder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="184"/>
        <source>As &amp;PDF...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="185"/>
        <source>As &amp;SVG...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="186"/>
        <source>As P&amp;NG...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="187"/>
        <source>Print Pre&amp;view...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="190"/>
        <source>&amp;Quit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="196"/>
        <source>&amp;Edit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="197"/>
        <source>&amp;Undo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="199"/>
        <source>&amp;Redo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="213"/>
        <source>Normally Open Contact</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="219"/>
        <source>Normally Closed Contact</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="225"/>
        <source>Coil</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="231"/>
        <source>Instruction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="237"/>
        <source>Horizontal Wire</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="238"/>
        <source>Vertical Link</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="248"/>
        <source>Insert Rung</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="249"/>
        <source>Delete Rung</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="250"/>
        <source>Insert Row</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="251"/>
        <source>Delete Row</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="253"/>
        <source>&amp;View</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="254"/>
        <source>Ladder and List &amp;Side by Side</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="258"/>
        <source>Zoom &amp;In</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="260"/>
        <source>Zoom &amp;Out</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="262"/>
        <source>&amp;Check Program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="265"/>
        <source>&amp;Language</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="278"/>
        <source>Language</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="279"/>
        <source>The new language applies when Rung Studio starts again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="282"/>
        <source>&amp;Help</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="283"/>
        <source>&amp;Keyboard...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="285"/>
        <source>Keyboard</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="286"/>
        <source>F5 normally open contact, F6 normally closed contact, F7 coil, F8 instruction
F9 horizontal wire, Shift+F9 vertical link
Type an instruction into the cell: LD X0, ANI X2, OUT Y1, TMR T0 K10
Insert: insert a cell, Ctrl+Insert: insert a row, Shift+Insert: insert a rung
Delete: clear, Ctrl+Delete: delete the row, Shift+Delete: delete the rung
Ctrl+Z / Ctrl+Y: undo / redo, Ctrl+wheel: zoom, F4: check the program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="293"/>
        <source>&amp;About Rung Studio</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="295"/>
        <source>About Rung Studio</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="296"/>
        <source>Rung Studio %1
Ladder and instruction-list editor for VPC, Vigor, CPM1 and PL110.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="315"/>
        <source>Ladder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="316"/>
        <source>Instruction List</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="377"/>
        <source>&lt;b&gt;%1&lt;/b&gt;&lt;br&gt;Target: %2, model %3&lt;br&gt;%4 rungs, %5 steps</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="379"/>
        <location filename="../app/gui/main_window.cpp" line="419"/>
        <location filename="../app/gui/main_window_files.cpp" line="319"/>
        <source>Untitled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="402"/>
        <source>%1 %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="404"/>
        <source>%1 / %2 steps</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="409"/>
        <source>Line %1, column %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window.cpp" line="413"/>
        <source>Rung %1, row %2, column %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_files.cpp" line="90"/>
        <source>Recover</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_files.cpp" line="91"/>
        <source>Rung Studio was not closed properly last time. Recover the unsaved program?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_files.cpp" line="115"/>
        <source>Cannot open the file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_files.cpp" line="131"/>
        <source>Unknown target %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_files.cpp" line="134"/>
        <location filename="../app/gui/main_window_files.cpp" line="266"/>
        <source>%1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_files.cpp" line="136"/>
        <source>%1 is larger than 64 MB</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_files.cpp" line="140"/>
        <source>%1, line %2, column %3: %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_files.cpp" line="147"/>
        <source>%1, line %2: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_files.cpp" line="167"/>
        <source>Cannot save</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_files.cpp" line="175"/>
        <source>Saved %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_files.cpp" line="183"/>
        <source>Unsaved changes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_files.cpp" line="183"/>
        <source>Save the changes to the program?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_files.cpp" line="194"/>
        <source>New Project</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_files.cpp" line="210"/>
        <source>PLC family:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_files.cpp" line="211"/>
        <source>Model:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_files.cpp" line="225"/>
        <source>Open</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_files.cpp" line="226"/>
        <source>Rung Studio projects (*.rung);;Instruction lists (*.il *.txt)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_files.cpp" line="238"/>
        <source>Save As</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_files.cpp" line="239"/>
        <source>Rung Studio projects (*.rung)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_files.cpp" line="251"/>
        <source>Import Instruction List</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_files.cpp" line="252"/>
        <source>Instruction lists (*.il *.txt);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_files.cpp" line="259"/>
        <source>Export Instruction List</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_files.cpp" line="259"/>
        <source>Instruction lists (*.il *.txt)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_files.cpp" line="265"/>
        <location filename="../app/gui/main_window_files.cpp" line="284"/>
        <source>Cannot export</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_files.cpp" line="270"/>
        <source>Export Ladder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_files.cpp" line="285"/>
        <source>%1 could not be written</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_files.cpp" line="318"/>
        <source>%1 — %2 — %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_files.cpp" line="325"/>
        <source>%1, page %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/gui/main_window_files.cpp" line="384"/>
        <source>Cannot open the example</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rung::app::Simulate</name>
    <message>
        <location filename="../app/cli/cli_simulate.cpp" line="20"/>
        <source>usage: rungstudio-cli simulate FILE [--target T] --scans N [--period MS] [--set DEV=VALUE@SCAN]... --trace DEV[,DEV...]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/cli/cli_simulate.cpp" line="48"/>
        <source>unexpected argument %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/cli/cli_simulate.cpp" line="58"/>
        <source>cannot read %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/cli/cli_simulate.cpp" line="65"/>
        <source>%1: no target; give --target or a &quot;; target: NAME&quot; first line</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/cli/cli_simulate.cpp" line="71"/>
        <source>unknown target %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/cli/cli_simulate.cpp" line="85"/>
        <location filename="../app/cli/cli_simulate.cpp" line="92"/>
        <source>error: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/cli/cli_simulate.cpp" line="86"/>
        <location filename="../app/cli/cli_simulate.cpp" line="96"/>
        <source>the program does not start</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/cli/cli_simulate.cpp" line="93"/>
        <source>warning: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/cli/cli_simulate.cpp" line="104"/>
        <source>runtime error at step %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rung::editor::Document</name>
    <message>
        <location filename="../editor/document.cpp" line="37"/>
        <source>Edit symbols</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../editor/document.cpp" line="128"/>
        <source>Insert rung</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../editor/document.cpp" line="133"/>
        <source>Delete rung</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location filename="../editor/document.cpp" line="133"/>
        <source>Delete %n rungs</source>
        <translation type="unfinished">
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <location filename="../editor/document.cpp" line="170"/>
        <source>Edit instruction list</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rung::editor::IlEditor</name>
    <message>
        <location filename="../editor/il_editor.cpp" line="197"/>
        <source>Instruction list</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rung::editor::IlLexer</name>
    <message>
        <location filename="../editor/il_editor.cpp" line="26"/>
        <source>Default</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../editor/il_editor.cpp" line="28"/>
        <source>Instruction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../editor/il_editor.cpp" line="30"/>
        <source>Device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../editor/il_editor.cpp" line="32"/>
        <source>Constant</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../editor/il_editor.cpp" line="34"/>
        <source>Comment</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../editor/il_editor.cpp" line="36"/>
        <source>Step number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../editor/il_editor.cpp" line="38"/>
        <source>Unknown word</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rung::editor::LadderView</name>
    <message>
        <location filename="../editor/ladder_view.cpp" line="36"/>
        <source>Ladder diagram</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../editor/ladder_view.cpp" line="222"/>
        <source>Type one instruction, for example &quot;%1 X0&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../editor/ladder_view.cpp" line="240"/>
        <source>%1 is drawn with vertical links, not typed into a cell</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../editor/ladder_view.cpp" line="244"/>
        <source>Contacts go in the grid; the right-hand column holds coils and boxes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../editor/ladder_view.cpp" line="261"/>
        <location filename="../editor/ladder_view.cpp" line="274"/>
        <source>Place %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../editor/ladder_view.cpp" line="296"/>
        <source>Draw a wire</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../editor/ladder_view.cpp" line="307"/>
        <source>Toggle a vertical link</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../editor/ladder_view.cpp" line="325"/>
        <source>Delete</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../editor/ladder_view.cpp" line="333"/>
        <source>Insert a cell</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../editor/ladder_view.cpp" line="339"/>
        <source>Insert a row</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../editor/ladder_view.cpp" line="347"/>
        <source>Delete a row</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rung::editor::ProblemsView</name>
    <message>
        <location filename="../editor/problems_view.cpp" line="13"/>
        <source>Severity</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../editor/problems_view.cpp" line="13"/>
        <source>Code</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../editor/problems_view.cpp" line="13"/>
        <source>Place</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../editor/problems_view.cpp" line="13"/>
        <source>Message</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../editor/problems_view.cpp" line="18"/>
        <source>Problems</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../editor/problems_view.cpp" line="34"/>
        <source>Error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../editor/problems_view.cpp" line="35"/>
        <source>Warning</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../editor/problems_view.cpp" line="36"/>
        <source>Note</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../editor/problems_view.cpp" line="40"/>
        <source>line %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../editor/problems_view.cpp" line="43"/>
        <source>rung %1, row %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../editor/problems_view.cpp" line="44"/>
        <source>rung %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../editor/problems_view.cpp" line="46"/>
        <source>%1 (fix available)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../editor/problems_view.cpp" line="65"/>
        <source>Show</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rung::model::Address</name>
    <message>
        <location filename="../model/address.cpp" line="124"/>
        <source>A device is missing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/address.cpp" line="138"/>
        <source>%1: a number is expected after %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/address.cpp" line="141"/>
        <source>%1 is not a device of %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/address.cpp" line="155"/>
        <source>%1: the number is too large</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/address.cpp" line="157"/>
        <source>%1: %2 is numbered in octal</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/address.cpp" line="165"/>
        <source>%1: a bit number is expected after the point</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/address.cpp" line="168"/>
        <location filename="../model/address.cpp" line="182"/>
        <source>%1: bit %2 is beyond 00..15</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/address.cpp" line="173"/>
        <source>%1: unexpected &apos;%2&apos; after the device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/address.cpp" line="221"/>
        <source>%1: %2 has no bit numbers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/address.cpp" line="224"/>
        <location filename="../model/address.cpp" line="251"/>
        <source>%1: %2 has no %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/address.cpp" line="240"/>
        <location filename="../model/address.cpp" line="254"/>
        <source>%1 is beyond %2&apos;s %3 %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/address.cpp" line="243"/>
        <source>%1 is beyond %2&apos;s %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/address.cpp" line="280"/>
        <source>A constant is missing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/address.cpp" line="303"/>
        <source>%1: %2 writes constants without K or H</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/address.cpp" line="309"/>
        <source>%1: # constants belong to CPM1 listings</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/address.cpp" line="314"/>
        <source>%1: write a constant as K (decimal) or H (hexadecimal)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/address.cpp" line="315"/>
        <source>%1: write a constant with # (e.g. #0150)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/address.cpp" line="324"/>
        <source>%1: digits are expected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/address.cpp" line="337"/>
        <source>%1: &apos;%2&apos; is not a digit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/address.cpp" line="344"/>
        <source>%1: the constant is too large</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rung::model::Checks</name>
    <message>
        <location filename="../model/checks_ladder.cpp" line="63"/>
        <source>Reverse current: power would cross an element right to left to reach row %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/checks_ladder.cpp" line="67"/>
        <source>Duplicate the shared contact into each branch</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/checks_ladder.cpp" line="80"/>
        <source>Open branch: row %1 is not connected to the left rail</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/checks_ladder.cpp" line="92"/>
        <source>%1 has no condition: it is wired straight to the left rail</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/checks_ladder.cpp" line="107"/>
        <source>This contact is not on any path from the left rail to an output</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/checks_list.cpp" line="142"/>
        <source>Rewrite the rung in the canonical form</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/checks_list.cpp" line="169"/>
        <source>More than %1 %2 in a row: the PLC rejects the program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/checks_list.cpp" line="198"/>
        <source>Stacked ANB: combine each block with ANB as soon as it is complete</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location filename="../model/checks_list.cpp" line="200"/>
        <source>Stacked ORB: %n blocks are open; an OR chain needs less stack</source>
        <translation type="unfinished">
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/checks_list.cpp" line="206"/>
        <source>A single contact joined with %1 is simpler as %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/checks_list.cpp" line="214"/>
        <source>A single device in parallel with a block belongs on the lower row: the block first, then an OR, drops the %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/checks_list.cpp" line="221"/>
        <source>The block after a single contact can move to the front and drop the %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/checks_list.cpp" line="234"/>
        <source>MPS nests more than %1 deep</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/checks_list.cpp" line="240"/>
        <source>%1 without a matching MPS</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/checks_list.cpp" line="247"/>
        <source>An output with no contacts of its own belongs on top of the branch and needs no %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location filename="../model/checks_list.cpp" line="262"/>
        <source>%n MPS left without MPP at the end of the rung</source>
        <translation type="unfinished">
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/checks_list.cpp" line="278"/>
        <source>END is missing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/checks_list.cpp" line="284"/>
        <source>Instructions after END are never executed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/checks_list.cpp" line="298"/>
        <source>IL inside IL: close the first with ILC</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/checks_list.cpp" line="304"/>
        <source>ILC without IL (&quot;IL (JMP) missing&quot;)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/checks_list.cpp" line="307"/>
        <source>IL-JMP interlace: the jump opened inside the interlock is still open</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/checks_list.cpp" line="316"/>
        <source>Jump number %1 is beyond 00..%2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/checks_list.cpp" line="324"/>
        <source>JMP inside JMP: close the first jump</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/checks_list.cpp" line="333"/>
        <source>A second %1 %2: several JMP may share a number, only one JME</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/checks_list.cpp" line="341"/>
        <source>%1 %2 without a JMP before it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/checks_list.cpp" line="347"/>
        <source>%1 without JMP (&quot;IL (JMP) missing&quot;)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/checks_list.cpp" line="350"/>
        <source>IL-JMP interlace: the interlock opened inside the jump is still open</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/checks_list.cpp" line="365"/>
        <source>IL without ILC</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/checks_list.cpp" line="368"/>
        <source>JMP without its end (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/checks_list.cpp" line="374"/>
        <source>JMP %1 has no JME %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/checks_list.cpp" line="376"/>
        <source>The step ladder is not closed with RET</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/checks_list.cpp" line="401"/>
        <source>Set value %1 is out of range</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/checks_list.cpp" line="417"/>
        <source>%1 cannot be written: %2 are read-only</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/checks_list.cpp" line="432"/>
        <source>Number %1 is used as a timer and as a counter; they share one bank</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/checks_list.cpp" line="454"/>
        <source>%1 is driven twice (&quot;Oper duplication&quot;); the first is on line %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/checks_list.cpp" line="457"/>
        <source>%1 is driven twice; the later one wins (first on line %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/checks_list.cpp" line="473"/>
        <source>The program needs %1 steps; %2 holds %3</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rung::model::Convert</name>
    <message>
        <location filename="../model/convert_to_ladder.cpp" line="269"/>
        <source>%1 has no block to continue; start the rung with a load</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/convert_to_ladder.cpp" line="277"/>
        <location filename="../model/convert_to_ladder.cpp" line="293"/>
        <source>%1 has no block to join in parallel</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location filename="../model/convert_to_ladder.cpp" line="284"/>
        <source>%1 needs two blocks, but %n is open</source>
        <translation type="unfinished">
            <numerusform></numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../model/convert_to_ladder.cpp" line="301"/>
        <source>MPS needs exactly one open block, but %n is open</source>
        <translation type="unfinished">
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/convert_to_ladder.cpp" line="312"/>
        <source>%1 without a matching MPS</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/convert_to_ladder.cpp" line="327"/>
        <source>%1 needs %2 input blocks, but %3 are open</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/convert_to_ladder.cpp" line="336"/>
        <location filename="../model/convert_to_list.cpp" line="43"/>
        <source>%1 has an input with no condition</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/convert_to_ladder.cpp" line="350"/>
        <location filename="../model/convert_to_ladder.cpp" line="353"/>
        <location filename="../model/convert_to_ladder.cpp" line="358"/>
        <location filename="../model/convert_to_list.cpp" line="53"/>
        <source>%1 has no condition</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/convert_to_ladder.cpp" line="354"/>
        <source>%1 needs one block, but %2 are open</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/convert_to_ladder.cpp" line="393"/>
        <source>The rung starting on line %1 ends without an output</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location filename="../model/convert_to_ladder.cpp" line="397"/>
        <source>The rung starting on line %1 leaves %n MPS without MPP</source>
        <translation type="unfinished">
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/convert_to_list.cpp" line="79"/>
        <source>%1 has no INV element</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/convert_to_list.cpp" line="80"/>
        <source>%1 has no such contact</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/convert_to_list.cpp" line="94"/>
        <source>%1 has no branch stack</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/convert_to_list.cpp" line="110"/>
        <source>A block cannot start with INV</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/convert_to_list.cpp" line="114"/>
        <source>An output has no condition</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/convert_to_list.cpp" line="249"/>
        <source>A box with several inputs must stand alone in its rung</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/convert_to_list.cpp" line="260"/>
        <source>Row %1 is not connected to the left rail</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/convert_to_list.cpp" line="263"/>
        <source>Reverse current: the network feeding row %1 can only close through an element crossed right to left</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rung::model::InstructionList</name>
    <message>
        <location filename="../model/il_parse.cpp" line="113"/>
        <source>Too many errors; the rest of the listing was not read</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/il_parse.cpp" line="215"/>
        <source>Unknown instruction &apos;%1&apos; for %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/il_parse.cpp" line="218"/>
        <source>Unknown instruction &apos;%1&apos; for %2; did you mean %3?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/il_parse.cpp" line="262"/>
        <source>%1 cannot compare values</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/il_parse.cpp" line="281"/>
        <source>A second operand is missing after &apos;%1&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location filename="../model/il_parse.cpp" line="351"/>
        <source>%1 needs %n operand(s): %2</source>
        <translation type="unfinished">
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/il_parse.cpp" line="360"/>
        <source>%1 takes no operand</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location filename="../model/il_parse.cpp" line="361"/>
        <source>Unexpected &apos;%1&apos;: %2 takes %n operand(s)</source>
        <translation type="unfinished">
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <location filename="../model/il_parse.cpp" line="424"/>
        <source>%1: a label number is expected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/il_parse.cpp" line="473"/>
        <source>%1: %2 is expected here</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/il_parse.cpp" line="479"/>
        <source>a timer</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/il_parse.cpp" line="483"/>
        <source>a counter</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/il_parse.cpp" line="487"/>
        <source>a step relay</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/il_parse.cpp" line="494"/>
        <source>a bit device</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rung::model::LadderText</name>
    <message>
        <location filename="../model/ladder_text.cpp" line="204"/>
        <source>A ladder text starts with &quot;LADDER &lt;target&gt; WIDTH &lt;n&gt;&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/ladder_text.cpp" line="208"/>
        <source>This ladder is for %1, not %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/ladder_text.cpp" line="214"/>
        <source>The cell width must be a number from 5 to 200</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/ladder_text.cpp" line="231"/>
        <source>Expected &quot;RUNG &lt;n&gt; ROWS &lt;rows&gt; COLUMNS &lt;columns&gt;&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/ladder_text.cpp" line="248"/>
        <location filename="../model/ladder_text.cpp" line="256"/>
        <source>The rung has fewer rows than its header says</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/ladder_text.cpp" line="270"/>
        <source>A row starts with the left rail &apos;|&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/ladder_text.cpp" line="284"/>
        <source>A cell is empty, a wire, or a contact &quot;-[ X0 ]-&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/ladder_text.cpp" line="300"/>
        <source>An output is written in parentheses: (OUT Y0)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/ladder_text.cpp" line="306"/>
        <source>(^) marks a further input of a box above it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/ladder_text.cpp" line="316"/>
        <source>One output instruction is expected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/ladder_text.cpp" line="366"/>
        <source>&apos;%1&apos; is not a contact mark (&apos; &apos;, &apos;/&apos;, &apos;P&apos;, &apos;N&apos;, &apos;~&apos;)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/ladder_text.cpp" line="370"/>
        <source>The contact has no device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/ladder_text.cpp" line="461"/>
        <source>&apos;%1&apos; is not a contact</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rung::model::Project</name>
    <message>
        <location filename="../model/project.cpp" line="105"/>
        <source>Line %1, column %2: the file is not valid JSON (%3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/project.cpp" line="112"/>
        <source>The file is JSON but not a Rung Studio project (no top-level object)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/project.cpp" line="116"/>
        <source>The file is JSON but not a Rung Studio project (&quot;format&quot; is not &quot;%1&quot;)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/project.cpp" line="121"/>
        <source>The project was written by a newer Rung Studio (schema %1); this version reads schema %2 and older</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/project.cpp" line="126"/>
        <source>&quot;schema&quot; must be a positive number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/project.cpp" line="131"/>
        <source>&quot;target&quot;: unknown PLC family &quot;%1&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/project.cpp" line="136"/>
        <source>&quot;model&quot;: %1 has no model &quot;%2&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/project.cpp" line="165"/>
        <source>setValues.%1: a number is expected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/project.cpp" line="199"/>
        <source>%1: a rung object is expected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/project.cpp" line="206"/>
        <source>%1: &quot;rows&quot; must be 1..1000 and &quot;columns&quot; 0..1000</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/project.cpp" line="213"/>
        <source>%1.cells: %2 rows are expected, the file has %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/project.cpp" line="222"/>
        <source>%1.cells[%2]: %3 cells are expected, the file has %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/project.cpp" line="256"/>
        <source>%1.links: [%2, %3] is outside the rung</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/project.cpp" line="265"/>
        <source>%1.outputs: the row is outside the rung</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/project.cpp" line="273"/>
        <source>one instruction is expected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/project.cpp" line="284"/>
        <source>%1.outputs: an input row is outside the rung</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/project.cpp" line="351"/>
        <source>%1: cannot open the file (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/project.cpp" line="356"/>
        <source>%1: the file is %2 MB; a project is at most %3 MB</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/project.cpp" line="375"/>
        <source>%1: cannot write the file (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/project.cpp" line="381"/>
        <source>%1: saving failed (%2); the previous file is unchanged</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rung::model::Target</name>
    <message>
        <location filename="../model/target_cpm1.cpp" line="36"/>
        <source>input channels</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_cpm1.cpp" line="39"/>
        <source>output channels</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_cpm1.cpp" line="41"/>
        <source>work channels</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_cpm1.cpp" line="43"/>
        <source>special channels</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_cpm1.cpp" line="47"/>
        <source>holding relays</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_cpm1.cpp" line="52"/>
        <location filename="../model/target_pl110.cpp" line="79"/>
        <location filename="../model/target_vigor.cpp" line="115"/>
        <location filename="../model/target_vpc.cpp" line="61"/>
        <source>timers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_cpm1.cpp" line="56"/>
        <location filename="../model/target_pl110.cpp" line="81"/>
        <location filename="../model/target_vigor.cpp" line="116"/>
        <location filename="../model/target_vpc.cpp" line="66"/>
        <source>counters</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_cpm1.cpp" line="61"/>
        <source>data memory</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_cpm1.cpp" line="65"/>
        <source>read-only data memory</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_cpm1.cpp" line="72"/>
        <source>always ON</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_cpm1.cpp" line="74"/>
        <source>always OFF</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_cpm1.cpp" line="76"/>
        <location filename="../model/target_pl110.cpp" line="122"/>
        <location filename="../model/target_vigor.cpp" line="137"/>
        <source>ON for the first scan</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_cpm1.cpp" line="78"/>
        <location filename="../model/target_vigor.cpp" line="145"/>
        <source>1 min clock</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_cpm1.cpp" line="80"/>
        <source>0.02 s clock</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_cpm1.cpp" line="82"/>
        <location filename="../model/target_vpc.cpp" line="123"/>
        <source>0.1 s clock</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_cpm1.cpp" line="84"/>
        <source>0.2 s clock</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_cpm1.cpp" line="86"/>
        <location filename="../model/target_vigor.cpp" line="143"/>
        <location filename="../model/target_vpc.cpp" line="125"/>
        <source>1 s clock</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_cpm1.cpp" line="88"/>
        <source>analog setting 0 (BCD 0..200)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_cpm1.cpp" line="90"/>
        <source>analog setting 1 (BCD 0..200)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_cpm1.cpp" line="95"/>
        <location filename="../model/target_pl110.cpp" line="145"/>
        <location filename="../model/target_vigor.cpp" line="199"/>
        <location filename="../model/target_vpc.cpp" line="130"/>
        <source>Start a block with a normally open contact</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_cpm1.cpp" line="98"/>
        <location filename="../model/target_pl110.cpp" line="146"/>
        <location filename="../model/target_vigor.cpp" line="202"/>
        <location filename="../model/target_vpc.cpp" line="131"/>
        <source>Start a block with a normally closed contact</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_cpm1.cpp" line="101"/>
        <location filename="../model/target_pl110.cpp" line="148"/>
        <location filename="../model/target_vigor.cpp" line="211"/>
        <location filename="../model/target_vpc.cpp" line="133"/>
        <source>Normally open contact in series</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_cpm1.cpp" line="103"/>
        <location filename="../model/target_pl110.cpp" line="149"/>
        <location filename="../model/target_vigor.cpp" line="214"/>
        <location filename="../model/target_vpc.cpp" line="134"/>
        <source>Normally closed contact in series</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_cpm1.cpp" line="105"/>
        <location filename="../model/target_pl110.cpp" line="152"/>
        <location filename="../model/target_vigor.cpp" line="223"/>
        <location filename="../model/target_vpc.cpp" line="136"/>
        <source>Normally open contact in parallel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_cpm1.cpp" line="107"/>
        <location filename="../model/target_pl110.cpp" line="153"/>
        <location filename="../model/target_vigor.cpp" line="226"/>
        <location filename="../model/target_vpc.cpp" line="137"/>
        <source>Normally closed contact in parallel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_cpm1.cpp" line="111"/>
        <location filename="../model/target_pl110.cpp" line="158"/>
        <location filename="../model/target_vigor.cpp" line="247"/>
        <location filename="../model/target_vpc.cpp" line="139"/>
        <source>Connect the last two blocks in series</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_cpm1.cpp" line="113"/>
        <location filename="../model/target_pl110.cpp" line="160"/>
        <location filename="../model/target_vigor.cpp" line="250"/>
        <location filename="../model/target_vpc.cpp" line="141"/>
        <source>Connect the last two blocks in parallel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_cpm1.cpp" line="115"/>
        <location filename="../model/target_pl110.cpp" line="193"/>
        <location filename="../model/target_vigor.cpp" line="262"/>
        <location filename="../model/target_vpc.cpp" line="143"/>
        <source>Output coil</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_cpm1.cpp" line="117"/>
        <location filename="../model/target_vpc.cpp" line="146"/>
        <source>Inverted output coil</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_cpm1.cpp" line="120"/>
        <source>Set (latch) a bit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_cpm1.cpp" line="122"/>
        <source>Reset a bit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_cpm1.cpp" line="125"/>
        <source>Keep: set = last but one block, reset = last block; reset wins</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_cpm1.cpp" line="131"/>
        <location filename="../model/target_vigor.cpp" line="271"/>
        <source>ON for one scan on a rising edge</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_cpm1.cpp" line="135"/>
        <location filename="../model/target_vigor.cpp" line="274"/>
        <source>ON for one scan on a falling edge</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_cpm1.cpp" line="139"/>
        <source>Timer, 0.1 s, counts down from the BCD set value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_cpm1.cpp" line="144"/>
        <source>High-speed timer, 0.01 s, counts down from the BCD set value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_cpm1.cpp" line="149"/>
        <source>Down counter: count = last but one block, reset = last block</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_cpm1.cpp" line="154"/>
        <source>Reversible counter: up, down and reset inputs; wraps at the limits</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_cpm1.cpp" line="161"/>
        <location filename="../model/target_vpc.cpp" line="187"/>
        <source>Interlock: what follows runs under this condition</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_cpm1.cpp" line="165"/>
        <location filename="../model/target_vpc.cpp" line="190"/>
        <source>Clear the interlock</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_cpm1.cpp" line="168"/>
        <source>Jump: while OFF, skip to the JME with the same number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_cpm1.cpp" line="173"/>
        <source>End of the jump with this number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_cpm1.cpp" line="177"/>
        <source>Move a channel or a constant</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_cpm1.cpp" line="182"/>
        <location filename="../model/target_vigor.cpp" line="297"/>
        <source>No operation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_cpm1.cpp" line="185"/>
        <location filename="../model/target_pl110.cpp" line="283"/>
        <location filename="../model/target_vigor.cpp" line="296"/>
        <location filename="../model/target_vpc.cpp" line="195"/>
        <source>End of the program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_pl110.cpp" line="39"/>
        <source>IF contact: ON while S1 ? S2 is true</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_pl110.cpp" line="66"/>
        <source>digital inputs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_pl110.cpp" line="70"/>
        <source>digital outputs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_pl110.cpp" line="73"/>
        <source>bistable relays</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_pl110.cpp" line="75"/>
        <source>markers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_pl110.cpp" line="85"/>
        <source>variables</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_pl110.cpp" line="91"/>
        <source>special markers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_pl110.cpp" line="97"/>
        <location filename="../model/target_vpc.cpp" line="89"/>
        <source>analog inputs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_pl110.cpp" line="101"/>
        <location filename="../model/target_vpc.cpp" line="94"/>
        <source>analog outputs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_pl110.cpp" line="104"/>
        <source>timer presets</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_pl110.cpp" line="106"/>
        <source>counter presets</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_pl110.cpp" line="108"/>
        <source>EEPROM words</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_pl110.cpp" line="111"/>
        <source>MMC words</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_pl110.cpp" line="114"/>
        <source>display characters</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_pl110.cpp" line="120"/>
        <source>RUN/STOP (1 = RUN)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_pl110.cpp" line="124"/>
        <source>60 s clock (30 s ON, 30 s OFF)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_pl110.cpp" line="126"/>
        <source>1 s clock (0.5 s ON, 0.5 s OFF)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_pl110.cpp" line="128"/>
        <location filename="../model/target_vpc.cpp" line="119"/>
        <source>toggles every scan</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_pl110.cpp" line="130"/>
        <source>TEST: inputs are taken from SM37</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_pl110.cpp" line="132"/>
        <source>counters C1..C16 off, timers T49..T64 on</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_pl110.cpp" line="134"/>
        <source>last scan time (0.1 ms)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_pl110.cpp" line="136"/>
        <location filename="../model/target_vigor.cpp" line="151"/>
        <source>minimum scan time (0.1 ms)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_pl110.cpp" line="138"/>
        <location filename="../model/target_vigor.cpp" line="153"/>
        <source>maximum scan time (0.1 ms)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_pl110.cpp" line="162"/>
        <source>NOT contact: invert the power flow</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_pl110.cpp" line="166"/>
        <source>P contact: power flows for one scan when it turns ON</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_pl110.cpp" line="170"/>
        <source>N contact: power flows for one scan when it turns OFF</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_pl110.cpp" line="176"/>
        <source>Start a block with an immediate input contact</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_pl110.cpp" line="178"/>
        <source>Start a block with a normally closed immediate input contact</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_pl110.cpp" line="181"/>
        <source>Immediate input contact in series</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_pl110.cpp" line="183"/>
        <source>Normally closed immediate input contact in series</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_pl110.cpp" line="186"/>
        <source>Immediate input contact in parallel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_pl110.cpp" line="188"/>
        <source>Normally closed immediate input contact in parallel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_pl110.cpp" line="195"/>
        <source>Immediate output coil: writes the terminal at once</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_pl110.cpp" line="200"/>
        <source>Bistable relay coil: each activation toggles the relay</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_pl110.cpp" line="205"/>
        <source>Set a bit (0..15) of a word to 1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_pl110.cpp" line="208"/>
        <source>Reset a bit (0..15) of a word to 0</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_pl110.cpp" line="214"/>
        <source>On-delay timer: T ON once the time reaches PT; OFF resets</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_pl110.cpp" line="218"/>
        <source>Off-delay timer: T ON at once, OFF when PT has elapsed after OFF</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_pl110.cpp" line="224"/>
        <source>Accumulating on-delay timer: keeps its time while OFF</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_pl110.cpp" line="232"/>
        <source>Up counter: UP, DOWN and RESET inputs; C ON while the count &gt;= PV</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_pl110.cpp" line="238"/>
        <source>Down counter from PV: UP, DOWN and RESET (load PV) inputs; C ON at 0</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_pl110.cpp" line="248"/>
        <source>Math formula: D = S1 op S2, op one of + - * / | &amp; ^ &lt;&lt; &gt;&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_pl110.cpp" line="252"/>
        <source>Move a value or a word to D</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_pl110.cpp" line="254"/>
        <source>Move n words from S (or the value S) to D</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_pl110.cpp" line="257"/>
        <source>Indexed move: D[index] = S, the area used as a vector</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_pl110.cpp" line="263"/>
        <source>Store a text string in words</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_pl110.cpp" line="265"/>
        <source>Set the range of an AI, TR, AQ or PID output</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_pl110.cpp" line="266"/>
        <source>Send data on a serial port</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_pl110.cpp" line="267"/>
        <source>Serial communication on COM1/COM2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_pl110.cpp" line="268"/>
        <source>Communication with an expansion</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_pl110.cpp" line="269"/>
        <source>Tune an on/off positioner</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_pl110.cpp" line="270"/>
        <source>On/off positioner</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_pl110.cpp" line="271"/>
        <source>Start a PID loop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_pl110.cpp" line="272"/>
        <source>PID control loop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_pl110.cpp" line="273"/>
        <source>Set the output of a PID loop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_pl110.cpp" line="274"/>
        <source>Generator set control</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_pl110.cpp" line="275"/>
        <source>Convert a value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_pl110.cpp" line="276"/>
        <source>Set a display parameter</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_pl110.cpp" line="277"/>
        <source>Format a display parameter</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_pl110.cpp" line="278"/>
        <source>Place a display parameter</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="33"/>
        <source>Compare contact: ON while S1 ? S2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="93"/>
        <location filename="../model/target_vpc.cpp" line="52"/>
        <source>inputs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="98"/>
        <location filename="../model/target_vpc.cpp" line="57"/>
        <source>outputs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="102"/>
        <location filename="../model/target_vpc.cpp" line="71"/>
        <source>auxiliary relays</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="104"/>
        <source>latched auxiliary relays</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="107"/>
        <source>special relays</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="111"/>
        <source>step relays</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="113"/>
        <source>latched step relays</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="118"/>
        <source>latched counters</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="121"/>
        <source>32-bit counters</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="125"/>
        <source>data registers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="127"/>
        <source>latched data registers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="130"/>
        <source>special registers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="135"/>
        <source>ON while the PLC runs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="139"/>
        <source>10 ms clock</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="141"/>
        <source>100 ms clock</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="147"/>
        <source>ON for one scan when an MBUS cycle completes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="149"/>
        <source>current scan time (0.1 ms)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="156"/>
        <source>parallel operation or RS communication error, PLC keeps running</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="159"/>
        <source>parallel link: this unit is the master</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="161"/>
        <source>parallel link: this unit is a slave</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="163"/>
        <source>parallel operation normal</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="165"/>
        <source>CP2 modem: start dialing (OFF to ON)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="167"/>
        <source>CP2 modem: dialing failed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="169"/>
        <source>RS instruction send flag</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="171"/>
        <source>RS instruction receive done</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="173"/>
        <source>CP2 modem CD signal</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="175"/>
        <source>time-out during RS</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="177"/>
        <source>parallel operation high-speed transfer</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="179"/>
        <source>CPU link communication failed (master); M9184..M9190 slaves 1..7</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="182"/>
        <source>RS communication error code</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="184"/>
        <source>display mode of the display screen</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="186"/>
        <source>number of the D register shown in mode 3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="188"/>
        <source>computer link station number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="190"/>
        <source>current network scan time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="192"/>
        <source>maximum network scan time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="205"/>
        <source>Start a block with a rising-edge contact</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="208"/>
        <source>Start a block with a falling-edge contact</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="217"/>
        <source>Rising-edge contact in series</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="220"/>
        <source>Falling-edge contact in series</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="229"/>
        <source>Rising-edge contact in parallel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="232"/>
        <source>Falling-edge contact in parallel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="253"/>
        <source>Push the result onto the branch stack</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="256"/>
        <source>Read the top of the branch stack</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="258"/>
        <source>Pop the branch stack</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="260"/>
        <source>Invert the result</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="264"/>
        <source>Set (latch) a device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="267"/>
        <source>Reset a device, a timer or a counter</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="278"/>
        <source>On-delay timer, 100 ms units</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="285"/>
        <source>Counter: counts rising edges, reset with RST</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="291"/>
        <source>Step ladder: start of step S</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="294"/>
        <source>End of the step ladder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="303"/>
        <source>Move S to D</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="305"/>
        <source>Move n words from S to D</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="309"/>
        <source>Compare S1 with S2: D, D+1, D+2 = &gt;, =, &lt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="312"/>
        <source>Reset every device from D1 to D2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="315"/>
        <source>D = S1 + S2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="317"/>
        <source>D = S1 - S2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="320"/>
        <source>D, D+1 = S1 x S2 (32-bit product)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="322"/>
        <source>D = S1 / S2, D+1 = remainder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="325"/>
        <source>D = D + 1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="327"/>
        <source>D = D - 1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vigor.cpp" line="332"/>
        <source>Communication or conversion instruction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vpc.cpp" line="30"/>
        <source>Compare contact between two decimal operands</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vpc.cpp" line="74"/>
        <source>retentive auxiliary relays</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vpc.cpp" line="80"/>
        <location filename="../model/target_vpc.cpp" line="84"/>
        <source>system relays</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vpc.cpp" line="98"/>
        <source>registers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vpc.cpp" line="102"/>
        <source>parallel output (o00..o11)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vpc.cpp" line="105"/>
        <source>parallel input (i00..i11)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vpc.cpp" line="111"/>
        <source>RUN: always ON</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vpc.cpp" line="113"/>
        <source>ERR: program error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vpc.cpp" line="115"/>
        <source>CON: PC connected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vpc.cpp" line="117"/>
        <source>VPCIO connected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vpc.cpp" line="121"/>
        <source>0.01 s clock</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vpc.cpp" line="156"/>
        <source>Transfer while the condition is OFF: d,s  d+s  d-s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vpc.cpp" line="158"/>
        <source>Transfer while the condition is ON: d,s  d+s  d-s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vpc.cpp" line="169"/>
        <source>Latching relay: set = last but one block, reset = last block</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vpc.cpp" line="175"/>
        <source>Timer: 00..15 count down, 16..31 count up, 0.01 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vpc.cpp" line="181"/>
        <source>Counter: count = last but one block, reset = last block</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vpc.cpp" line="192"/>
        <source>Jump: skip up to JPE while the condition is OFF</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../model/target_vpc.cpp" line="194"/>
        <source>End of a jump</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rung::simulator::Compiler</name>
    <message>
        <location filename="../simulator/compiler.cpp" line="59"/>
        <source>%1 is not simulated: it does nothing in the simulator</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../simulator/compiler.cpp" line="89"/>
        <source>%1 is not a bit device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../simulator/compiler.cpp" line="101"/>
        <source>constant %1 is out of range</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../simulator/compiler.cpp" line="106"/>
        <source>%1 is not a word device or a constant</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../simulator/compiler.cpp" line="162"/>
        <source>%1 needs %2 open blocks before it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../simulator/compiler.cpp" line="200"/>
        <source>more than %1 open blocks</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../simulator/compiler.cpp" line="234"/>
        <source>%1 is not a timer</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../simulator/compiler.cpp" line="271"/>
        <source>%1 is not a counter</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../simulator/compiler.cpp" line="317"/>
        <source>%1 needs three bit devices from %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../simulator/compiler.cpp" line="334"/>
        <source>%1 needs two devices of one kind, the first not after the second</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../simulator/compiler.cpp" line="382"/>
        <source>unknown operator %1 (use + - * / | &amp; ^ &lt;&lt; &gt;&gt;)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../simulator/compiler.cpp" line="399"/>
        <source>%1 needs a bit: a bit device, or a word and a bit number 0..15</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../simulator/compiler.cpp" line="426"/>
        <source>%1 needs a count from 1 to %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../simulator/compiler.cpp" line="440"/>
        <source>the block of %1 words runs past the end of its area</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../simulator/compiler.cpp" line="531"/>
        <source>label %1 ends more than one jump</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../simulator/compiler.cpp" line="543"/>
        <source>jump %1 has no end after it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../simulator/compiler.cpp" line="549"/>
        <source>%1 without a jump before it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../simulator/compiler.cpp" line="558"/>
        <source>%1 has no end</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../simulator/compiler.cpp" line="573"/>
        <source>unknown instruction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../simulator/compiler.cpp" line="592"/>
        <source>more than %1 nested %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../simulator/compiler.cpp" line="601"/>
        <source>%1 without MPS before it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../simulator/compiler.cpp" line="632"/>
        <source>%1 cannot be reset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../simulator/compiler.cpp" line="637"/>
        <source>%1 is not a device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../simulator/compiler.cpp" line="740"/>
        <source>the program has no target</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rung::simulator::Engine</name>
    <message>
        <location filename="../simulator/engine.cpp" line="240"/>
        <source>set value %1 is not a BCD number; the instruction is skipped</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../simulator/engine.cpp" line="516"/>
        <location filename="../simulator/engine.cpp" line="568"/>
        <source>division by zero; the destination is unchanged</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rung::simulator::Trace</name>
    <message>
        <location filename="../simulator/trace.cpp" line="23"/>
        <source>unknown device %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../simulator/trace.cpp" line="49"/>
        <source>%1 needs a value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../simulator/trace.cpp" line="50"/>
        <source>unexpected argument %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../simulator/trace.cpp" line="59"/>
        <source>%1 needs a positive number, not &quot;%2&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../simulator/trace.cpp" line="71"/>
        <source>--set needs DEV=VALUE@SCAN, not &quot;%1&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../simulator/trace.cpp" line="100"/>
        <source>unknown option %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../simulator/trace.cpp" line="105"/>
        <source>--scans and --trace are required</source>
        <translation type="unfinished"></translation>
    </message>
</context>
</TS>
