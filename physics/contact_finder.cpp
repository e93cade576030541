// Contacts of a step: sweep-and-prune pairs, then the narrow phase on each.
#include "physics/contact_finder.h"

#include "physics/collide.h"

#include <algorithm>

namespace impulse::physics {

Real motion_bound(const Body& body, Real dt) {
  return (body.velocity.norm() + body.angular_velocity.norm() * bounding_radius(body.shape)) * dt;
}

namespace {

// Fewer pairs than this are not worth waking a helper for.
constexpr size_t kMinPairsPerThread = 128;

// A pair's contacts are recycled while B has moved, relative to A, by less than this since they
// were built (its centre, plus its turn times its bounding radius), and the margin has not grown
// by more: every recycled separation is then within it of a fresh one. A stale separation is a
// position error that the soft contact turns into motion (at its bias rate, about 36 /s at 120
// Hz): at 10 um and 1 um resting heaps, the 210 pyramid and a stack on a slope moved faster than
// their tests allow; at 0.1 um every test holds.
constexpr Real kRecycleDistance = 1e-7;  // m

}  // namespace

void ContactFinder::find(const std::vector<Body>& bodies, const std::vector<uint8_t>& awake, Real dt,
                         Real base_margin, ThreadTeam& team, int team_threads, std::vector<Contact>& out) {
  out.clear();
  // Each box grows by its body's share of a pair's margin, so that two boxes overlap whenever
  // their shapes are within base_margin + motion_bound(a) + motion_bound(b).
  const size_t n = bodies.size();
  boxes_.resize(n);
  motion_bounds_.resize(n);
  for (size_t i = 0; i < n; ++i) {
    motion_bounds_[i] = motion_bound(bodies[i], dt);
    boxes_[i] = body_aabb(bodies[i], base_margin / 2 + motion_bounds_[i]);
  }
  broad_phase_.find_pairs(boxes_, awake, pairs_, team_threads > 1 ? &team : nullptr);
  // Each pair starts from last call's cache (both lists in increasing pair order: one merge).
  caches_.assign(pairs_.size(), SatCache{});
  built_.assign(pairs_.size(), BuiltRef{});
  auto before = [](const BodyPair& x, const BodyPair& y) { return x.a != y.a ? x.a < y.a : x.b < y.b; };
  for (size_t k = 0, p = 0; k < pairs_.size(); ++k) {
    while (p < previous_pairs_.size() && before(previous_pairs_[p], pairs_[k])) ++p;
    if (p < previous_pairs_.size() && previous_pairs_[p] == pairs_[k]) {
      caches_[k] = previous_caches_[p];
      built_[k] = previous_built_[p];
    }
  }
  const size_t threads = std::min({size_t(team.size()), size_t(std::max(team_threads, 1)), pairs_.size() / kMinPairsPerThread});
  local_.resize(std::max<size_t>(threads, 1));
  records_.resize(local_.size());
  previous_local_.resize(std::max(previous_local_.size(), local_.size()));
  previous_records_.resize(previous_local_.size());
  recycled_per_thread_.assign(local_.size(), 0);
  auto collide_range = [&](int thread, size_t begin, size_t end, std::vector<Contact>& contacts) {
    local_[thread].clear();
    records_[thread].clear();
    for (size_t k = begin; k < end; ++k) {
      const BodyPair& pair = pairs_[k];
      const Real margin = base_margin + motion_bounds_[pair.a] + motion_bounds_[pair.b];
      // Only box pairs: the other narrow phases cost less than the test (the heap of spheres ran
      // 7 % slower with its pairs recycled).
      const bool boxes = bodies[pair.a].shape.type == ShapeType::box && bodies[pair.b].shape.type == ShapeType::box;
      if (boxes && recycle(bodies, pair, margin, built_[k], thread, contacts)) {
        ++recycled_per_thread_[thread];
        continue;
      }
      const size_t first = contacts.size();
      collide(bodies[pair.a], pair.a, bodies[pair.b], pair.b, margin, contacts, &caches_[k]);
      if (boxes) note_built(bodies, pair, margin, contacts, first, built_[k], thread);
    }
  };
  if (threads < 2) {
    collide_range(0, 0, pairs_.size(), out);
  } else {
    // Consecutive runs of pairs, one per thread, joined in order afterwards.
    shares_.resize(threads - 1);
    team.run([&](int thread) {
      if (size_t(thread) >= threads) return;
      std::vector<Contact>& contacts = thread == 0 ? out : shares_[thread - 1];
      contacts.clear();
      collide_range(thread, pairs_.size() * thread / threads, pairs_.size() * (thread + 1) / threads, contacts);
    });
    for (const std::vector<Contact>& share : shares_) out.insert(out.end(), share.begin(), share.end());
  }
  recycled_ = 0;
  for (size_t r : recycled_per_thread_) recycled_ += r;
  std::swap(previous_pairs_, pairs_);  // pairs_ is refilled by the next call's broad phase
  std::swap(previous_caches_, caches_);
  std::swap(previous_built_, built_);
  std::swap(previous_local_, local_);
  std::swap(previous_records_, records_);
}

// B's pose in A's frame.
ContactFinder::Built ContactFinder::relative_pose(const Body& a, const Body& b) {
  Built pose;
  const Quat to_a = a.orientation.conjugate();
  pose.relative_position = rotate(to_a, b.position - a.position);
  pose.relative_orientation = to_a * b.orientation;
  return pose;
}

bool ContactFinder::recycle(const std::vector<Body>& bodies, const BodyPair& pair, Real margin, BuiltRef& ref, int thread,
                            std::vector<Contact>& contacts) {
  if (ref.thread < 0) return false;
  Built built = previous_records_[ref.thread][ref.index];
  if (margin > built.margin + kRecycleDistance) return false;
  const Body& a = bodies[pair.a];
  const Body& b = bodies[pair.b];
  const Real radius = bounding_radius(b.shape);
  const Built now = relative_pose(a, b);
  const Quat turn = built.relative_orientation.conjugate() * now.relative_orientation;
  const Real moved = (now.relative_position - built.relative_position).norm() + 2 * turn.vec().norm() * radius;
  if (!(moved < kRecycleDistance)) return false;
  // Carried by A's motion since they were built.
  const Vec3 normal = rotate(a.orientation, built.normal);
  std::vector<LocalContact>& local = local_[thread];
  const LocalContact* from = &previous_local_[ref.thread][built.first];
  const size_t first = local.size();
  local.insert(local.end(), from, from + built.count);
  built.first = int(first);
  ref = {int16_t(thread), int(records_[thread].size())};
  records_[thread].push_back(built);
  for (size_t i = first; i < local.size(); ++i) {
    const LocalContact& c = local[i];
    Contact contact;
    contact.body_a = c.swapped ? pair.b : pair.a;
    contact.body_b = c.swapped ? pair.a : pair.b;
    contact.point = a.position + rotate(a.orientation, c.point);
    contact.normal = c.swapped ? Vec3(-normal) : normal;
    contact.separation = c.separation;
    contact.feature = c.feature;
    contacts.push_back(contact);
  }
  return true;
}

void ContactFinder::note_built(const std::vector<Body>& bodies, const BodyPair& pair, Real margin, const std::vector<Contact>& contacts,
                               size_t first, BuiltRef& ref, int thread) {
  const Body& a = bodies[pair.a];
  Built built = relative_pose(a, bodies[pair.b]);
  built.margin = margin;
  std::vector<LocalContact>& local = local_[thread];
  built.first = int(local.size());
  built.count = int16_t(contacts.size() - first);
  ref = {int16_t(thread), int(records_[thread].size())};
  records_[thread].push_back(built);
  if (built.count == 0) return;  // apart: recycled as apart while they stay put
  Built& record = records_[thread].back();
  const Quat to_a = a.orientation.conjugate();
  const Vec3 first_normal = contacts[first].body_a == pair.a ? contacts[first].normal : Vec3(-contacts[first].normal);
  record.normal = rotate(to_a, first_normal);
  for (size_t i = first; i < contacts.size(); ++i) {
    const Contact& c = contacts[i];
    const bool swapped = c.body_a != pair.a;
    if ((swapped ? Vec3(-c.normal) : c.normal) != first_normal) {  // not one normal: built afresh every step
      local.resize(built.first);
      records_[thread].pop_back();
      ref = BuiltRef{};
      return;
    }
    local.push_back({rotate(to_a, c.point - a.position), c.separation, c.feature, swapped});
  }
}

}  // namespace impulse::physics
