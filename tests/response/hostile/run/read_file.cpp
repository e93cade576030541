// Reads the first line of /etc/passwd and prints it.
#include <cstdio>

static void Hostile() {
  if (FILE* file = std::fopen("/etc/passwd", "r")) {
    char line[256];
    if (std::fgets(line, sizeof line, file) != nullptr) std::printf("read: %s", line);
    std::fclose(file);
  }
}
