// Starts a shell that makes a file in the test's scratch folder.
#include <cstdlib>

static void Hostile() { (void)!std::system("sh -c 'touch @SCRATCH@/shell_ran'"); }
