// hcomb2rings: see libcore/app/Hcomb2RingsTool.hpp.
#include "app/Hcomb2RingsTool.hpp"

int main(int argc, char** argv) {
    return hvi::app::Hcomb2RingsTool().run(argc, argv);
}
