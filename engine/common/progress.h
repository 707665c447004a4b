#pragma once
// Long work (an environment made ready, a model's images decoded) reports how far it is and
// asks whether to go on.
#include <functional>

namespace patina {

// Told the fraction done now and then, from any thread; false stops the work.
using Progress = std::function<bool(float)>;

}  // namespace patina
