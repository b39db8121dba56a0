#include "seaflex/post/beam_results.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "seaflex/math/gauss_legendre.hpp"

namespace seaflex::post {

namespace {
constexpr double kPi = std::numbers::pi;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
}  // namespace

const std::array<BeamQuantityInfo, kBeamQuantityCount>& beam_quantities() {
  static const std::array<BeamQuantityInfo, kBeamQuantityCount> kInfo = {{
      {"x", "m"},
      {"y", "m"},
      {"z", "m"},
      {"strain", "-"},
      {"tension_wall", "N"},
      {"tension_effective", "N"},
      {"curvature", "1/m"},
      {"moment", "N m"},
      {"moment_x", "N m"},
      {"moment_y", "N m"},
      {"moment_z", "N m"},
      {"pressure_internal", "Pa"},
      {"pressure_external", "Pa"},
      {"stress_axial", "Pa"},
      {"stress_bending", "Pa"},
      {"stress_von_mises", "Pa"},
  }};
  return kInfo;
}

BeamResults::BeamResults(const AncfBeam& beam, PipePressure pressure, int gauss_points)
    : BeamResults(beam, std::vector<PipePressure>(beam.sections().size(), pressure), gauss_points) {
}

BeamResults::BeamResults(const AncfBeam& beam, std::vector<PipePressure> pressures,
                         int gauss_points)
    : beam_(beam), pressures_(std::move(pressures)) {
  if (pressures_.size() != beam.sections().size())
    throw std::invalid_argument("BeamResults: one pipe pressure per beam section needed");
  const math::QuadratureRule rule =
      gauss_points > 0 ? math::gauss_legendre_unit(gauss_points) : math::QuadratureRule{};
  const int n = beam.num_elements();
  for (int k = 0; k <= n; ++k) {
    stations_.push_back({std::min(k, n - 1), k == n ? 1.0 : 0.0, beam.node_arc_length(k), k});
    if (k == n) break;
    for (double xi : rule.points)
      stations_.push_back({k, xi, beam.node_arc_length(k) + xi * beam.element_length(k), -1});
  }
  for (const BeamStation& st : stations_) {
    own_.push_back(sample(st.element, st.xi));
    // interior node: the mean of the two elements
    left_.push_back(st.node > 0 && st.node < n ? sample(st.node - 1, 1.0) : Sample{});
  }
}

BeamResults::Sample BeamResults::sample(int element, double xi) const {
  const double l = beam_.element_length(element);
  const double l_kernel = beam_.elasticity(element).length();
  return {element, ancf_cable::shape(xi, l), ancf_cable::shape_dx(xi, l),
          ancf_cable::shape_dx(xi, l_kernel), ancf_cable::shape_dxx(xi, l_kernel)};
}

BeamResults::Point BeamResults::evaluate(const Sample& sample, const Coordinates& c) const {
  const int element = sample.element;
  const double l = beam_.element_length(element);
  // r' (and r'') from the relative node matrix: free of the round-off of far positions
  Point p;
  p.r = ancf_cable::as_nodes(c.e) * sample.s;
  p.rp = c.R * sample.s_x;
  if (beam_.options().axial == ancf_cable::AxialModel::kL1) {
    p.eps = ((c.R.col(2) - c.R.col(0)).norm() - l) / l;  // thesis eq. (24)
  } else {
    p.eps = 0.5 * (p.rp.squaredNorm() - 1.0);  // thesis eq. (12)
  }
  // the curvature of the beam's bending model: the moment the model carries
  const BeamSection& sec = beam_.section(element);
  p.m = sec.EI() * beam_.elasticity(element).curvature_vector(Vec3(c.R * sample.s_x_kernel),
                                                              Vec3(c.R * sample.s_xx_kernel));
  p.t_eff = sec.EA() * p.eps * p.rp.norm();
  return p;
}

void BeamResults::compute(const State& state, MatX& out) const {
  out.resize(num_stations(), kBeamQuantityCount);
  // free surface of the contents: the beam's highest node
  double z_top = -std::numeric_limits<double>::infinity();
  for (int k = 0; k < beam_.num_nodes(); ++k)
    z_top = std::max(z_top, state.q[beam_.node_index(k) + 2]);
  // each element's coordinates once: a station needs its own element and, at an interior
  // node, the one before it, which the previous stations used (neighbours alternate slots)
  std::array<Coordinates, 2> cache;
  auto coordinates = [&](int element) -> const Coordinates& {
    Coordinates& c = cache[static_cast<std::size_t>(element & 1)];
    if (c.element != element) {
      c.element = element;
      c.e = beam_.element_coordinates(state.q, element);
      c.R = ancf_cable::relative_nodes(c.e);
    }
    return c;
  };
  for (Index i = 0; i < num_stations(); ++i) {
    const BeamStation& st = stations_[static_cast<std::size_t>(i)];
    // a node between two sections takes the section of the element after it
    const BeamSection& sec = beam_.section(st.element);
    const PipePressure& pressure = pressures_[beam_.section_index(st.element)];
    const double EI = sec.EI();
    const double A_e = 0.25 * kPi * pressure.external_diameter * pressure.external_diameter;
    const double A_i = 0.25 * kPi * pressure.contents_diameter * pressure.contents_diameter;
    const bool pipe = sec.outer_diameter > 0.0;
    const double ro = 0.5 * sec.outer_diameter, ri = 0.5 * sec.inner_diameter;
    const auto at = static_cast<std::size_t>(i);
    Point p = evaluate(own_[at], coordinates(own_[at].element));
    if (left_[at].element >= 0) {  // interior node: mean of the two elements
      const Point left = evaluate(left_[at], coordinates(left_[at].element));
      p.eps = 0.5 * (p.eps + left.eps);
      p.m = 0.5 * (p.m + left.m);
      p.t_eff = 0.5 * (p.t_eff + left.t_eff);
    }
    const double z = p.r.z();
    const double p_e = pressure.water_density * pressure.gravity * std::max(0.0, -z);
    const double p_i = pressure.contents_density * pressure.gravity * (z_top - z);
    const double T_eff = p.t_eff;
    const double T_wall = T_eff + p_i * A_i - p_e * A_e;  // DNV-OS-F201 effective tension
    const double M = p.m.norm();
    auto row = out.row(i);
    row(static_cast<int>(BeamQuantity::kX)) = p.r.x();
    row(static_cast<int>(BeamQuantity::kY)) = p.r.y();
    row(static_cast<int>(BeamQuantity::kZ)) = z;
    row(static_cast<int>(BeamQuantity::kStrain)) = p.eps;
    row(static_cast<int>(BeamQuantity::kTensionWall)) = T_wall;
    row(static_cast<int>(BeamQuantity::kTensionEffective)) = T_eff;
    row(static_cast<int>(BeamQuantity::kCurvature)) = EI > 0.0 ? M / EI : 0.0;
    row(static_cast<int>(BeamQuantity::kMoment)) = M;
    row(static_cast<int>(BeamQuantity::kMomentX)) = p.m.x();
    row(static_cast<int>(BeamQuantity::kMomentY)) = p.m.y();
    row(static_cast<int>(BeamQuantity::kMomentZ)) = p.m.z();
    row(static_cast<int>(BeamQuantity::kPressureInternal)) = p_i;
    row(static_cast<int>(BeamQuantity::kPressureExternal)) = p_e;
    row(static_cast<int>(BeamQuantity::kStressAxial)) = T_wall / sec.area;
    if (pipe) {
      // outer fibre: Lame hoop and radial stress, axial stress plus or minus bending
      const double sb = M * ro / sec.second_moment;
      const double sr = -p_e;
      const double sh = (2.0 * p_i * ri * ri - p_e * (ro * ro + ri * ri)) / (ro * ro - ri * ri);
      // the larger square of the two fibres: one square root (sqrt is monotone); a state
      // that is not finite gives NaN, not 0 (std::max keeps its first argument on NaN)
      auto square = [&](double sign) {
        const double sz = T_wall / sec.area + sign * sb;
        return 0.5 * ((sz - sh) * (sz - sh) + (sh - sr) * (sh - sr) + (sr - sz) * (sr - sz));
      };
      const double vm2 = std::max(square(1.0), square(-1.0));
      const double vm = std::sqrt(vm2);
      row(static_cast<int>(BeamQuantity::kStressBending)) = sb;
      row(static_cast<int>(BeamQuantity::kStressVonMises)) = vm;
    } else {
      row(static_cast<int>(BeamQuantity::kStressBending)) = kNaN;
      row(static_cast<int>(BeamQuantity::kStressVonMises)) = kNaN;
    }
  }
}

}  // namespace seaflex::post
