#include "render/transforms.h"

#include <cmath>

namespace impulse::render {

Eigen::Matrix4f look_at(const Eigen::Vector3f& eye, const Eigen::Vector3f& target, const Eigen::Vector3f& up) {
  const Eigen::Vector3f forward = (target - eye).normalized();
  const Eigen::Vector3f right = forward.cross(up).normalized();
  const Eigen::Vector3f true_up = right.cross(forward);
  Eigen::Matrix4f view = Eigen::Matrix4f::Identity();
  view.block<1, 3>(0, 0) = right.transpose();
  view.block<1, 3>(1, 0) = true_up.transpose();
  view.block<1, 3>(2, 0) = -forward.transpose();
  view(0, 3) = -right.dot(eye);
  view(1, 3) = -true_up.dot(eye);
  view(2, 3) = forward.dot(eye);
  return view;
}

Eigen::Matrix4f perspective(float fov_y_radians, float aspect, float near_distance, float far_distance) {
  const float focal = 1.0f / std::tan(fov_y_radians / 2.0f);
  Eigen::Matrix4f projection = Eigen::Matrix4f::Zero();
  projection(0, 0) = focal / aspect;
  projection(1, 1) = focal;
  projection(2, 2) = (far_distance + near_distance) / (near_distance - far_distance);
  projection(2, 3) = 2.0f * far_distance * near_distance / (near_distance - far_distance);
  projection(3, 2) = -1.0f;
  return projection;
}

Eigen::Matrix4f orthographic(float half_width, float half_height, float near_distance, float far_distance) {
  Eigen::Matrix4f projection = Eigen::Matrix4f::Identity();
  projection(0, 0) = 1.0f / half_width;
  projection(1, 1) = 1.0f / half_height;
  projection(2, 2) = -2.0f / (far_distance - near_distance);
  projection(2, 3) = -(far_distance + near_distance) / (far_distance - near_distance);
  return projection;
}

Eigen::Matrix4f place(const Eigen::Vector3f& translation, const Eigen::Quaternionf& rotation,
                      const Eigen::Vector3f& scale) {
  Eigen::Matrix4f model = Eigen::Matrix4f::Identity();
  model.block<3, 3>(0, 0) = rotation.normalized().toRotationMatrix() * scale.asDiagonal();
  model.block<3, 1>(0, 3) = translation;
  return model;
}

}  // namespace impulse::render
