// The store stage of the default method: after each sub-step the impulses added to the step's
// totals, and after the last one the impulses kept for the records, the next step's warm start and
// the sub-step estimate (stack_sink.h).
#include "physics/contact_solver.h"
#include "physics/step_buffer.h"
#include "physics/friction.h"

#include <algorithm>

namespace impulse::physics {

// For a block's first place: its manifolds' sub-step impulses added to the step's totals.
void ContactSolver::add_to_totals(int place) {
  if (lane_of_place_[place].lane != 0) return;
  ManifoldLanes& block = lanes_[lane_of_place_[place].block];
  for (int i = 0; i < block.points; ++i) {
    PointLanes& p = lane_points_[block.first_point + i];
    p.total_normal_impulse = p.total_normal_impulse + p.normal_impulse;
  }
  block.total_tangent_impulse1 = block.total_tangent_impulse1 + block.tangent_impulse1;
  block.total_tangent_impulse2 = block.total_tangent_impulse2 + block.tangent_impulse2;
}

// The step's impulses, from its lane back to its manifold and points: for the records, the loads
// and the next step's warm start.
void ContactSolver::copy_back(int place) {
  const auto [index, l] = lane_of_place_[place];
  const ManifoldLanes& block = lanes_[index];
  ManifoldConstraint& m = manifolds_[place];
  m.tangent_impulse1 = block.tangent_impulse1[l];
  m.tangent_impulse2 = block.tangent_impulse2[l];
  m.twist_impulse = block.twist_impulse[l];
  m.total_tangent_impulse1 = block.total_tangent_impulse1[l];
  m.total_tangent_impulse2 = block.total_tangent_impulse2[l];
  for (int i = 0; i < m.count; ++i) {
    constraints_[m.first + i].normal_impulse = lane_points_[block.first_point + i].normal_impulse[l];
    constraints_[m.first + i].total_normal_impulse = lane_points_[block.first_point + i].total_normal_impulse[l];
  }
}

void ContactSolver::store_impulses() {
  impulses_stored_ = true;
  stored_h_ = h_;
  resize_for_step(loads_, manifolds_.size());
  resize_for_step(warm_manifolds_, manifolds_.size());
  resize_for_step(warm_points_, constraints_.size());
  schedule_.for_each_place(*team_, [&](int place) {
    copy_back(place);
    const ManifoldConstraint& m = manifolds_[place];
    warm_manifolds_[place] = {m.first, m.count, m.tangent_impulse1 * m.tangent1 + m.tangent_impulse2 * m.tangent2, m.twist_impulse};
    for (int i = 0; i < m.count; ++i) warm_points_[m.first + i] = {constraints_[m.first + i].feature, constraints_[m.first + i].normal_impulse};
    ManifoldLoad& load = loads_[place];
    load = {m.a, m.b, 0, 0, m.normal};
    for (int i = 0; i < m.count; ++i) {
      load.impulse += constraints_[m.first + i].total_normal_impulse / std::max(substeps_, 1);
      load.normal_mass += constraints_[m.first + i].normal_mass;
    }
    // For the records: each point's share of the friction, by its share of the normal impulse.
    Real normal_sum = 0;
    for (int i = 0; i < m.count; ++i) normal_sum += constraints_[m.first + i].total_normal_impulse;
    for (int i = 0; i < m.count; ++i) {
      ContactConstraint& c = constraints_[m.first + i];
      const Real share = normal_sum > 0 ? c.total_normal_impulse / normal_sum : Real(1) / m.count;
      c.total_tangent_impulse1 = share * m.total_tangent_impulse1;
      c.total_tangent_impulse2 = share * m.total_tangent_impulse2;
    }
  });
}

int ContactSolver::manifold_of_constraint(int constraint) const {
  return int(std::upper_bound(first_of_place_.begin(), first_of_place_.end(), constraint) - first_of_place_.begin()) - 1;
}

}  // namespace impulse::physics
