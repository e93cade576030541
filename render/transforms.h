// The 4x4 matrices of the GL pipeline (right-handed world, y up, clip z in [-1, 1]).
#pragma once
#include <Eigen/Geometry>

namespace impulse::render {

// World to camera space looking from `eye` at `target`. `up` must not be parallel to the view.
Eigen::Matrix4f look_at(const Eigen::Vector3f& eye, const Eigen::Vector3f& target, const Eigen::Vector3f& up);
Eigen::Matrix4f perspective(float fov_y_radians, float aspect, float near_distance, float far_distance);
Eigen::Matrix4f orthographic(float half_width, float half_height, float near_distance, float far_distance);

// Model matrix: translate * rotate * scale.
Eigen::Matrix4f place(const Eigen::Vector3f& translation, const Eigen::Quaternionf& rotation,
                      const Eigen::Vector3f& scale);

}  // namespace impulse::render
