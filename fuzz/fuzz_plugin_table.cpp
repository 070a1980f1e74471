// libFuzzer target: the validation of a plug-in's engine table (check_plugin_table, what
// PluginLibrary::load runs after dlopen and the ABI check; comparisons/engines/outside/plugin_library.h),
// on tables built from the fuzzer's bytes instead of a shared library. Rejections must be
// EngineError (an io::InputError); anything else is a finding, and so is an accepted table that
// breaks a rule load() promises: 1 to 1000 engines, every name 1-64 of [A-Za-z0-9_.-] not
// starting with '-' and distinct, a dynamics engine with all of create/step/read/destroy,
// claimed_order in [0, 100], at least one function per engine.
// Input: byte 0 the engine count (255: a count past 1000 with no array behind it, which must be
// rejected before it is read; 254: a null array; else b % 9), then per engine: a name length
// byte (255: a null name; else b % 72), the name's bytes, a byte of which functions are set
// (bit k: tri_tri, segment_plane, ccd_vertex_face, ccd_edge_edge, create, step, read, destroy),
// and the claimed order as fuzz_coordinates.h reads a coordinate.
#include "fuzz_common.h"
#include "fuzz_coordinates.h"

#include "comparisons/engines/outside/engine_error.h"
#include "comparisons/engines/outside/plugin_library.h"

#include <set>

namespace {

constexpr const char* kTarget = "fuzz_plugin_table";

int tri_tri(const double*, const double*) { return 0; }
int segment_plane(const tecido_plane*, const double*, const double*, double*) { return 0; }
int ccd(const double*, const double*, double*) { return 0; }
void* create(const tecido_scene*, char*, size_t) { return nullptr; }
int step(void*, double, int64_t) { return 0; }
void read(const void*, double*, double*) {}
void destroy(void*) {}

tecido_engine engine_from(tecido::fuzz::Bytes& in, std::string& name_store, double* orders, int k) {
  tecido_engine e{};
  const std::uint8_t len = in.u8();
  if (len != 255) {
    for (int i = 0; i < len % 72; ++i) name_store.push_back(static_cast<char>(in.u8()));
    e.name = name_store.c_str();
  }
  const std::uint8_t f = in.u8();
  if (f & 1) e.tri_tri = &tri_tri;
  if (f & 2) e.segment_plane = &segment_plane;
  if (f & 4) e.ccd_vertex_face = &ccd;
  if (f & 8) e.ccd_edge_edge = &ccd;
  if (f & 16) e.create = &create;
  if (f & 32) e.step = &step;
  if (f & 64) e.read = &read;
  if (f & 128) e.destroy = &destroy;
  orders[k] = tecido::fuzz::decode_coordinate(in, orders, k);
  e.claimed_order = orders[k];
  return e;
}

void check_accepted(const tecido_plugin& t) {
  using tecido::fuzz::finding;
  if (t.engine_count < 1 || t.engine_count > 1000 || !t.engines) finding(kTarget, "accepted an engine count of " + std::to_string(t.engine_count));
  std::set<std::string> names;
  for (std::size_t k = 0; k < t.engine_count; ++k) {
    const tecido_engine& e = t.engines[k];
    if (!e.name) finding(kTarget, "accepted a null name");
    const std::string name = e.name;
    if (!tecido::outside::valid_engine_name(name) || name.size() > 64 || name[0] == '-') finding(kTarget, "accepted the name " + name);
    for (char c : name)
      if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '.' && c != '-') finding(kTarget, "accepted the name " + name);
    if (!names.insert(name).second) finding(kTarget, "accepted the name " + name + " twice");
    const int dyn = !!e.create + !!e.step + !!e.read + !!e.destroy;
    if (dyn != 0 && dyn != 4) finding(kTarget, "accepted a partial dynamics engine " + name);
    if (!(e.claimed_order >= 0.0 && e.claimed_order <= 100.0)) finding(kTarget, "accepted claimed_order " + std::to_string(e.claimed_order));
    if (!e.tri_tri && !e.segment_plane && !e.ccd_vertex_face && !e.ccd_edge_edge && dyn == 0) finding(kTarget, "accepted an engine without functions");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  tecido::fuzz::Bytes in(data, size);
  const std::uint8_t count = in.u8();
  const std::size_t n = count >= 254 ? 0 : count % 9;
  std::vector<std::string> names(n);
  std::vector<tecido_engine> engines;
  double orders[9];
  for (std::size_t k = 0; k < n; ++k) engines.push_back(engine_from(in, names[k], orders, static_cast<int>(k)));
  tecido_plugin t{};
  t.abi_version = TECIDO_PLUGIN_ABI_VERSION;
  t.engine_count = count == 255 ? 1001 + in.u16() : n;
  t.engines = count >= 254 || engines.empty() ? (count == 255 ? engines.data() : nullptr) : engines.data();
  tecido::fuzz::expect_only_input_errors(kTarget, [&] {
    tecido::outside::check_plugin_table("fuzz.so", t);
    check_accepted(t);
  });
  return 0;
}
