// Prints a million lines.
#include <cstdio>

static void Hostile() {
  for (int i = 0; i < 1000000; ++i) std::printf("line %d of a million\n", i);
}
