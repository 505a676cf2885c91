// The aabench command line. All parsing and dispatch live in harness/cli/cli.cpp.
#include "harness/cli/cli.h"

int main(int argc, char** argv) { return aabench::run_cli(argc, argv); }
