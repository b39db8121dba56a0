// Basic numeric types shared by every seaflex module. SI units throughout.
#pragma once

#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <cstdint>

namespace seaflex {

using Index = Eigen::Index;
using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using VecX = Eigen::VectorXd;
using MatX = Eigen::MatrixXd;
using SpMat = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

/// Standard gravity (m/s^2), used when a model gives none.
inline constexpr double kStandardGravity = 9.80665;

}  // namespace seaflex
