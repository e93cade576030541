// Forks in a loop. Bounded, and each child exits at once: a sandbox that fails this costs the
// machine 50 short processes, and the test fails on the missing report.
#include <sys/wait.h>
#include <unistd.h>

static void Hostile() {
  for (int i = 0; i < 50; ++i) {
    const pid_t child = fork();
    if (child == 0) _exit(0);
    if (child > 0) waitpid(child, nullptr, 0);
  }
}
