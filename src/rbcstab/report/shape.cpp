#include "rbcstab/report/shape.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <numbers>
#include <sstream>

#include "rbcstab/core/constants.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/io/files.hpp"
#include "rbcstab/model/coefficients.hpp"

namespace rbcstab {

namespace {
// sqrt((2l+1)/(4 pi)) (-1)^m sqrt((l-m)!/(l+m)!) P_l^m(cos theta) for m = 0..l: wigner_column
// holds exactly the normalised P_l^m (no Condon-Shortley phase) at entries l + m.
std::vector<double> harmonic_theta_factors(int l, double theta) {
  const std::vector<double> col = wigner_column(l, theta);
  const double norm = std::sqrt((2.0 * l + 1) / (4 * kPi));
  std::vector<double> out(std::size_t(l) + 1);
  for (int m = 0; m <= l; ++m) out[std::size_t(m)] = norm * (m % 2 ? -1.0 : 1.0) * col[std::size_t(l + m)];
  return out;
}

// rho at one direction from per-l theta factors (index [l - 2][m]).
double rho_from_factors(const ModeAmplitudes& f, const std::vector<std::vector<double>>& factors, double phi) {
  double rho = 1;
  for (int l = 2; l <= f.L; ++l) {
    const auto& th = factors[std::size_t(l - 2)];
    rho += th[0] * f.at(l, 0).real();
    for (int m = 1; m <= l; ++m) {
      const std::complex<double> e(std::cos(m * phi), std::sin(m * phi));
      rho += 2 * th[std::size_t(m)] * (f.at(l, m) * e).real();
    }
  }
  return rho;
}

std::vector<std::vector<double>> all_factors(int L, double theta) {
  std::vector<std::vector<double>> factors;
  for (int l = 2; l <= L; ++l) factors.push_back(harmonic_theta_factors(l, theta));
  return factors;
}
}  // namespace

std::complex<double> spherical_harmonic(int l, int m, double theta, double phi) {
  require(l >= 0, "l", l, "an integer >= 0");
  require(std::abs(m) <= l, "m", m, "an integer in [-l, l]");
  require_finite("theta", theta);
  require_finite("phi", phi);
  const int am = std::abs(m);
  const double th = harmonic_theta_factors(l, theta)[std::size_t(am)];
  const std::complex<double> y = th * std::complex<double>(std::cos(am * phi), std::sin(am * phi));
  return m >= 0 ? y : (am % 2 ? -1.0 : 1.0) * std::conj(y);
}

double shape_radius(const ModeAmplitudes& f, double theta, double phi) {
  require_finite("theta", theta);
  require_finite("phi", phi);
  return rho_from_factors(f, all_factors(f.L, theta), phi);
}

void ShapeGridOptions::validate() const {
  require(n_theta >= 2 && n_theta <= 4096, "n_theta", n_theta, "an integer in [2, 4096]");
  require(n_phi >= 3 && n_phi <= 8192, "n_phi", n_phi, "an integer in [3, 8192]");
}

ShapeGrid shape_on_grid(const ModeAmplitudes& f, const ShapeGridOptions& options) {
  options.validate();
  ShapeGrid g;
  g.n_theta = options.n_theta;
  g.n_phi = options.n_phi;
  for (int i = 0; i <= g.n_theta; ++i) g.theta.push_back(kPi * i / g.n_theta);
  for (int j = 0; j <= g.n_phi; ++j) g.phi.push_back(2 * kPi * j / g.n_phi);
  g.rho.reserve(g.theta.size() * g.phi.size());
  for (int i = 0; i <= g.n_theta; ++i) {
    const auto factors = all_factors(f.L, g.theta[std::size_t(i)]);
    for (int j = 0; j <= g.n_phi; ++j)
      g.rho.push_back(j == g.n_phi ? g.rho[g.rho.size() - std::size_t(g.n_phi)]  // exact seam copy
                                   : rho_from_factors(f, factors, g.phi[std::size_t(j)]));
  }
  const auto [lo, hi] = std::minmax_element(g.rho.begin(), g.rho.end());
  g.rho_min = *lo;
  g.rho_max = *hi;
  return g;
}

SurfaceMesh surface_mesh(const ShapeGrid& g) {
  require(g.n_theta >= 2 && g.n_phi >= 3 && g.rho.size() == std::size_t(g.n_theta + 1) * std::size_t(g.n_phi + 1),
          "grid", double(g.rho.size()), "a grid from shape_on_grid");
  SurfaceMesh m;
  auto add = [&](double theta, double phi, double rho) {
    m.points.push_back(
        {rho * std::sin(theta) * std::cos(phi), rho * std::sin(theta) * std::sin(phi), rho * std::cos(theta)});
    m.rho.push_back(rho);
    m.theta.push_back(theta);
    m.phi.push_back(phi);
  };
  add(0, 0, g.at(0, 0));  // north pole: 0
  for (int i = 1; i < g.n_theta; ++i)
    for (int j = 0; j < g.n_phi; ++j) add(g.theta[std::size_t(i)], g.phi[std::size_t(j)], g.at(i, j));
  add(kPi, 0, g.at(g.n_theta, 0));  // south pole: last
  const int south = int(m.points.size()) - 1;
  auto ring = [&](int i, int j) { return 1 + (i - 1) * g.n_phi + (j % g.n_phi); };
  // Outward orientation: (d/dtheta) x (d/dphi) points outward, so a triangle (theta, phi) ->
  // (theta + dtheta, phi) -> (theta, phi + dphi) is counter-clockwise seen from outside.
  for (int j = 0; j < g.n_phi; ++j) m.triangles.push_back({0, ring(1, j), ring(1, j + 1)});
  for (int i = 1; i < g.n_theta - 1; ++i)
    for (int j = 0; j < g.n_phi; ++j) {
      m.triangles.push_back({ring(i, j), ring(i + 1, j), ring(i + 1, j + 1)});
      m.triangles.push_back({ring(i, j), ring(i + 1, j + 1), ring(i, j + 1)});
    }
  for (int j = 0; j < g.n_phi; ++j) m.triangles.push_back({ring(g.n_theta - 1, j), south, ring(g.n_theta - 1, j + 1)});
  return m;
}

std::string to_vtk_legacy(const SurfaceMesh& mesh, const std::string& title) {
  std::ostringstream ss;
  ss << std::setprecision(17);
  std::string t = title.substr(0, 255);
  std::replace(t.begin(), t.end(), '\n', ' ');
  ss << "# vtk DataFile Version 3.0\n" << t << "\nASCII\nDATASET POLYDATA\n";
  ss << "POINTS " << mesh.points.size() << " double\n";
  for (const auto& p : mesh.points) ss << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  ss << "POLYGONS " << mesh.triangles.size() << ' ' << 4 * mesh.triangles.size() << '\n';
  for (const auto& c : mesh.triangles) ss << "3 " << c[0] << ' ' << c[1] << ' ' << c[2] << '\n';
  ss << "POINT_DATA " << mesh.points.size() << "\nSCALARS rho double 1\nLOOKUP_TABLE default\n";
  for (double r : mesh.rho) ss << r << '\n';
  return ss.str();
}

std::string to_vtk_xml(const SurfaceMesh& mesh) {
  std::ostringstream ss;
  ss << std::setprecision(17);
  ss << "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
     << "<PolyData>\n<Piece NumberOfPoints=\"" << mesh.points.size() << "\" NumberOfVerts=\"0\" NumberOfLines=\"0\""
     << " NumberOfStrips=\"0\" NumberOfPolys=\"" << mesh.triangles.size() << "\">\n";
  ss << "<PointData Scalars=\"rho\">\n<DataArray type=\"Float64\" Name=\"rho\" format=\"ascii\">\n";
  for (double r : mesh.rho) ss << r << '\n';
  ss << "</DataArray>\n</PointData>\n<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" "
        "format=\"ascii\">\n";
  for (const auto& p : mesh.points) ss << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  ss << "</DataArray>\n</Points>\n<Polys>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (const auto& c : mesh.triangles) ss << c[0] << ' ' << c[1] << ' ' << c[2] << '\n';
  ss << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  for (std::size_t k = 1; k <= mesh.triangles.size(); ++k) ss << 3 * k << '\n';
  ss << "</DataArray>\n</Polys>\n</Piece>\n</PolyData>\n</VTKFile>\n";
  return ss.str();
}

std::string to_ply(const SurfaceMesh& mesh, const std::string& comment) {
  std::ostringstream ss;
  ss << std::setprecision(17);
  std::string c = comment;
  std::replace(c.begin(), c.end(), '\n', ' ');
  ss << "ply\nformat ascii 1.0\ncomment " << c << "\nelement vertex " << mesh.points.size()
     << "\nproperty double x\nproperty double y\nproperty double z\nproperty double rho\n"
     << "element face " << mesh.triangles.size() << "\nproperty list uchar int vertex_indices\nend_header\n";
  for (std::size_t k = 0; k < mesh.points.size(); ++k)
    ss << mesh.points[k][0] << ' ' << mesh.points[k][1] << ' ' << mesh.points[k][2] << ' ' << mesh.rho[k] << '\n';
  for (const auto& t : mesh.triangles) ss << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
  return ss.str();
}

void write_vtk_legacy(const std::string& path, const SurfaceMesh& mesh, const std::string& title) {
  write_file_atomic(path, to_vtk_legacy(mesh, title));
}
void write_vtk_xml(const std::string& path, const SurfaceMesh& mesh) { write_file_atomic(path, to_vtk_xml(mesh)); }
void write_ply(const std::string& path, const SurfaceMesh& mesh, const std::string& comment) {
  write_file_atomic(path, to_ply(mesh, comment));
}

std::string to_csv(const ShapeGrid& g) {
  std::ostringstream ss;
  ss << std::setprecision(17) << "i,j,theta,phi,rho\n";
  for (int i = 0; i <= g.n_theta; ++i)
    for (int j = 0; j <= g.n_phi; ++j)
      ss << i << ',' << j << ',' << g.theta[std::size_t(i)] << ',' << g.phi[std::size_t(j)] << ',' << g.at(i, j)
         << '\n';
  return ss.str();
}

nlohmann::json to_json(const ShapeExport& e) {
  nlohmann::json files = nlohmann::json::array();
  for (const ShapeFile& f : e.files)
    files.push_back({{"t", f.t}, {"file", f.path}, {"rho_min", f.rho_min}, {"rho_max", f.rho_max}});
  return {{"model", to_string(e.model)}, {"status", to_string(e.status)}, {"reason", e.reason}, {"files", files}};
}

std::string to_text(const ShapeExport& e) {
  std::ostringstream ss;
  for (const ShapeFile& f : e.files)
    ss << f.path << "  t = " << f.t << ", rho in [" << f.rho_min << ", " << f.rho_max << "]\n";
  return ss.str();
}

}  // namespace rbcstab
