// hvi-assess: see libcore/app/HviAssessTool.hpp.
#include "app/HviAssessTool.hpp"

int main(int argc, char** argv) { return hvi::app::HviAssessTool().run(argc, argv); }
