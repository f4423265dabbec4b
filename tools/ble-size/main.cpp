// ble-size: see libcore/app/BleSizeTool.hpp.
#include "app/BleSizeTool.hpp"

int main(int argc, char** argv) { return hvi::app::BleSizeTool().run(argc, argv); }
