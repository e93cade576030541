#include "physics/joint_solver.h"

#include "physics/normal_impulse.h"

#include <algorithm>
#include <stdexcept>

namespace impulse::physics {

namespace {

// How far each body has moved since the step began, applied to its anchor.
Vec3 anchor_now(const BodyState& s, const Vec3& anchor) { return s.dp + rotate(s.dq, anchor); }

// Velocity of B's point at rb relative to A's point at ra (the opposite of relative_velocity).
Vec3 velocity_b_minus_a(const BodyState& sa, const BodyState& sb, const Vec3& ra, const Vec3& rb) {
  return -relative_velocity(sa, sb, ra, rb);
}

}  // namespace

Joint make_joint(const JointDef& def, const std::vector<Body>& bodies) {
  const int n = int(bodies.size());
  auto check_body = [&](int index, const char* which) {
    if (index != kWorld && (index < 0 || index >= n))
      throw std::invalid_argument(std::string("joint body ") + which + " does not exist");
  };
  check_body(def.body_a, "A");
  check_body(def.body_b, "B");
  if (def.body_a == def.body_b) throw std::invalid_argument("a joint needs two different bodies");
  auto to_local = [&](int index, const Vec3& world_point) -> Vec3 {
    if (index == kWorld) return world_point;
    const Body& body = bodies[index];
    return body.orientation.conjugate() * (world_point - body.position);
  };
  auto axis_local = [&](int index, const Vec3& world_axis) -> Vec3 {
    return index == kWorld ? world_axis : Vec3(bodies[index].orientation.conjugate() * world_axis);
  };

  Joint joint;
  joint.name = def.name;
  joint.type = def.type;
  joint.body_a = def.body_a;
  joint.body_b = def.body_b;
  if (def.type == JointType::distance) {
    joint.local_anchor_a = to_local(def.body_a, def.anchor_a);
    joint.local_anchor_b = to_local(def.body_b, def.anchor_b);
    joint.length = def.length > 0 ? def.length : (def.anchor_b - def.anchor_a).norm();
    joint.rope = def.rope;
    if (!(joint.length > 1e-6)) throw std::invalid_argument("a distance joint needs a length > 0");
  } else {
    joint.local_anchor_a = to_local(def.body_a, def.anchor);
    joint.local_anchor_b = to_local(def.body_b, def.anchor);
    if (def.type == JointType::hinge) {
      if (def.axis.norm() < 1e-9) throw std::invalid_argument("a hinge needs a non-zero axis");
      joint.local_axis_a = axis_local(def.body_a, def.axis.normalized());
      joint.local_axis_b = axis_local(def.body_b, def.axis.normalized());
    }
  }
  return joint;
}

void JointSolver::prepare(std::vector<Joint>& joints, const std::vector<Body>& bodies, const std::vector<int>& slots,
                          Real hertz, Real damping_ratio, Real h) {
  softness_ = make_softness(hertz, damping_ratio, h);
  const int world = int(bodies.size());
  prepared_.clear();
  // The joints' clusters: bodies linked through joints, by slot (union-find, the world apart).
  std::vector<int> parent(bodies.size() + 1);
  for (size_t i = 0; i < parent.size(); ++i) parent[i] = int(i);
  auto root = [&](int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (Joint& joint : joints) {
    Prepared p;
    p.joint = &joint;
    p.a = joint.body_a == kWorld ? world : slots[joint.body_a];
    p.b = joint.body_b == kWorld ? world : slots[joint.body_b];
    const Quat qa = joint.body_a == kWorld ? Quat::Identity() : bodies[joint.body_a].orientation;
    const Quat qb = joint.body_b == kWorld ? Quat::Identity() : bodies[joint.body_b].orientation;
    const Vec3 ca = joint.body_a == kWorld ? Vec3::Zero() : bodies[joint.body_a].position;
    const Vec3 cb = joint.body_b == kWorld ? Vec3::Zero() : bodies[joint.body_b].position;
    p.anchor_a = qa * joint.local_anchor_a;
    p.anchor_b = qb * joint.local_anchor_b;
    p.delta_centre = cb - ca;
    p.axis_a = qa * joint.local_axis_a;
    p.axis_b = qb * joint.local_axis_b;
    p.length = joint.length;
    prepared_.push_back(p);
    if (p.a != world && p.b != world) parent[root(p.a)] = root(p.b);
  }
  cluster_of_slot_.assign(bodies.size() + 1, -1);
  for (Prepared& p : prepared_) {
    p.cluster = root(p.a != world ? p.a : p.b);
    for (int slot : {p.a, p.b})
      if (slot != world) cluster_of_slot_[slot] = p.cluster;
  }
}

void JointSolver::warm_start(SolverBodies& bodies) const {
  for (const Prepared& p : prepared_) {
    BodyState& sa = bodies.states[p.a];
    BodyState& sb = bodies.states[p.b];
    const Mat3& inv_ia = bodies.inertia[p.a].inv_inertia;
    const Mat3& inv_ib = bodies.inertia[p.b].inv_inertia;
    const Joint& j = *p.joint;
    const Vec3 ra = rotate(sa.dq, p.anchor_a), rb = rotate(sb.dq, p.anchor_b);
    Vec3 linear = j.impulse.linear;
    Vec3 angular = Vec3::Zero();
    if (j.type == JointType::distance) {
      const Vec3 d = p.delta_centre + anchor_now(sb, p.anchor_b) - anchor_now(sa, p.anchor_a);
      linear = j.impulse.axial * d.normalized();
    }
    if (j.type == JointType::hinge) {
      Vec3 t1, t2;
      tangent_basis(rotate(sa.dq, p.axis_a), t1, t2);
      angular = j.impulse.angular[0] * t1 + j.impulse.angular[1] * t2;
    }
    apply_impulse(sa, inv_ia, sb, inv_ib, ra, rb, -linear);  // +linear on B, -linear on A
    sa.w -= inv_ia * angular;
    sb.w += inv_ib * angular;
  }
}

void JointSolver::solve(SolverBodies& bodies, Real inv_h, bool use_bias) {
  const Rows rows = use_bias ? Rows{softness_.bias_rate, softness_.mass_scale, softness_.impulse_scale} : Rows{};
  for (Prepared& p : prepared_) solve_joint(p, bodies, inv_h, rows, p.joint->impulse);
}

void JointSolver::begin_impact(int slot_a, int slot_b) {
  impact_joints_.clear();
  const int ca = jointed(slot_a) ? cluster_of_slot_[slot_a] : -1, cb = jointed(slot_b) ? cluster_of_slot_[slot_b] : -1;
  impact_slots_.clear();
  const int world = int(cluster_of_slot_.size()) - 1;
  for (int k = 0; k < int(prepared_.size()); ++k) {
    const Prepared& p = prepared_[k];
    if (p.cluster != ca && p.cluster != cb) continue;
    impact_joints_.push_back(k);
    for (int slot : {p.a, p.b})
      if (slot != world && std::find(impact_slots_.begin(), impact_slots_.end(), slot) == impact_slots_.end()) impact_slots_.push_back(slot);
  }
  impact_impulses_.assign(prepared_.size(), JointImpulse{});
}

Real JointSolver::hold(SolverBodies& bodies, Real inv_h) {
  Real largest = 0;
  for (int k : impact_joints_) largest = std::max(largest, solve_joint(prepared_[k], bodies, inv_h, Rows{}, impact_impulses_[k]));
  return largest;
}

// One pass over a joint's rows, accumulating into `acc`; returns the largest change of an impulse.
Real JointSolver::solve_joint(const Prepared& p, SolverBodies& bodies, Real inv_h, const Rows& rows, JointImpulse& acc) {
  BodyState& sa = bodies.states[p.a];
  BodyState& sb = bodies.states[p.b];
  const Mat3& inv_ia = bodies.inertia[p.a].inv_inertia;
  const Mat3& inv_ib = bodies.inertia[p.b].inv_inertia;
  const Joint& j = *p.joint;
  const Vec3 ra = rotate(sa.dq, p.anchor_a), rb = rotate(sb.dq, p.anchor_b);
  // Where B's anchor is relative to A's (zero when the joint holds).
  const Vec3 separation = p.delta_centre + anchor_now(sb, p.anchor_b) - anchor_now(sa, p.anchor_a);
  Real largest = 0;

  if (j.type == JointType::hinge) {
    // Two angular rows: no relative spin across the hinge axis.
    const Vec3 axis_a = rotate(sa.dq, p.axis_a), axis_b = rotate(sb.dq, p.axis_b);
    Vec3 t[2];
    tangent_basis(axis_a, t[0], t[1]);
    const Vec3 misalignment = axis_a.cross(axis_b);
    const Mat3 inv_i = inv_ia + inv_ib;
    Eigen::Matrix<Real, 2, 2> k;
    for (int r = 0; r < 2; ++r)
      for (int c = 0; c < 2; ++c) k(r, c) = t[r].dot(inv_i * t[c]);
    if (k.determinant() > 1e-12) {
      const Vec3 dw = sb.w - sa.w;
      const Eigen::Matrix<Real, 2, 1> cdot(dw.dot(t[0]), dw.dot(t[1]));
      const Eigen::Matrix<Real, 2, 1> c(misalignment.dot(t[0]), misalignment.dot(t[1]));
      const Eigen::Matrix<Real, 2, 1> old(acc.angular[0], acc.angular[1]);
      const Eigen::Matrix<Real, 2, 1> impulse = -rows.mass_scale * k.inverse() * (cdot + rows.bias_rate * c) - rows.impulse_scale * old;
      acc.angular[0] += impulse[0];
      acc.angular[1] += impulse[1];
      largest = impulse.cwiseAbs().maxCoeff();
      const Vec3 angular = impulse[0] * t[0] + impulse[1] * t[1];
      sa.w -= inv_ia * angular;
      sb.w += inv_ib * angular;
    }
  }

  if (j.type == JointType::ball || j.type == JointType::hinge) {
    // Three linear rows: the anchors stay together.
    const Mat3 k = (sa.inv_mass + sb.inv_mass) * Mat3::Identity() + skew(ra) * inv_ia * skew(ra).transpose() +
                   skew(rb) * inv_ib * skew(rb).transpose();
    const Vec3 cdot = velocity_b_minus_a(sa, sb, ra, rb);
    const Vec3 impulse = -rows.mass_scale * k.ldlt().solve(cdot + rows.bias_rate * separation) - rows.impulse_scale * acc.linear;
    acc.linear += impulse;
    apply_impulse(sa, inv_ia, sb, inv_ib, ra, rb, -impulse);
    return std::max(largest, impulse.cwiseAbs().maxCoeff());
  }

  // Distance: one row along A->B.
  const Real length = separation.norm();
  if (length < 1e-9) return largest;
  const Vec3 u = separation / length;
  const Real c = length - p.length;
  const Vec3 ra_cross_u = ra.cross(u), rb_cross_u = rb.cross(u);
  const Real k = inverse_effective_mass_of_rows(sa.inv_mass + sb.inv_mass, ra_cross_u, inv_ia * ra_cross_u, rb_cross_u, inv_ib * rb_cross_u);  // eq. 13's
  if (k <= 0) return largest;
  const Real cdot = u.dot(velocity_b_minus_a(sa, sb, ra, rb));
  Real impulse;
  if (j.rope && c < 0) {
    impulse = -(cdot + c * inv_h) / k;  // slack: may tighten up to the length this sub-step
  } else {
    impulse = -rows.mass_scale * (cdot + rows.bias_rate * c) / k - rows.impulse_scale * acc.axial;
  }
  const Real old = acc.axial;
  acc.axial = j.rope ? std::min(old + impulse, Real(0)) : old + impulse;  // a rope only pulls
  apply_impulse(sa, inv_ia, sb, inv_ib, ra, rb, -(acc.axial - old) * u);
  return std::max(largest, std::abs(acc.axial - old));
}

}  // namespace impulse::physics
