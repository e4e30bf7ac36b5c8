<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en">
<context>
    <name>rung::app::CompareWindow</name>
    <message numerus="yes">
        <location filename="../app/gui/compare_window.cpp" line="+198"/>
        <source>%n rung(s) differ.</source>
        <translation>
            <numerusform>%n rung differs.</numerusform>
            <numerusform>%n rungs differ.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+7"/>
        <source>%n difference(s) besides the rungs (symbols, set values, watch lists): see the Report.</source>
        <translation>
            <numerusform>%n difference besides the rungs (symbols, set values, watch lists): see the Report.</numerusform>
            <numerusform>%n differences besides the rungs (symbols, set values, watch lists): see the Report.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>rung::app::MainWindow</name>
    <message numerus="yes">
        <location filename="../app/gui/main_window.cpp" line="+211"/>
        <source>%n rung(s)</source>
        <translation>
            <numerusform>%n rung</numerusform>
            <numerusform>%n rungs</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>%n step(s)</source>
        <translation>
            <numerusform>%n step</numerusform>
            <numerusform>%n steps</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/main_window_tools.cpp" line="+124"/>
        <source>Paste %n rungs</source>
        <translation>
            <numerusform>Paste %n rung</numerusform>
            <numerusform>Paste %n rungs</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+45"/>
        <source>%n place(s) changed</source>
        <translation>
            <numerusform>%n place changed</numerusform>
            <numerusform>%n places changed</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+49"/>
        <source>%n row(s) of the symbol table name no device of this PLC and are left out of the file: %1. Export the other symbols?</source>
        <translation>
            <numerusform>%n row of the symbol table names no device of this PLC and is left out of the file: %1. Export the other symbols?</numerusform>
            <numerusform>%n rows of the symbol table name no device of this PLC and are left out of the file: %1. Export the other symbols?</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>rung::app::NetworkTrafficView</name>
    <message numerus="yes">
        <location filename="../app/gui/network_traffic_view.cpp" line="+307"/>
        <source>%n frame(s)</source>
        <translation>
            <numerusform>%n frame</numerusform>
            <numerusform>%n frames</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>rung::app::NetworkWindow</name>
    <message numerus="yes">
        <location filename="../app/gui/network_window_session.cpp" line="+351"/>
        <source>%1, %2, %n station(s)</source>
        <extracomment>%1 run state, %2 virtual time, %3 number of stations</extracomment>
        <translation>
            <numerusform>%1, %2, %n station</numerusform>
            <numerusform>%1, %2, %n stations</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>rung::app::PlcopenImportDialog</name>
    <message numerus="yes">
        <location filename="../app/gui/plcopen_exchange.cpp" line="+215"/>
        <source>Everything in the file is imported: %n rung(s).</source>
        <translation>
            <numerusform>Everything in the file is imported: %n rung.</numerusform>
            <numerusform>Everything in the file is imported: %n rungs.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>%n item(s) of the file are not imported; %1 variable(s) have no device yet.</source>
        <translation>
            <numerusform>%n item of the file is not imported; %1 variable(s) have no device yet.</numerusform>
            <numerusform>%n items of the file are not imported; %1 variable(s) have no device yet.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>rung::app::SimulationController</name>
    <message numerus="yes">
        <location filename="../app/gui/simulation_controller.cpp" line="+101"/>
        <source>The program has %n error(s): the simulation does not start; the Problems list shows them</source>
        <translation>
            <numerusform>The program has %n error: the simulation does not start; the Problems list shows it</numerusform>
            <numerusform>The program has %n errors: the simulation does not start; the Problems list shows them</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>rung::app::TestsPanel</name>
    <message numerus="yes">
        <location filename="../app/gui/tests_panel.cpp" line="+343"/>
        <source>passed: %n expectation(s)</source>
        <translation>
            <numerusform>passed: %n expectation</numerusform>
            <numerusform>passed: %n expectations</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+5"/>
        <source>FAILED: %n expectation(s)</source>
        <translation>
            <numerusform>FAILED: %n expectation</numerusform>
            <numerusform>FAILED: %n expectations</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>rung::editor::Document</name>
    <message numerus="yes">
        <location filename="../editor/document.cpp" line="+155"/>
        <source>Delete %n rungs</source>
        <translation>
            <numerusform>Delete %n rung</numerusform>
            <numerusform>Delete %n rungs</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>rung::editor::TimingChart</name>
    <message numerus="yes">
        <location filename="../editor/timing_chart.cpp" line="+417"/>
        <source>B − A: %1 (%n scan(s))</source>
        <extracomment>the time between the cursors, and how many scans that is</extracomment>
        <translation>
            <numerusform>B − A: %1 (%n scan)</numerusform>
            <numerusform>B − A: %1 (%n scans)</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>rung::model::Checks</name>
    <message numerus="yes">
        <location filename="../model/checks/checks_blocks_and_stack.cpp" line="+147"/>
        <source>Stacked %1: %n blocks are open; an OR chain needs less stack</source>
        <translation>
            <numerusform>Stacked %1: %n block is open; an OR chain needs less stack</numerusform>
            <numerusform>Stacked %1: %n blocks are open; an OR chain needs less stack</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+98"/>
        <source>%n MPS left without MPP at the end of the rung</source>
        <translation>
            <numerusform>%n MPS left without MPP at the end of the rung</numerusform>
            <numerusform>%n MPS left without MPP at the end of the rung</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>rung::model::Convert</name>
    <message numerus="yes">
        <location filename="../model/convert/convert_to_ladder.cpp" line="+310"/>
        <source>%1 needs two blocks, but %n is open</source>
        <translation>
            <numerusform>%1 needs two blocks, but %n is open</numerusform>
            <numerusform>%1 needs two blocks, but %n are open</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+19"/>
        <source>MPS needs exactly one open block, but %n is open</source>
        <translation>
            <numerusform>MPS needs exactly one open block, but %n is open</numerusform>
            <numerusform>MPS needs exactly one open block, but %n are open</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+100"/>
        <source>The rung starting on line %1 leaves %n MPS without MPP</source>
        <translation>
            <numerusform>The rung starting on line %1 leaves %n MPS without MPP</numerusform>
            <numerusform>The rung starting on line %1 leaves %n MPS without MPP</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>rung::model::InstructionList</name>
    <message numerus="yes">
        <location filename="../model/listing/il_parse.cpp" line="+506"/>
        <source>%1 needs %n operand(s): %2</source>
        <translation>
            <numerusform>%1 needs %n operand: %2</numerusform>
            <numerusform>%1 needs %n operands: %2</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+10"/>
        <source>Unexpected &apos;%1&apos;: %2 takes %n operand(s)</source>
        <translation>
            <numerusform>Unexpected &apos;%1&apos;: %2 takes %n operand</numerusform>
            <numerusform>Unexpected &apos;%1&apos;: %2 takes %n operands</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>rung::network::TrafficDecode</name>
    <message numerus="yes">
        <location filename="../network/traffic_decode.cpp" line="+79"/>
        <source>the frame stops after %n byte(s): cut short or not a frame</source>
        <translation>
            <numerusform>the frame stops after %n byte: cut short or not a frame</numerusform>
            <numerusform>the frame stops after %n bytes: cut short or not a frame</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+5"/>
        <source>%n byte(s) after the end of the frame</source>
        <translation>
            <numerusform>%n byte after the end of the frame</numerusform>
            <numerusform>%n bytes after the end of the frame</numerusform>
        </translation>
    </message>
</context>
</TS>
