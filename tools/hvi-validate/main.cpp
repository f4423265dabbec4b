// hvi-validate: see libcore/app/HviValidateTool.hpp.
#include "app/HviValidateTool.hpp"

int main(int argc, char** argv) {
    return hvi::app::HviValidateTool().run(argc, argv);
}
