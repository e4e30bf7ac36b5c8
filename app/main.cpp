#include "app/gui/application.h"

int main(int argc, char **argv) {
    return rung::app::runGui(argc, argv);
}
