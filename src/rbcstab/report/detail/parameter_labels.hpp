#pragma once
// A parameter and its value as figures and titles write them, from its row of the parameter table
// (model/parameter_table.hpp): "$\lambda = 5$" (mathtext; inf as \infty) and "lambda = 5" (plain text), at
// four significant digits. Which parameters a figure names is the figure's choice; how each reads is the table's.
#include <string>

#include "rbcstab/model/parameter_table.hpp"

namespace rbcstab::detail {

std::string tex_value(SceneParameter q, double value);
std::string plain_value(SceneParameter q, double value);

}  // namespace rbcstab::detail
