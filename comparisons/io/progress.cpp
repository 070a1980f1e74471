#include "comparisons/io/progress.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <unistd.h>

namespace tecido::io {

namespace {
constexpr int kBarWidth = 30;
constexpr auto kMinInterval = std::chrono::milliseconds(200);  // at most ~5 redraws a second
}  // namespace

Progress::Progress(std::size_t total, std::string label)
    : Progress(total, std::move(label), std::cerr, ::isatty(2) == 1) {
  rate_limited_ = true;
}

Progress::Progress(std::size_t total, std::string label, std::ostream& out, bool enabled)
    : total_(total), label_(std::move(label)), out_(&out), enabled_(enabled), rate_limited_(false),
      start_(std::chrono::steady_clock::now()), last_draw_(start_) {
  std::lock_guard<std::mutex> lock(mutex_);
  draw_locked(true);
}

Progress::~Progress() { finish(); }

std::string Progress::line(const std::string& label, std::size_t done, std::size_t total, double seconds) {
  const std::size_t shown = std::min(done, total);
  const int filled = total > 0 ? static_cast<int>(kBarWidth * shown / total) : kBarWidth;
  std::string bar(static_cast<std::size_t>(filled), '#');
  bar.append(static_cast<std::size_t>(kBarWidth - filled), '.');
  const double rate = seconds > 0.0 ? static_cast<double>(done) / seconds : 0.0;
  std::string eta = "--:--";
  if (shown >= total) {
    eta = "0:00";
  } else if (rate > 0.0) {
    const double left = static_cast<double>(total - shown) / rate;
    if (left < 1e7) {
      const long long s = std::llround(std::ceil(left));
      eta = fmt::format("{}:{:02d}", s / 60, static_cast<int>(s % 60));
    }
  }
  return fmt::format("{} [{}] {}/{}  {:.2f}/s  ETA {}", label, bar, done, total, rate, eta);
}

void Progress::draw_locked(bool force) {
  if (!enabled_ || finished_) return;
  const auto now = std::chrono::steady_clock::now();
  if (!force && rate_limited_ && now - last_draw_ < kMinInterval) return;
  last_draw_ = now;
  const std::string text = line(label_, done_, total_, std::chrono::duration<double>(now - start_).count());
  std::string padded = "\r" + text;
  if (text.size() < last_width_) padded.append(last_width_ - text.size(), ' ');
  last_width_ = text.size();
  *out_ << padded << std::flush;
}

void Progress::tick(std::size_t n) {
  std::lock_guard<std::mutex> lock(mutex_);
  done_ += n;
  draw_locked(false);
}

void Progress::finish() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (finished_) return;
  draw_locked(true);
  if (enabled_) *out_ << "\n" << std::flush;
  finished_ = true;
}

}  // namespace tecido::io
