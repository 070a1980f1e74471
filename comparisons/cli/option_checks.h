#pragma once
/// Validators for the command line's values, run by CLI11 while it parses (before any work):
/// a value out of its domain is a usage error naming the option, e.g.
/// "tecido: --dt: must be > 0 (got 0)", exit 2. Every numeric option and every path of every
/// subcommand has one; the limits are those of comparisons/io/limits.h.
#include <CLI/CLI.hpp>

#include <cstdint>
#include <initializer_list>
#include <string>

namespace tecido::cli {

/// A finite number x with lo < x (lo_open) or lo <= x, and x <= hi.
CLI::Validator number_in(double lo, bool lo_open, double hi);
/// An integer (decimal digits, optional sign; no fraction or exponent) in [lo, hi].
CLI::Validator integer_in(long long lo, long long hi);
/// A non-negative integer up to 2^64 - 1 (seeds).
CLI::Validator unsigned_integer();
/// A non-empty text (paths: an empty one would silently mean "not given").
CLI::Validator non_empty();
/// One of `names`.
CLI::Validator one_of(std::initializer_list<const char*> names);
/// "i/n" with 0 <= i < n <= kMaxShards.
CLI::Validator shard_spec();

}  // namespace tecido::cli
