// The aabench command line. All parsing and dispatch live in harness/cli.cpp.
#include "harness/cli.h"

int main(int argc, char** argv) { return aabench::run_cli(argc, argv); }
