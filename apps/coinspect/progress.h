// A progress line for long work (`coinspect run`, `coinspect eval`): simulated time / total,
// score, detected points and the real-time factor. On a terminal one line is redrawn in place
// ('\r', at most 10 times per wall second); otherwise (a pipe, a file) a plain line is printed
// each time another 10 % of the total simulated time is reached, so logs stay short and, apart
// from the factor, the same from run to run.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdio>
#include <string>

namespace coinspect::app {

class ProgressLine {
 public:
  // Auto: Terminal when `out` is a terminal (isatty), else Plain. Tests force one of the others.
  enum class Style { Auto, Terminal, Plain };

  ProgressLine(std::FILE* out, std::string label, double totalSimSeconds,
               Style style = Style::Auto);
  // Ends a line left open on a terminal (an error message then starts on a line of its own).
  ~ProgressLine();
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  // The total once it is known better (a mission's end is its take-off time + the budget).
  void setTotal(double totalSimSeconds);
  void update(double simTime, double score, size_t detected, size_t totalPoints);
  // Terminal: draws the last state and ends the line. Plain: prints the last state unless the
  // 100 % line was printed already (a run that ended early). Later calls do nothing.
  void finish();

  bool terminal() const { return terminal_; }

 private:
  using Clock = std::chrono::steady_clock;
  std::string text() const;
  void draw();

  std::FILE* out_;
  std::string label_;
  double total_;
  bool terminal_;
  Clock::time_point start_;
  Clock::time_point lastDraw_;
  bool drawn_ = false;  // terminal: something is on the open line
  bool finished_ = false;
  bool lastPrinted_ = false;  // plain: the latest update has been printed
  int tenthsPrinted_ = 0;     // plain: 10 % steps printed so far
  size_t width_ = 0;          // terminal: length of the line drawn last, to blank leftovers
  double simTime_ = 0.0, score_ = 0.0;
  size_t detected_ = 0, totalPoints_ = 0;
};

}  // namespace coinspect::app
