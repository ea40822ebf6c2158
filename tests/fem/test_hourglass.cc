// The one-point cell's hourglass stiffness (fem/hourglass.h): blind to every linear field on
// a distorted hexahedron and of rank 12 (the hourglass modes); on a box, the energies of
// single hourglass modes against the deviatoric energy of the trilinear field integrated by
// hand; and the isotropic shear modulus of a law's tangent at rest.
#include "fem/hourglass.h"
#include "materials/material_registry.h"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <array>
#include <cmath>

using namespace vulnus;
using Eigen::Matrix3d;
using Eigen::Vector3d;

namespace
{
constexpr int n_nodes = 8;

/// A hexahedron's nodes (deal.II's vertex order, x fastest), its shape-function gradients at
/// the centre and at the 2 x 2 x 2 Gauss points, and the points' weights.
struct Cell
{
  std::array<Vector3d, n_nodes> X, centre;
  std::array<Vector3d, 8 * n_nodes> points;
  std::array<double, 8> w{};

  explicit Cell(const std::array<Vector3d, n_nodes>& nodes) : X(nodes)
  {
    const double g = 0.5 / std::sqrt(3.0);
    gradients(Vector3d(0.5, 0.5, 0.5), centre.data());
    for (int q = 0; q < 8; ++q)
    {
      const Vector3d xi(0.5 + ((q & 1) ? g : -g), 0.5 + ((q >> 1 & 1) ? g : -g),
                        0.5 + ((q >> 2 & 1) ? g : -g));
      w[q] = gradients(xi, &points[q * n_nodes]) / 8.0;
    }
  }

  /// Gradients at reference point xi in [0, 1]^3; returns det of the map.
  double gradients(const Vector3d& xi, Vector3d* out) const
  {
    std::array<Vector3d, n_nodes> dN;
    Matrix3d map = Matrix3d::Zero();
    for (int a = 0; a < n_nodes; ++a)
    {
      const Vector3d s(a & 1, (a >> 1) & 1, (a >> 2) & 1);
      auto f = [&](int k) { return s[k] > 0.5 ? xi[k] : 1.0 - xi[k]; };
      auto df = [&](int k) { return s[k] > 0.5 ? 1.0 : -1.0; };
      dN[a] = Vector3d(df(0) * f(1) * f(2), f(0) * df(1) * f(2), f(0) * f(1) * df(2));
      map += X[a] * dN[a].transpose();
    }
    const Matrix3d inverse_transpose = map.inverse().transpose();
    for (int a = 0; a < n_nodes; ++a)
      out[a] = inverse_transpose * dN[a];
    return map.determinant();
  }

  fem::HourglassMatrix stiffness() const
  {
    return fem::hourglass_stiffness(X.data(), centre.data(), points.data(), w.data(), 8);
  }
};

std::array<Vector3d, n_nodes> box(const Vector3d& size)
{
  std::array<Vector3d, n_nodes> X;
  for (int a = 0; a < n_nodes; ++a)
    X[a] = Vector3d(a & 1, (a >> 1) & 1, (a >> 2) & 1).cwiseProduct(size);
  return X;
}
} // namespace

TEST(Hourglass, BlindToLinearFieldsAndOfRankTwelveOnADistortedCell)
{
  std::array<Vector3d, n_nodes> X = box(Vector3d(1e-3, 1e-3, 1e-3));
  for (int a = 0; a < n_nodes; ++a)
    X[a] += 1e-4 * Vector3d(std::sin(3.0 * a), std::cos(5.0 * a), std::sin(7.0 * a + 1));
  const fem::HourglassMatrix S = Cell(X).stiffness();
  EXPECT_LT((S - S.transpose()).norm(), 1e-13 * S.norm());
  // u = c + A X, rigid rotations and every strain among them.
  const Matrix3d A = (Matrix3d() << 0.3, -0.2, 0.1, 0.5, 0.05, -0.4, 0.2, 0.7, -0.1).finished();
  const Vector3d c(1e-4, -2e-4, 3e-4);
  Eigen::Matrix<double, 24, 1> u;
  for (int a = 0; a < n_nodes; ++a)
    u.segment<3>(3 * a) = c + A * X[a];
  EXPECT_LT((S * u).norm(), 1e-12 * S.norm() * u.norm());
  const Eigen::SelfAdjointEigenSolver<fem::HourglassMatrix> eigen(S);
  const double largest = eigen.eigenvalues().maxCoeff();
  int positive = 0;
  for (int i = 0; i < 24; ++i)
  {
    EXPECT_GT(eigen.eigenvalues()[i], -1e-12 * largest);
    positive += eigen.eigenvalues()[i] > 1e-8 * largest;
  }
  EXPECT_EQ(positive, 12); // 24 dofs less 12 linear fields
}

TEST(Hourglass, ModeEnergiesOnABoxAreTheFullElementsDeviatoricEnergies)
{
  // u_x = q H(xi, eta, zeta), xi etc. in [-1, 1] (d xi / dx = 2 / hx): the energy per unit
  // mu, V times the cell mean of dev eps : dev eps, integrated by hand (the mean of xi^2 is
  // 1/3, of xi^2 eta^2 1/9; the full rule integrates both exactly).
  const double hx = 1e-3, hy = 2e-3, hz = 1.5e-3, V = hx * hy * hz, q = 1e-6;
  const fem::HourglassMatrix S = Cell(box(Vector3d(hx, hy, hz))).stiffness();
  struct Mode
  {
    int (*sign)(int a);
    double energy; // per unit mu
  };
  const Mode modes[] = {
    {[](int a) { return (((a >> 1) & 1) ? 1 : -1) * (((a >> 2) & 1) ? 1 : -1); }, // eta zeta
     V * q * q * 2.0 / 3.0 * (1 / (hy * hy) + 1 / (hz * hz))},
    {[](int a) { return ((a & 1) ? 1 : -1) * (((a >> 2) & 1) ? 1 : -1); }, // xi zeta
     V * q * q * (8.0 / (9.0 * hx * hx) + 2.0 / (3.0 * hz * hz))},
    {[](int a) { return ((a & 1) ? 1 : -1) * (((a >> 1) & 1) ? 1 : -1) * (((a >> 2) & 1) ? 1 : -1); },
     V * q * q * (8.0 / (27.0 * hx * hx) + 2.0 / (9.0 * hy * hy) + 2.0 / (9.0 * hz * hz))},
  };
  for (const Mode& mode : modes)
  {
    Eigen::Matrix<double, 24, 1> u = Eigen::Matrix<double, 24, 1>::Zero();
    for (int a = 0; a < n_nodes; ++a)
      u[3 * a] = q * mode.sign(a);
    EXPECT_NEAR(0.5 * u.dot(S * u), mode.energy, 1e-12 * mode.energy);
  }
}

TEST(Hourglass, ShearModulusOfTheTangentAtRest)
{
  materials::MaterialParameters steel;
  steel.model = "elastic plastic";
  const auto law = materials::create_material(steel);
  const materials::Tangent A =
    law->tangent(Matrix3d::Identity(), Vector3d::UnitX(), materials::PointState());
  EXPECT_NEAR(fem::isotropic_shear_modulus(A), steel.elastic_plastic.shear_modulus,
              1e-9 * steel.elastic_plastic.shear_modulus);
  // The fibre-reinforced tissue: the orientation average does not depend on the fibre.
  const auto tissue = materials::create_material(materials::MaterialParameters());
  const double along_x = fem::isotropic_shear_modulus(
    tissue->tangent(Matrix3d::Identity(), Vector3d::UnitX(), materials::PointState()));
  const double oblique = fem::isotropic_shear_modulus(tissue->tangent(
    Matrix3d::Identity(), Vector3d(1.0, 2.0, -0.5).normalized(), materials::PointState()));
  EXPECT_GT(along_x, 0.0);
  EXPECT_NEAR(oblique, along_x, 1e-9 * along_x);
}
