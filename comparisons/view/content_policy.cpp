#include "comparisons/view/content_policy.h"

namespace tecido::view {

std::string content_policy_meta(bool with_scripts) {
  return std::string("<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; script-src ") +
         (with_scripts ? "'self'" : "'none'") +
         "; style-src 'self'; img-src 'self'; base-uri 'none'; form-action 'none'\">";
}

}  // namespace tecido::view
