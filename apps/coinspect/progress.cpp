#include "progress.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>

namespace coinspect::app {

namespace {

// Redraws on a terminal are at least this far apart in wall time (10 per second).
constexpr double kRedrawInterval = 0.1;

}  // namespace

ProgressLine::ProgressLine(std::FILE* out, std::string label, double totalSimSeconds, Style style)
    : out_(out),
      label_(std::move(label)),
      total_(totalSimSeconds),
      terminal_(style == Style::Terminal || (style == Style::Auto && ::isatty(::fileno(out)) == 1)),
      start_(Clock::now()),
      lastDraw_(start_) {}

ProgressLine::~ProgressLine() {
  if (terminal_ && drawn_ && !finished_) {
    std::fputc('\n', out_);
    std::fflush(out_);
  }
}

void ProgressLine::setTotal(double totalSimSeconds) {
  total_ = totalSimSeconds;
}

std::string ProgressLine::text() const {
  const double wall = std::chrono::duration<double>(Clock::now() - start_).count();
  const double fraction = total_ > 0.0 ? std::clamp(simTime_ / total_, 0.0, 1.0) : 1.0;
  char line[256];
  std::snprintf(line, sizeof line,
                "%-10s t %.1f / %.1f s (%3.0f %%), Q = %.2f, detected %zu / %zu, %.1fx real time",
                label_.c_str(), simTime_, total_, 100.0 * fraction, score_, detected_, totalPoints_,
                wall > 0.0 ? simTime_ / wall : 0.0);
  return line;
}

void ProgressLine::draw() {
  const std::string line = text();
  if (terminal_) {
    // Spaces blank what a longer previous line left; no terminal escape codes needed.
    std::fprintf(out_, "\r%s%*s", line.c_str(),
                 static_cast<int>(width_ > line.size() ? width_ - line.size() : 0), "");
    width_ = line.size();
    drawn_ = true;
  } else {
    std::fprintf(out_, "%s\n", line.c_str());
  }
  std::fflush(out_);
  lastDraw_ = Clock::now();
}

void ProgressLine::update(double simTime, double score, size_t detected, size_t totalPoints) {
  if (finished_) return;
  simTime_ = simTime;
  score_ = score;
  detected_ = detected;
  totalPoints_ = totalPoints;
  if (terminal_) {
    const double sinceDraw = std::chrono::duration<double>(Clock::now() - lastDraw_).count();
    if (!drawn_ || sinceDraw >= kRedrawInterval) draw();
    return;
  }
  // Plain: one line when the update reaches another 10 % step (several steps at once: one line).
  const int tenths =
      total_ > 0.0 ? std::min(10, static_cast<int>(std::floor(10.0 * simTime / total_ + 1e-9))) : 0;
  lastPrinted_ = tenths > tenthsPrinted_;
  if (lastPrinted_) {
    tenthsPrinted_ = tenths;
    draw();
  }
}

void ProgressLine::finish() {
  if (finished_) return;
  if (terminal_) {
    draw();
    std::fputc('\n', out_);
    std::fflush(out_);
  } else if (!lastPrinted_ && tenthsPrinted_ < 10) {
    draw();
  }
  finished_ = true;
}

}  // namespace coinspect::app
