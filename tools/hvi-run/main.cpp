// hvi-run: see libcore/app/HviRunTool.hpp.
#include "app/HviRunTool.hpp"

int main(int argc, char** argv) { return hvi::app::HviRunTool().run(argc, argv); }
