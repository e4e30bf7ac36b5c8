#pragma once

namespace rung::app {

// Creates the QApplication, installs the translators, opens the main window with the file
// given on the command line, and runs the event loop.
int runGui(int argc, char **argv);

} // namespace rung::app
