#include "comparisons/suites/tolerances.h"

#include "comparisons/io/input_error.h"

namespace tecido::suites {

Tolerances Tolerances::load(const std::string& path) {
  io::Json doc = io::read_json_file(path);
  io::JsonReader r(path);
  r.require_object(doc, "");
  for (auto it = doc.begin(); it != doc.end(); ++it) {
    if (!it.key().empty() && it.key()[0] == '_') continue;
    const std::string w = io::child("", it.key());
    r.require_object(it.value(), w);
    for (auto jt = it.value().begin(); jt != it.value().end(); ++jt) {
      if (!jt.key().empty() && jt.key()[0] == '_') continue;
      r.number(jt.value(), io::child(w, jt.key()), 1e300);
    }
  }
  return Tolerances(std::move(doc), path);
}

double Tolerances::get(const std::string& pointer) const {
  // nlohmann throws on pointers that do not fit the document's shape (an array index that is
  // not a number, a malformed pointer): that is the same "missing tolerance" to the user.
  const io::Json* v = nullptr;
  try {
    const io::Json::json_pointer p(pointer);
    if (doc_.contains(p)) v = &doc_.at(p);
  } catch (const io::Json::exception&) {
    v = nullptr;
  }
  if (!v) throw io::InputError(file_, pointer, "missing tolerance");
  if (!v->is_number()) throw io::InputError(file_, pointer, "expected a number");
  return v->get<double>();
}

Band Tolerances::at_most(const std::string& pointer, double scale) const {
  return Band{0.0, get(pointer) * scale, pointer};
}

Band Tolerances::at_least(const std::string& pointer, double hi) const { return Band{get(pointer), hi, pointer}; }

Band Tolerances::around(const std::string& pointer, double center) const {
  const double w = get(pointer);
  return Band{center - w, center + w, pointer};
}

Band Tolerances::between(const std::string& lo_pointer, const std::string& hi_pointer) const {
  return Band{get(lo_pointer), get(hi_pointer), lo_pointer + " " + hi_pointer};
}

}  // namespace tecido::suites
