/* impulse/workshop_abi.h: how impulse calls a compiled response (a shared object built from a
 * student's file by `impulse response`). Plain C, so that the engine and the shared object agree
 * whatever compiled each. Nothing here is for the student to use. */
#ifndef IMPULSE_WORKSHOP_ABI_H
#define IMPULSE_WORKSHOP_ABI_H

#define IMPULSE_WORKSHOP_ABI_VERSION 1

#ifdef __cplusplus
extern "C" {
#endif

/* One body of a contact, as listing 1's RigidBody: matrices row by row (m[row][column]), the
 * orientation w, x, y, z. */
struct impulse_workshop_body {
  float centre[3];
  float inv_mass;
  float lin_velocity[3];
  float forces[3];
  float inv_inertia[9];
  float ang_velocity[3];
  float orientation[4];
  float torques[3];
  float world_inv_inertia[9];
  float restitution;
  float friction;
};

struct impulse_workshop_contact {
  float point[3];
  float normal[3];
  float penetration;
  float time_step;
};

/* The entry point: AddCollisionImpulse(c0, c1, point, normal, penetration) on the two bodies,
 * their velocities written back. Returns 0, or 1 with the reason in `message` (a C string). */
typedef int (*impulse_workshop_respond_function)(struct impulse_workshop_body* c0, struct impulse_workshop_body* c1,
                                                 const struct impulse_workshop_contact* contact, char* message,
                                                 int message_size);
#define IMPULSE_WORKSHOP_ENTRY "impulse_workshop_respond"
#define IMPULSE_WORKSHOP_VERSION_SYMBOL "impulse_workshop_abi_version"

#ifdef __cplusplus
}
#endif

#endif /* IMPULSE_WORKSHOP_ABI_H */
