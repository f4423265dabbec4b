// hvi-sweep: see libcore/app/HviSweepTool.hpp.
#include "app/HviSweepTool.hpp"

int main(int argc, char** argv) {
    return hvi::app::HviSweepTool().run(argc, argv);
}
