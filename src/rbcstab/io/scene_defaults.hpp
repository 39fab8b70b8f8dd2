#pragma once
// Scene keys whose default is not a value but a choice each computation makes: run.L (the truncation policy,
// analysis/truncation.hpp: each command states its L) and initial.beta (a run uses the scene's 0.001, a
// continuation its kind's own, default_beta in continuation/scene_kinds.hpp). What a result depends on is
// then whether the key was given, not only its value: a front end shows such a key as unset until it is given
// (Python: None), and a copy of a scene carries whether it was.
#include "rbcstab/io/scene_file.hpp"

namespace rbcstab {

inline bool default_is_a_choice(const SceneKey& key) { return key.path() == "run.L" || key.path() == "initial.beta"; }

}  // namespace rbcstab
