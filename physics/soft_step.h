// The stages of one sub-step of the default method (Box2D v3's soft step; its solver.c lists them
// the same way), written once. Contacts and joints are its participants: each stage runs the
// joints (on one thread) and then the contacts' sweep over every manifold in the sweeps' order.
//
//   1. integrate velocities (gravity)
//   2. warm start: last sub-step's impulses applied again
//   3. solve with the soft position bias; a contact that meets fast enough bounces at the moment
//      of contact (contact_bounce.cpp), with the joints on its bodies held; then the impact passes
//   4. integrate positions
//   5. relax: solve again without the bias, then add the sub-step's impulses to the step's totals
//
// The whole sub-step is one job of the thread team: its threads meet at a barrier between the
// stages instead of being woken for each.
#pragma once
#include "physics/contact_solver.h"
#include "physics/joint_solver.h"

#include <atomic>
#include <cstdint>
#include <memory>

namespace impulse::physics {

class SoftStep {
 public:
  // One sub-step of h. `joints` may be null (no joints). integrate_velocity(slot) and
  // integrate_position(slot) move one body's state.
  template <class IntegrateVelocity, class IntegratePosition>
  void substep(ContactSolver& contacts, JointSolver* joints, SolverBodies& bodies, Real h, IntegrateVelocity&& integrate_velocity,
               IntegratePosition&& integrate_position);

 private:
  // Per thread and per parity of the sweep's epoch: the last sweep's
  // epoch in which one of its manifolds bounced (bounce_flag). Two per thread, because a thread
  // that has left a pass's barrier may already write the next pass's flag while another still
  // reads this pass's: with one flag it could overwrite it, the other would read "nothing
  // bounced", leave the passes and wait at another barrier than this one, for ever. A write two
  // passes on comes after the next barrier, which every reader has passed. On the heap, as the
  // sweeps' progress counters: atomics cannot move with the world.
  static constexpr int kImpactPasses = 32;
  struct alignas(64) BounceEpoch {
    std::atomic<uint64_t> value{0};
  };
  std::unique_ptr<BounceEpoch[]> bounced_;
  int bounced_threads_ = 0;
  std::atomic<uint64_t>& bounce_flag(int thread, uint64_t epoch) { return bounced_[2 * thread + (epoch & 1)].value; }
};

template <class IntegrateVelocity, class IntegratePosition>
void SoftStep::substep(ContactSolver& contacts, JointSolver* joints, SolverBodies& bodies, Real h,
                       IntegrateVelocity&& integrate_velocity, IntegratePosition&& integrate_position) {
  SweepSchedule& schedule = contacts.schedule();
  ThreadTeam& team = contacts.team();
  // One epoch per sweep, increasing in the order the sweeps run: a place waits for another
  // thread's counter to reach its sweep's epoch, so a sweep numbered below one already run would
  // not wait at all (warm start, solve, the impact passes, relax).
  contacts.hold_joints(joints);
  const uint64_t epoch = schedule.new_epochs(3 + kImpactPasses);
  const uint64_t first_pass = epoch + 2, relax = first_pass + kImpactPasses;
  const bool parallel = schedule.parallel();
  if (bounced_threads_ < team.size()) {  // the flags only grow: a sweep's epoch is newer than any value
    bounced_ = std::make_unique<BounceEpoch[]>(2 * team.size());
    bounced_threads_ = team.size();
  }
  auto meet = [&] { if (parallel) team.barrier(); };
  // The joints are solved by the first thread alone, between the contacts' sweeps.
  auto joint_stage = [&](int thread, auto&& stage) {
    if (!joints) return;
    if (thread == 0) stage();
    meet();
  };
  // Whether a thread bounced something in the sweep of `sweep_epoch` (read after a barrier: every
  // thread reads the same and takes the same way).
  auto bounced_in = [&](uint64_t sweep_epoch) {
    for (int thread = 0; thread < team.size(); ++thread)
      if (bounce_flag(thread, sweep_epoch).load(std::memory_order_relaxed) == sweep_epoch) return true;
    return false;
  };
  schedule.run(team, [&](int thread) {
    schedule.slot_share(thread, [&](int slot) {
      integrate_velocity(slot);
      bodies.warm[size_t(slot)] = WarmStartChange{};
    });
    meet();
    joint_stage(thread, [&] { joints->warm_start(bodies); });
    schedule.sweep_share(thread, epoch, [&](int place, int) { contacts.warm_start_manifolds(place, bodies); });
    meet();
    joint_stage(thread, [&] { joints->solve(bodies, 1 / h, true); });
    bool bounced = false;
    schedule.sweep_share(thread, epoch + 1, [&](int place, int width) { bounced |= contacts.solve_manifolds(place, width, bodies, 1 / h, true); });
    if (bounced) bounce_flag(thread, epoch + 1).store(epoch + 1, std::memory_order_relaxed);
    meet();
    // The impacts pass on: a bounce sets bodies moving into their neighbours within the same
    // sub-step, which the sweep above may have visited before it. Pass after pass of bounces
    // alone, until one bounces nothing: every pair that closes is answered by eq. 5 in the order
    // the hits reach it (sequential impulses; Guendelman, Bridson and Fedkiw 2003), never by the
    // relax pass's inelastic rows. Each pass keeps momentum, angular momentum, and with e = 1 the
    // energy; passes beyond kImpactPasses are left to the rows.
    for (uint64_t pass = first_pass, last = epoch + 1; bounced_in(last) && pass < relax; last = pass++) {
      bounced = false;
      schedule.sweep_share(thread, pass, [&](int place, int width) { bounced |= contacts.bounce_manifolds(place, width, bodies, h); });
      if (bounced) bounce_flag(thread, pass).store(pass, std::memory_order_relaxed);
      meet();
    }
    schedule.slot_share(thread, integrate_position);
    meet();
    joint_stage(thread, [&] { joints->solve(bodies, 1 / h, false); });
    schedule.sweep_share(thread, relax, [&](int place, int width) {
      contacts.solve_manifolds(place, width, bodies, 1 / h, false);
      contacts.add_to_totals(place);  // the relax pass is the sub-step's last word on them
    });
  });
  contacts.end_substep();
}

}  // namespace impulse::physics
