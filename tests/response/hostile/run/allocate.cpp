// Allocates 64 GiB, 64 MiB at a time, touching every page. The test runs impulse-respond under
// an outer limit of 4 GiB of address space, so that a sandbox that fails this cannot make the
// machine swap; the report names the limit in force, which must be the sandbox's.
#include <cstddef>
#include <cstring>

static void Hostile() {
  constexpr std::size_t kBlock = std::size_t(64) << 20;
  for (std::size_t total = 0; total < (std::size_t(64) << 30); total += kBlock) std::memset(new char[kBlock], 1, kBlock);
}
