// A template whose every instantiation doubles its argument list: the compiler's memory runs out
// (or its time), never the machine's.
template <class... T> struct Doubling { using type = typename Doubling<T..., T...>::type; };
using Boom = Doubling<int>::type;
static void AddCollisionImpulse(RigidBody& c0, RigidBody& c1, const Vector3& hitPoint, const Vector3& normal, float penetration) {}
