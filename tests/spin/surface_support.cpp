#include "surface_support.hpp"

#include "spin/field.hpp"

namespace rollspin::test {

using namespace geometry;

double oracleDifferenceStep(double R) { return 2e-3 * std::min(1.0, R); }

double rotationGap(const spin::Su2& u, const Eigen::Matrix3d& q) {
  const Eigen::Matrix3d d = u.rotationMatrix().transpose() * q;
  const Eigen::Vector3d axisTimesSin(d(2, 1) - d(1, 2), d(0, 2) - d(2, 0), d(1, 0) - d(0, 1));
  return std::atan2(0.5 * axisTimesSin.norm(), 0.5 * (d.trace() - 1.0));
}

OracleComparison compareWithKinematics(const ContactPath& path, double R, spin::Method method, long long steps,
                                       long long kinematicSteps, std::size_t samples) {
  const std::vector<double> s = spin::uniformSamples(path.length(), samples);
  const auto q = kinematics::RollingKinematics(path, R, {kinematicSteps, oracleDifferenceStep(R)}).orientations(s);
  return compareWithOrientations(path, R, method, steps, s, q);
}

OracleComparison compareWithOrientations(const ContactPath& path, double R, spin::Method method, long long steps,
                                         const std::vector<double>& s, const std::vector<Eigen::Matrix3d>& q) {
  std::vector<spin::Su2> u(s.size());
  const spin::SolveStats st =
      spin::Propagator(path, R, method, steps).run(s, [&](std::size_t j, double, const spin::Su2& v) { u[j] = v; });
  EXPECT_EQ(st.status, spin::SolveStatus::Ok);
  OracleComparison c;
  c.unitarityError = st.unitarityError;
  for (std::size_t j = 0; j < s.size(); ++j) c.worstGap = std::max(c.worstGap, rotationGap(u[j], q[j]));
  return c;
}

Residuals rollingResiduals(const ContactPath& path, double R, spin::Method method, long long steps,
                           std::size_t samples) {
  const double L = path.length();
  std::vector<double> cuts{0.0};
  for (double b : path.breakpoints()) cuts.push_back(b);
  cuts.push_back(L);
  const std::vector<double> sampleS = spin::uniformSamples(L, samples);
  // Each sample's 9-point stencil stays inside its breakpoint segment.
  std::vector<double> all;
  std::vector<std::size_t> usable;
  for (std::size_t i = 0; i < sampleS.size(); ++i) {
    const double s = sampleS[i];
    std::size_t seg = 0;
    while (seg + 2 < cuts.size() && s >= cuts[seg + 1]) ++seg;
    const double a = cuts[seg], b = cuts[seg + 1];
    const double h = std::min(1e-3 * std::min(1.0, R), (b - a) / 16.0);
    const double first = std::clamp(s - 4 * h, a, b - 8 * h);
    usable.push_back(i);
    for (int k = 0; k < 9; ++k) all.push_back(first + k * h);
    all.push_back(s);
  }
  std::vector<std::size_t> order(all.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](auto x, auto y) { return all[x] < all[y]; });
  std::vector<double> sorted;
  for (auto i : order) sorted.push_back(all[i]);
  std::vector<spin::Su2> qSorted(sorted.size()), q(all.size());
  const auto st = spin::Propagator(path, R, method, steps).run(sorted, [&](std::size_t j, double, const spin::Su2& u) {
    qSorted[j] = u;
  });
  EXPECT_EQ(st.status, spin::SolveStatus::Ok);
  for (std::size_t j = 0; j < order.size(); ++j) q[order[j]] = qSorted[j];

  const kinematics::RollingKinematics kin(path, R, {1000, oracleDifferenceStep(R)});
  Residuals worst;
  for (std::size_t n = 0; n < usable.size(); ++n) {
    const double s = sampleS[usable[n]];
    const std::vector<double> nodes(all.begin() + static_cast<long>(n * 10),
                                    all.begin() + static_cast<long>(n * 10 + 9));
    const auto w = kinematics::firstDerivativeWeights(nodes, s);
    spin::Su2 dq{0, 0, 0, 0};
    for (int k = 0; k < 9; ++k) {
      const spin::Su2& u = q[n * 10 + static_cast<std::size_t>(k)];
      dq = {dq.w + w[k] * u.w, dq.x + w[k] * u.x, dq.y + w[k] * u.y, dq.z + w[k] * u.z};
    }
    const spin::Su2 omegaQuat = dq * q[n * 10 + 9].conjugate();
    const Eigen::Vector3d omega = 2.0 * omegaQuat.vec();
    const Eigen::Vector3d normal = path.normal(s);
    // dC/ds from the oracle's own stencil on point/normal (inside the segment).
    const Eigen::Vector3d centreVelocity = kin.centreVelocity(s);
    worst.slip = std::max(worst.slip, (centreVelocity - R * omega.cross(normal)).norm());
    worst.spin = std::max(worst.spin, std::abs(omega.dot(normal)));
  }
  return worst;
}

long long generousSteps(const ContactPath& path, double R) {
  const double rotation = spin::integratedFieldStrength(path, R);
  return std::max<long long>(4000, static_cast<long long>(400.0 * (rotation + path.length())));
}

}  // namespace rollspin::test
