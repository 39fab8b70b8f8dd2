// Shapes rebuilt from amplitudes: Y_lm against GSL, closed forms, rotation, mesh and VTK/PLY files.
#include <gsl/gsl_sf_legendre.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <numbers>
#include <set>
#include <sstream>

#include "rbcstab/core/error.hpp"
#include "rbcstab/model/coefficients.hpp"
#include "rbcstab/model/scene.hpp"
#include "rbcstab/report/shape.hpp"

namespace rbcstab {
namespace {

constexpr double pi = std::numbers::pi;

// GSL's sphPlm includes the Condon-Shortley phase: sqrt((2l+1)/4pi (l-m)!/(l+m)!) (-1)^m P_l^m.
// That is the paper's normalisation with P_l^m free of the phase, i.e. Y_lm(theta, 0) for m >= 0.
TEST(SphericalHarmonic, MatchesGslUpToLTwenty) {
  for (int l = 0; l <= 20; ++l)
    for (int m = -l; m <= l; ++m)
      for (double theta : {0.0, 0.3, 1.1, pi / 2, 2.0, 3.0, pi}) {
        const double phi = 0.7;
        const int am = std::abs(m);
        const double p = gsl_sf_legendre_sphPlm(l, am, std::cos(theta));
        std::complex<double> expected = p * std::complex<double>(std::cos(am * phi), std::sin(am * phi));
        if (m < 0) expected = (am % 2 ? -1.0 : 1.0) * std::conj(expected);
        const std::complex<double> y = spherical_harmonic(l, m, theta, phi);
        // Both are O(1) three-term recurrences in double precision: agreement to 1e-13 absolute.
        EXPECT_NEAR(y.real(), expected.real(), 1e-13) << l << ' ' << m << ' ' << theta;
        EXPECT_NEAR(y.imag(), expected.imag(), 1e-13) << l << ' ' << m << ' ' << theta;
      }
}

TEST(SphericalHarmonic, KnownLowOrderForms) {
  const double th = 0.9, ph = 0.4;
  // Y_22 = (1/4) sqrt(15/(2 pi)) sin^2 th e^{2 i ph}; Y_21 = -(1/2) sqrt(15/(2 pi)) sin th cos th e^{i ph}.
  const std::complex<double> y22 =
      0.25 * std::sqrt(15 / (2 * pi)) * std::pow(std::sin(th), 2) * std::polar(1.0, 2 * ph);
  const std::complex<double> y21 = -0.5 * std::sqrt(15 / (2 * pi)) * std::sin(th) * std::cos(th) * std::polar(1.0, ph);
  EXPECT_LT(std::abs(spherical_harmonic(2, 2, th, ph) - y22), 1e-15);
  EXPECT_LT(std::abs(spherical_harmonic(2, 1, th, ph) - y21), 1e-15);
  EXPECT_THROW(spherical_harmonic(2, 3, th, ph), InvalidArgument);
  EXPECT_THROW(spherical_harmonic(2, 1, std::nan(""), ph), InvalidArgument);
}

// Axisymmetric l = 2 shape: rho = 1 + f20 sqrt(5/(16 pi)) (3 cos^2 th - 1), closed form.
TEST(ShapeRadius, AxisymmetricL2ClosedForm) {
  ModeAmplitudes f(2);
  f.at(2, 0) = -0.7;
  for (double th = 0; th <= pi; th += 0.13)
    for (double ph : {0.0, 1.0, 4.0}) {
      const double expected = 1 - 0.7 * std::sqrt(5 / (16 * pi)) * (3 * std::cos(th) * std::cos(th) - 1);
      EXPECT_NEAR(shape_radius(f, th, ph), expected, 1e-15);
    }
}

// A generic real shape: rho from m >= 0 only equals the full complex sum over m = -l..l, whose
// imaginary part vanishes (f_{l,-m} = (-1)^m conj f_{l,m}).
TEST(ShapeRadius, EqualsFullComplexSumAndIsReal) {
  ModeAmplitudes f(6);
  for (int l = 2; l <= 6; ++l)
    for (int m = 0; m <= l; ++m) {
      const std::complex<double> v(0.05 * std::sin(l + 2.0 * m), m ? 0.03 * std::cos(3.0 * l - m) : 0.0);
      f.at(l, m) = v;
      f.at(l, -m) = (m % 2 ? -1.0 : 1.0) * std::conj(v);
    }
  for (double th : {0.2, 1.0, 2.5})
    for (double ph : {0.0, 2.2, 5.9}) {
      std::complex<double> full = 1;
      for (int l = 2; l <= 6; ++l)
        for (int m = -l; m <= l; ++m) {
          const int am = std::abs(m);
          std::complex<double> y = gsl_sf_legendre_sphPlm(l, am, std::cos(th)) * std::polar(1.0, am * ph);
          if (m < 0) y = (am % 2 ? -1.0 : 1.0) * std::conj(y);
          full += y * f.at(l, m);
        }
      EXPECT_NEAR(full.imag(), 0, 1e-15);
      EXPECT_NEAR(shape_radius(f, th, ph), full.real(), 1e-14);
    }
}

// The scene's orientation beta rotates the axisymmetric shape about the y axis: the amplitudes
// built with wigner_column give rho_beta(n) = rho_0(R_y(beta) n) with the Y_lm above, i.e. the
// symmetry axis moves from z to (-sin beta, 0, cos beta): a rotation by -beta about y. The mirror
// z -> -z (a symmetry of simple shear in the x-y plane) maps it onto +beta, so the physics does not
// depend on the sense. Checked for l = 2..5 at once, odd l included.
TEST(ShapeRadius, SceneOrientationIsARotationAboutY) {
  Scene s;
  s.L = 5;
  s.delta = 0.02;
  for (double beta : {0.3, 1.0, pi / 2}) {
    s.beta = beta;
    const InitialState init = initial_state(s);
    Scene axi = s;
    axi.beta = 0;
    const InitialState init0 = initial_state(axi);
    for (double th : {0.1, 0.8, 1.7, 2.9})
      for (double ph : {0.0, 1.3, 3.5}) {
        const double x = std::sin(th) * std::cos(ph), y = std::sin(th) * std::sin(ph), z = std::cos(th);
        // n rotated by R_y(beta); rho_beta then has its axis at R_y(-beta) z = (-sin beta, 0, cos beta).
        const double xr = std::cos(beta) * x + std::sin(beta) * z, zr = -std::sin(beta) * x + std::cos(beta) * z;
        const double th0 = std::acos(std::clamp(zr, -1.0, 1.0)), ph0 = std::atan2(y, xr);
        EXPECT_NEAR(shape_radius(init.f, th, ph), shape_radius(init0.f, th0, ph0), 1e-13) << beta;
      }
  }
}

TEST(ShapeGrid, MatchesPointEvaluationAndRange) {
  ModeAmplitudes f(4);
  f.at(2, 0) = -0.5;
  f.at(2, 2) = {0.2, 0.1};
  f.at(2, -2) = std::conj(f.at(2, 2));
  f.at(3, 1) = {0.05, -0.02};
  f.at(3, -1) = -std::conj(f.at(3, 1));
  const ShapeGrid g = shape_on_grid(f, {8, 12});
  ASSERT_EQ(g.theta.size(), 9u);
  ASSERT_EQ(g.phi.size(), 13u);
  double lo = 1e300, hi = -1e300;
  for (int i = 0; i <= 8; ++i)
    for (int j = 0; j <= 12; ++j) {
      EXPECT_NEAR(g.at(i, j), shape_radius(f, g.theta[std::size_t(i)], g.phi[std::size_t(j)]), 1e-14);
      lo = std::min(lo, g.at(i, j));
      hi = std::max(hi, g.at(i, j));
    }
  EXPECT_EQ(g.rho_min, lo);
  EXPECT_EQ(g.rho_max, hi);
  EXPECT_THROW(shape_on_grid(f, {1, 12}), InvalidArgument);
  EXPECT_THROW(shape_on_grid(f, {8, 2}), InvalidArgument);
}

// Signed volume by the divergence theorem: sum over triangles of p0 . (p1 x p2) / 6.
double mesh_volume(const SurfaceMesh& m) {
  double v = 0;
  for (const auto& t : m.triangles) {
    const auto& a = m.points[std::size_t(t[0])];
    const auto& b = m.points[std::size_t(t[1])];
    const auto& c = m.points[std::size_t(t[2])];
    v += a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
  }
  return v / 6;
}

TEST(SurfaceMesh, ClosedOutwardAndConverging) {
  ModeAmplitudes sphere(2);
  const SurfaceMesh m = surface_mesh(shape_on_grid(sphere, {40, 80}));
  EXPECT_EQ(m.points.size(), 2u + 39u * 80u);
  EXPECT_EQ(m.triangles.size(), 2u * 80u * 39u);
  // Every directed edge appears once and its reverse once: closed and consistently oriented.
  std::map<std::pair<int, int>, int> edges;
  for (const auto& t : m.triangles)
    for (int k = 0; k < 3; ++k) ++edges[{t[std::size_t(k)], t[std::size_t((k + 1) % 3)]}];
  for (const auto& [e, n] : edges) {
    EXPECT_EQ(n, 1);
    EXPECT_EQ(edges.count({e.second, e.first}), 1u);
  }
  // Inscribed polyhedron of the unit sphere: volume below 4 pi / 3 by O(h^2); h = pi/40 gives < 1%.
  const double v = mesh_volume(m);
  EXPECT_GT(v, 0.99 * 4 * pi / 3);
  EXPECT_LT(v, 4 * pi / 3);
  for (std::size_t k = 0; k < m.points.size(); ++k)
    EXPECT_NEAR(std::hypot(m.points[k][0], m.points[k][1], m.points[k][2]), m.rho[k], 1e-15);
}

// Reads a legacy ASCII POLYDATA file back (the subset the writer emits).
struct VtkRead {
  std::vector<std::array<double, 3>> points;
  std::vector<std::vector<int>> polys;
  std::vector<double> rho;
};
VtkRead read_vtk_legacy(const std::string& text) {
  std::istringstream in(text);
  std::string line;
  VtkRead r;
  std::getline(in, line);
  EXPECT_EQ(line, "# vtk DataFile Version 3.0");
  std::getline(in, line);  // title
  std::getline(in, line);
  EXPECT_EQ(line, "ASCII");
  std::getline(in, line);
  EXPECT_EQ(line, "DATASET POLYDATA");
  std::string word, type;
  std::size_t n = 0, size = 0;
  in >> word >> n >> type;
  EXPECT_EQ(word, "POINTS");
  r.points.resize(n);
  for (auto& p : r.points) in >> p[0] >> p[1] >> p[2];
  in >> word >> n >> size;
  EXPECT_EQ(word, "POLYGONS");
  std::size_t total = 0;
  for (std::size_t k = 0; k < n; ++k) {
    int c = 0;
    in >> c;
    std::vector<int> ids(static_cast<std::size_t>(c));
    for (auto& id : ids) in >> id;
    total += 1 + ids.size();
    r.polys.push_back(ids);
  }
  EXPECT_EQ(total, size);
  in >> word >> n;
  EXPECT_EQ(word, "POINT_DATA");
  std::string name, dtype, lut, lutname;
  int comps = 0;
  in >> word >> name >> dtype >> comps >> lut >> lutname;
  EXPECT_EQ(name, "rho");
  r.rho.resize(n);
  for (auto& v : r.rho) in >> v;
  EXPECT_FALSE(in.fail());
  return r;
}

TEST(ShapeFiles, VtkLegacyReadsBackExactly) {
  ModeAmplitudes f(3);
  f.at(2, 0) = -0.6;
  f.at(3, 2) = {0.04, 0.03};
  f.at(3, -2) = std::conj(f.at(3, 2));
  const SurfaceMesh m = surface_mesh(shape_on_grid(f, {10, 16}));
  const std::string path = ::testing::TempDir() + "/shape_test.vtk";
  write_vtk_legacy(path, m, "test shape\nsecond line");
  std::ifstream file(path);
  std::stringstream buf;
  buf << file.rdbuf();
  const VtkRead r = read_vtk_legacy(buf.str());
  ASSERT_EQ(r.points.size(), m.points.size());
  ASSERT_EQ(r.polys.size(), m.triangles.size());
  for (std::size_t k = 0; k < m.points.size(); ++k) {
    for (std::size_t c = 0; c < 3; ++c) EXPECT_EQ(r.points[k][c], m.points[k][c]);  // 17 digits round-trip
    EXPECT_EQ(r.rho[k], m.rho[k]);
    // The point lies at the reconstructed radius in its direction.
    EXPECT_NEAR(std::hypot(r.points[k][0], r.points[k][1], r.points[k][2]), shape_radius(f, m.theta[k], m.phi[k]),
                1e-14);
  }
  for (std::size_t k = 0; k < m.triangles.size(); ++k) {
    ASSERT_EQ(r.polys[k].size(), 3u);
    for (std::size_t c = 0; c < 3; ++c) {
      EXPECT_EQ(r.polys[k][c], m.triangles[k][c]);
      EXPECT_GE(r.polys[k][c], 0);
      EXPECT_LT(r.polys[k][c], int(m.points.size()));
    }
  }
}

TEST(ShapeFiles, PlyAndVtpHeadersCountElements) {
  ModeAmplitudes f(2);
  f.at(2, 0) = -0.3;
  const SurfaceMesh m = surface_mesh(shape_on_grid(f, {6, 8}));
  const std::string ply = to_ply(m, "c");
  EXPECT_NE(ply.find("element vertex " + std::to_string(m.points.size()) + "\n"), std::string::npos);
  EXPECT_NE(ply.find("element face " + std::to_string(m.triangles.size()) + "\n"), std::string::npos);
  // Header + one line per vertex and per face.
  const auto lines = std::count(ply.begin(), ply.end(), '\n');
  const auto header = std::count(ply.begin(), ply.begin() + long(ply.find("end_header")), '\n') + 1;
  EXPECT_EQ(std::size_t(lines - header), m.points.size() + m.triangles.size());
  const std::string vtp = to_vtk_xml(m);
  EXPECT_NE(vtp.find("NumberOfPoints=\"" + std::to_string(m.points.size()) + "\""), std::string::npos);
  EXPECT_NE(vtp.find("NumberOfPolys=\"" + std::to_string(m.triangles.size()) + "\""), std::string::npos);
  EXPECT_THROW(write_ply("/nonexistent-dir/x.ply", m, "c"), std::runtime_error);
}

}  // namespace
}  // namespace rbcstab
