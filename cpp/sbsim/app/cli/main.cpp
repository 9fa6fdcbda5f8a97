#include <string>
#include <vector>

#include "sbsim/app/cli/Program.h"

int main(int argc, char** argv) { return sbsim::app::runProgram(std::vector<std::string>(argv + 1, argv + argc)); }
