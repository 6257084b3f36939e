// Along every timeline sample of every test scene: the rolling constraint
// holds, with ω taken from the solver's quaternions (not from the field):
//   no slip  |dC/ds − R ω × n| ≤ 1e-9,   no spin  |ω · n| ≤ 1e-9,
// where (0, ω) = 2 q' ⊗ q⁻¹ and q' comes from an 8th-order finite difference
// of the solver's own dense output.
#include <gtest/gtest.h>

#include <functional>
#include <numbers>
#include <numeric>

#include "kinematics/rolling_kinematics.hpp"
#include "oracle_support.hpp"
#include "support/numbers.hpp"
#include "support/test_paths.hpp"

using namespace rollspin;
using namespace rollspin::test;
using rollspin::test::kPi;

namespace {

struct Scene {
  const char* name;
  std::function<std::unique_ptr<geometry::ContactPath>()> make;
  double R;
};

const Scene kScenes[] = {
    {"floor line", [] { return planeLine(Eigen::Vector3d::UnitZ(), 7.0); }, 1.0},
    {"wall line", [] { return planeLine(Eigen::Vector3d(0, -1, 0), 7.0); }, 0.5},
    {"lollipop", [] { return lollipopPath(3.0); }, 1.0},
    {"lollipop cw 2 turns", [] { return lollipopPath(2.0, 2.0, false); }, 0.7},
    {"tennis ball", [] { return lollipopPath(1.0); }, 1.0},
    {"sphere outside", [] { return sphereParallel(3.0, true, kPi / 3); }, 1.0},
    {"sphere outside r=R", [] { return sphereParallel(1.0, true, 2.0); }, 1.0},
    {"sphere inside", [] { return sphereParallel(3.0, false, kPi / 4); }, 1.0},
    {"penny", [] { return sphereParallel(3.0, false, kPi / 2, 1.0, false); }, 1.0},
};

struct Residuals {
  double slip = 0.0, spin = 0.0;
};

Residuals residuals(const geometry::ContactPath& path, double R, spin::Method method) {
  const double L = path.length(), h = 1e-3 * std::min(1.0, R);
  const std::vector<double> samples = spin::uniformSamples(L, 61);
  // Every stencil point of every sample, sorted, evaluated in one march.
  std::vector<std::vector<double>> stencils;
  std::vector<double> all;
  for (double s : samples) {
    double first = std::clamp(s - 4 * h, 0.0, L - 8 * h);
    std::vector<double> nodes;
    for (int k = 0; k < 9; ++k) nodes.push_back(first + k * h);
    stencils.push_back(nodes);
    all.insert(all.end(), nodes.begin(), nodes.end());
  }
  std::vector<std::size_t> order(all.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](auto a, auto b) { return all[a] < all[b]; });
  std::vector<double> sorted;
  for (auto i : order) sorted.push_back(all[i]);
  std::vector<spin::Su2> qSorted(sorted.size()), q(all.size());
  const auto st = spin::Propagator(path, R, method, 20000).run(sorted, [&](std::size_t j, double, const spin::Su2& u) {
    qSorted[j] = u;
  });
  EXPECT_EQ(st.status, spin::SolveStatus::Ok);
  for (std::size_t j = 0; j < order.size(); ++j) q[order[j]] = qSorted[j];
  std::vector<spin::Su2> atSample(samples.size());
  (void)spin::Propagator(path, R, method, 20000).run(samples, [&](std::size_t j, double, const spin::Su2& u) {
    atSample[j] = u;
  });

  const kinematics::RollingKinematics kin(path, R, {1000, 0.0});
  Residuals worst;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const auto w = kinematics::firstDerivativeWeights(stencils[i], samples[i]);
    spin::Su2 dq{0, 0, 0, 0};
    for (int k = 0; k < 9; ++k) {
      const spin::Su2& u = q[i * 9 + k];
      dq = {dq.w + w[k] * u.w, dq.x + w[k] * u.x, dq.y + w[k] * u.y, dq.z + w[k] * u.z};
    }
    const spin::Su2 omegaQuat = dq * atSample[i].conjugate();
    const Eigen::Vector3d omega = 2.0 * omegaQuat.vec();
    const Eigen::Vector3d n = path.normal(samples[i]);
    worst.slip = std::max(worst.slip, (kin.centreVelocity(samples[i]) - R * omega.cross(n)).norm());
    worst.spin = std::max(worst.spin, std::abs(omega.dot(n)));
  }
  return worst;
}

}  // namespace

TEST(TimelineResiduals, NoSlipNoSpinAlongEverySample) {
  for (const Scene& scene : kScenes) {
    const auto path = scene.make();
    for (spin::Method m : {spin::Method::Exact, spin::Method::Magnus4}) {
      const Residuals r = residuals(*path, scene.R, m);
      EXPECT_LE(r.slip, 1e-9) << scene.name << " " << spin::methodName(m);
      EXPECT_LE(r.spin, 1e-9) << scene.name << " " << spin::methodName(m);
    }
  }
}
