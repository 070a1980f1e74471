// libFuzzer target: the tolerance file (suites::Tolerances). Two paths, both as the CLI uses
// them: Tolerances::load(path) on the bytes written to a scratch file (the validating reader
// behind `tecido suite --tolerances FILE`), and Tolerances(Json, file) on the parsed bytes
// followed by get() of the pointers the suites ask for and of every key the document has.
// Both may reject only with io::InputError; a number get() returns from a loaded file must be
// finite.
#include "fuzz_common.h"

#include "comparisons/suites/suite.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <unistd.h>

namespace {

constexpr const char* kTarget = "fuzz_tolerances";

/// JSON pointer escaping (RFC 6901), so that any key, even with '/' or '~', is asked for exactly.
std::string escape(const std::string& key) {
  std::string out;
  for (char c : key) out += c == '~' ? std::string("~0") : c == '/' ? std::string("~1") : std::string(1, c);
  return out;
}

/// Pointers the suites ask for, plus the shapes a hostile file might confuse, including empty
/// tokens ("/", "/order/"): nlohmann::json 3.11.2's contains() answers true for an empty token
/// into an array and at() then throws out_of_range; get() turns that into InputError now.
const char* const kPointers[] = {"/order/band", "/order/roundoff_floor", "/order/too_big", "/plane/core_agreement_random",
                                 "/tritri/core_min_agreement", "/drift/momentum_rel", "", "/order", "/order/band/x",
                                 "/0", "/0/0", "/a~1b/c~0d", "/order/0", "/order/-", "/order/01", "/", "/order/", "//"};

void ask_everything(const tecido::suites::Tolerances& tol, const tecido::io::Json& doc, bool loaded) {
  auto ask = [&](const std::string& pointer) {
    try {
      const double v = tol.get(pointer);
      if (loaded && !std::isfinite(v)) tecido::fuzz::finding(kTarget, "loaded file gives a non-finite tolerance at " + pointer);
    } catch (const tecido::io::InputError&) {
    }
  };
  for (const char* p : kPointers) ask(p);
  if (!doc.is_object()) return;
  for (auto it = doc.begin(); it != doc.end(); ++it) {
    const std::string w = "/" + escape(it.key());
    ask(w);
    if (!it.value().is_object()) continue;
    for (auto jt = it.value().begin(); jt != it.value().end(); ++jt) ask(w + "/" + escape(jt.key()));
  }
}

/// A scratch file per process, removed at exit; in /dev/shm when there is one (rewriting a
/// truncated file on ext4 flushes it to disk at every close, 100 times slower).
struct Scratch {
  std::string path = (::access("/dev/shm", W_OK) == 0 ? std::string("/dev/shm") : std::string("/tmp")) +
                     "/tecido-fuzz-tolerances-" + std::to_string(::getpid()) + ".json";
  ~Scratch() { std::remove(path.c_str()); }
};

const std::string& scratch_path() {
  static const Scratch scratch;
  return scratch.path;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text = tecido::fuzz::as_text(data, size);
  // The constructor from an already-parsed document (no validation of its own).
  tecido::fuzz::expect_only_input_errors(kTarget, [&] {
    const tecido::io::Json doc = tecido::fuzz::parse_checked(kTarget, text);
    const tecido::suites::Tolerances tol(doc, "fuzz.json");
    ask_everything(tol, doc, false);
  });
  // The validating loader, through a file.
  {
    std::ofstream out(scratch_path(), std::ios::binary | std::ios::trunc);
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
  }
  tecido::fuzz::expect_only_input_errors(kTarget, [&] {
    const tecido::suites::Tolerances tol = tecido::suites::Tolerances::load(scratch_path());
    const tecido::io::Json doc = tecido::io::parse_json_text(text, "fuzz.json");
    ask_everything(tol, doc, true);
  });
  return 0;
}
