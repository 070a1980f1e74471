#include "query_calls.h"

#include "arrays.h"
#include "engine_choice.h"

#include "comparisons/engines/ccd_engines.h"
#include "comparisons/engines/run_engines.h"
#include "comparisons/engines/tri_tri_engines.h"
#include "comparisons/io/input_error.h"

#include <pybind11/numpy.h>

#include <algorithm>
#include <chrono>
#include <limits>

namespace tecido::python {

namespace {

/// The coordinate bound of the pairs file (comparisons/io/tri_pairs.h).
constexpr double kMaxTriTriCoordinate = 1e15;

void check_same_count(std::size_t n, std::size_t m, const std::string& first, const std::string& second) {
  if (n != m)
    throw io::UsageError(second + ": " + std::to_string(m) + " queries, but " + first + " has " + std::to_string(n));
}

[[noreturn]] void no_answer(const std::string& engine, std::size_t query) {
  throw io::UsageError("engine " + engine + " gives no answer to query " + std::to_string(query) +
                       " (pass answered=True for a mask of the answered queries)");
}

/// The answers as arrays: hits, the value of each hit (`value`), and which were answered. Without
/// `answered`, an unanswered query is a ValueError naming the engine and the query.
template <class Answer, class Hit, class Value>
py::object answer_arrays(const std::vector<std::optional<Answer>>& answers, const std::string& engine, bool answered,
                         Hit hit_of, Value value_of, bool with_values) {
  const auto n = static_cast<py::ssize_t>(answers.size());
  py::array_t<bool> hits(n), known(n);
  py::array_t<double> values(n);
  bool* h = hits.mutable_data();
  bool* k = known.mutable_data();
  double* v = values.mutable_data();
  for (py::ssize_t i = 0; i < n; ++i) {
    const auto& a = answers[static_cast<std::size_t>(i)];
    if (!a && !answered) no_answer(engine, static_cast<std::size_t>(i));
    k[i] = a.has_value();
    h[i] = a && hit_of(*a);
    v[i] = a && hit_of(*a) ? value_of(*a) : std::numeric_limits<double>::quiet_NaN();
  }
  if (!with_values) return answered ? py::object(py::make_tuple(hits, known)) : py::object(hits);
  return answered ? py::make_tuple(hits, values, known) : py::make_tuple(hits, values);
}

CcdKind parse_kind(const std::string& kind) {
  if (kind == "vf" || kind == "vertex-face") return CcdKind::VertexFace;
  if (kind == "ee" || kind == "edge-edge") return CcdKind::EdgeEdge;
  throw io::UsageError("kind: expected \"vf\" (vertex-face) or \"ee\" (edge-edge), got \"" + kind + "\"");
}

std::vector<outside::TriTriQuery> tri_tri_queries(py::handle a, py::handle b) {
  const std::vector<Vec3> pa = point_array(a, "a", 3, kMaxTriTriCoordinate);
  const std::vector<Vec3> pb = point_array(b, "b", 3, kMaxTriTriCoordinate);
  check_same_count(pa.size() / 3, pb.size() / 3, "a", "b");
  std::vector<outside::TriTriQuery> q(pa.size() / 3);
  for (std::size_t i = 0; i < q.size(); ++i)
    for (std::size_t c = 0; c < 3; ++c) q[i].a[c] = pa[3 * i + c], q[i].b[c] = pb[3 * i + c];
  return q;
}

std::vector<std::string> builtin_tri_tri() { return tri_tri_engine_names(nullptr); }

}  // namespace

py::object tri_tri_call(py::handle a, py::handle b, py::handle engine, bool answered) {
  const EngineChoice e = choose_engine(engine, builtin_tri_tri(), "tri-tri", &outside::Capabilities::tri_tri);
  const TriTriEngine* builtin = find_tri_tri_engine(e.name);
  if (!builtin) {  // a Python engine: the batch through its door (run_engines.h)
    const std::vector<outside::TriTriQuery> queries = tri_tri_queries(a, b);
    std::vector<std::optional<bool>> answers;
    {
      py::gil_scoped_release release;
      answers = tri_tri_answers(e.name, queries, e.outside.get());
    }
    return answer_arrays(answers, e.name, answered, [](bool h) { return h; }, [](bool) { return 0.0; }, false);
  }
  // A built-in engine: its test on the arrays as they are read, straight into the result, with no
  // copy of the input (what tri_tri_answers does for a batch, without the batch: per pair, the
  // cost of the call is then the reading and checking of 18 numbers).
  const PointBlocks pa(a, "a", 3, kMaxTriTriCoordinate), pb(b, "b", 3, kMaxTriTriCoordinate);
  check_same_count(pa.size(), pb.size(), "a", "b");
  const auto n = static_cast<py::ssize_t>(pa.size());
  py::array_t<bool> hits(n), known(n);
  bool* h = hits.mutable_data();
  bool* k = known.mutable_data();
  {
    py::gil_scoped_release release;
    for (py::ssize_t i = 0; i < n; ++i) {
      const auto u = static_cast<std::size_t>(i);
      const Triangle ta = {pa.point(u, 0), pa.point(u, 1), pa.point(u, 2)};
      const Triangle tb = {pb.point(u, 0), pb.point(u, 1), pb.point(u, 2)};
      const std::optional<bool> r = builtin->test(ta, tb);
      h[i] = r.value_or(false);
      k[i] = r.has_value();
    }
  }
  for (py::ssize_t i = 0; i < n && !answered; ++i)
    if (!k[i]) no_answer(e.name, static_cast<std::size_t>(i));
  return answered ? py::object(py::make_tuple(hits, known)) : py::object(hits);
}

py::object ccd_call(py::handle t0, py::handle t1, const std::string& kind, py::handle engine, bool answered) {
  const CcdKind k = parse_kind(kind);
  const EngineChoice e = choose_engine(engine, ccd_engine_names(nullptr), "ccd", &outside::Capabilities::ccd_vertex_face);
  const double any = std::numeric_limits<double>::max();
  const std::vector<Vec3> x0 = point_array(t0, "t0", 4, any), x1 = point_array(t1, "t1", 4, any);
  check_same_count(x0.size() / 4, x1.size() / 4, "t0", "t1");
  std::vector<CcdQuery> queries(x0.size() / 4);
  for (std::size_t i = 0; i < queries.size(); ++i) {
    queries[i].kind = k;
    for (std::size_t c = 0; c < 4; ++c) queries[i].x0[c] = x0[4 * i + c], queries[i].x1[c] = x1[4 * i + c];
  }
  std::vector<std::optional<CcdAnswer>> answers;
  {
    py::gil_scoped_release release;
    answers = ccd_answers(e.name, queries, e.outside.get());
  }
  return answer_arrays(answers, e.name, answered, [](const CcdAnswer& c) { return c.hit; },
                       [](const CcdAnswer& c) { return c.toi; }, true);
}

double time_tri_tri(py::handle a, py::handle b, const std::string& engine, int repeats) {
  const TriTriEngine* e = find_tri_tri_engine(engine);
  if (!e) throw io::UsageError("engine: not a built-in tri-tri engine: \"" + engine + "\"");
  const std::vector<outside::TriTriQuery> queries = tri_tri_queries(a, b);
  if (queries.empty()) return 0.0;
  py::gil_scoped_release release;
  double best = std::numeric_limits<double>::infinity();
  volatile long hits = 0;
  for (int r = 0; r < std::max(1, repeats); ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    long h = 0;
    for (const auto& q : queries) h += e->test(q.a, q.b).value_or(false);
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    hits = hits + h;
  }
  return best / static_cast<double>(queries.size());
}

}  // namespace tecido::python
