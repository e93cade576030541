// Lists the test's scratch folder and prints what it holds.
#include <cstdio>
#include <dirent.h>

static void Hostile() {
  if (DIR* directory = opendir("@SCRATCH@")) {
    while (const dirent* entry = readdir(directory)) std::printf("listed: %s\n", entry->d_name);
    closedir(directory);
  }
}
