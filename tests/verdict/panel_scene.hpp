#pragma once
// A paper panel's scene file from scenes/ (RBCSTAB_SCENES_DIR), for the verdict tests.
#include <string>

#include "rbcstab/io/scene_file.hpp"

namespace rbcstab::test {

inline SceneFile panel(const std::string& name) {
  return load_scene(std::string(RBCSTAB_SCENES_DIR) + "/" + name + ".toml");
}

}  // namespace rbcstab::test
