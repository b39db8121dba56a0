#include "seaflex/solvers/modal.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <numbers>

#include "seaflex/core/errors.hpp"

namespace seaflex {

ModalResult solve_modes(const Dae& dae, const State& state, int count) {
  const Index n = dae.num_coordinates(), m = dae.num_constraints();
  DaeEval eval = dae.make_eval();
  DaeRequest req;
  req.forces = false;
  req.matrix = true;
  req.multiplier_hessian = true;
  req.scales.kq = 1.0;
  dae.evaluate(state, req, eval);
  const MatX A = MatX(eval.kkt.matrix());
  MatX K = A.topLeftCorner(n, n);
  const MatX Cq = A.bottomLeftCorner(m, n);
  req.scales = MatrixScales{1.0, 0.0, 0.0};
  req.multiplier_hessian = false;
  dae.evaluate(state, req, eval);
  const MatX M = MatX(eval.kkt.matrix()).topLeftCorner(n, n);

  // orthonormal basis Z of the null space of C_q
  MatX Z;
  if (m == 0) {
    Z = MatX::Identity(n, n);
  } else {
    Eigen::ColPivHouseholderQR<MatX> qr(Cq.transpose());
    const Index rank = qr.rank();
    const MatX Qfull = qr.householderQ() * MatX::Identity(n, n);
    Z = Qfull.rightCols(n - rank);
  }
  MatX Kr = Z.transpose() * K * Z;
  Kr = 0.5 * (Kr + Kr.transpose());  // L1 and T2 tangents are not exactly symmetric
  const MatX Mr = Z.transpose() * M * Z;
  Eigen::GeneralizedSelfAdjointEigenSolver<MatX> solver(Kr, Mr);
  if (solver.info() != Eigen::Success)
    throw SolverError("modal analysis: the generalized eigenproblem failed", state.t);
  const Index k = (count <= 0 || count > Kr.rows()) ? Kr.rows() : count;
  ModalResult result;
  const VecX& w2 = solver.eigenvalues();
  if (w2.size() > 0) {
    result.lowest_omega2 = w2.minCoeff();
    const double floor = -1e-12 * w2.cwiseAbs().maxCoeff();
    result.unstable = static_cast<int>((w2.array() < floor).count());
  }
  result.omega = solver.eigenvalues().head(k).cwiseMax(0.0).cwiseSqrt();
  result.frequency_hz = result.omega / (2.0 * std::numbers::pi);
  result.shapes = Z * solver.eigenvectors().leftCols(k);
  result.mass_shapes = M * result.shapes;
  return result;
}

}  // namespace seaflex
