#pragma once
// The cell's shape rho(theta, phi) = 1 + sum_{l,m} Y_{l,m}(theta, phi) f_{l,m}   (Eq. rho_rho0)
// rebuilt from the amplitudes of any model level (System::amplitudes), on a (theta, phi) grid and
// as a closed triangle mesh for VTK / PLY export and rendering.
#include <array>
#include <complex>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "rbcstab/integrate/integrator.hpp"
#include "rbcstab/model/amplitudes.hpp"
#include "rbcstab/model/system.hpp"

namespace rbcstab {

// Y_{l,m}(theta, phi) = [(2l+1)/(4 pi) (l-m)!/(l+m)!]^{1/2} (-1)^m P_l^m(cos theta) e^{i m phi}
// (Appendix A), P_l^m without the Condon-Shortley phase, so Y is the usual physics harmonic and
// Y_{l,-m} = (-1)^m conj(Y_{l,m}). Stable for large l (normalised recurrence, no factorials).
std::complex<double> spherical_harmonic(int l, int m, double theta, double phi);

// rho at one direction. Uses only m >= 0 and the reality condition f_{l,-m} = (-1)^m conj(f_{l,m}),
// so the result is real by construction; a state that breaks the symmetry is projected onto it.
double shape_radius(const ModeAmplitudes& f, double theta, double phi);

// rho on theta_i = pi i / n_theta (i = 0..n_theta, both poles), phi_j = 2 pi j / n_phi
// (j = 0..n_phi, the seam phi = 2 pi repeated so a plotter can close the surface).
struct ShapeGrid {
  int n_theta = 0, n_phi = 0;
  std::vector<double> theta, phi;  // n_theta + 1 and n_phi + 1 values
  std::vector<double> rho;         // [i * (n_phi + 1) + j]
  double rho_min = 0, rho_max = 0;
  double at(int i, int j) const { return rho[std::size_t(i) * std::size_t(n_phi + 1) + std::size_t(j)]; }
};
struct ShapeGridOptions {
  int n_theta = 64;       // polar resolution: resolves l <= ~n_theta/3 without visible facets
  int n_phi = 128;        // azimuthal resolution (2 n_theta keeps the facets square at the equator)
  void validate() const;  // n_theta in [2, 4096], n_phi in [3, 8192]
};
ShapeGrid shape_on_grid(const ModeAmplitudes& f, const ShapeGridOptions& options = {});

// Closed surface: one point per pole, n_phi points on every inner ring (the seam is not
// repeated); triangles oriented with outward normals for a star-shaped surface (rho > 0).
struct SurfaceMesh {
  std::vector<std::array<double, 3>> points;  // x = rho sin th cos ph, y = rho sin th sin ph, z = rho cos th
  std::vector<std::array<int, 3>> triangles;
  std::vector<double> rho;         // distance from the origin, per point
  std::vector<double> theta, phi;  // per point
};
SurfaceMesh surface_mesh(const ShapeGrid& grid);

// Writers (ASCII; open in ParaView). Each throws std::runtime_error naming the path on failure
// and writes atomically. The scalar field is "rho" (distance from the origin).
std::string to_vtk_legacy(const SurfaceMesh& mesh, const std::string& title);
std::string to_vtk_xml(const SurfaceMesh& mesh);  // VTK XML PolyData (.vtp)
std::string to_ply(const SurfaceMesh& mesh, const std::string& comment);
void write_vtk_legacy(const std::string& path, const SurfaceMesh& mesh, const std::string& title);
void write_vtk_xml(const std::string& path, const SurfaceMesh& mesh);
void write_ply(const std::string& path, const SurfaceMesh& mesh, const std::string& comment);

// The grid as CSV, one row per node "i,j,theta,phi,rho" (17 significant digits).
std::string to_csv(const ShapeGrid& grid);

// What `rbcstab shape` wrote: per file its time, path and the grid's rho range; with the run's model,
// status and reason (a failed run writes shapes up to where it stopped).
struct ShapeFile {
  double t = 0;
  std::string path;
  double rho_min = 0, rho_max = 0;
};
struct ShapeExport {
  ModelLevel model = ModelLevel::reduced;
  IntegrationStatus status = IntegrationStatus::success;
  std::string reason;
  std::vector<ShapeFile> files;
};
nlohmann::json to_json(
    const ShapeExport& e);  // {"model", "status", "reason", "files": [{"t", "file", "rho_min", "rho_max"}]}
std::string to_text(const ShapeExport& e);  // one line per file: path, t and rho range

}  // namespace rbcstab
