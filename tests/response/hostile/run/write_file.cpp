// Writes a file into the test's scratch folder (@SCRATCH@), which the test then finds empty.
#include <cstdio>

static void Hostile() {
  if (FILE* file = std::fopen("@SCRATCH@/written.txt", "w")) {
    std::fputs("written by graded code\n", file);
    std::fclose(file);
  }
}
