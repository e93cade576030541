// The benchmark's scenes in Bullet (the peer): btDiscreteDynamicsWorld with
// btSequentialImpulseConstraintSolver and btDbvtBroadphase, default settings, 10 iterations, one
// fixed 1/60 s step per stepSimulation. Only this file includes Bullet.
#include "tests/bench/physics_scenes.h"

#include <btBulletDynamicsCommon.h>

#include <memory>

namespace impulse::bench {

namespace {

class BulletEngine {
 public:
  BulletEngine(const Scene& scene, bool sleep)
      : dispatcher_(&configuration_), world_(&dispatcher_, &broadphase_, &solver_, &configuration_) {
    world_.setGravity(btVector3(0, btScalar(-9.81), 0));
    world_.getSolverInfo().m_numIterations = 10;
    for (const BodySpec& spec : scene.bodies) {
      btCollisionShape* shape = shape_for(spec);
      const btScalar mass = spec.is_static ? 0 : 1;
      btVector3 inertia(0, 0, 0);
      if (!spec.is_static) shape->calculateLocalInertia(mass, inertia);
      btRigidBody::btRigidBodyConstructionInfo info(mass, nullptr, shape, inertia);
      info.m_startWorldTransform.setOrigin(btVector3(btScalar(spec.position.x), btScalar(spec.position.y), btScalar(spec.position.z)));
      info.m_startWorldTransform.setRotation(btQuaternion(btScalar(spec.orientation.x), btScalar(spec.orientation.y),
                                                          btScalar(spec.orientation.z), btScalar(spec.orientation.w)));
      info.m_friction = btScalar(kFriction);
      info.m_restitution = btScalar(kRestitution);
      auto body = std::make_unique<btRigidBody>(info);
      if (!spec.is_static && !sleep) body->setActivationState(DISABLE_DEACTIVATION);
      world_.addRigidBody(body.get());
      if (!spec.is_static) dynamic_.push_back(body.get());
      bodies_.push_back(std::move(body));
    }
  }
  ~BulletEngine() {
    for (auto& body : bodies_) world_.removeRigidBody(body.get());
  }
  BulletEngine(const BulletEngine&) = delete;
  BulletEngine& operator=(const BulletEngine&) = delete;

  void step() { world_.stepSimulation(btScalar(kTimeStep), 0); }
  V3 position(int i) const {
    const btVector3& p = dynamic_[i]->getCenterOfMassPosition();
    return {p.x(), p.y(), p.z()};
  }
  double speed(int i) const { return dynamic_[i]->getLinearVelocity().length(); }
  bool all_asleep() const {
    for (const btRigidBody* body : dynamic_)
      if (body->isActive()) return false;
    return true;
  }

 private:
  btCollisionShape* shape_for(const BodySpec& spec) {
    if (spec.kind == Kind::sphere) {
      if (sphere_ && sphere_->getRadius() == btScalar(spec.radius)) return sphere_;
      auto shape = std::make_unique<btSphereShape>(btScalar(spec.radius));
      sphere_ = shape.get();
      shapes_.push_back(std::move(shape));
      return sphere_;
    }
    const btVector3 half(btScalar(spec.half.x), btScalar(spec.half.y), btScalar(spec.half.z));
    if (!spec.is_static && unit_box_ && half == btVector3(btScalar(0.5), btScalar(0.5), btScalar(0.5))) return unit_box_;
    shapes_.push_back(std::make_unique<btBoxShape>(half));
    if (!spec.is_static && half == btVector3(btScalar(0.5), btScalar(0.5), btScalar(0.5))) unit_box_ = shapes_.back().get();
    return shapes_.back().get();
  }

  btDefaultCollisionConfiguration configuration_;
  btCollisionDispatcher dispatcher_;
  btDbvtBroadphase broadphase_;
  btSequentialImpulseConstraintSolver solver_;
  btDiscreteDynamicsWorld world_;
  std::vector<std::unique_ptr<btCollisionShape>> shapes_;
  btSphereShape* sphere_ = nullptr;
  btCollisionShape* unit_box_ = nullptr;
  std::vector<std::unique_ptr<btRigidBody>> bodies_;
  std::vector<btRigidBody*> dynamic_;
};

}  // namespace

void run_bullet(const Scene& scene, const Run& run, RunResult& out) {
  const auto t0 = std::chrono::steady_clock::now();
  BulletEngine engine(scene, run.sleep);
  out.build_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  measure(engine, scene, run, out);
}

std::string bullet_description() {
  return "Bullet " + std::to_string(btGetVersion() / 100) + "." + std::to_string(btGetVersion() % 100) + " (" +
         (sizeof(btScalar) == 8 ? "double" : "single") + " precision)";
}

}  // namespace impulse::bench
