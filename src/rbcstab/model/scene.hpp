#pragma once
// A scene: material, flow, stress-free shape, orientation, perturbations, truncation and horizon.
// It builds the initial amplitudes as the paper does (Sec. IV, Appendix A) and picks the smallest
// model level that is exact for it.
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "rbcstab/model/amplitudes.hpp"
#include "rbcstab/model/parameters.hpp"
#include "rbcstab/model/physical.hpp"
#include "rbcstab/model/system.hpp"

namespace rbcstab {

// The truncation L: modes l = 2..L. One rule for every caller: an integer in [min_L, max_L]; the scene's
// range is [kMinL, kMaxL], and a computation that needs a mode l >= 3 (min_L = 3) or that is dense in L (the
// full equilibrium problem, max_L = 16) narrows it and says why. Throws InvalidArgument(name, "L = 17 is out
// of range: must be an integer in [2, 16] (why)").
inline constexpr int kMinL = 2, kMaxL = 100;
void require_L(long long L, int min_L = kMinL, int max_L = kMaxL, std::string_view why = {},
               std::string_view name = "L");

struct Scene {
  std::string name = "fig3_op";        // label carried into outputs: one line of printable text
  Parameters parameters;               // defaults: the paper's Fig. 3 case
  double beta = 0.001;                 // rotation of the axisymmetric shapes about y (0: out of plane, pi/2: in plane)
  double delta = 1e-3;                 // perturbation Delta_l(0) put in f_{l,0} for every l = 3..L
  std::map<int, double> delta_l;       // per-mode overrides of delta
  std::map<int, double> rest_delta_l;  // stress-free l >= 3 content Delta0_l (only the full model holds it)
  int L = 10;                          // truncation: modes l = 2..L (require_L)
  double T = 500;                      // horizon
  double dt = 1;                       // output sampling interval
  ModelLevel model = ModelLevel::automatic;  // forced level, or automatic
  // A physical scene's inputs (SI): B, C and the numbers their inputs give were derived from them
  // (physical_parameters); times are in units of 1/shear_rate.
  std::optional<PhysicalCell> physical;

  void validate() const;             // throws InvalidArgument naming the key (parameter domains: parameter_table.hpp)
  double perturbation(int l) const;  // delta_l with overrides applied
  double rest_perturbation(int l) const;
};

struct SceneFile;  // io/scene_file.hpp

// A scene that passed validate(): the calls a computation makes on its scene take one and do not check it again,
// while a library caller with a plain Scene gets every check (each such call has a Scene overload that validates).
// Only the validated() functions make one, so holding one means this very scene was checked; it refers to the
// scene, which must outlive it and not change while it is used (except to an L that validated_at_L accepted).
class ValidScene {
 public:
  const Scene& operator*() const { return *scene_; }
  const Scene* operator->() const { return scene_; }

 private:
  explicit ValidScene(const Scene& scene) : scene_(&scene) {}
  friend ValidScene validated(const Scene& scene);
  friend ValidScene validated(const SceneFile& file);  // io: the check whose messages name flags and files
  friend ValidScene validated_at_L(const ValidScene& valid, Scene& copy, int L);
  const Scene* scene_;
};
ValidScene validated(const Scene& scene);  // scene.validate(), then the proof of it
// The valid scene at another L: copy = *valid with copy.L = L, checking only what L decides (its range, and the
// modes delta_l and rest_delta_l set below it), since every other key is the valid scene's.
ValidScene validated_at_L(const ValidScene& valid, Scene& copy, int L);
// The reduced companion of a scene: same material and orientation, only the l = 2 block, perturbations
// dropped (Sec. III): the Fig. 2 r, Psi, the sigma_R(t) of Fig. 3, the truncation rule's certified transient.
Scene reduced_scene(const Scene& s);

struct InitialState {
  ModeAmplitudes f;  // current shape f_{l,m}(0)
  ModeAmplitudes g;  // stress-free shape g_{l,m}(0)
};

// f_{2,m} = -sqrt(Delta/a_2) D^(2)_{m,0}(beta), f_{l,m} = +sqrt(delta_l/a_l) D^(l)_{m,0}(beta),
// g likewise with Delta0 and the rest perturbations. Delta_2(0) = Delta, as in the paper.
InitialState initial_state(const Scene& scene);
InitialState initial_state(const ValidScene& scene);

struct LevelChoice {
  ModelLevel level = ModelLevel::automatic;  // automatic only before a choice is made
  bool exact = false;                        // the chosen level represents the scene without approximation
  std::string reason;                        // why this level (and what is dropped if not exact)
};
// The smallest exact level unless scene.model forces one; forcing a level that cannot hold the
// scene's stress-free shape throws InvalidArgument("model", ...).
LevelChoice choose_level(const Scene& scene, const InitialState& init);

std::unique_ptr<System> make_system(const Parameters& p, const InitialState& init, ModelLevel level);

// The system a scene runs on, as a simulation builds it (validates the scene): its initial amplitudes, the
// level choice, the system, and the warnings a run reports (the parameters', and the level's if it approximates).
struct SceneSystem {
  InitialState init;
  LevelChoice level;
  std::unique_ptr<System> system;
  std::vector<std::string> warnings;
};
SceneSystem make_scene_system(const Scene& scene);
SceneSystem make_scene_system(const ValidScene& scene);

}  // namespace rbcstab
