// foam2layers: see libcore/app/Foam2LayersTool.hpp.
#include "app/Foam2LayersTool.hpp"

int main(int argc, char** argv) {
    return hvi::app::Foam2LayersTool().run(argc, argv);
}
