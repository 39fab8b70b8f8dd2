#pragma once
// Parsing a scene file's TOML text, shared by every module that reads a table of it (io: the scene;
// sweep: [diagram]; report: [fig6e], [continuation]). Internal: it exposes toml++ types, which the
// installed headers never do.
#include <sstream>
#include <string>
#include <toml++/toml.h>

#include "rbcstab/core/error.hpp"

namespace rbcstab::detail {

// The root table; a syntax error becomes InvalidArgument("scene", "<source>:<line>:<column>: ...").
inline toml::table parse_scene_toml(const std::string& text, const std::string& source) {
  try {
    return toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    std::ostringstream msg;
    msg << source << ":" << e.source().begin.line << ":" << e.source().begin.column << ": " << e.description();
    throw InvalidArgument("scene", "cannot parse scene file " + msg.str());
  }
}

}  // namespace rbcstab::detail
