#include "comparisons/suites/suite.h"

#include <cmath>

namespace tecido::suites {

Check make_check(std::string name, double value, double lo, double hi, std::string note) {
  Check c;
  c.name = std::move(name);
  c.value = value;
  c.lo = lo;
  c.hi = hi;
  c.pass = std::isfinite(value) ? (value >= lo && value <= hi) : false;
  c.note = std::move(note);
  return c;
}

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

}  // namespace tecido::suites
