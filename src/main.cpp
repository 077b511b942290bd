// granule: the command-line entry point (src/app/command_line.cpp).
#include "app/command_line.hpp"

int main(int argc, char** argv) { return granule::app::run_granule(argc, argv); }
