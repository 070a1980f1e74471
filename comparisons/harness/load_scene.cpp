// A scene file as the public Scene (include/tecido/harness.h: load_scene): the reader `tecido run`
// uses, its errors as the command line words them.
#include "comparisons/io/input_error.h"
#include "comparisons/io/scene_json.h"
#include "core/api/scene_access.h"

#include <tecido/harness.h>

#include <stdexcept>

namespace tecido::harness {

core::Scene load_scene(const std::string& path) {
  try {
    return core::detail::SceneAccess::wrap(io::load_scene(path));
  } catch (const io::FileError& e) {
    throw std::runtime_error(e.what());
  } catch (const io::InputError& e) {
    throw std::invalid_argument(e.what());
  }
}

}  // namespace tecido::harness
